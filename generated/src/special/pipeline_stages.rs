//! The checks of pipeline creation over its shader stages: entry points, execution
//! modes, the interfaces between stages, and the resources each stage declares.

use super::pipeline::{States, Targets};
use super::refuse;
use crate::handles::*;
use crate::Result;
use ash::vk;

/// The stages: each at most once, a vertex shader, tessellation stages in pairs
/// with their state and the patch-list topology.
pub(super) fn check_stages(states: &States<'_>, at: &str) -> Result<()> {
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
pub(super) mod mode {
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
pub(super) fn check_execution_modes(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
    use vk::ShaderStageFlags as S;
    let entry = |stage: S| states.entry_point(device, stage);
    let limits = crate::special::limits(device);
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
pub(super) fn check_stage_interfaces(
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
            let Some(e) = crate::special::shader::stage_entry_point(device, s) else {
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
    record: &crate::state::RenderPassRecord,
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
pub(super) fn check_stage_linking(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
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
pub(super) fn check_point_size(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
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
pub(super) fn check_present(
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
pub(super) fn check_stage_resources(
    device: &Device,
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    states: &States<'_>,
    colors: usize,
    at: &str,
) -> Result<()> {
    let Some(layout) = device.live().pipeline_layout(raw.layout) else {
        return Ok(());
    };
    let max = u64::from(crate::special::limits(device).max_per_stage_resources);
    for s in states.stages {
        let mut count = limited_resources(&layout, s.stage);
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
pub(super) fn limited_resources(
    layout: &crate::state::LayoutRecord,
    stage: vk::ShaderStageFlags,
) -> u64 {
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
