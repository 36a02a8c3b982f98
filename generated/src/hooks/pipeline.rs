//! The checks of graphics pipeline creation over the pipeline's state as a whole:
//! derivatives, the set of shader stages and the topology they need, the state
//! structs the pipeline must have, what its subpass (or, for dynamic rendering, its
//! chained `VkPipelineRenderingCreateInfo`) renders to, and fixed-function values
//! that need a feature unless their state is dynamic.
//!
//! tuff emits no graphics pipeline library, so every pipeline is complete: it has
//! vertex input and pre-rasterization shader state, and fragment shader and fragment
//! output interface state unless rasterization is discarded (and not dynamically).

use super::*;

/// The state structs a graphics create info points to.
struct States<'a> {
    stages: &'a [vk::PipelineShaderStageCreateInfo<'a>],
    vertex_input: Option<&'a vk::PipelineVertexInputStateCreateInfo<'a>>,
    assembly: Option<&'a vk::PipelineInputAssemblyStateCreateInfo<'a>>,
    tessellation: Option<&'a vk::PipelineTessellationStateCreateInfo<'a>>,
    viewport: Option<&'a vk::PipelineViewportStateCreateInfo<'a>>,
    raster: Option<&'a vk::PipelineRasterizationStateCreateInfo<'a>>,
    multisample: Option<&'a vk::PipelineMultisampleStateCreateInfo<'a>>,
    depth_stencil: Option<&'a vk::PipelineDepthStencilStateCreateInfo<'a>>,
    blend: Option<&'a vk::PipelineColorBlendStateCreateInfo<'a>>,
    blend_attachments: &'a [vk::PipelineColorBlendAttachmentState],
    dynamic: &'a [vk::DynamicState],
}

impl<'a> States<'a> {
    /// # Safety
    ///
    /// `raw` is a safe create info's: each pointer set through a safe setter, to a
    /// struct that outlives it, and each array stored with its count.
    unsafe fn of(raw: &'a vk::GraphicsPipelineCreateInfo<'a>) -> Self {
        // SAFETY: as the caller promises.
        unsafe {
            let blend = raw.p_color_blend_state.as_ref();
            States {
                stages: crate::retention::raw_slice(raw.p_stages, raw.stage_count),
                vertex_input: raw.p_vertex_input_state.as_ref(),
                assembly: raw.p_input_assembly_state.as_ref(),
                tessellation: raw.p_tessellation_state.as_ref(),
                viewport: raw.p_viewport_state.as_ref(),
                raster: raw.p_rasterization_state.as_ref(),
                multisample: raw.p_multisample_state.as_ref(),
                depth_stencil: raw.p_depth_stencil_state.as_ref(),
                blend,
                blend_attachments: blend.map_or(&[][..], |b| {
                    crate::retention::raw_slice(b.p_attachments, b.attachment_count)
                }),
                dynamic: raw.p_dynamic_state.as_ref().map_or(&[][..], |d| {
                    crate::retention::raw_slice(d.p_dynamic_states, d.dynamic_state_count)
                }),
            }
        }
    }

    /// The entry point the pipeline's `stage` stage names, if it has that stage.
    fn entry_point(
        &self,
        device: &Device,
        stage: vk::ShaderStageFlags,
    ) -> Option<crate::spirv::EntryPoint> {
        let s = self.stages.iter().find(|s| s.stage == stage)?;
        crate::hooks::stage_entry_point(device, s)
    }

    fn dynamic(&self, state: vk::DynamicState) -> bool {
        self.dynamic.contains(&state)
    }

    /// Whether the pipeline has fragment shader and fragment output interface state.
    fn fragment(&self) -> bool {
        self.dynamic(vk::DynamicState::RASTERIZER_DISCARD_ENABLE)
            || self
                .raster
                .is_none_or(|r| r.rasterizer_discard_enable == vk::FALSE)
    }
}

/// What a graphics pipeline renders to: its subpass's color formats and
/// depth/stencil format, or those of its chained `VkPipelineRenderingCreateInfo`.
struct Targets {
    colors: Vec<vk::Format>,
    depth: Option<vk::Format>,
    /// The subpass's or the rendering's view mask.
    view_mask: u32,
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
                crate::retention::raw_slice(
                    v.p_vertex_binding_descriptions,
                    v.vertex_binding_description_count,
                ),
                crate::retention::raw_slice(
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
    check_specialization(states.stages, at)
}

/// Each stage's specialization constants are named once each.
fn check_specialization(stages: &[vk::PipelineShaderStageCreateInfo<'_>], at: &str) -> Result<()> {
    for (k, s) in stages.iter().enumerate() {
        // SAFETY: the safe setter stores a reference that outlives the create info.
        let Some(spec) = (unsafe { s.p_specialization_info.as_ref() }) else {
            continue;
        };
        // SAFETY: the safe setter stores the entries with their count.
        let entries =
            unsafe { crate::retention::raw_slice(spec.p_map_entries, spec.map_entry_count) };
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
        check_specialization(core::slice::from_ref(&raw.stage), &at)?;
        if let Some(layout) = device.live().pipeline_layout(raw.layout) {
            let count = stage_resources(&layout, vk::ShaderStageFlags::COMPUTE);
            let max = u64::from(crate::hooks::limits(device).max_per_stage_resources);
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

/// The stages: each at most once, a vertex shader, tessellation stages in pairs
/// with their state and the patch-list topology.
fn check_stages(states: &States<'_>, at: &str) -> Result<()> {
    let mut seen = vk::ShaderStageFlags::empty();
    for (j, s) in states.stages.iter().enumerate() {
        // With rasterization discarded for good, the pipeline has no fragment shader
        // state for a fragment stage to belong to.
        if s.stage == vk::ShaderStageFlags::FRAGMENT && !states.fragment() {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-06894",
                format!("{at}.pStages[{j}] is a fragment stage, and the pipeline discards rasterization statically, so it has no fragment shader state"),
            )?;
        }
        if seen.intersects(s.stage) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-stage-06897",
                format!(
                    "{at}.pStages[{j}].stage ({:?}) is the stage of an earlier element",
                    s.stage
                ),
            )?;
        }
        seen |= s.stage;
    }
    if !seen.contains(vk::ShaderStageFlags::VERTEX) {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-stage-00727",
            format!("{at} has no vertex shader stage"),
        )?;
    }
    let control = seen.contains(vk::ShaderStageFlags::TESSELLATION_CONTROL);
    let evaluation = seen.contains(vk::ShaderStageFlags::TESSELLATION_EVALUATION);
    if control && !evaluation {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-pStages-00729",
            format!("{at} has a tessellation control stage without an evaluation stage"),
        )?;
    }
    if evaluation && !control {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-pStages-00730",
            format!("{at} has a tessellation evaluation stage without a control stage"),
        )?;
    }
    if control && evaluation && states.tessellation.is_none() {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-pStages-00731",
            format!("{at} has tessellation stages but no pTessellationState"),
        )?;
    }
    let patches = states
        .assembly
        .is_some_and(|a| a.topology == vk::PrimitiveTopology::PATCH_LIST);
    if (control || evaluation) && states.assembly.is_some() && !patches {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-pStages-00736",
            format!("{at} has tessellation stages, so its topology must be VK_PRIMITIVE_TOPOLOGY_PATCH_LIST"),
        )?;
    }
    if patches && !(control || evaluation) {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-topology-00737",
            format!(
                "{at}'s topology is VK_PRIMITIVE_TOPOLOGY_PATCH_LIST without tessellation stages"
            ),
        )?;
    }
    Ok(())
}

/// SPIR-V execution modes a graphics pipeline's stages rely on.
mod mode {
    pub const INVOCATIONS: u32 = 0;
    pub const POINT_MODE: u32 = 10;
    pub const INPUT_POINTS: u32 = 19;
    pub const INPUT_LINES: u32 = 20;
    pub const INPUT_LINES_ADJACENCY: u32 = 21;
    pub const TRIANGLES: u32 = 22;
    pub const INPUT_TRIANGLES_ADJACENCY: u32 = 23;
    pub const QUADS: u32 = 24;
    pub const ISOLINES: u32 = 25;
    pub const OUTPUT_VERTICES: u32 = 26;
    /// The tessellation subdivisions.
    pub const SUBDIVISIONS: [u32; 3] = [TRIANGLES, QUADS, ISOLINES];
    /// A geometry shader's input primitives.
    pub const GEOMETRY_INPUTS: [u32; 5] = [
        INPUT_POINTS,
        INPUT_LINES,
        INPUT_LINES_ADJACENCY,
        TRIANGLES,
        INPUT_TRIANGLES_ADJACENCY,
    ];
}

/// The execution modes of a graphics pipeline's tessellation and geometry stages,
/// read from their modules' entry points: tessellation stages that agree on a
/// subdivision (00732, 00733) and an output patch size (00734, 00735) within
/// `maxTessellationPatchSize` (00713); a geometry stage with an output vertex count
/// (00714) and an invocation count (00715) within the limits, whose input primitive
/// is what the topology (00738) or the tessellation stages (00739) give it.
fn check_execution_modes(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
    use vk::ShaderStageFlags as S;
    let entry = |stage: S| states.entry_point(device, stage);
    let limits = crate::hooks::limits(device);
    let (control, evaluation, geometry) = (
        entry(S::TESSELLATION_CONTROL),
        entry(S::TESSELLATION_EVALUATION),
        entry(S::GEOMETRY),
    );
    let tessellation = [&control, &evaluation];
    let tessellated = control.is_some() && evaluation.is_some();
    if tessellated {
        let subdivisions: Vec<u32> = tessellation
            .iter()
            .filter_map(|e| e.as_ref()?.first_of(&mode::SUBDIVISIONS))
            .collect();
        if subdivisions.is_empty() {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-00732",
                format!(
                    "{at}'s tessellation stages name no subdivision (Triangles, Quads or Isolines)"
                ),
            )?;
        }
        if subdivisions.windows(2).any(|w| w[0] != w[1]) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-00733",
                format!(
                    "{at}'s tessellation stages name different subdivisions ({subdivisions:?})"
                ),
            )?;
        }
        let sizes: Vec<u32> = tessellation
            .iter()
            .filter_map(|e| e.as_ref()?.mode(mode::OUTPUT_VERTICES)?.first().copied())
            .collect();
        if sizes.is_empty() {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-00734",
                format!("{at}'s tessellation stages name no output patch size (OutputVertices)"),
            )?;
        }
        if sizes.windows(2).any(|w| w[0] != w[1]) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-00735",
                format!("{at}'s tessellation stages name different output patch sizes ({sizes:?})"),
            )?;
        }
        let max = limits.max_tessellation_patch_size;
        if let Some(size) = sizes.iter().find(|n| **n == 0 || **n > max) {
            refuse(
                "VUID-VkPipelineShaderStageCreateInfo-stage-00713",
                format!("{at}'s tessellation output patch size ({size}) is not within 1 and maxTessellationPatchSize ({max})"),
            )?;
        }
    }
    let Some(geometry) = geometry else {
        return Ok(());
    };
    let vertices = geometry
        .mode(mode::OUTPUT_VERTICES)
        .and_then(|o| o.first().copied());
    let max = limits.max_geometry_output_vertices;
    if !vertices.is_some_and(|n| n > 0 && n <= max) {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-stage-00714",
            format!("{at}'s geometry stage's output vertex count ({vertices:?}) is not within 1 and maxGeometryOutputVertices ({max})"),
        )?;
    }
    let invocations = geometry
        .mode(mode::INVOCATIONS)
        .and_then(|o| o.first().copied());
    let max = limits.max_geometry_shader_invocations;
    if !invocations.is_some_and(|n| n > 0 && n <= max) {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-stage-00715",
            format!("{at}'s geometry stage's invocation count ({invocations:?}) is not within 1 and maxGeometryShaderInvocations ({max})"),
        )?;
    }
    let input = geometry.first_of(&mode::GEOMETRY_INPUTS);
    if tessellated {
        // What the tessellator emits: points, lines for isolines, else triangles.
        let points = tessellation.iter().any(|e| {
            e.as_ref()
                .is_some_and(|e| e.mode(mode::POINT_MODE).is_some())
        });
        let lines = tessellation.iter().any(|e| {
            e.as_ref()
                .and_then(|e| e.first_of(&mode::SUBDIVISIONS))
                .is_some_and(|m| m == mode::ISOLINES)
        });
        let wanted = if points {
            mode::INPUT_POINTS
        } else if lines {
            mode::INPUT_LINES
        } else {
            mode::TRIANGLES
        };
        if input != Some(wanted) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-00739",
                format!("{at}'s geometry stage's input primitive (mode {input:?}) is not the tessellation stages' output (mode {wanted})"),
            )?;
        }
        return Ok(());
    }
    let Some(assembly) = states.assembly else {
        return Ok(());
    };
    use vk::PrimitiveTopology as T;
    let wanted = match assembly.topology {
        T::POINT_LIST => mode::INPUT_POINTS,
        T::LINE_LIST | T::LINE_STRIP => mode::INPUT_LINES,
        T::LINE_LIST_WITH_ADJACENCY | T::LINE_STRIP_WITH_ADJACENCY => mode::INPUT_LINES_ADJACENCY,
        T::TRIANGLE_LIST | T::TRIANGLE_STRIP | T::TRIANGLE_FAN => mode::TRIANGLES,
        T::TRIANGLE_LIST_WITH_ADJACENCY | T::TRIANGLE_STRIP_WITH_ADJACENCY => {
            mode::INPUT_TRIANGLES_ADJACENCY
        }
        _ => return Ok(()),
    };
    if input != Some(wanted) {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-pStages-00738",
            format!("{at}'s geometry stage's input primitive (mode {input:?}) is not the one its topology {:?} gives (mode {wanted})", assembly.topology),
        )?;
    }
    Ok(())
}

/// What the stages' entry points declare and write against what the pipeline renders
/// to: with a view mask, no tessellation or geometry stage without the multiview
/// feature for it (06047, 06048; 06057, 06058 in dynamic rendering) and no `Layer`
/// written (06049, 07718) or in an interface (06050, 06059), nor in dynamic
/// rendering a `ViewIndex` in an interface (07719, as the 1.3.239 rule reads); a
/// fragment stage's input attachments only in a render pass (06056, and no
/// `InputAttachment` capability, 06061), none of them unused in the subpass (06038);
/// and a fragment stage that reads `PrimitiveId` after a geometry stage that writes
/// it (00740).
fn check_stage_interfaces(
    device: &Device,
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    states: &States<'_>,
    targets: &Targets,
    at: &str,
) -> Result<()> {
    use vk::ShaderStageFlags as S;
    const LAYER: u32 = 9;
    const VIEW_INDEX: u32 = 4440;
    const PRIMITIVE_ID: u32 = 7;
    const INPUT: u32 = 1;
    const INPUT_ATTACHMENT_CAPABILITY: u32 = 40;
    let pass = raw.render_pass != vk::RenderPass::null();
    let entry = |stage: S| states.entry_point(device, stage);
    let has = |stage: S| states.stages.iter().any(|s| s.stage == stage);
    let pick =
        |in_pass: &'static str, rendering: &'static str| if pass { in_pass } else { rendering };
    if targets.view_mask != 0 {
        let (tessellation, geometry) = device.live().with_features(|f| {
            (
                f.v11.multiview_tessellation_shader == vk::TRUE,
                f.v11.multiview_geometry_shader == vk::TRUE,
            )
        });
        if !tessellation && (has(S::TESSELLATION_CONTROL) || has(S::TESSELLATION_EVALUATION)) {
            refuse(
                pick("VUID-VkGraphicsPipelineCreateInfo-renderPass-06047", "VUID-VkGraphicsPipelineCreateInfo-renderPass-06057"),
                format!("{at} renders with view mask {:#x} and has tessellation stages, and the device has not enabled multiviewTessellationShader", targets.view_mask),
            )?;
        }
        if !geometry && has(S::GEOMETRY) {
            refuse(
                pick("VUID-VkGraphicsPipelineCreateInfo-renderPass-06048", "VUID-VkGraphicsPipelineCreateInfo-renderPass-06058"),
                format!("{at} renders with view mask {:#x} and has a geometry stage, and the device has not enabled multiviewGeometryShader", targets.view_mask),
            )?;
        }
        for s in states.stages {
            let Some(e) = crate::hooks::stage_entry_point(device, s) else {
                continue;
            };
            if e.writes.contains(&LAYER) {
                refuse(
                    pick(
                        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06049",
                        "VUID-VkGraphicsPipelineCreateInfo-renderPass-07718",
                    ),
                    format!(
                        "{at} renders with view mask {:#x}, and its {:?} stage writes Layer",
                        targets.view_mask, s.stage
                    ),
                )?;
            }
            if !pass && e.builtins.iter().any(|(b, _, _)| *b == VIEW_INDEX) {
                refuse(
                    "VUID-VkGraphicsPipelineCreateInfo-renderPass-07719",
                    format!("{at} renders with view mask {:#x} in dynamic rendering, and its {:?} stage's interface has a ViewIndex variable", targets.view_mask, s.stage),
                )?;
            }
            if e.builtins.iter().any(|(b, _, _)| *b == LAYER) {
                refuse(
                    pick("VUID-VkGraphicsPipelineCreateInfo-renderPass-06050", "VUID-VkGraphicsPipelineCreateInfo-renderPass-06059"),
                    format!("{at} renders with view mask {:#x}, and its {:?} stage's interface has a Layer variable", targets.view_mask, s.stage),
                )?;
            }
        }
    }
    let fragment = states.stages.iter().find(|s| s.stage == S::FRAGMENT);
    if let Some(interface) = fragment.and_then(|s| device.live().shader_module(s.module)) {
        let inputs = interface
            .resources
            .iter()
            .filter(|r| r.kind == crate::spirv::ResourceKind::InputAttachment);
        if !pass {
            if inputs.clone().next().is_some() {
                refuse(
                    "VUID-VkGraphicsPipelineCreateInfo-renderPass-06056",
                    format!("{at} is made for dynamic rendering, and its fragment stage reads an input attachment"),
                )?;
            }
            if interface
                .capabilities
                .contains(&INPUT_ATTACHMENT_CAPABILITY)
            {
                refuse(
                    "VUID-VkGraphicsPipelineCreateInfo-renderPass-06061",
                    format!("{at} is made for dynamic rendering, and its fragment stage declares the InputAttachment capability"),
                )?;
            }
        } else if let Some(record) = device.live().render_pass(raw.render_pass) {
            let subpass = record.inputs.get(raw.subpass as usize);
            for r in inputs {
                let unused = r
                    .input_index
                    .and_then(|i| subpass?.get(i as usize))
                    .is_some_and(|(a, _)| *a == vk::ATTACHMENT_UNUSED);
                if unused {
                    refuse(
                        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06038",
                        format!("{at}'s fragment stage reads input attachment {:?}, which subpass {} defines as VK_ATTACHMENT_UNUSED", r.input_index, raw.subpass),
                    )?;
                }
                check_input_aspects(&record, subpass.map_or(&[][..], |s| s), r, at)?;
            }
        }
    }
    let reads_primitive = entry(S::FRAGMENT).is_some_and(|e| {
        e.builtins
            .iter()
            .any(|(b, s, _)| *b == PRIMITIVE_ID && *s == INPUT)
    });
    if let Some(g) = entry(S::GEOMETRY).filter(|_| reads_primitive) {
        if !g.writes.contains(&PRIMITIVE_ID) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-00740",
                format!("{at}'s fragment stage reads PrimitiveId, and its geometry stage does not write it"),
            )?;
        }
    }
    Ok(())
}

/// An input attachment variable reads only aspects its subpass's references name
/// (pStages-01565): a float variable reads the depth aspect of a depth/stencil
/// attachment, an integer one its stencil aspect, and a color attachment its color
/// aspect. A variable that spans several input indices is held to each; one whose
/// count or numeric type is not known, to every reference from its index on.
fn check_input_aspects(
    record: &crate::retention::RenderPassRecord,
    inputs: &[(u32, vk::ImageAspectFlags)],
    r: &crate::spirv::Resource,
    at: &str,
) -> Result<()> {
    type A = vk::ImageAspectFlags;
    let Some(first) = r.input_index else {
        return Ok(());
    };
    let numeric = r.image.map_or(0, |i| i.numeric);
    let last = match r.count {
        0 => inputs.len() as u32,
        n => first.saturating_add(n),
    };
    for index in first..last {
        let Some(&(attachment, mask)) = inputs.get(index as usize) else {
            continue;
        };
        let Some(&(format, _, _)) = record.attachments.get(attachment as usize) else {
            continue;
        };
        if mask.is_empty() {
            continue;
        }
        let present = crate::formats::aspects(format).unwrap_or(A::empty());
        let reads = if present.intersects(A::DEPTH | A::STENCIL) {
            match numeric {
                1 => A::DEPTH,
                2 => A::STENCIL,
                _ => A::DEPTH | A::STENCIL,
            }
        } else {
            A::COLOR
        };
        if !mask.contains(reads) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-01565",
                format!("{at}'s fragment stage reads the {reads:?} aspect of input attachment {index} (attachment {attachment}, {format:?}), and the render pass lets it read {mask:?} alone"),
            )?;
        }
    }
    Ok(())
}

/// The linking rules between consecutive shader stages (the Shader Interfaces
/// chapter): every user-defined input of a stage matches an output of the stage
/// before it at the same location and component, of the same type (or, with
/// `maintenance4`, a vector of more components), both per-patch or neither; and
/// between two stages that are not fragment stages, the built-in blocks match
/// exactly. An input that no output writes is refused too, as later registries'
/// rules read; a type the SPIR-V reader cannot follow matches nothing. Between
/// pre-rasterization stages that is pStages-00742, into the fragment stage
/// None-04889.
fn check_stage_linking(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
    use vk::ShaderStageFlags as S;
    let order = [
        S::VERTEX,
        S::TESSELLATION_CONTROL,
        S::TESSELLATION_EVALUATION,
        S::GEOMETRY,
        S::FRAGMENT,
    ];
    let present: Vec<(S, crate::spirv::EntryPoint)> = order
        .iter()
        .filter_map(|&stage| Some((stage, states.entry_point(device, stage)?)))
        .collect();
    let narrowing = device.live().with_features(|f| f.v13.maintenance4) == vk::TRUE;
    for pair in present.windows(2) {
        let [(from, producer), (to, consumer)] = pair else {
            continue;
        };
        let rule = match *to {
            S::FRAGMENT => "VUID-VkGraphicsPipelineCreateInfo-None-04889",
            _ => "VUID-VkGraphicsPipelineCreateInfo-pStages-00742",
        };
        for input in consumer.io.iter().filter(|v| !v.output) {
            let output = producer.io.iter().find(|v| {
                v.output
                    && v.location != u32::MAX
                    && (v.location, v.component, v.patch)
                        == (input.location, input.component, input.patch)
            });
            let what = match output {
                None => "no output of",
                Some(o) if o.ty.matches(&input.ty, narrowing) => continue,
                Some(_) => "an output of another type in",
            };
            let patch = if input.patch { "patch " } else { "" };
            refuse(
                rule,
                format!(
                    "{at}'s {to:?} stage reads the {patch}input at location {} component {} ({:?}), which is {what} its {from:?} stage",
                    input.location, input.component, input.ty
                ),
            )?;
        }
        let [inputs, _] = &consumer.builtin_blocks;
        let [_, outputs] = &producer.builtin_blocks;
        if *to != S::FRAGMENT && !inputs.is_empty() && inputs != outputs {
            refuse(
                rule,
                format!(
                    "{at}'s {to:?} stage reads the built-in block {inputs:?} (BuiltIn, array size), and its {from:?} stage writes {outputs:?}: they must match exactly"
                ),
            )?;
        }
    }
    Ok(())
}

/// The last pre-rasterization stage writes `PointSize` where it rasterizes points
/// and the device reads it there: a vertex stage alone with a point list (07722), a
/// tessellation evaluation stage in point mode with no geometry stage (07723), or a
/// geometry stage that outputs points (07725), while
/// `shaderTessellationAndGeometryPointSize` is enabled for the last two; without
/// it, they must not write it (07724, 07726).
fn check_point_size(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
    use vk::ShaderStageFlags as S;
    const POINT_SIZE: u32 = 1;
    const OUTPUT_POINTS: u32 = 27;
    let entry = |stage: S| states.entry_point(device, stage);
    let sized = device
        .live()
        .with_features(|f| f.v10.shader_tessellation_and_geometry_point_size)
        == vk::TRUE;
    let (geometry, evaluation) = (entry(S::GEOMETRY), entry(S::TESSELLATION_EVALUATION));
    let (last, points, written, unwritten, what) = if let Some(g) = geometry {
        let points = g.mode(OUTPUT_POINTS).is_some();
        (
            g,
            points,
            "VUID-VkGraphicsPipelineCreateInfo-Geometry-07725",
            "VUID-VkGraphicsPipelineCreateInfo-Geometry-07726",
            "geometry stage outputs points",
        )
    } else if let Some(e) = evaluation {
        let points = e.mode(mode::POINT_MODE).is_some();
        (
            e,
            points,
            "VUID-VkGraphicsPipelineCreateInfo-TessellationEvaluation-07723",
            "VUID-VkGraphicsPipelineCreateInfo-TessellationEvaluation-07724",
            "tessellation evaluation stage is in point mode",
        )
    } else {
        let Some(v) = entry(S::VERTEX) else {
            return Ok(());
        };
        let points = states
            .assembly
            .is_some_and(|a| a.topology == vk::PrimitiveTopology::POINT_LIST);
        if points && !v.writes.contains(&POINT_SIZE) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-Vertex-07722",
                format!("{at} draws a point list with a vertex stage alone, which does not write PointSize"),
            )?;
        }
        return Ok(());
    };
    let writes = last.writes.contains(&POINT_SIZE);
    if points && sized && !writes {
        refuse(
            written,
            format!("{at}'s {what} and does not write PointSize, which the device's shaderTessellationAndGeometryPointSize reads"),
        )?;
    }
    if points && !sized && writes {
        refuse(
            unwritten,
            format!("{at}'s {what} and writes PointSize, and the device has not enabled shaderTessellationAndGeometryPointSize"),
        )?;
    }
    Ok(())
}

/// The state structs and layout a complete pipeline needs.
fn check_present(
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    states: &States<'_>,
    at: &str,
) -> Result<()> {
    let needs = [
        (
            states.vertex_input.is_some(),
            "VUID-VkGraphicsPipelineCreateInfo-pStages-02097",
            "pVertexInputState",
        ),
        (
            states.assembly.is_some(),
            "VUID-VkGraphicsPipelineCreateInfo-pStages-02098",
            "pInputAssemblyState",
        ),
        (
            states.raster.is_some(),
            "VUID-VkGraphicsPipelineCreateInfo-pRasterizationState-06601",
            "pRasterizationState",
        ),
        (
            raw.layout != vk::PipelineLayout::null(),
            "VUID-VkGraphicsPipelineCreateInfo-layout-06602",
            "layout",
        ),
        (
            states
                .raster
                .is_none_or(|r| r.rasterizer_discard_enable != vk::FALSE)
                || states.viewport.is_some(),
            "VUID-VkGraphicsPipelineCreateInfo-rasterizerDiscardEnable-00750",
            "pViewportState (rasterization is not discarded)",
        ),
        (
            !states.fragment() || states.multisample.is_some(),
            "VUID-VkGraphicsPipelineCreateInfo-rasterizerDiscardEnable-00751",
            "pMultisampleState (the pipeline has fragment output state)",
        ),
        (
            !states.dynamic(vk::DynamicState::RASTERIZER_DISCARD_ENABLE)
                || states.viewport.is_some(),
            "VUID-VkGraphicsPipelineCreateInfo-pViewportState-04892",
            "pViewportState (rasterizer discard is dynamic)",
        ),
    ];
    for (given, vuid, what) in needs {
        if !given {
            refuse(vuid, format!("{at} has no {what}"))?;
        }
    }
    Ok(())
}

/// Each stage the pipeline uses reaches at most `maxPerStageResources` resources
/// through its layout (01688): the descriptors of the kinds that limit counts, in set
/// layouts without `UPDATE_AFTER_BIND_POOL`, visible to the stage, and for the
/// fragment stage its `colors` color attachments.
fn check_stage_resources(
    device: &Device,
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    states: &States<'_>,
    colors: usize,
    at: &str,
) -> Result<()> {
    let Some(layout) = device.live().pipeline_layout(raw.layout) else {
        return Ok(());
    };
    let max = u64::from(crate::hooks::limits(device).max_per_stage_resources);
    for s in states.stages {
        let mut count = stage_resources(&layout, s.stage);
        if s.stage == vk::ShaderStageFlags::FRAGMENT {
            count += colors as u64;
        }
        if count > max {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-layout-01688",
                format!("{at}'s {:?} stage reaches {count} resources through its layout (and color attachments), past maxPerStageResources ({max})", s.stage),
            )?;
        }
    }
    Ok(())
}

/// The resources of `layout` that count against `maxPerStageResources` for `stage`:
/// the descriptors of the limited kinds in its set layouts without
/// `UPDATE_AFTER_BIND_POOL` that the stage can see.
fn stage_resources(layout: &crate::retention::LayoutRecord, stage: vk::ShaderStageFlags) -> u64 {
    use vk::DescriptorType as T;
    layout
        .sets
        .iter()
        .filter(|set| !set.update_after_bind)
        .flat_map(|set| set.bindings.iter())
        .filter(|b| b.stages.contains(stage))
        .filter(|b| {
            matches!(
                b.ty,
                T::SAMPLER
                    | T::COMBINED_IMAGE_SAMPLER
                    | T::SAMPLED_IMAGE
                    | T::STORAGE_IMAGE
                    | T::UNIFORM_TEXEL_BUFFER
                    | T::STORAGE_TEXEL_BUFFER
                    | T::UNIFORM_BUFFER
                    | T::STORAGE_BUFFER
                    | T::UNIFORM_BUFFER_DYNAMIC
                    | T::STORAGE_BUFFER_DYNAMIC
                    | T::INPUT_ATTACHMENT
            )
        })
        .map(|b| u64::from(b.count))
        .sum()
}

/// A subpass that uses no attachment rasterizes at a sample count the device
/// supports without attachments (`framebufferNoAttachmentsSampleCounts`, 00758).
fn check_zero_attachments(
    device: &Device,
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    states: &States<'_>,
    at: &str,
) -> Result<()> {
    let (Some(record), Some(multisample)) = (
        device.live().render_pass(raw.render_pass),
        states.multisample,
    ) else {
        return Ok(());
    };
    if record.no_attachments.get(raw.subpass as usize) != Some(&true) {
        return Ok(());
    }
    let samples = multisample.rasterization_samples;
    let supported = crate::hooks::limits(device).framebuffer_no_attachments_sample_counts;
    if !supported.contains(samples) {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-subpass-00758",
            format!("{at}'s subpass uses no attachment, and its rasterizationSamples ({samples:?}) is not among framebufferNoAttachmentsSampleCounts ({supported:?})"),
        )?;
    }
    Ok(())
}

/// The subpass's targets, from the render pass's record.
fn subpass_targets(
    device: &Device,
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    at: &str,
) -> Result<Targets> {
    let Some(record) = device.live().render_pass(raw.render_pass) else {
        return Ok(Targets {
            colors: Vec::new(),
            depth: None,
            view_mask: 0,
        });
    };
    let count = record.view_masks.len();
    let subpass = raw.subpass as usize;
    if subpass >= count {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06046",
            format!(
                "{at}.subpass ({subpass}) is not a subpass of its render pass, which has {count}"
            ),
        )?;
    }
    Ok(Targets {
        colors: record
            .color_formats
            .get(subpass)
            .cloned()
            .unwrap_or_default(),
        depth: record.depth_formats.get(subpass).copied().flatten(),
        view_mask: record.view_masks.get(subpass).copied().unwrap_or(0),
    })
}

/// The targets of dynamic rendering, from a chained `VkPipelineRenderingCreateInfo`
/// (none without one), and its rules.
fn rendering_targets(
    device: &Device,
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    at: &str,
) -> Result<Targets> {
    let (dynamic_rendering, multiview) = device
        .live()
        .with_features(|f| (f.v13.dynamic_rendering, f.v11.multiview));
    if dynamic_rendering == vk::FALSE {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-dynamicRendering-06576",
            format!("{at} has no render pass, and the device was created without dynamicRendering"),
        )?;
    }
    // SAFETY: `raw` is a safe struct's.
    let rendering: Option<&vk::PipelineRenderingCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::PIPELINE_RENDERING_CREATE_INFO,
        )
    };
    let Some(r) = rendering else {
        return Ok(Targets {
            colors: Vec::new(),
            depth: None,
            view_mask: 0,
        });
    };
    if r.view_mask != 0 && multiview == vk::FALSE {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-multiview-06577",
            format!("{at}'s VkPipelineRenderingCreateInfo::viewMask is {:#x}, but the device was created without multiview", r.view_mask),
        )?;
    }
    let highest = 32 - r.view_mask.leading_zeros();
    if let Some(max) = super::render_pass::multiview_view_count(device) {
        if highest > max {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-renderPass-06578",
                format!("{at}'s VkPipelineRenderingCreateInfo::viewMask ({:#x}) names view {}, past maxMultiviewViewCount ({max})", r.view_mask, highest - 1),
            )?;
        }
    }
    // SAFETY: the safe setter stores the formats with their count.
    let colors = unsafe {
        crate::retention::raw_slice(r.p_color_attachment_formats, r.color_attachment_count)
    };
    let (depth, stencil) = (r.depth_attachment_format, r.stencil_attachment_format);
    // Values of the API first: the format queries below hand them to the driver.
    let scope = device.scope();
    for &f in colors {
        crate::checks::enum_format(
            f,
            &scope,
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06580",
        )?;
    }
    crate::checks::enum_format(
        depth,
        &scope,
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06583",
    )?;
    crate::checks::enum_format(
        stencil,
        &scope,
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06584",
    )?;
    let defined = |f: vk::Format| f != vk::Format::UNDEFINED;
    for (k, &f) in colors.iter().enumerate().filter(|(_, f)| defined(**f)) {
        if !features(device, f)?.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT) {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-renderPass-06581",
                format!(
                    "{at}'s pColorAttachmentFormats[{k}] ({f:?}) has no color attachment feature"
                ),
            )?;
        }
    }
    let aspects = |f| crate::formats::aspects(f).unwrap_or_default();
    for (format, what, feature_vuid, aspect, aspect_vuid) in [
        (
            depth,
            "depthAttachmentFormat",
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06585",
            vk::ImageAspectFlags::DEPTH,
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06587",
        ),
        (
            stencil,
            "stencilAttachmentFormat",
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06586",
            vk::ImageAspectFlags::STENCIL,
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06588",
        ),
    ] {
        if !defined(format) {
            continue;
        }
        if !aspects(format).contains(aspect) {
            refuse(
                aspect_vuid,
                format!("{at}'s {what} ({format:?}) has no {aspect:?} aspect"),
            )?;
        }
        if !features(device, format)?.contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT) {
            refuse(
                feature_vuid,
                format!("{at}'s {what} ({format:?}) has no depth/stencil attachment feature"),
            )?;
        }
    }
    if defined(depth) && defined(stencil) && depth != stencil {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06589",
            format!("{at}'s depthAttachmentFormat ({depth:?}) and stencilAttachmentFormat ({stencil:?}) differ"),
        )?;
    }
    Ok(Targets {
        colors: colors.to_vec(),
        depth: [depth, stencil].into_iter().find(|f| defined(*f)),
        view_mask: r.view_mask,
    })
}

/// What a color blend state and a depth/stencil state need of the targets.
fn check_targets(
    device: &Device,
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    states: &States<'_>,
    targets: &Targets,
    at: &str,
) -> Result<()> {
    let pass = raw.render_pass != vk::RenderPass::null();
    let pick = |with_pass, without| if pass { with_pass } else { without };
    if pass && targets.depth.is_some() && states.depth_stencil.is_none() {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06043",
            format!(
                "{at}'s subpass uses a depth/stencil attachment, but it has no pDepthStencilState"
            ),
        )?;
    }
    let colors = targets.colors.len();
    if colors == 0 {
        return Ok(());
    }
    let Some(blend) = states.blend else {
        if pass {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-renderPass-06044",
                format!("{at}'s subpass uses color attachments, but it has no pColorBlendState"),
            )?;
        }
        return Ok(());
    };
    if blend.attachment_count as usize != colors {
        refuse(
            pick(
                "VUID-VkGraphicsPipelineCreateInfo-renderPass-06042",
                "VUID-VkGraphicsPipelineCreateInfo-renderPass-06055",
            ),
            format!(
                "{at}'s pColorBlendState has {} attachments, but it renders to {colors} colors",
                blend.attachment_count
            ),
        )?;
    }
    for (k, (a, &format)) in states
        .blend_attachments
        .iter()
        .zip(&targets.colors)
        .enumerate()
    {
        if a.blend_enable == vk::FALSE || format == vk::Format::UNDEFINED {
            continue;
        }
        if !features(device, format)?.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT_BLEND) {
            refuse(
                pick(
                    "VUID-VkGraphicsPipelineCreateInfo-renderPass-06041",
                    "VUID-VkGraphicsPipelineCreateInfo-renderPass-06062",
                ),
                format!("{at} blends into color attachment {k}, whose format {format:?} does not support blending"),
            )?;
        }
    }
    Ok(())
}

/// Without independentBlend, every color attachment blends the same way.
fn check_blend_identical(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
    if device.live().features().independent_blend == vk::TRUE {
        return Ok(());
    }
    let key = |a: &vk::PipelineColorBlendAttachmentState| {
        (
            a.blend_enable,
            a.src_color_blend_factor,
            a.dst_color_blend_factor,
            a.color_blend_op,
            a.src_alpha_blend_factor,
            a.dst_alpha_blend_factor,
            a.alpha_blend_op,
            a.color_write_mask,
        )
    };
    let mut all = states.blend_attachments.iter();
    if let Some(first) = all.next() {
        if let Some(k) = all.position(|a| key(a) != key(first)) {
            refuse(
                "VUID-VkPipelineColorBlendStateCreateInfo-pAttachments-00605",
                format!("{at}'s color blend attachment {} differs from attachment 0, but the device does not enable independentBlend", k + 1),
            )?;
        }
    }
    Ok(())
}

/// The viewport state's counts against the dynamic states that replace them, and
/// its static scissors. With rasterization discarded (and not dynamically) the
/// state is not read.
fn check_viewport_state(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
    let Some(v) = states.viewport else {
        return Ok(());
    };
    let discarded = states
        .raster
        .is_some_and(|r| r.rasterizer_discard_enable == vk::TRUE)
        && !states.dynamic(vk::DynamicState::RASTERIZER_DISCARD_ENABLE);
    if discarded {
        return Ok(());
    }
    let viewports_counted = states.dynamic(vk::DynamicState::VIEWPORT_WITH_COUNT);
    let scissors_counted = states.dynamic(vk::DynamicState::SCISSOR_WITH_COUNT);
    // Without Vulkan 1.3 or VK_EXT_extended_dynamic_state no count can be dynamic,
    // and the rules are the registry's plain "greater than 0".
    let exts = device.exts();
    let counts_can_be_dynamic = exts.version(3) || exts.named("VK_EXT_extended_dynamic_state");
    if !viewports_counted && v.viewport_count == 0 {
        match counts_can_be_dynamic {
            true => refuse(
                "VUID-VkPipelineViewportStateCreateInfo-viewportCount-04135",
                format!("{at}'s viewportCount is 0, and VK_DYNAMIC_STATE_VIEWPORT_WITH_COUNT is not dynamic"),
            )?,
            false => refuse(
                "VUID-VkPipelineViewportStateCreateInfo-viewportCount-arraylength",
                format!("{at}'s viewportCount is 0"),
            )?,
        }
    }
    if !scissors_counted && v.scissor_count == 0 {
        match counts_can_be_dynamic {
            true => refuse(
                "VUID-VkPipelineViewportStateCreateInfo-scissorCount-04136",
                format!(
                    "{at}'s scissorCount is 0, and VK_DYNAMIC_STATE_SCISSOR_WITH_COUNT is not dynamic"
                ),
            )?,
            false => refuse(
                "VUID-VkPipelineViewportStateCreateInfo-scissorCount-arraylength",
                format!("{at}'s scissorCount is 0"),
            )?,
        }
    }
    if !viewports_counted && !scissors_counted && v.viewport_count != v.scissor_count {
        refuse(
            "VUID-VkPipelineViewportStateCreateInfo-scissorCount-04134",
            format!(
                "{at}'s viewportCount ({}) and scissorCount ({}) differ",
                v.viewport_count, v.scissor_count
            ),
        )?;
    }
    if !scissors_counted && !states.dynamic(vk::DynamicState::SCISSOR) && !v.p_scissors.is_null() {
        // SAFETY: the safe setter stores the scissors with their count.
        let scissors = unsafe { crate::retention::raw_slice(v.p_scissors, v.scissor_count) };
        check_scissors(
            scissors,
            (
                "VUID-VkPipelineViewportStateCreateInfo-x-02821",
                "VUID-VkPipelineViewportStateCreateInfo-offset-02822",
                "VUID-VkPipelineViewportStateCreateInfo-offset-02823",
            ),
        )?;
    }
    Ok(())
}

/// Values that need a feature unless their state is dynamic, and the dynamic
/// states that replace a count.
fn check_fixed_function(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
    let f = device.live().features();
    if let Some(r) = states.raster {
        if f.wide_lines == vk::FALSE
            && !states.dynamic(vk::DynamicState::LINE_WIDTH)
            && r.line_width != 1.0
        {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00749",
                format!(
                    "{at}'s lineWidth is {}, but the device was created without wideLines",
                    r.line_width
                ),
            )?;
        }
        if f.depth_bias_clamp == vk::FALSE
            && !states.dynamic(vk::DynamicState::DEPTH_BIAS)
            && r.depth_bias_enable == vk::TRUE
            && r.depth_bias_clamp != 0.0
        {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00754",
                format!("{at}'s depthBiasClamp is {}, but the device was created without depthBiasClamp", r.depth_bias_clamp),
            )?;
        }
    }
    if let Some(d) = states.depth_stencil.filter(|_| states.fragment()) {
        let inside = |v: f32| (0.0..=1.0).contains(&v);
        if !states.dynamic(vk::DynamicState::DEPTH_BOUNDS)
            && d.depth_bounds_test_enable == vk::TRUE
            && !(inside(d.min_depth_bounds) && inside(d.max_depth_bounds))
        {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00755",
                format!(
                    "{at}'s depth bounds ({}, {}) are not both between 0.0 and 1.0",
                    d.min_depth_bounds, d.max_depth_bounds
                ),
            )?;
        }
    }
    for (with_count, plain, count, what, zero_vuid, both_vuid) in [
        (
            vk::DynamicState::VIEWPORT_WITH_COUNT,
            vk::DynamicState::VIEWPORT,
            states.viewport.map_or(0, |v| v.viewport_count),
            "viewport",
            "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-03379",
            "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04132",
        ),
        (
            vk::DynamicState::SCISSOR_WITH_COUNT,
            vk::DynamicState::SCISSOR,
            states.viewport.map_or(0, |v| v.scissor_count),
            "scissor",
            "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-03380",
            "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04133",
        ),
    ] {
        if !states.dynamic(with_count) {
            continue;
        }
        if count != 0 {
            refuse(
                zero_vuid,
                format!("{at} sets its {what} count dynamically, so the viewport state's count must be 0, not {count}"),
            )?;
        }
        if states.dynamic(plain) {
            refuse(
                both_vuid,
                format!("{at} makes both {plain:?} and {with_count:?} dynamic"),
            )?;
        }
    }
    Ok(())
}

/// What an image of `format` can do with either tiling.
fn features(device: &Device, format: vk::Format) -> Result<vk::FormatFeatureFlags> {
    device
        .parent()
        .get_format_properties(format)
        .map(|p| p.linear_tiling_features | p.optimal_tiling_features)
}
