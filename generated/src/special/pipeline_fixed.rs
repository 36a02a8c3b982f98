//! The checks of graphics pipeline creation over its fixed-function state: render
//! targets, blending, viewports, and the state that is dynamic or static.

use super::draw_state::check_scissors;
use super::pipeline::{States, Targets};
use super::{chained, refuse};
use crate::handles::*;
use crate::Result;
use ash::vk;

/// A subpass that uses no attachment rasterizes at a sample count the device
/// supports without attachments (`framebufferNoAttachmentsSampleCounts`, 00758).
pub(super) fn check_zero_attachments(
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
    let supported = crate::special::limits(device).framebuffer_no_attachments_sample_counts;
    if !supported.contains(samples) {
        refuse(
            "VUID-VkGraphicsPipelineCreateInfo-subpass-00758",
            format!("{at}'s subpass uses no attachment, and its rasterizationSamples ({samples:?}) is not among framebufferNoAttachmentsSampleCounts ({supported:?})"),
        )?;
    }
    Ok(())
}

/// The subpass's targets, from the render pass's record.
pub(super) fn subpass_targets(
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

/// The rules of a pipeline's `VkPipelineRenderingCreateInfo` formats and view mask.
const PIPELINE_FORMATS: super::rendering::FormatRules = super::rendering::FormatRules {
    multiview: "VUID-VkGraphicsPipelineCreateInfo-multiview-06577",
    view_count: "VUID-VkGraphicsPipelineCreateInfo-renderPass-06578",
    values: [
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06580",
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06583",
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06584",
    ],
    color_feature: "VUID-VkGraphicsPipelineCreateInfo-renderPass-06581",
    depth: [
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06587",
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06585",
    ],
    stencil: [
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06588",
        "VUID-VkGraphicsPipelineCreateInfo-renderPass-06586",
    ],
    same: "VUID-VkGraphicsPipelineCreateInfo-renderPass-06589",
};

/// The targets of dynamic rendering, from a chained `VkPipelineRenderingCreateInfo`
/// (none without one), and its rules.
pub(super) fn rendering_targets(
    device: &Device,
    raw: &vk::GraphicsPipelineCreateInfo<'_>,
    at: &str,
) -> Result<Targets> {
    let dynamic_rendering = device.live().with_features(|f| f.v13.dynamic_rendering);
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
    // SAFETY: the safe setter stores the formats with their count.
    let formats = unsafe {
        crate::state::RenderingFormats::from_raw(
            r.view_mask,
            r.p_color_attachment_formats,
            r.color_attachment_count,
            r.depth_attachment_format,
            r.stencil_attachment_format,
        )
    };
    super::rendering::formats_checks(
        device,
        &formats,
        &PIPELINE_FORMATS,
        &format!("{at}'s VkPipelineRenderingCreateInfo"),
    )?;
    let defined = |f: vk::Format| f != vk::Format::UNDEFINED;
    Ok(Targets {
        depth: [formats.depth, formats.stencil]
            .into_iter()
            .find(|f| defined(*f)),
        colors: formats.colors,
        view_mask: r.view_mask,
    })
}

/// What a color blend state and a depth/stencil state need of the targets.
pub(super) fn check_targets(
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
pub(super) fn check_blend_identical(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
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
pub(super) fn check_viewport_state(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
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
        let scissors = unsafe { crate::state::raw_slice(v.p_scissors, v.scissor_count) };
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
pub(super) fn check_fixed_function(device: &Device, states: &States<'_>, at: &str) -> Result<()> {
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
pub(super) fn features(device: &Device, format: vk::Format) -> Result<vk::FormatFeatureFlags> {
    device
        .parent()
        .get_format_properties(format)
        .map(|p| p.linear_tiling_features | p.optimal_tiling_features)
}
