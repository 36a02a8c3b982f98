//! Pipelines: compute and graphics pipeline creation (each create info, derivatives,
//! caches, creation feedback) and the record the device keeps of each.

use super::pipeline_fixed::{
    check_blend_identical, check_fixed_function, check_targets, check_viewport_state,
    check_zero_attachments, rendering_targets, subpass_targets,
};
use super::pipeline_stages::{
    check_execution_modes, check_point_size, check_present, check_stage_interfaces,
    check_stage_linking, check_stage_resources, check_stages, limited_resources,
};
use super::shader::{
    check_constant_sizes, check_shader_layout, check_specialization_data, check_stage_builtins,
    check_stage_subgroups, declared_resources,
};
use super::{chained, limits, refuse};
use crate::handles::*;
use crate::state::{LayoutRecord, PipelineRecord};
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;
use tuff_runtime::Vrc;

/// Holds the pipeline cache a pipeline creation uses for the call: a cache created
/// with `VK_PIPELINE_CACHE_CREATE_EXTERNALLY_SYNCHRONIZED_BIT` must not be used by
/// two threads at once (`VUID-vkCreateGraphicsPipelines-pipelineCache-02876`,
/// `VUID-vkCreateComputePipelines-pipelineCache-02873`), and one without it costs
/// the lock only.
pub(crate) fn pipeline_cache_hold(
    _device: &Device,
    cache: Option<&PipelineCache>,
) -> Result<Vec<tuff_runtime::HostSyncGuard>> {
    Ok(tuff_runtime::lock_all(
        cache.map(|c| c.host_sync().clone()).into_iter().collect(),
    ))
}

/// A chained `VkPipelineCreationFeedbackCreateInfo` (in `next`, the chain of a create
/// info of `stages` stages) names where the driver writes the pipeline's feedback
/// (`parameter`: the safe struct has no setter for it, so a safe program's is NULL)
/// and as many stage feedbacks as stages, or none (`count`).
fn check_creation_feedback(
    next: *const core::ffi::c_void,
    stages: u32,
    (parameter, count): (&'static str, &'static str),
    at: &dyn core::fmt::Display,
) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let feedback: Option<&vk::PipelineCreationFeedbackCreateInfo<'_>> = unsafe {
        chained(
            next,
            vk::StructureType::PIPELINE_CREATION_FEEDBACK_CREATE_INFO,
        )
    };
    let Some(feedback) = feedback else {
        return Ok(());
    };
    if feedback.p_pipeline_creation_feedback.is_null() {
        refuse(
            parameter,
            format!("{at}: a chained VkPipelineCreationFeedbackCreateInfo's pPipelineCreationFeedback is NULL, and the driver writes through it"),
        )?;
    }
    let n = feedback.pipeline_stage_creation_feedback_count;
    if n != 0 && n != stages {
        refuse(
            count,
            format!("{at}: pipelineStageCreationFeedbackCount ({n}) is neither 0 nor the pipeline's stage count ({stages})"),
        )?;
    }
    Ok(())
}

/// The checks of `vkCreateComputePipelines` that keep the driver inside the
/// specialization data.
pub(crate) fn create_compute_pipelines_checks(
    device: &Device,
    create_infos: &[ComputePipelineCreateInfo<'_>],
) -> Result<()> {
    compute_pipeline_state_checks(device, create_infos)?;
    for (i, info) in create_infos.iter().enumerate() {
        let raw = info.as_raw();
        check_specialization_data(&raw.stage, &format_args!("pCreateInfos[{i}].stage"))?;
        check_constant_sizes(device, &raw.stage, &format_args!("pCreateInfos[{i}].stage"))?;
        check_stage_subgroups(device, &raw.stage, &format_args!("pCreateInfos[{i}].stage"))?;
        check_creation_feedback(
            raw.p_next,
            1,
            (
                "VUID-VkPipelineCreationFeedbackCreateInfo-pPipelineCreationFeedback-parameter",
                "VUID-VkComputePipelineCreateInfo-pipelineStageCreationFeedbackCount-06566",
            ),
            &format_args!("pCreateInfos[{i}]"),
        )?;
        check_shader_layout(
            device,
            &raw.stage,
            raw.layout,
            "VUID-VkComputePipelineCreateInfo-layout-00703",
            &format_args!("pCreateInfos[{i}].stage"),
        )?;
    }
    Ok(())
}

/// The checks of `vkCreateGraphicsPipelines` that keep the driver from reading through
/// a NULL array or past the specialization data: the stages are given, and the
/// viewports and scissors are given or dynamic.
pub(crate) fn create_graphics_pipelines_checks(
    device: &Device,
    create_infos: &[GraphicsPipelineCreateInfo<'_>],
) -> Result<()> {
    for (i, info) in create_infos.iter().enumerate() {
        let raw = info.as_raw();
        if raw.stage_count > 0 && raw.p_stages.is_null() {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-06600",
                format!(
                    "pCreateInfos[{i}]: stageCount is {} but pStages is not set",
                    raw.stage_count
                ),
            )?;
        }
        check_creation_feedback(
            raw.p_next,
            raw.stage_count,
            (
                "VUID-VkPipelineCreationFeedbackCreateInfo-pPipelineCreationFeedback-parameter",
                "VUID-VkGraphicsPipelineCreateInfo-pipelineStageCreationFeedbackCount-06594",
            ),
            &format_args!("pCreateInfos[{i}]"),
        )?;
        // SAFETY: the safe setter stores the stages with their count.
        let stages = unsafe { crate::state::raw_slice(raw.p_stages, raw.stage_count) };
        for (j, stage) in stages.iter().enumerate() {
            // Before the stage's module is read for the stage: a stage no graphics
            // pipeline state has (compute, say) is refused as such.
            let graphics = vk::ShaderStageFlags::VERTEX
                | vk::ShaderStageFlags::TESSELLATION_CONTROL
                | vk::ShaderStageFlags::TESSELLATION_EVALUATION
                | vk::ShaderStageFlags::GEOMETRY
                | vk::ShaderStageFlags::FRAGMENT;
            if !graphics.contains(stage.stage) || stage.stage.is_empty() {
                refuse(
                    "VUID-VkGraphicsPipelineCreateInfo-pStages-06896",
                    format!("pCreateInfos[{i}].pStages[{j}].stage ({:?}) is no stage of pre-rasterization or fragment shader state", stage.stage),
                )?;
            }
            check_specialization_data(stage, &format_args!("pCreateInfos[{i}].pStages[{j}]"))?;
            check_constant_sizes(
                device,
                stage,
                &format_args!("pCreateInfos[{i}].pStages[{j}]"),
            )?;
            check_stage_builtins(
                device,
                stage,
                &format_args!("pCreateInfos[{i}].pStages[{j}]"),
            )?;
            check_stage_subgroups(
                device,
                stage,
                &format_args!("pCreateInfos[{i}].pStages[{j}]"),
            )?;
            check_shader_layout(
                device,
                stage,
                raw.layout,
                "VUID-VkGraphicsPipelineCreateInfo-layout-00756",
                &format_args!("pCreateInfos[{i}].pStages[{j}]"),
            )?;
        }
        // SAFETY: the safe setters store references that outlive the create info, and
        // each array with its count.
        let (viewport, dynamic, raster) = unsafe {
            (
                raw.p_viewport_state.as_ref(),
                raw.p_dynamic_state.as_ref().map_or(&[][..], |d| {
                    crate::state::raw_slice(d.p_dynamic_states, d.dynamic_state_count)
                }),
                raw.p_rasterization_state.as_ref(),
            )
        };
        let Some(viewport) = viewport else { continue };
        let has =
            |a: vk::DynamicState, b: vk::DynamicState| dynamic.iter().any(|d| *d == a || *d == b);
        // With rasterization discarded (and not dynamically), the viewport state is
        // not read.
        let discarded = raster.is_some_and(|r| r.rasterizer_discard_enable == vk::TRUE)
            && !has(
                vk::DynamicState::RASTERIZER_DISCARD_ENABLE,
                vk::DynamicState::RASTERIZER_DISCARD_ENABLE,
            );
        if discarded {
            continue;
        }
        let max = limits(device).max_viewports;
        let multi = device.live().features().multi_viewport == vk::TRUE;
        for (count, what, limit_vuid, multi_vuid) in [
            (
                viewport.viewport_count,
                "viewportCount",
                "VUID-VkPipelineViewportStateCreateInfo-viewportCount-01218",
                "VUID-VkPipelineViewportStateCreateInfo-viewportCount-01216",
            ),
            (
                viewport.scissor_count,
                "scissorCount",
                "VUID-VkPipelineViewportStateCreateInfo-scissorCount-01219",
                "VUID-VkPipelineViewportStateCreateInfo-scissorCount-01217",
            ),
        ] {
            if !multi && count > 1 {
                refuse(multi_vuid, format!("pCreateInfos[{i}]: without the multiViewport feature {what} must be at most 1 ({count})"))?;
            }
            if count > max {
                refuse(
                    limit_vuid,
                    format!(
                        "pCreateInfos[{i}]: {what} must be at most maxViewports ({count} > {max})"
                    ),
                )?;
            }
        }
        let dynamic_viewports = has(
            vk::DynamicState::VIEWPORT,
            vk::DynamicState::VIEWPORT_WITH_COUNT,
        );
        if viewport.viewport_count > 0 && viewport.p_viewports.is_null() && !dynamic_viewports {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04130",
                format!("pCreateInfos[{i}]: the viewports are neither given ({} without an array) nor dynamic", viewport.viewport_count),
            )?;
        }
        let dynamic_scissors = has(
            vk::DynamicState::SCISSOR,
            vk::DynamicState::SCISSOR_WITH_COUNT,
        );
        if viewport.scissor_count > 0 && viewport.p_scissors.is_null() && !dynamic_scissors {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04131",
                format!("pCreateInfos[{i}]: the scissors are neither given ({} without an array) nor dynamic", viewport.scissor_count),
            )?;
        }
    }
    Ok(())
}

/// The device remembers each pipeline's bind point, layout and the vertex bindings
/// its vertex shader reads.
fn pipelines_created(
    device: &Device,
    pipelines: &[Pipeline],
    bind_point: vk::PipelineBindPoint,
    records: impl Iterator<Item = (vk::PipelineLayout, PipelineRecord)>,
) {
    for (p, (layout, record)) in pipelines.iter().zip(records) {
        if let Some(layout) = device.live().pipeline_layout(layout) {
            device.live().pipeline_created(
                p.raw(),
                PipelineRecord {
                    bind_point,
                    layout,
                    ..record
                },
            );
        }
    }
}

/// The depth/stencil state of a pipeline that writes neither aspect (a compute
/// pipeline's).
const NO_DEPTH_STENCIL_WRITES: crate::state::DepthStencil = crate::state::DepthStencil {
    depth_test: false,
    depth_write: false,
    stencil_test: false,
    ops: [[vk::StencilOp::KEEP; 3]; 2],
    masks: [0; 2],
    discard: true,
};

/// A graphics pipeline's static depth/stencil and rasterizer discard state (no
/// depth/stencil state: neither test).
fn static_depth_stencil(raw: &vk::GraphicsPipelineCreateInfo<'_>) -> crate::state::DepthStencil {
    // SAFETY: the safe setters store references that outlive the create info.
    let (ds, raster) = unsafe {
        (
            raw.p_depth_stencil_state.as_ref(),
            raw.p_rasterization_state.as_ref(),
        )
    };
    let ops = |s: &vk::StencilOpState| [s.fail_op, s.pass_op, s.depth_fail_op];
    crate::state::DepthStencil {
        depth_test: ds.is_some_and(|d| d.depth_test_enable != vk::FALSE),
        depth_write: ds.is_some_and(|d| d.depth_write_enable != vk::FALSE),
        stencil_test: ds.is_some_and(|d| d.stencil_test_enable != vk::FALSE),
        ops: ds.map_or([[vk::StencilOp::KEEP; 3]; 2], |d| {
            [ops(&d.front), ops(&d.back)]
        }),
        masks: ds.map_or([0; 2], |d| [d.front.write_mask, d.back.write_mask]),
        discard: raster.is_some_and(|r| r.rasterizer_discard_enable != vk::FALSE),
    }
}

/// A pipeline's record before its bind point and layout are filled in: what a
/// compute pipeline has, the resources and push constants its stages' modules
/// declare; a graphics pipeline's adds its fixed-function state.
fn pipeline_record(
    flags: vk::PipelineCreateFlags,
    declared: crate::special::shader::Declared,
) -> PipelineRecord {
    PipelineRecord {
        bind_point: vk::PipelineBindPoint::COMPUTE,
        flags,
        layout: Vrc::new(LayoutRecord {
            push_ranges: Vec::new(),
            set_dynamics: Vec::new(),
            sets: Vec::new(),
        }),
        vertex_bindings: 0,
        vertex_reads: Vec::new(),
        samples: vk::SampleCountFlags::empty(),
        pass: None,
        dynamic: 0,
        rendering: None,
        resources: declared.resources,
        push: declared.push,
        descriptor_uses: declared.uses,
        viewports: (0, 0),
        depth_stencil: NO_DEPTH_STENCIL_WRITES,
        blend: 0,
    }
}

/// The vertex-buffer bindings (the first 64) that a graphics pipeline's vertex
/// shader reads: those of the attributes at locations its entry point declares as
/// inputs.
pub(super) fn vertex_bindings(
    device: &Device,
    info: &vk::GraphicsPipelineCreateInfo<'_>,
) -> (u64, Vec<crate::state::VertexRead>) {
    // SAFETY: the safe struct stores every array with its length, and a stage's
    // module and name from wrappers and C strings that outlive the create info.
    let stages = unsafe { crate::state::raw_slice(info.p_stages, info.stage_count) };
    let Some(vertex) = stages
        .iter()
        .find(|s| s.stage == vk::ShaderStageFlags::VERTEX)
    else {
        return (0, Vec::new());
    };
    let Some(interface) = device.live().shader_module(vertex.module) else {
        return (0, Vec::new());
    };
    // SAFETY: as above.
    let name = unsafe { std::ffi::CStr::from_ptr(vertex.p_name) }.to_bytes();
    // SAFETY: as above.
    let Some(input) = (unsafe { info.p_vertex_input_state.as_ref() }) else {
        return (0, Vec::new());
    };
    // SAFETY: as above.
    let (attributes, bindings) = unsafe {
        (
            crate::state::raw_slice(
                input.p_vertex_attribute_descriptions,
                input.vertex_attribute_description_count,
            ),
            crate::state::raw_slice(
                input.p_vertex_binding_descriptions,
                input.vertex_binding_description_count,
            ),
        )
    };
    let read: Vec<_> = attributes
        .iter()
        .filter(|a| interface.reads_vertex_location(name, a.location))
        .collect();
    let mask = read
        .iter()
        .filter(|a| a.binding < 64)
        .fold(0, |mask, a| mask | 1 << a.binding);
    // What each binding's read attributes reach, past the start of a vertex: an
    // attribute of a format the registry does not describe reaches past any buffer.
    let mut reads: Vec<crate::state::VertexRead> = Vec::new();
    for a in read {
        let size = crate::formats::block(a.format, vk::ImageAspectFlags::COLOR)
            .map_or(u64::MAX, |(bytes, _)| u64::from(bytes));
        let end = u64::from(a.offset).saturating_add(size);
        if let Some(r) = reads.iter_mut().find(|r| r.binding == a.binding) {
            r.end = r.end.max(end);
        } else if let Some(b) = bindings.iter().find(|b| b.binding == a.binding) {
            reads.push(crate::state::VertexRead {
                binding: a.binding,
                stride: b.stride,
                instance: b.input_rate == vk::VertexInputRate::INSTANCE,
                end,
            });
        }
    }
    (mask, reads)
}

/// [`pipelines_created`] for `vkCreateComputePipelines`.
pub(crate) fn compute_pipelines_created(
    device: &Device,
    created: Vec<Pipeline>,
    create_infos: &[ComputePipelineCreateInfo<'_>],
) -> Vec<Pipeline> {
    let records = create_infos.iter().map(|i| {
        (
            i.as_raw().layout,
            pipeline_record(
                i.as_raw().flags,
                declared_resources(device, std::iter::once(&i.as_raw().stage)),
            ),
        )
    });
    pipelines_created(device, &created, vk::PipelineBindPoint::COMPUTE, records);
    created
}

/// [`pipelines_created`] for `vkCreateGraphicsPipelines`.
pub(crate) fn graphics_pipelines_created(
    device: &Device,
    created: Vec<Pipeline>,
    create_infos: &[GraphicsPipelineCreateInfo<'_>],
) -> Vec<Pipeline> {
    let records = create_infos.iter().map(|i| {
        let raw = i.as_raw();
        // SAFETY: the safe setter stores a reference that outlives the create info.
        let samples = unsafe { raw.p_multisample_state.as_ref() }
            .map_or(vk::SampleCountFlags::empty(), |m| m.rasterization_samples);
        // SAFETY: as above, and the state's array with its count.
        let dynamic = unsafe { raw.p_dynamic_state.as_ref() }.map_or(0, |d| {
            unsafe { crate::state::raw_slice(d.p_dynamic_states, d.dynamic_state_count) }
                .iter()
                .fold(0, |bits, s| bits | crate::state::dynamic_bit(*s))
        });
        let pass = device
            .live()
            .render_pass(raw.render_pass)
            .map(|r| (r, raw.subpass));
        let rendering = (raw.render_pass == vk::RenderPass::null()).then(|| {
            // SAFETY: the chain of a safe struct, and the type its sType names; the
            // safe setter stores the formats with their count.
            let info: Option<&vk::PipelineRenderingCreateInfo<'_>> = unsafe {
                chained(
                    raw.p_next,
                    vk::StructureType::PIPELINE_RENDERING_CREATE_INFO,
                )
            };
            // SAFETY: the safe setter stores the formats with their count.
            Vrc::new(info.map_or_else(Default::default, |i| unsafe {
                crate::state::RenderingFormats::from_raw(
                    i.view_mask,
                    i.p_color_attachment_formats,
                    i.color_attachment_count,
                    i.depth_attachment_format,
                    i.stencil_attachment_format,
                )
            }))
        });
        (raw.layout, {
            let (vertex_bindings, vertex_reads) = vertex_bindings(device, raw);
            PipelineRecord {
                vertex_bindings,
                vertex_reads,
                samples,
                pass,
                dynamic,
                rendering,
                // SAFETY: the safe setter stores a reference that outlives the
                // info.
                viewports: unsafe { raw.p_viewport_state.as_ref() }
                    .map_or((0, 0), |v| (v.viewport_count, v.scissor_count)),
                depth_stencil: static_depth_stencil(raw),
                // SAFETY: the safe setter stores a reference that outlives the info,
                // and the attachments with their count.
                blend: unsafe { raw.p_color_blend_state.as_ref() }.map_or(0, |c| {
                    unsafe { crate::state::raw_slice(c.p_attachments, c.attachment_count) }
                        .iter()
                        .take(32)
                        .enumerate()
                        .filter(|(_, a)| a.blend_enable == vk::TRUE)
                        .fold(0, |bits, (i, _)| bits | (1 << i))
                }),
                // SAFETY: the safe struct stores its stages with their count.
                ..pipeline_record(
                    raw.flags,
                    declared_resources(
                        device,
                        unsafe { crate::state::raw_slice(raw.p_stages, raw.stage_count) }.iter(),
                    ),
                )
            }
        })
    });
    pipelines_created(device, &created, vk::PipelineBindPoint::GRAPHICS, records);
    created
}

/// A cache starts empty: initial data is refused, as tuff cannot tell whether it
/// came from `vkGetPipelineCacheData` (a driver may trust its contents past the
/// header). Data saved to disk comes back through `create_pipeline_cache_unchecked`.
pub(crate) fn create_pipeline_cache_checks(
    create_info: &PipelineCacheCreateInfo<'_>,
) -> Result<()> {
    let size = create_info.as_raw().initial_data_size;
    if size != 0 {
        refuse(
            "VUID-VkPipelineCacheCreateInfo-initialDataSize-00769",
            format!("{size} bytes of initial data: tuff cannot tell whether they came from vkGetPipelineCacheData, which the rule needs (a driver may trust their contents past the header); `create_pipeline_cache_unchecked` takes them on the caller's word"),
        )?;
    }
    Ok(())
}

/// A merge into a cache that is not also one of its sources.
pub(crate) fn merge_pipeline_caches_checks(
    dst_cache: &PipelineCache,
    src_caches: &[&PipelineCache],
) -> Result<()> {
    if src_caches.iter().any(|c| c.raw() == dst_cache.raw()) {
        refuse(
            "VUID-vkMergePipelineCaches-dstCache-00770",
            "`dstCache` must not appear in the list of source caches",
        )?;
    }
    Ok(())
}

/// The state structs a graphics create info points to.
pub(super) struct States<'a> {
    pub(super) stages: &'a [vk::PipelineShaderStageCreateInfo<'a>],
    pub(super) vertex_input: Option<&'a vk::PipelineVertexInputStateCreateInfo<'a>>,
    pub(super) assembly: Option<&'a vk::PipelineInputAssemblyStateCreateInfo<'a>>,
    pub(super) tessellation: Option<&'a vk::PipelineTessellationStateCreateInfo<'a>>,
    pub(super) viewport: Option<&'a vk::PipelineViewportStateCreateInfo<'a>>,
    pub(super) raster: Option<&'a vk::PipelineRasterizationStateCreateInfo<'a>>,
    pub(super) multisample: Option<&'a vk::PipelineMultisampleStateCreateInfo<'a>>,
    pub(super) depth_stencil: Option<&'a vk::PipelineDepthStencilStateCreateInfo<'a>>,
    pub(super) blend: Option<&'a vk::PipelineColorBlendStateCreateInfo<'a>>,
    pub(super) blend_attachments: &'a [vk::PipelineColorBlendAttachmentState],
    pub(super) dynamic: &'a [vk::DynamicState],
}

impl<'a> States<'a> {
    /// # Safety
    ///
    /// `raw` is a safe create info's: each pointer set through a safe setter, to a
    /// struct that outlives it, and each array stored with its count.
    pub(super) unsafe fn of(raw: &'a vk::GraphicsPipelineCreateInfo<'a>) -> Self {
        // SAFETY: as the caller promises.
        unsafe {
            let blend = raw.p_color_blend_state.as_ref();
            States {
                stages: crate::state::raw_slice(raw.p_stages, raw.stage_count),
                vertex_input: raw.p_vertex_input_state.as_ref(),
                assembly: raw.p_input_assembly_state.as_ref(),
                tessellation: raw.p_tessellation_state.as_ref(),
                viewport: raw.p_viewport_state.as_ref(),
                raster: raw.p_rasterization_state.as_ref(),
                multisample: raw.p_multisample_state.as_ref(),
                depth_stencil: raw.p_depth_stencil_state.as_ref(),
                blend,
                blend_attachments: blend.map_or(&[][..], |b| {
                    crate::state::raw_slice(b.p_attachments, b.attachment_count)
                }),
                dynamic: raw.p_dynamic_state.as_ref().map_or(&[][..], |d| {
                    crate::state::raw_slice(d.p_dynamic_states, d.dynamic_state_count)
                }),
            }
        }
    }

    /// The entry point the pipeline's `stage` stage names, if it has that stage.
    pub(super) fn entry_point(
        &self,
        device: &Device,
        stage: vk::ShaderStageFlags,
    ) -> Option<crate::spirv::EntryPoint> {
        let s = self.stages.iter().find(|s| s.stage == stage)?;
        crate::special::shader::stage_entry_point(device, s)
    }

    pub(super) fn dynamic(&self, state: vk::DynamicState) -> bool {
        self.dynamic.contains(&state)
    }

    /// Whether the pipeline has fragment shader and fragment output interface state.
    pub(super) fn fragment(&self) -> bool {
        self.dynamic(vk::DynamicState::RASTERIZER_DISCARD_ENABLE)
            || self
                .raster
                .is_none_or(|r| r.rasterizer_discard_enable == vk::FALSE)
    }
}

/// What a graphics pipeline renders to: its subpass's color formats and
/// depth/stencil format, or those of its chained `VkPipelineRenderingCreateInfo`.
pub(super) struct Targets {
    pub(super) colors: Vec<vk::Format>,
    pub(super) depth: Option<vk::Format>,
    /// The subpass's or the rendering's view mask.
    pub(super) view_mask: u32,
}

/// The checks of `vkCreateGraphicsPipelines` over each pipeline's state as a
/// whole. They read the render pass's record and query format features, so they
/// run after the checks of the values.
pub(crate) fn graphics_pipeline_state_checks(
    device: &Device,
    create_infos: &[GraphicsPipelineCreateInfo<'_>],
) -> Result<()> {
    let flags: Vec<vk::PipelineCreateFlags> =
        create_infos.iter().map(|i| i.as_raw().flags).collect();
    for (i, info) in create_infos.iter().enumerate() {
        let raw = info.as_raw();
        // SAFETY: `raw` is a safe struct's.
        let states = unsafe { States::of(raw) };
        let at = format!("pCreateInfos[{i}]");
        if raw.flags.contains(vk::PipelineCreateFlags::DISPATCH_BASE) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-flags-00764",
                format!("{at}.flags includes VK_PIPELINE_CREATE_DISPATCH_BASE, which only compute pipelines take"),
            )?;
        }
        check_derivative(
            device,
            raw.flags,
            (raw.base_pipeline_handle, raw.base_pipeline_index),
            (i, &flags),
            &GRAPHICS_DERIVATIVE,
            &at,
        )?;
        check_stages(&states, &at)?;
        check_execution_modes(device, &states, &at)?;
        check_point_size(device, &states, &at)?;
        check_present(raw, &states, &at)?;
        let targets = match raw.render_pass == vk::RenderPass::null() {
            false => subpass_targets(device, raw, &at)?,
            true => rendering_targets(device, raw, &at)?,
        };
        check_stage_interfaces(device, raw, &states, &targets, &at)?;
        check_stage_linking(device, &states, &at)?;
        if states.fragment() && raw.render_pass == vk::RenderPass::null() {
            // Dynamic rendering's formats ask for the states that write them.
            if targets.depth.is_some() && states.depth_stencil.is_none() {
                refuse(
                    "VUID-VkGraphicsPipelineCreateInfo-renderPass-06053",
                    format!(
                        "{at} renders to a depth or stencil format and has no pDepthStencilState"
                    ),
                )?;
            }
            if !targets.colors.is_empty() && states.blend.is_none() {
                refuse(
                    "VUID-VkGraphicsPipelineCreateInfo-renderPass-06054",
                    format!(
                        "{at} renders to {} color attachments and has no pColorBlendState",
                        targets.colors.len()
                    ),
                )?;
            }
        }
        if states.fragment() && raw.render_pass != vk::RenderPass::null() {
            check_zero_attachments(device, raw, &states, &at)?;
        }
        if states.fragment() {
            check_targets(device, raw, &states, &targets, &at)?;
            check_blend_identical(device, &states, &at)?;
        }
        check_stage_resources(device, raw, &states, targets.colors.len(), &at)?;
        check_viewport_state(device, &states, &at)?;
        check_fixed_function(device, &states, &at)?;
        check_state_structs(device, &states, &at)?;
    }
    Ok(())
}

/// The rules of the state structs that read one struct at a time: dynamic states
/// once each, vertex bindings and locations once each and every attribute's binding
/// described, a list topology without primitive restart, adjacency only with
/// geometryShader, a patch size within maxTessellationPatchSize, a sample-shading
/// fraction within [0, 1], a defined logic operation, and each stage's
/// specialization constants once each.
fn check_state_structs(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
    // The features these states need are VK_EXT_extended_dynamic_state2's, which no
    // device made through the safe `create_device` enables (it is outside the
    // emitted API).
    let unavailable = [
        (
            vk::DynamicState::LOGIC_OP_EXT,
            "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04869",
            "extendedDynamicState2LogicOp",
        ),
        (
            vk::DynamicState::PATCH_CONTROL_POINTS_EXT,
            "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04870",
            "extendedDynamicState2PatchControlPoints",
        ),
    ];
    for (state, vuid, feature) in unavailable {
        if states.dynamic.contains(&state) {
            refuse(
                vuid,
                format!("{at}'s pDynamicStates names {state:?}, and the device has not enabled {feature}"),
            )?;
        }
    }
    if let Some(i) =
        (1..states.dynamic.len()).find(|&i| states.dynamic[..i].contains(&states.dynamic[i]))
    {
        refuse(
            "VUID-VkPipelineDynamicStateCreateInfo-pDynamicStates-01442",
            format!(
                "{at}'s pDynamicStates[{i}] ({:?}) is named twice",
                states.dynamic[i]
            ),
        )?;
    }
    if let Some(v) = states.vertex_input {
        // SAFETY: the safe setters store each array with its count.
        let (bindings, attributes) = unsafe {
            (
                crate::state::raw_slice(
                    v.p_vertex_binding_descriptions,
                    v.vertex_binding_description_count,
                ),
                crate::state::raw_slice(
                    v.p_vertex_attribute_descriptions,
                    v.vertex_attribute_description_count,
                ),
            )
        };
        if let Some(i) = (1..bindings.len()).find(|&i| {
            bindings[..i]
                .iter()
                .any(|b| b.binding == bindings[i].binding)
        }) {
            refuse(
                "VUID-VkPipelineVertexInputStateCreateInfo-pVertexBindingDescriptions-00616",
                format!(
                    "{at}'s vertex binding {} is described twice",
                    bindings[i].binding
                ),
            )?;
        }
        if let Some(i) = (1..attributes.len()).find(|&i| {
            attributes[..i]
                .iter()
                .any(|a| a.location == attributes[i].location)
        }) {
            refuse(
                "VUID-VkPipelineVertexInputStateCreateInfo-pVertexAttributeDescriptions-00617",
                format!(
                    "{at}'s vertex location {} is described twice",
                    attributes[i].location
                ),
            )?;
        }
        if let Some(a) = attributes
            .iter()
            .find(|a| !bindings.iter().any(|b| b.binding == a.binding))
        {
            refuse(
                "VUID-VkPipelineVertexInputStateCreateInfo-binding-00615",
                format!("{at}'s attribute at location {} reads binding {}, which no binding description describes", a.location, a.binding),
            )?;
        }
        for a in attributes {
            let buffer = device
                .live()
                .format_properties(device.parent(), a.format)?
                .buffer_features;
            if !buffer.contains(vk::FormatFeatureFlags::VERTEX_BUFFER) {
                refuse(
                    "VUID-VkVertexInputAttributeDescription-format-00623",
                    format!("{at}'s attribute at location {} has format {:?}, whose buffer features lack VERTEX_BUFFER", a.location, a.format),
                )?;
            }
        }
    }
    if let Some(a) = states.assembly {
        use vk::PrimitiveTopology as T;
        let t = a.topology;
        let list = matches!(
            t,
            T::POINT_LIST
                | T::LINE_LIST
                | T::TRIANGLE_LIST
                | T::LINE_LIST_WITH_ADJACENCY
                | T::TRIANGLE_LIST_WITH_ADJACENCY
                | T::PATCH_LIST
        );
        if list && a.primitive_restart_enable != vk::FALSE {
            refuse(
                "VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00428",
                format!("{at} enables primitive restart with the list topology {t:?}"),
            )?;
        }
        let adjacency = matches!(
            t,
            T::LINE_LIST_WITH_ADJACENCY
                | T::LINE_STRIP_WITH_ADJACENCY
                | T::TRIANGLE_LIST_WITH_ADJACENCY
                | T::TRIANGLE_STRIP_WITH_ADJACENCY
        );
        if adjacency && device.live().features().geometry_shader == vk::FALSE {
            refuse(
                "VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00429",
                format!("{at}'s topology {t:?} needs the geometryShader feature"),
            )?;
        }
    }
    if let Some(t) = states.tessellation {
        let max = limits(device).max_tessellation_patch_size;
        if t.patch_control_points == 0 || t.patch_control_points > max {
            refuse(
                "VUID-VkPipelineTessellationStateCreateInfo-patchControlPoints-01214",
                format!("{at}'s patchControlPoints ({}) is not within 1 to maxTessellationPatchSize ({max})", t.patch_control_points),
            )?;
        }
    }
    if let Some(m) = states.multisample {
        if !(0.0..=1.0).contains(&m.min_sample_shading) {
            refuse(
                "VUID-VkPipelineMultisampleStateCreateInfo-minSampleShading-00786",
                format!(
                    "{at}'s minSampleShading ({}) is outside [0, 1]",
                    m.min_sample_shading
                ),
            )?;
        }
    }
    if let Some(b) = states.blend {
        let defined = (vk::LogicOp::CLEAR.as_raw()..=vk::LogicOp::SET.as_raw())
            .contains(&b.logic_op.as_raw());
        if b.logic_op_enable != vk::FALSE && !defined {
            refuse(
                "VUID-VkPipelineColorBlendStateCreateInfo-logicOpEnable-00607",
                format!(
                    "{at} enables a logic operation of no VkLogicOp value ({})",
                    b.logic_op.as_raw()
                ),
            )?;
        }
    }
    check_specialization_names(states.stages, at)
}

/// Each stage's specialization constants are named once each.
fn check_specialization_names(
    stages: &[vk::PipelineShaderStageCreateInfo<'_>],
    at: &str,
) -> Result<()> {
    for (k, s) in stages.iter().enumerate() {
        // SAFETY: the safe setter stores a reference that outlives the create info.
        let Some(spec) = (unsafe { s.p_specialization_info.as_ref() }) else {
            continue;
        };
        // SAFETY: the safe setter stores the entries with their count.
        let entries = unsafe { crate::state::raw_slice(spec.p_map_entries, spec.map_entry_count) };
        if let Some(i) = (1..entries.len()).find(|&i| {
            entries[..i]
                .iter()
                .any(|e| e.constant_id == entries[i].constant_id)
        }) {
            refuse(
                "VUID-VkSpecializationInfo-constantID-04911",
                format!(
                    "{at}.pStages[{k}] specializes constant {} twice",
                    entries[i].constant_id
                ),
            )?;
        }
    }
    Ok(())
}

/// The rules of a derivative pipeline, by create info: graphics or compute.
struct DerivativeRules {
    neither: &'static str,
    bad_index: &'static str,
    both_handle: &'static str,
    /// A base named by index comes earlier in the create infos.
    earlier: &'static str,
    /// The base allows derivatives.
    allows: &'static str,
}

const GRAPHICS_DERIVATIVE: DerivativeRules = DerivativeRules {
    neither: "VUID-VkGraphicsPipelineCreateInfo-flags-00722",
    bad_index: "VUID-VkGraphicsPipelineCreateInfo-flags-00723",
    both_handle: "VUID-VkGraphicsPipelineCreateInfo-flags-00724",
    earlier: "VUID-vkCreateGraphicsPipelines-flags-00720",
    allows: "VUID-vkCreateGraphicsPipelines-flags-00721",
};

const COMPUTE_DERIVATIVE: DerivativeRules = DerivativeRules {
    neither: "VUID-VkComputePipelineCreateInfo-flags-00697",
    bad_index: "VUID-VkComputePipelineCreateInfo-flags-00698",
    both_handle: "VUID-VkComputePipelineCreateInfo-flags-00699",
    earlier: "VUID-vkCreateComputePipelines-flags-00695",
    allows: "VUID-vkCreateComputePipelines-flags-00696",
};

/// A derivative names its base one way only: by handle, or by the index of an
/// earlier create info of the call (whose flags are `all`; it is element `i`), and
/// the base allows derivatives (a pipeline by handle, as the device recorded it).
fn check_derivative(
    device: &Device,
    flags: vk::PipelineCreateFlags,
    (handle, index): (vk::Pipeline, i32),
    (i, all): (usize, &[vk::PipelineCreateFlags]),
    rules: &DerivativeRules,
    at: &str,
) -> Result<()> {
    if !flags.contains(vk::PipelineCreateFlags::DERIVATIVE) {
        return Ok(());
    }
    let count = all.len();
    let handle_flags =
        (handle != vk::Pipeline::null()).then(|| device.live().pipeline(handle).map(|p| p.flags));
    let handle = handle != vk::Pipeline::null();
    if !handle && index == -1 {
        refuse(
            rules.neither,
            format!("{at} is a derivative with neither a base pipeline handle nor an index"),
        )?;
    }
    if !handle && (index < 0 || index as usize >= count) {
        refuse(
            rules.bad_index,
            format!("{at}.basePipelineIndex ({index}) is no index into the {count} create infos"),
        )?;
    }
    if handle && index != -1 {
        refuse(
            rules.both_handle,
            format!("{at} names a base pipeline by handle and by index ({index})"),
        )?;
    }
    if !handle && index >= 0 && index as usize >= i {
        refuse(
            rules.earlier,
            format!("{at} names create info {index} as its base pipeline, which does not come before it"),
        )?;
    }
    let base = match handle_flags {
        Some(recorded) => recorded,
        None => usize::try_from(index)
            .ok()
            .and_then(|b| all.get(b).copied()),
    };
    if base.is_some_and(|b| !b.contains(vk::PipelineCreateFlags::ALLOW_DERIVATIVES)) {
        refuse(
            rules.allows,
            format!("{at}'s base pipeline was not created with VK_PIPELINE_CREATE_ALLOW_DERIVATIVES_BIT"),
        )?;
    }
    Ok(())
}

/// The checks of `vkCreateComputePipelines` over each create info as a whole: its
/// stage is a compute stage, and a derivative names its base one way.
pub(crate) fn compute_pipeline_state_checks(
    device: &Device,
    create_infos: &[ComputePipelineCreateInfo<'_>],
) -> Result<()> {
    let flags: Vec<vk::PipelineCreateFlags> =
        create_infos.iter().map(|i| i.as_raw().flags).collect();
    for (i, info) in create_infos.iter().enumerate() {
        let raw = info.as_raw();
        let at = format!("pCreateInfos[{i}]");
        if raw.stage.stage != vk::ShaderStageFlags::COMPUTE {
            refuse(
                "VUID-VkComputePipelineCreateInfo-stage-00701",
                format!(
                    "{at}.stage.stage is {:?}, not VK_SHADER_STAGE_COMPUTE_BIT",
                    raw.stage.stage
                ),
            )?;
        }
        check_derivative(
            device,
            raw.flags,
            (raw.base_pipeline_handle, raw.base_pipeline_index),
            (i, &flags),
            &COMPUTE_DERIVATIVE,
            &at,
        )?;
        check_specialization_names(core::slice::from_ref(&raw.stage), &at)?;
        if let Some(layout) = device.live().pipeline_layout(raw.layout) {
            let count = limited_resources(&layout, vk::ShaderStageFlags::COMPUTE);
            let max = u64::from(crate::special::limits(device).max_per_stage_resources);
            if count > max {
                refuse(
                    "VUID-VkComputePipelineCreateInfo-layout-01687",
                    format!("{at}'s compute stage reaches {count} resources through its layout, past maxPerStageResources ({max})"),
                )?;
            }
        }
    }
    Ok(())
}
