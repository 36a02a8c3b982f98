//! Draws and dispatches: the recorded state each needs (pipeline, sets, vertex and index
//! buffers, dynamic state, push constants, attachments and blending), checked once per
//! change of the bound state.

use super::draw_descriptors::{
    bound_descriptor_checks, descriptor_layout_checks, protected_checks, DESCRIPTOR_LAYOUT,
};
use super::refuse;
use crate::recorder::{Recorder, Scope};
use crate::state::{PipelineRecord, SetLayoutRecord};
use crate::{Error, Result};
use ash::vk;
use ash::vk::Handle as _;
use smallvec::SmallVec;
use tuff_runtime::Vrc;

/// The vertices and instances a direct draw fetches: (first vertex, vertex count,
/// first instance, instance count, the rule they break past a vertex buffer, the
/// rule of the last instance index in a multiview render pass instance).
pub(crate) type Vertices = Option<(u32, u32, u32, u32, &'static str, &'static str)>;

/// Refuses a draw in a render pass instance with a view mask whose last instance
/// index is past `maxMultiviewInstanceIndex`.
fn multiview_instances<S: Scope>(
    recorder: &Recorder<'_, S>,
    first_instance: u32,
    instance_count: u32,
    vuid: &'static str,
) -> Result<()> {
    let multiview = recorder.instance.as_ref().is_some_and(|i| i.view_mask != 0);
    if !multiview || instance_count == 0 {
        return Ok(());
    }
    let device = recorder.device();
    let max = device.live().max_multiview_instance(|| {
        super::render_pass::multiview_properties(device).map(|m| m.max_multiview_instance_index)
    });
    let last = u64::from(first_instance) + u64::from(instance_count) - 1;
    match max {
        Some(max) if last > u64::from(max) => refuse(
            vuid,
            format!("the draw's last instance index ({last}) is past maxMultiviewInstanceIndex ({max}) in a multiview render pass instance"),
        ),
        Some(_) => Ok(()),
        None => refuse(
            vuid,
            "a Vulkan 1.0 instance cannot ask maxMultiviewInstanceIndex, so no multiview draw is checked",
        ),
    }
}

/// A draw: a graphics pipeline and its sets and vertex buffers bound
/// ([`bound_pipeline_checks`]), the state it draws with ([`draw_state_checks`]),
/// and for a direct draw, the vertices it fetches inside the bound vertex buffers.
pub(crate) fn draw_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    pipeline_vuid: &'static str,
    sets_vuid: &'static str,
    vertex_vuid: &'static str,
    vertices: Vertices,
    rules: &DrawRules,
) -> Result<()> {
    recorder.verify_state(0, |recorder| {
        // Before the descriptors' layouts: a descriptor that names an attachment is
        // refused for what it does to the attachment's memory first.
        attachment_checks(recorder, &rules.attachments)?;
        bound_pipeline_checks(
            recorder,
            vk::PipelineBindPoint::GRAPHICS,
            pipeline_vuid,
            sets_vuid,
            Some(vertex_vuid),
            &rules.shader,
        )?;
        stride_checks(recorder)?;
        draw_state_checks(recorder, rules)
    })?;
    let Some((first, count, first_instance, instance_count, vuid, _)) = vertices else {
        return Ok(());
    };
    let params = (vuid, [first, count, first_instance, instance_count], 0);
    recorder.verify_draw_params(params, |recorder| vertices_checks(recorder, vertices))
}

/// The vertices and instances of one draw (a direct draw's parameters, or the
/// arguments of an indirect one the host wrote): its last instance index in a
/// multiview instance, and its vertex fetches inside the bound vertex buffers.
pub(crate) fn vertices_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    vertices: Vertices,
) -> Result<()> {
    let Some((first_vertex, vertex_count, first_instance, instance_count, vuid, multiview)) =
        vertices
    else {
        return Ok(());
    };
    multiview_instances(recorder, first_instance, instance_count, multiview)?;
    vertex_fetch_checks(
        recorder,
        (u64::from(first_vertex), u64::from(vertex_count)),
        (first_instance, instance_count),
        vuid,
    )
}

/// Refuses a draw whose bound pipeline has the vertex binding stride dynamic where
/// a stride `vkCmdBindVertexBuffers2` set is neither 0 nor as long as the extent of
/// the attributes the vertex shader fetches from its binding (the rule of the bind,
/// checked where the pipeline that gives the attributes is known).
fn stride_checks<S: Scope>(recorder: &Recorder<'_, S>) -> Result<()> {
    let bound = &recorder.bound[0];
    let Some(pipeline) = &bound.pipeline else {
        return Ok(());
    };
    let dynamic = crate::state::dynamic_bit(vk::DynamicState::VERTEX_INPUT_BINDING_STRIDE);
    if pipeline.dynamic & dynamic == 0 {
        return Ok(());
    }
    for read in &pipeline.vertex_reads {
        let Some(Some(range)) = bound.vertex_ranges.get(read.binding as usize) else {
            continue;
        };
        if let Some(stride) = range.stride.filter(|s| *s != 0 && *s < read.end) {
            refuse(
                "VUID-vkCmdBindVertexBuffers2-pStrides-06209",
                format!("the stride bound at binding {} is {stride}, and the attributes the bound pipeline's vertex shader fetches from it reach {} bytes", read.binding, read.end),
            )?;
        }
    }
    Ok(())
}

/// Refuses a draw that fetches vertices `(first, count)` or instances past the end
/// of the vertex buffer bound at a binding the bound pipeline's vertex shader reads.
fn vertex_fetch_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    (first_vertex, vertex_count): (u64, u64),
    (first_instance, instance_count): (u32, u32),
    vuid: &'static str,
) -> Result<()> {
    let Some(pipeline) = &recorder.bound[0].pipeline else {
        return Ok(());
    };
    let bound = &recorder.bound[0];
    let dynamic_stride = pipeline.dynamic
        & crate::state::dynamic_bit(vk::DynamicState::VERTEX_INPUT_BINDING_STRIDE)
        != 0;
    if pipeline.vertex_reads.is_empty() {
        return Ok(());
    }
    for read in &pipeline.vertex_reads {
        let (first, count) = if read.instance {
            (u64::from(first_instance), u64::from(instance_count))
        } else {
            (first_vertex, vertex_count)
        };
        if count == 0 {
            continue;
        }
        let Some(Some(range)) = bound.vertex_ranges.get(read.binding as usize) else {
            continue;
        };
        let stride = match (dynamic_stride, range.stride) {
            (true, Some(stride)) => stride,
            _ => u64::from(read.stride),
        };
        let last = first.saturating_add(count - 1);
        let needed = last.saturating_mul(stride).saturating_add(read.end);
        if needed > range.bytes {
            refuse(
                vuid,
                format!("the draw fetches {needed} bytes from the vertex buffer bound at binding {}, which holds {} past its offset", read.binding, range.bytes),
            )?;
        }
    }
    Ok(())
}

/// The rules of one draw command about the state it draws with.
pub(crate) struct DrawRules {
    /// The bound pipeline's render pass is compatible with the instance's.
    pub render_pass: &'static str,
    /// The bound pipeline's subpass is the instance's current one.
    pub subpass: &'static str,
    /// Every dynamic state of the bound pipeline is set.
    pub dynamic_set: &'static str,
    /// No state static in the bound pipeline was set since it was bound.
    pub static_unset: &'static str,
    /// Rules naming one dynamic state that must be set: (its bit, the rule).
    pub named: [(u32, &'static str); 5],
    /// In dynamic rendering, what the bound pipeline was made for against the
    /// instance: the view mask, the color attachment count, a color format, a
    /// color format for an attachment with no view, the depth format, one for no
    /// depth view, the stencil format, one for no stencil view.
    pub rendering: RenderingRules,
    /// Depth and stencil writes against read-only attachment layouts: in any
    /// instance (depth, stencil), then in dynamic rendering by the layout the
    /// attachment info names (depth and stencil in `DEPTH_STENCIL_READ_ONLY_OPTIMAL`,
    /// in `DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL` and
    /// `DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL`, in `DEPTH_READ_ONLY_OPTIMAL` and
    /// `STENCIL_READ_ONLY_OPTIMAL`).
    /// Then the pipeline's rasterization samples against the attachments'.
    pub read_only: ReadOnlyRules,
    /// The viewport and scissor counts set with their counts: the viewport count
    /// against the pipeline's scissor count, the scissor count against its viewport
    /// count, and both against each other.
    pub counts: CountRules,
    /// What its shaders read ([`ShaderRules`]).
    pub shader: ShaderRules,
    /// The instance's attachments as the draw reaches them: an input attachment
    /// variable's index names an input attachment of the subpass, its view is
    /// compatible with the framebuffer's, no descriptor reaches an attachment's
    /// memory (written by the shader, or read), and blending only on attachments
    /// whose format supports it.
    pub attachments: AttachmentRules,
}

/// The rules of [`DrawRules::rendering`], one VUID each.
#[derive(Debug)]
pub(crate) struct RenderingRules {
    /// The view mask (`viewMask-06178`).
    pub view_mask: &'static str,
    /// The color attachment count (`colorAttachmentCount-06179`).
    pub color_count: &'static str,
    /// A color format (`colorAttachmentCount-06180`).
    pub color_format: &'static str,
    /// A color format, for an attachment with no view (`colorAttachmentCount-07616`).
    pub color_no_view: &'static str,
    /// The depth format (`pDepthAttachment-06181`).
    pub depth_format: &'static str,
    /// The depth format, with no depth view (`pDepthAttachment-07617`).
    pub depth_no_view: &'static str,
    /// The stencil format (`pStencilAttachment-06182`).
    pub stencil_format: &'static str,
    /// The stencil format, with no stencil view (`pStencilAttachment-07618`).
    pub stencil_no_view: &'static str,
}

/// The rules of [`DrawRules::read_only`], one VUID each.
#[derive(Debug)]
pub(crate) struct ReadOnlyRules {
    /// Depth writes against a read-only depth layout, in any instance (`None-06886`).
    pub depth: &'static str,
    /// Stencil writes against a read-only stencil layout, in any instance (`None-06887`).
    pub stencil: &'static str,
    /// Depth writes in dynamic rendering, in `DEPTH_STENCIL_READ_ONLY_OPTIMAL` (`imageView-06172`).
    pub depth_in_both_read_only: &'static str,
    /// Stencil writes there (`imageView-06173`).
    pub stencil_in_both_read_only: &'static str,
    /// Depth writes in `DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL` (`imageView-06174`).
    pub depth_in_depth_read_only_stencil_attachment: &'static str,
    /// Stencil writes in `DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL` (`imageView-06175`).
    pub stencil_in_depth_attachment_stencil_read_only: &'static str,
    /// Depth writes in `DEPTH_READ_ONLY_OPTIMAL` (`imageView-06176`).
    pub depth_in_depth_read_only: &'static str,
    /// Stencil writes in `STENCIL_READ_ONLY_OPTIMAL` (`imageView-06177`).
    pub stencil_in_stencil_read_only: &'static str,
    /// The pipeline's rasterization samples against the attachments' (`rasterizationSamples-04740`).
    pub rasterization_samples: &'static str,
}

/// The rules of [`DrawRules::counts`], one VUID each.
#[derive(Debug)]
pub(crate) struct CountRules {
    /// The viewport count set against the pipeline's scissor count (`viewportCount-03417`).
    pub viewports: &'static str,
    /// The scissor count set against its viewport count (`scissorCount-03418`).
    pub scissors: &'static str,
    /// Both counts set against each other (`viewportCount-03419`).
    pub both: &'static str,
}

/// The rules of [`DrawRules::attachments`], one VUID each.
#[derive(Debug)]
pub(crate) struct AttachmentRules {
    /// An input attachment variable's `InputAttachmentIndex` names an input
    /// attachment of the subpass (`OpTypeImage-07468`).
    pub input_index: &'static str,
    /// Its descriptor's view is compatible with the framebuffer's (`None-07469`).
    pub input_view: &'static str,
    /// No descriptor the shader writes reaches an attachment's memory (`None-06537`).
    pub memory_written: &'static str,
    /// No other descriptor reaches it (`None-06538`).
    pub memory_read: &'static str,
    /// Blending only on attachments whose format supports it (`blendEnable-04727`).
    pub blend: &'static str,
}

/// The rules of a draw or dispatch about what its shaders read, one VUID each.
#[derive(Debug)]
pub(crate) struct ShaderRules {
    /// An image view's type for the image variable's `Dim` and `Arrayed` (`viewType-07752`).
    pub view_type: &'static str,
    /// Its format's numeric type for the variable's sampled type (`format-07753`).
    pub view_numeric: &'static str,
    /// Every descriptor the shaders read was written (`None-02699`).
    pub written: &'static str,
    /// The push constants the shaders read were set (`maintenance4-06425`).
    pub push_constants: &'static str,
    /// Atomic operations only on views whose format supports them (`None-02691`).
    pub atomics: &'static str,
    /// Depth comparison only on views whose format supports it (`None-06479`).
    pub depth_comparison: &'static str,
    /// Storage image writes of `Unknown` format only where the format allows (`OpTypeImage-07027`).
    pub write_without_format: &'static str,
    /// Storage image reads of `Unknown` format only where the format allows (`OpTypeImage-07028`).
    pub read_without_format: &'static str,
    /// No protected resource reached from an unprotected command buffer (`commandBuffer-02707`).
    pub protected_access: &'static str,
    /// No draw or dispatch in a protected command buffer (the command's own rule).
    pub protected_command_buffer: &'static str,
    /// A LINEAR filter only on views whose format supports it (`magFilter-04553`).
    pub linear_filter: &'static str,
    /// A LINEAR mipmap mode likewise (`mipmapMode-04770`).
    pub linear_mipmap: &'static str,
    /// Unnormalized coordinates only on 1D and 2D views (`None-02702`).
    pub unnormalized_view_type: &'static str,
    /// With unnormalized coordinates, no ImplicitLod, Dref or Proj sampling (`None-02703`).
    pub unnormalized_instructions: &'static str,
    /// With unnormalized coordinates, no LOD bias or offset (`None-02704`).
    pub unnormalized_bias_offset: &'static str,
    /// Image views written with as many components as their format has (`None-04115`).
    pub image_write_components: &'static str,
    /// Texel buffer views likewise (`OpImageWrite-04469`).
    pub texel_write_components: &'static str,
    /// Storage texel buffer writes of `Unknown` format only where the format allows (`OpTypeImage-07029`).
    pub texel_write_without_format: &'static str,
    /// Storage texel buffer reads likewise (`OpTypeImage-07030`).
    pub texel_read_without_format: &'static str,
    /// Views with a Y'CbCr conversion only sampled (`None-06550`).
    pub ycbcr_sampling: &'static str,
    /// And without `ConstOffset` or `Offset` (`ConstOffset-06551`).
    pub ycbcr_offset: &'static str,
}

/// The dynamic states whose rule a draw command names apart from the general one:
/// primitive topology, vertex input binding stride, rasterizer discard enable,
/// depth bias enable and primitive restart enable.
pub(crate) const NAMED_STATES: [u32; 5] = {
    use crate::state::dynamic_bit;
    use vk::DynamicState as D;
    [
        dynamic_bit(D::PRIMITIVE_TOPOLOGY),
        dynamic_bit(D::VERTEX_INPUT_BINDING_STRIDE),
        dynamic_bit(D::RASTERIZER_DISCARD_ENABLE),
        dynamic_bit(D::DEPTH_BIAS_ENABLE),
        dynamic_bit(D::PRIMITIVE_RESTART_ENABLE),
    ]
};

/// Refuses a draw whose bound graphics pipeline was made for another render pass
/// or subpass than the instance's, one of whose dynamic states is not set (or was
/// set before a pipeline bound since had it static), or after a command that set a
/// state the pipeline has static.
#[inline]
fn draw_state_checks<S: Scope>(recorder: &Recorder<'_, S>, rules: &DrawRules) -> Result<()> {
    let Some(pipeline) = &recorder.bound[0].pipeline else {
        return Ok(());
    };
    if let Some(instance) = &recorder.instance {
        match (&pipeline.pass, &instance.record) {
            (Some((made_for, subpass)), Some(current)) => {
                if !Vrc::ptr_eq(made_for, current) && !made_for.compatible(current) {
                    refuse(
                        rules.render_pass,
                        "the bound pipeline was created for a render pass that is not compatible with the render pass instance's",
                    )?;
                }
                if *subpass != instance.subpass {
                    refuse(
                        rules.subpass,
                        format!("the bound pipeline was created for subpass {subpass}, and the render pass instance is in subpass {}", instance.subpass),
                    )?;
                }
            }
            (None, Some(_)) => refuse(
                rules.render_pass,
                "the bound pipeline was created for dynamic rendering, inside a render pass instance",
            )?,
            _ => {}
        }
    }
    if let (Some(made_for), Some(current)) = (
        &pipeline.rendering,
        recorder
            .instance
            .as_ref()
            .and_then(|i| i.rendering.as_ref()),
    ) {
        rendering_checks(made_for, current, &rules.rendering)?;
    }
    let (valid, since_bind) = recorder.dynamic;
    let missing = pipeline.dynamic & !valid;
    if missing != 0 {
        let vuid = rules
            .named
            .iter()
            .find(|(bit, _)| missing & bit != 0)
            .map_or(rules.dynamic_set, |(_, vuid)| vuid);
        refuse(
            vuid,
            format!("dynamic state bit {} of the bound pipeline was not set since a pipeline with it static was bound (or at all)", missing.trailing_zeros()),
        )?;
    }
    let stale = since_bind & !pipeline.dynamic;
    if stale != 0 {
        refuse(
            rules.static_unset,
            format!("dynamic state bit {} was set since the bound pipeline was bound, and the pipeline has it static", stale.trailing_zeros()),
        )?;
    }
    count_checks(recorder.counts, pipeline, &rules.counts)?;
    read_only_checks(recorder, pipeline, &rules.read_only)
}

/// The depth, stencil and rasterizer discard values a draw uses: the bound
/// pipeline's, or the recording's where the pipeline has them dynamic.
fn draw_values<S: Scope>(
    recorder: &Recorder<'_, S>,
    pipeline: &PipelineRecord,
) -> crate::state::DepthStencil {
    let mut values = pipeline.depth_stencil;
    values.take(&recorder.depth_stencil, pipeline.dynamic);
    values
}

/// Refuses a draw that rasterizes another sample count than the instance's
/// attachments have, or writes depth or stencil where the instance's depth/stencil
/// attachment has that aspect in a read-only layout (or where its layouts are not
/// known).
fn read_only_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    pipeline: &PipelineRecord,
    rules: &ReadOnlyRules,
) -> Result<()> {
    let Some(instance) = &recorder.instance else {
        return Ok(());
    };
    let values = draw_values(recorder, pipeline);
    if !values.discard {
        if let (Some(samples), false) = (instance.attachment_samples(), pipeline.samples.is_empty())
        {
            if samples != pipeline.samples {
                refuse(
                    rules.rasterization_samples,
                    format!("the bound pipeline rasterizes {:?} samples, and the render pass instance's attachments have {samples:?}", pipeline.samples),
                )?;
            }
        }
    }
    let (depth, stencil) = (values.writes_depth(), values.writes_stencil());
    if !depth && !stencil {
        return Ok(());
    }
    let Some((depth_layout, stencil_layout)) = instance.depth_stencil_layouts() else {
        return refuse(
            if depth { rules.depth } else { rules.stencil },
            "the draw writes the depth/stencil attachment, whose layouts are not known here (a secondary that continues dynamic rendering: its inheritance info does not give them)",
        );
    };
    type L = vk::ImageLayout;
    // Per aspect: whether the draw writes it, its layout, the layouts that hold it
    // read-only with the dynamic-rendering rule each names, the rule of any
    // instance, and its name with what the draw does to it.
    let aspects = [
        (
            depth,
            depth_layout,
            [
                (L::DEPTH_STENCIL_READ_ONLY_OPTIMAL, rules.depth_in_both_read_only),
                (L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL, rules.depth_in_depth_read_only_stencil_attachment),
                (L::DEPTH_READ_ONLY_OPTIMAL, rules.depth_in_depth_read_only),
            ],
            rules.depth,
            ("depth", "writes depth (depth test and writes enabled)"),
        ),
        (
            stencil,
            stencil_layout,
            [
                (L::DEPTH_STENCIL_READ_ONLY_OPTIMAL, rules.stencil_in_both_read_only),
                (L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL, rules.stencil_in_depth_attachment_stencil_read_only),
                (L::STENCIL_READ_ONLY_OPTIMAL, rules.stencil_in_stencil_read_only),
            ],
            rules.stencil,
            ("stencil", "may write stencil (stencil test enabled, a face with a write mask and an operation other than KEEP)"),
        ),
    ];
    for (writes, layout, read_only, any_instance, (aspect, what)) in aspects {
        let (true, Some(layout)) = (writes, layout) else {
            continue;
        };
        let named = read_only.iter().find(|(l, _)| *l == layout);
        let rule = match named {
            Some((_, rule)) if instance.dynamic => Some(*rule),
            Some(_) => Some(any_instance),
            None if layout == L::READ_ONLY_OPTIMAL => Some(any_instance),
            None => None,
        };
        if let Some(rule) = rule {
            refuse(
                rule,
                format!(
                    "the draw {what}, and the depth/stencil attachment's {aspect} aspect is in {layout:?}"
                ),
            )?;
        }
    }
    Ok(())
}

/// Refuses a draw whose viewport and scissor counts, where the bound pipeline has
/// them dynamic with their counts, differ from each other or from the count the
/// pipeline has static.
fn count_checks(
    (viewports, scissors): (Option<u32>, Option<u32>),
    pipeline: &PipelineRecord,
    rules: &CountRules,
) -> Result<()> {
    use crate::state::dynamic_bit;
    let with = |state| pipeline.dynamic & dynamic_bit(state) != 0;
    let (static_viewports, static_scissors) = pipeline.viewports;
    match (
        with(vk::DynamicState::VIEWPORT_WITH_COUNT),
        with(vk::DynamicState::SCISSOR_WITH_COUNT),
    ) {
        (true, false) if viewports != Some(static_scissors) => refuse(
            rules.viewports,
            format!("the viewport count set ({viewports:?}) is not the bound pipeline's scissor count ({static_scissors})"),
        ),
        (false, true) if scissors != Some(static_viewports) => refuse(
            rules.scissors,
            format!("the scissor count set ({scissors:?}) is not the bound pipeline's viewport count ({static_viewports})"),
        ),
        (true, true) if viewports.is_none() || viewports != scissors => refuse(
            rules.both,
            format!("the viewport count set ({viewports:?}) is not the scissor count set ({scissors:?})"),
        ),
        _ => Ok(()),
    }
}

/// Refuses a pipeline made for other dynamic rendering than the instance's: its
/// view mask, color attachment count or formats (`UNDEFINED` where the instance's
/// attachment has no view), or depth or stencil format differ.
fn rendering_checks(
    made_for: &crate::state::RenderingFormats,
    current: &crate::state::RenderingFormats,
    rules: &RenderingRules,
) -> Result<()> {
    let undefined = vk::Format::UNDEFINED;
    if made_for.view_mask != current.view_mask {
        refuse(
            rules.view_mask,
            format!("the bound pipeline was made for view mask {:#x}, and the render pass instance has {:#x}", made_for.view_mask, current.view_mask),
        )?;
    }
    if made_for.colors.len() != current.colors.len() {
        refuse(
            rules.color_count,
            format!("the bound pipeline was made for {} color attachments, and the render pass instance has {}", made_for.colors.len(), current.colors.len()),
        )?;
    }
    for (i, (made, now)) in made_for.colors.iter().zip(&current.colors).enumerate() {
        if *now == undefined && *made != undefined {
            refuse(
                rules.color_no_view,
                format!("color attachment {i} has no view, and the bound pipeline was made for format {made:?} there"),
            )?;
        }
        if *now != undefined && made != now {
            refuse(
                rules.color_format,
                format!("color attachment {i} is of format {now:?}, and the bound pipeline was made for {made:?}"),
            )?;
        }
    }
    for (made, now, (defined_rule, undefined_rule), what) in [
        (
            made_for.depth,
            current.depth,
            (rules.depth_format, rules.depth_no_view),
            "depth",
        ),
        (
            made_for.stencil,
            current.stencil,
            (rules.stencil_format, rules.stencil_no_view),
            "stencil",
        ),
    ] {
        if now == undefined && made != undefined {
            refuse(
                undefined_rule,
                format!("the {what} attachment has no view, and the bound pipeline was made for format {made:?}"),
            )?;
        }
        if now != undefined && made != now {
            refuse(
                defined_rule,
                format!("the {what} attachment is of format {now:?}, and the bound pipeline was made for {made:?}"),
            )?;
        }
    }
    Ok(())
}

/// Refuses a draw or dispatch whose pipeline's shaders read push constants that were
/// not all pushed, with a layout compatible for push constants with the pipeline's,
/// unless the device enabled `maintenance4` (which lets them read undefined values).
fn push_constant_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    pipeline: &PipelineRecord,
    vuid: &'static str,
) -> Result<()> {
    let Some((start, end)) = pipeline.push else {
        return Ok(());
    };
    if start >= end
        || recorder
            .device()
            .live()
            .with_features(|f| f.v13.maintenance4)
            == vk::TRUE
    {
        return Ok(());
    }
    let pushed = recorder.pushed.as_ref();
    let compatible = pushed.is_some_and(|p| p.layout.same_push_ranges(&pipeline.layout));
    if !compatible {
        return refuse(
            vuid,
            format!("the bound pipeline's shaders read push constants (bytes {start} to {end}), and none were pushed with a layout of the same push-constant ranges"),
        );
    }
    if let Some(byte) = pushed.and_then(|p| p.first_unset(start, end)) {
        return refuse(
            vuid,
            format!("the bound pipeline's shaders read push constants (bytes {start} to {end}), and byte {byte} was not pushed"),
        );
    }
    Ok(())
}

/// A draw or dispatch reads its sets' image descriptors in the layouts they state:
/// subresources the recording has not touched need those layouts at its start,
/// which its submission checks.
pub(crate) fn descriptor_layouts_used<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    bind_point: vk::PipelineBindPoint,
) {
    let Some(i) = crate::recorder::Bound::index(bind_point) else {
        return;
    };
    // A run of draws on one state requires the same layouts: the first does.
    if recorder.layouts_used_again(i) {
        return;
    }
    let bound = &recorder.bound[i];
    let n = bound.pipeline.as_ref().map_or(0, |p| p.layout.sets.len());
    // Most draws read no image descriptor: nothing to collect.
    let image = |l: &crate::state::SetImages| {
        l.iter()
            .any(|(_, d)| d.kind == crate::state::SlotKind::Image)
    };
    if !bound.images.iter().take(n).flatten().any(image) {
        return;
    }
    let lists: SmallVec<[crate::state::SetImages; 4]> =
        bound.images.iter().take(n).flatten().cloned().collect();
    // An input attachment of the render pass instance is in the layout its subpass
    // gives it, which the draw's checks compared (not one the recording leaves).
    let in_pass = recorder.instance.as_ref().is_some_and(|i| !i.dynamic);
    let inputs = lists.iter().any(|l| l.iter().any(|(_, d)| d.input));
    let attachments = if in_pass && inputs {
        recorder.pass_images.to_vec()
    } else {
        Vec::new()
    };
    let (live, layouts) = recorder.layouts_mut();
    let images = lists
        .iter()
        .flat_map(|l| l.iter().map(|(_, d)| d))
        .filter(|d| d.kind == crate::state::SlotKind::Image)
        .filter(|d| !(d.input && attachments.contains(&d.image)));
    for d in images {
        layouts.require(live, d.image, d.sel, d.layout, DESCRIPTOR_LAYOUT);
    }
}

/// A dispatch's state checks ([`bound_pipeline_checks`]), once per state, and no
/// dynamic state set since its compute pipeline was bound (`static_unset`: the
/// pipeline has every state static).
pub(crate) fn dispatch_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    pipeline_vuid: &'static str,
    sets_vuid: &'static str,
    static_unset: &'static str,
    shader: &ShaderRules,
) -> Result<()> {
    recorder.verify_state(1, |recorder| {
        bound_pipeline_checks(
            recorder,
            vk::PipelineBindPoint::COMPUTE,
            pipeline_vuid,
            sets_vuid,
            None,
            shader,
        )?;
        let set = recorder.compute_dynamic;
        if set != 0 && recorder.bound[1].pipeline.is_some() {
            refuse(
                static_unset,
                format!("dynamic state bit {} was set since the bound compute pipeline was bound, and a compute pipeline has every state static", set.trailing_zeros()),
            )?;
        }
        Ok(())
    })
}

/// A dispatch with a base group other than zero needs a compute pipeline created
/// with `DISPATCH_BASE` (00427); the pipeline itself was checked bound before.
pub(crate) fn dispatch_base_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    base_group_x: u32,
    base_group_y: u32,
    base_group_z: u32,
) -> Result<()> {
    let base = [base_group_x, base_group_y, base_group_z];
    let Some(pipeline) = &recorder.bound[1].pipeline else {
        return Ok(());
    };
    if base != [0; 3]
        && !pipeline
            .flags
            .contains(vk::PipelineCreateFlags::DISPATCH_BASE)
    {
        refuse(
            "VUID-vkCmdDispatchBase-baseGroupX-00427",
            format!("the base group is {base:?}, and the bound compute pipeline was not created with VK_PIPELINE_CREATE_DISPATCH_BASE_BIT"),
        )?;
    }
    Ok(())
}

/// A draw or dispatch has a pipeline bound at its bind point (02700), a set bound
/// at every set number of that pipeline's layout, of the same set layout (02697),
/// the descriptors and push constants its shaders read ([`bound_descriptor_checks`],
/// [`push_constant_checks`]), and its image descriptors in their layouts. Which sets the shaders use is not known here, so every set of the layout
/// must be bound: a program that leaves an unused set unbound is refused too.
fn bound_pipeline_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    bind_point: vk::PipelineBindPoint,
    pipeline_vuid: &'static str,
    sets_vuid: &'static str,
    vertex_vuid: Option<&'static str>,
    shader: &ShaderRules,
) -> Result<()> {
    let Some(bound) = crate::recorder::Bound::index(bind_point).map(|i| &recorder.bound[i]) else {
        return Ok(());
    };
    let Some(pipeline) = &bound.pipeline else {
        return refuse(
            pipeline_vuid,
            format!("no {bind_point:?} pipeline is bound"),
        );
    };
    for (n, wanted) in pipeline.layout.sets.iter().enumerate() {
        let ok = bound
            .sets
            .get(n)
            .and_then(Option::as_ref)
            .is_some_and(|got| SetLayoutRecord::matches(got, wanted));
        if !ok {
            refuse(
                sets_vuid,
                format!("set {n} of the bound pipeline's layout has no descriptor set of its set layout bound"),
            )?;
        }
    }
    // A binding the vertex shader reads through an attribute, with no buffer bound:
    // the device would fetch from no memory.
    let unbound = pipeline.vertex_bindings & !bound.vertex;
    if let (Some(vuid), true) = (vertex_vuid, unbound != 0) {
        refuse(
            vuid,
            format!(
                "the bound pipeline's vertex shader reads binding {}, which has no vertex buffer bound",
                unbound.trailing_zeros()
            ),
        )?;
    }
    bound_descriptor_checks(recorder.device(), bound, pipeline, shader)?;
    protected_checks(
        recorder,
        shader.protected_access,
        shader.protected_command_buffer,
    )?;
    push_constant_checks(recorder, pipeline, shader.push_constants)?;
    descriptor_layout_checks(recorder, bound)
}

/// The images of the current subpass's attachments (those of the dynamic
/// rendering's views), or `None` where the recorder does not know them (a
/// secondary that continues an instance).
fn attachment_images<S: Scope>(
    recorder: &Recorder<'_, S>,
) -> Option<smallvec::SmallVec<[vk::Image; 4]>> {
    let instance = recorder.instance.as_ref()?;
    if instance.dynamic {
        return instance
            .rendering_images
            .as_ref()
            .map(|images| images.iter().copied().collect());
    }
    let record = instance.record.as_ref()?;
    let used = record.used.get(instance.subpass as usize)?;
    if used.is_empty() {
        return Some(smallvec::SmallVec::new());
    }
    if recorder.pass_images.is_empty() {
        return None;
    }
    Some(
        used.iter()
            .filter_map(|a| recorder.pass_images.get(*a as usize).copied())
            .collect(),
    )
}

/// Whether two bindings of memory overlap.
pub(super) fn overlaps(a: &crate::state::Binding, b: &crate::state::Binding) -> bool {
    let ((memory_a, offset_a, size_a), (memory_b, offset_b, size_b)) = (*a, *b);
    memory_a == memory_b
        && offset_a < offset_b.saturating_add(size_b)
        && offset_b < offset_a.saturating_add(size_a)
}

/// A draw's checks of the render pass instance's attachments as its shaders reach
/// them: each input attachment variable's `InputAttachmentIndex` names a used input
/// attachment of the current subpass (07468), and its descriptor views the image of
/// that attachment in its format (07469); no descriptor the shaders declare reaches
/// the memory of an attachment of the subpass (06537 where the shader may write it,
/// 06538 otherwise: which commands of the subpass write each attachment is not
/// followed); and blending only on color attachments whose format features have
/// `COLOR_ATTACHMENT_BLEND` (04727). Where the attachments are not known (a
/// secondary continuing an instance without its framebuffer), a draw whose shaders
/// declare a descriptor of memory is refused.
fn attachment_checks<S: Scope>(recorder: &Recorder<'_, S>, rules: &AttachmentRules) -> Result<()> {
    use crate::spirv::ResourceKind as K;
    use crate::state::SlotKind;
    let (Some(instance), Some(pipeline)) = (&recorder.instance, &recorder.bound[0].pipeline) else {
        return Ok(());
    };
    let bound = &recorder.bound[0];
    let live = recorder.device().live();
    let slots = |r: &crate::spirv::Resource| {
        let binding = r.binding;
        bound
            .images
            .get(r.set as usize)
            .and_then(Option::as_ref)
            .into_iter()
            .flat_map(|list| list.iter())
            .filter(move |((b, _), _)| *b == binding)
            .map(|(_, d)| *d)
    };
    let images = attachment_images(recorder);
    for r in pipeline.resources.iter() {
        if r.kind == K::InputAttachment {
            let inputs = instance
                .record
                .as_ref()
                .filter(|_| !instance.dynamic)
                .and_then(|rec| rec.inputs.get(instance.subpass as usize));
            let attachment = match (r.input_index, inputs) {
                (Some(i), Some(inputs)) => inputs
                    .get(i as usize)
                    .map(|(a, _)| *a)
                    .filter(|a| *a != vk::ATTACHMENT_UNUSED),
                _ => None,
            };
            let Some(attachment) = attachment else {
                refuse(
                    rules.input_index,
                    format!("set {} binding {}: the shader reads an input attachment (InputAttachmentIndex {:?}) that the current subpass does not have", r.set, r.binding, r.input_index),
                )?;
                continue;
            };
            let format = instance
                .record
                .as_ref()
                .and_then(|rec| rec.attachments.get(attachment as usize))
                .map(|a| a.0);
            let image = recorder.pass_images.get(attachment as usize).copied();
            for d in slots(r).filter(|d| d.kind == SlotKind::Image) {
                if Some(d.format) != format || image.is_some_and(|i| i != d.image) {
                    refuse(
                        rules.input_view,
                        format!("set {} binding {}: the input attachment's view (format {:?}) is not compatible with attachment {attachment} of the framebuffer (format {format:?})", r.set, r.binding, d.format),
                    )?;
                }
            }
            continue;
        }
        for d in slots(r) {
            let object = match d.kind {
                SlotKind::Image => live.binding(d.image),
                SlotKind::TexelBuffer | SlotKind::Buffer => live.binding(d.buffer),
                SlotKind::Sampler => continue,
            };
            let writes = match r.kind {
                K::StorageBuffer => true,
                K::StorageImage | K::StorageTexelBuffer => {
                    r.ops & (crate::spirv::ops::WRITE | crate::spirv::ops::ATOMIC) != 0
                }
                _ => false,
            };
            let vuid = if writes {
                rules.memory_written
            } else {
                rules.memory_read
            };
            let Some(images) = &images else {
                return refuse(
                    vuid,
                    format!("set {} binding {}: the render pass instance's attachments are not known in this secondary command buffer, so a descriptor of memory may alias one", r.set, r.binding),
                );
            };
            for a in images {
                let same = d.kind == SlotKind::Image && d.image == *a;
                let aliased = match (&object, live.binding(*a)) {
                    (Some(o), Some(b)) => overlaps(o, &b),
                    _ => false,
                };
                if same || aliased {
                    refuse(
                        vuid,
                        format!("set {} binding {}: the descriptor reaches the memory of an attachment of the current subpass (image 0x{:x}), which the shader {} other than as an attachment", r.set, r.binding, a.as_raw(), if writes { "may write" } else { "reads" }),
                    )?;
                }
            }
        }
    }
    blend_checks(recorder, instance, pipeline, rules.blend)
}

/// Refuses a draw whose bound pipeline blends into a color attachment whose
/// format's features lack `COLOR_ATTACHMENT_BLEND` (unless it discards
/// rasterization). The features are those of optimal tiling, and of linear tiling
/// too where an attachment's image is linear or the attachments are not known.
fn blend_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    instance: &crate::recorder::PassInstance,
    pipeline: &PipelineRecord,
    vuid: &'static str,
) -> Result<()> {
    if pipeline.blend == 0 || draw_values(recorder, pipeline).discard {
        return Ok(());
    }
    let formats: Vec<vk::Format> = if instance.dynamic {
        instance
            .rendering
            .as_ref()
            .map_or_else(Vec::new, |r| r.colors.clone())
    } else {
        instance
            .record
            .as_ref()
            .and_then(|r| r.color_formats.get(instance.subpass as usize).cloned())
            .unwrap_or_default()
    };
    let device = recorder.device();
    let live = device.live();
    let linear = attachment_images(recorder).is_none_or(|images| {
        images.iter().any(|i| {
            live.image(*i)
                .is_some_and(|r| r.tiling == vk::ImageTiling::LINEAR)
        })
    });
    for (i, format) in formats.iter().enumerate() {
        if i >= 32 || pipeline.blend & (1 << i) == 0 || *format == vk::Format::UNDEFINED {
            continue;
        }
        let props = live.format_properties(device.parent(), *format)?;
        let mut features = props.optimal_tiling_features;
        if linear {
            features &= props.linear_tiling_features;
        }
        if !features.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT_BLEND) {
            refuse(
                vuid,
                format!("the bound pipeline blends into color attachment {i}, and the features of its format {format:?} lack COLOR_ATTACHMENT_BLEND"),
            )?;
        }
    }
    Ok(())
}

/// A direct indexed draw's index count, first index, first instance, instance
/// count and vertex offset, with the rules of the indices read inside the index
/// buffer (07825), of the last instance in a multiview instance (02688) and of the
/// vertices fetched inside the vertex buffers (02721).
pub(crate) type IndexedRange = (
    u32,
    u32,
    u32,
    u32,
    i32,
    &'static str,
    &'static str,
    &'static str,
);

/// Refuses an indexed draw that could fetch vertices past a bound vertex buffer.
/// The indices are the index buffer's contents, which the device reads and the host
/// does not know, so the vertices are those of every index the index type holds (an
/// index buffer any safe program can fill); a device with `robustBufferAccess`
/// enabled keeps every fetch inside the bound range instead, and nothing is refused.
fn indexed_fetch_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    ty: vk::IndexType,
    vertex_offset: i32,
    instances: (u32, u32),
    vuid: &'static str,
) -> Result<()> {
    let robust = recorder
        .device()
        .live()
        .with_features(|f| f.v10.robust_buffer_access);
    let reads = recorder.bound[0]
        .pipeline
        .as_ref()
        .is_some_and(|p| !p.vertex_reads.is_empty());
    if robust == vk::TRUE || !reads {
        return Ok(());
    }
    let largest: u64 = match ty {
        vk::IndexType::UINT16 => u64::from(u16::MAX),
        vk::IndexType::UINT8_EXT => u64::from(u8::MAX),
        _ => u64::from(u32::MAX),
    };
    let Ok(first) = u64::try_from(vertex_offset) else {
        return refuse(
            vuid,
            format!("the draw's vertex offset ({vertex_offset}) is negative, so an index it reads can name a vertex before the bound vertex buffers; enable robustBufferAccess to draw with it"),
        );
    };
    vertex_fetch_checks(recorder, (first, largest + 1), instances, vuid).map_err(|e| match e {
        Error::Validation { vuid, message } => Error::Validation {
            vuid,
            message: format!("{message}: an indexed draw may fetch any vertex its {ty:?} indices name (the index buffer's contents are not known on the host); enable robustBufferAccess, or bind vertex buffers that hold every such vertex"),
        },
        other => other,
    })
}

/// An indexed draw: a pipeline and its sets bound ([`bound_pipeline_checks`]), an index
/// buffer bound (07312), and, for a direct draw (`range`: index count, first index and
/// the rule), the indices it reads inside that buffer. Whether robustBufferAccess2 is
/// enabled is not known here, so the range is checked whatever it is.
pub(crate) fn indexed_draw_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    pipeline_vuid: &'static str,
    sets_vuid: &'static str,
    bound_vuid: &'static str,
    vertex_vuid: &'static str,
    range: Option<IndexedRange>,
    draw: &DrawRules,
) -> Result<()> {
    draw_checks(recorder, pipeline_vuid, sets_vuid, vertex_vuid, None, draw)?;
    if recorder.bound[0].index.is_none() {
        return refuse(bound_vuid, "no index buffer is bound");
    }
    let Some((count, first, first_instance, instance_count, vertex_offset, vuid, ..)) = range
    else {
        return Ok(());
    };
    let params = (
        vuid,
        [first, count, first_instance, instance_count],
        vertex_offset,
    );
    recorder.verify_draw_params(params, |recorder| indexed_range_checks(recorder, range))
}

/// The indices, vertices and instances of one indexed draw (a direct draw's
/// parameters, or the arguments of an indirect one the host wrote): the indices it
/// reads inside the bound index buffer, its last instance index in a multiview
/// instance, and the vertices its indices can name inside the bound vertex buffers.
/// Nothing without an index buffer bound, which the command's own check refuses.
pub(crate) fn indexed_range_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    range: Option<IndexedRange>,
) -> Result<()> {
    let Some((size, offset, ty)) = recorder.bound[0].index else {
        return Ok(());
    };
    let Some((count, first, first_instance, instance_count, vertex_offset, vuid, multiview, fetch)) =
        range
    else {
        return Ok(());
    };
    multiview_instances(recorder, first_instance, instance_count, multiview)?;
    let index_size: u64 = match ty {
        vk::IndexType::UINT16 => 2,
        vk::IndexType::UINT32 => 4,
        vk::IndexType::UINT8_EXT => 1,
        _ => return Ok(()),
    };
    let end = index_size * (u64::from(first) + u64::from(count)) + offset;
    if end > size {
        refuse(
            vuid,
            format!("the draw reads indices up to byte {end} of an index buffer of {size} bytes (firstIndex = {first}, indexCount = {count}, offset = {offset})"),
        )?;
    }
    // A draw of no index or no instance fetches no vertex.
    if count == 0 || instance_count == 0 {
        return Ok(());
    }
    indexed_fetch_checks(
        recorder,
        ty,
        vertex_offset,
        (first_instance, instance_count),
        fetch,
    )
}
