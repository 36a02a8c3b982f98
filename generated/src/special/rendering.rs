//! Dynamic rendering: `vkCmdBeginRendering`'s attachments (each read into one
//! [`Slot`], whose rules are written once and named by the slot's VUIDs), its render
//! area against the views and the device's limits, and the render pass instance the
//! recorder enters.

use super::refuse;
use crate::handles::Device;
use crate::recorder::{Recorder, Scope};
use crate::state::{ImageRecord, ViewRecord};
use crate::structs::*;
use crate::{Error, Result};
use ash::vk;
use tuff_runtime::Vrc;

type L = vk::ImageLayout;

/// Refuses a render pass instance that suspends or resumes: which commands run
/// between a suspended instance and the one that resumes it, across command buffers
/// and batches, is not followed, so a submission could not check its rules.
pub(crate) fn begin_rendering_checks<S: Scope>(
    _recorder: &Recorder<'_, S>,
    rendering_info: &RenderingInfo<'_>,
) -> Result<()> {
    let flags = vk::RenderingFlags::SUSPENDING | vk::RenderingFlags::RESUMING;
    if rendering_info.flags.intersects(flags) {
        return Err(Error::Misuse(
            "the safe begin_rendering does not suspend or resume render pass instances (their submission rules are not followed); use begin_rendering_unchecked, and keep VUID-VkSubmitInfo-pCommandBuffers-06014 to 06016 and 06193",
        ));
    }
    Ok(())
}

/// Which slot of a rendering info an attachment fills.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Color,
    Depth,
    Stencil,
}

/// The rules of one kind of attachment slot, by what they check (`""`: the slot has
/// no such rule).
struct SlotRules {
    kind: Kind,
    /// The view's usage (for the stencil slot: the image's stencil usage).
    usage: &'static str,
    /// The view's format has the slot's aspect.
    aspect: &'static str,
    /// Layouts `imageLayout` must not be, each set with its rule.
    layouts: &'static [(&'static [L], &'static str)],
    /// Layouts `resolveImageLayout` must not be, where the slot resolves.
    resolve_layouts: &'static [(&'static [L], &'static str)],
    /// `resolveMode` among the device's supported depth or stencil resolve modes.
    resolve_modes: &'static str,
}

const DS: &[L] = &[
    L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    L::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
];
const MIXED: &[L] = &[
    L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
    L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
];
const SEPARATE: &[L] = &[
    L::DEPTH_ATTACHMENT_OPTIMAL,
    L::DEPTH_READ_ONLY_OPTIMAL,
    L::STENCIL_ATTACHMENT_OPTIMAL,
    L::STENCIL_READ_ONLY_OPTIMAL,
];
const COLOR: &[L] = &[L::COLOR_ATTACHMENT_OPTIMAL];
const STENCIL_ONLY: &[L] = &[L::STENCIL_ATTACHMENT_OPTIMAL, L::STENCIL_READ_ONLY_OPTIMAL];
const DEPTH_ONLY: &[L] = &[L::DEPTH_ATTACHMENT_OPTIMAL, L::DEPTH_READ_ONLY_OPTIMAL];

const COLOR_SLOT: SlotRules = SlotRules {
    kind: Kind::Color,
    usage: "VUID-VkRenderingInfo-colorAttachmentCount-06087",
    aspect: "",
    layouts: &[
        (DS, "VUID-VkRenderingInfo-colorAttachmentCount-06090"),
        (MIXED, "VUID-VkRenderingInfo-colorAttachmentCount-06096"),
        (SEPARATE, "VUID-VkRenderingInfo-colorAttachmentCount-06100"),
    ],
    resolve_layouts: &[
        (DS, "VUID-VkRenderingInfo-colorAttachmentCount-06091"),
        (MIXED, "VUID-VkRenderingInfo-colorAttachmentCount-06097"),
        (SEPARATE, "VUID-VkRenderingInfo-colorAttachmentCount-06101"),
    ],
    resolve_modes: "",
};

const DEPTH_SLOT: SlotRules = SlotRules {
    kind: Kind::Depth,
    usage: "VUID-VkRenderingInfo-pDepthAttachment-06088",
    aspect: "VUID-VkRenderingInfo-pDepthAttachment-06547",
    layouts: &[
        (COLOR, "VUID-VkRenderingInfo-pDepthAttachment-06092"),
        (STENCIL_ONLY, "VUID-VkRenderingInfo-pDepthAttachment-07732"),
    ],
    resolve_layouts: &[
        (COLOR, "VUID-VkRenderingInfo-pDepthAttachment-06093"),
        (
            &[L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL],
            "VUID-VkRenderingInfo-pDepthAttachment-06098",
        ),
        (STENCIL_ONLY, "VUID-VkRenderingInfo-pDepthAttachment-07733"),
    ],
    resolve_modes: "VUID-VkRenderingInfo-pDepthAttachment-06102",
};

const STENCIL_SLOT: SlotRules = SlotRules {
    kind: Kind::Stencil,
    usage: "VUID-VkRenderingInfo-pStencilAttachment-06089",
    aspect: "VUID-VkRenderingInfo-pStencilAttachment-06548",
    layouts: &[
        (COLOR, "VUID-VkRenderingInfo-pStencilAttachment-06094"),
        (DEPTH_ONLY, "VUID-VkRenderingInfo-pStencilAttachment-07734"),
    ],
    resolve_layouts: &[
        (COLOR, "VUID-VkRenderingInfo-pStencilAttachment-06095"),
        (
            &[L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL],
            "VUID-VkRenderingInfo-pStencilAttachment-06099",
        ),
        (DEPTH_ONLY, "VUID-VkRenderingInfo-pStencilAttachment-07735"),
    ],
    resolve_modes: "VUID-VkRenderingInfo-pStencilAttachment-06103",
};

/// Layouts no attachment is rendered in (`VkRenderingAttachmentInfo-imageView-06135`).
const NOT_ATTACHMENT: &[L] = &[
    L::UNDEFINED,
    L::SHADER_READ_ONLY_OPTIMAL,
    L::TRANSFER_SRC_OPTIMAL,
    L::TRANSFER_DST_OPTIMAL,
    L::PREINITIALIZED,
];

/// Layouts no resolve attachment is written in (06136).
const NOT_RESOLVE: &[L] = &[
    L::UNDEFINED,
    L::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
    L::SHADER_READ_ONLY_OPTIMAL,
    L::TRANSFER_SRC_OPTIMAL,
    L::TRANSFER_DST_OPTIMAL,
    L::PREINITIALIZED,
];

/// One attachment of a rendering info, with what the device recorded of its views.
struct Slot<'i> {
    /// Where it is, as the error names it.
    at: String,
    rules: &'static SlotRules,
    info: &'i vk::RenderingAttachmentInfo<'i>,
    /// Its view and the view's image, where both are recorded.
    view: Option<(ViewRecord, ImageRecord)>,
    /// Its resolve view and that view's image, likewise.
    resolve: Option<(ViewRecord, ImageRecord)>,
}

impl Slot<'_> {
    fn resolves(&self) -> bool {
        self.info.resolve_mode != vk::ResolveModeFlags::NONE
    }
}

/// The width and height of mip level `level` of an image.
fn level_size(image: &ImageRecord, level: u32) -> (u32, u32) {
    let at = |x: u32| (x.checked_shr(level).unwrap_or(0)).max(1);
    (at(image.extent.width), at(image.extent.height))
}

/// Refuses an attachment that breaks a rule of its own or of its slot.
fn check_slot(slot: &Slot<'_>, device: &crate::Device) -> Result<()> {
    let (info, at) = (slot.info, &slot.at);
    let Some((view, image)) = &slot.view else {
        return Ok(());
    };
    let layout = info.image_layout;
    if NOT_ATTACHMENT.contains(&layout) {
        refuse(
            "VUID-VkRenderingAttachmentInfo-imageView-06135",
            format!("{at}.imageLayout is {layout:?}, which no attachment is rendered in"),
        )?;
    }
    if layout == L::PRESENT_SRC_KHR {
        refuse(
            "VUID-VkRenderingAttachmentInfo-imageView-06145",
            format!("{at}.imageLayout is VK_IMAGE_LAYOUT_PRESENT_SRC_KHR"),
        )?;
    }
    for (layouts, vuid) in slot.rules.layouts {
        if layouts.contains(&layout) {
            refuse(
                vuid,
                format!("{at}.imageLayout is {layout:?}, which is not this slot's"),
            )?;
        }
    }
    let stencil = slot.rules.kind == Kind::Stencil;
    let usage = if stencil {
        image.stencil_usage.unwrap_or(view.usage)
    } else {
        view.usage
    };
    let wanted = if slot.rules.kind == Kind::Color {
        vk::ImageUsageFlags::COLOR_ATTACHMENT
    } else {
        vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT
    };
    if !usage.contains(wanted) {
        refuse(
            slot.rules.usage,
            format!("{at}.imageView's usage ({usage:?}) lacks {wanted:?}"),
        )?;
    }
    if !slot.rules.aspect.is_empty() {
        let aspect = if stencil {
            vk::ImageAspectFlags::STENCIL
        } else {
            vk::ImageAspectFlags::DEPTH
        };
        let has = crate::formats::aspects(view.format).unwrap_or_default();
        if !has.contains(aspect) {
            refuse(
                slot.rules.aspect,
                format!(
                    "{at}.imageView's format {:?} has no {aspect:?} aspect",
                    view.format
                ),
            )?;
        }
    }
    let mode = info.resolve_mode;
    if slot.rules.kind == Kind::Color && mode != vk::ResolveModeFlags::NONE {
        let integer = crate::formats::integer_signed(view.format).is_some();
        let (allowed, vuid) = if integer {
            (
                vk::ResolveModeFlags::SAMPLE_ZERO,
                "VUID-VkRenderingAttachmentInfo-imageView-06130",
            )
        } else {
            (
                vk::ResolveModeFlags::AVERAGE,
                "VUID-VkRenderingAttachmentInfo-imageView-06129",
            )
        };
        if mode != allowed {
            refuse(
                vuid,
                format!(
                    "{at}.resolveMode is {mode:?}, and the view's format {:?} resolves only by {allowed:?}",
                    view.format
                ),
            )?;
        }
    }
    if !slot.rules.resolve_modes.is_empty() && mode != vk::ResolveModeFlags::NONE {
        let mut ds = vk::PhysicalDeviceDepthStencilResolveProperties::default();
        if super::ask_properties2(device, &mut ds) {
            let supported = if stencil {
                ds.supported_stencil_resolve_modes
            } else {
                ds.supported_depth_resolve_modes
            };
            if !supported.contains(mode) {
                refuse(
                    slot.rules.resolve_modes,
                    format!("{at}.resolveMode {mode:?} is not among the device's supported modes ({supported:?})"),
                )?;
            }
        }
    }
    if !slot.resolves() {
        return Ok(());
    }
    if image.samples == vk::SampleCountFlags::TYPE_1 {
        refuse(
            "VUID-VkRenderingAttachmentInfo-imageView-06132",
            format!("{at} resolves, but its view has one sample"),
        )?;
    }
    if info.resolve_image_view == vk::ImageView::null() {
        refuse(
            "VUID-VkRenderingAttachmentInfo-imageView-06860",
            format!("{at} resolves, but names no resolveImageView"),
        )?;
    }
    let resolve_layout = info.resolve_image_layout;
    for (layouts, vuid) in [
        (
            NOT_RESOLVE,
            "VUID-VkRenderingAttachmentInfo-imageView-06136",
        ),
        (
            &[L::DEPTH_READ_ONLY_OPTIMAL, L::STENCIL_READ_ONLY_OPTIMAL][..],
            "VUID-VkRenderingAttachmentInfo-imageView-06137",
        ),
        (
            &[L::READ_ONLY_OPTIMAL][..],
            "VUID-VkRenderingAttachmentInfo-imageView-06142",
        ),
        (
            &[L::PRESENT_SRC_KHR][..],
            "VUID-VkRenderingAttachmentInfo-imageView-06146",
        ),
    ]
    .into_iter()
    .chain(slot.rules.resolve_layouts.iter().copied())
    {
        if layouts.contains(&resolve_layout) {
            refuse(
                vuid,
                format!("{at}.resolveImageLayout is {resolve_layout:?}, which a resolve attachment of this slot is not written in"),
            )?;
        }
    }
    if let Some((resolve, resolve_image)) = &slot.resolve {
        if resolve_image.samples != vk::SampleCountFlags::TYPE_1 {
            refuse(
                "VUID-VkRenderingAttachmentInfo-imageView-06864",
                format!(
                    "{at}.resolveImageView has {:?} samples, not one",
                    resolve_image.samples
                ),
            )?;
        }
        if resolve.format != view.format {
            refuse(
                "VUID-VkRenderingAttachmentInfo-imageView-06865",
                format!(
                    "{at}.resolveImageView's format {:?} is not imageView's {:?}",
                    resolve.format, view.format
                ),
            )?;
        }
    }
    Ok(())
}

/// The checks of `vkCmdBeginRendering`'s attachments, after the command's other
/// checks: each attachment's view against its slot (usage, aspect, layouts, resolve),
/// the views' sample counts, the depth and stencil slots against each other, the
/// render area against the views and the device's limits, and the view mask.
pub(crate) fn rendering_attachment_checks<'i, S: Scope>(
    recorder: &Recorder<'_, S>,
    rendering_info: &'i RenderingInfo<'i>,
) -> Result<()> {
    let device = recorder.device();
    let live = device.live();
    let raw = rendering_info.as_raw();
    if recorder.command_buffer().level() == vk::CommandBufferLevel::SECONDARY
        && raw
            .flags
            .contains(vk::RenderingFlags::CONTENTS_SECONDARY_COMMAND_BUFFERS)
    {
        refuse(
            "VUID-vkCmdBeginRendering-commandBuffer-06068",
            "a secondary command buffer's render pass instance cannot execute secondaries (VK_RENDERING_CONTENTS_SECONDARY_COMMAND_BUFFERS_BIT)",
        )?;
    }
    let limits = crate::state::limits(device);
    if raw.color_attachment_count > limits.max_color_attachments {
        refuse(
            "VUID-VkRenderingInfo-colorAttachmentCount-06106",
            format!(
                "colorAttachmentCount ({}) exceeds maxColorAttachments ({})",
                raw.color_attachment_count, limits.max_color_attachments
            ),
        )?;
    }
    // SAFETY: the safe setters stored the color attachments with their count and the
    // depth and stencil ones as references that outlive the info.
    let (color, depth, stencil) = unsafe {
        (
            crate::state::raw_slice(raw.p_color_attachments, raw.color_attachment_count),
            raw.p_depth_attachment.as_ref(),
            raw.p_stencil_attachment.as_ref(),
        )
    };
    let record = |v: vk::ImageView| {
        let view = live.view(v)?;
        Some((view, live.image(view.image)?))
    };
    let slot =
        |at: String, rules: &'static SlotRules, info: &'i vk::RenderingAttachmentInfo<'i>| Slot {
            at,
            rules,
            view: record(info.image_view),
            resolve: record(info.resolve_image_view),
            info,
        };
    let slots: Vec<Slot<'_>> = color
        .iter()
        .enumerate()
        .map(|(i, a)| slot(format!("pColorAttachments[{i}]"), &COLOR_SLOT, a))
        .chain(depth.map(|a| slot("pDepthAttachment".into(), &DEPTH_SLOT, a)))
        .chain(stencil.map(|a| slot("pStencilAttachment".into(), &STENCIL_SLOT, a)))
        .collect();
    for s in &slots {
        check_slot(s, device)?;
    }
    let exts = device.exts();
    let mixed = [
        "VK_AMD_mixed_attachment_samples",
        "VK_NV_framebuffer_mixed_samples",
        "VK_EXT_multisampled_render_to_single_sampled",
    ]
    .iter()
    .any(|e| exts.named(e));
    let mut samples = slots
        .iter()
        .filter_map(|s| s.view.as_ref())
        .map(|v| v.1.samples);
    if let Some(first) = samples.next() {
        if !mixed && samples.any(|s| s != first) {
            refuse(
                "VUID-VkRenderingInfo-multisampledRenderToSingleSampled-06857",
                "the attachments' views have different sample counts",
            )?;
        }
    }
    if let (Some(d), Some(s)) = (depth, stencil) {
        let null = vk::ImageView::null();
        if (d.image_view != null || s.image_view != null) && d.image_view != s.image_view {
            refuse(
                "VUID-VkRenderingInfo-pDepthAttachment-06085",
                "pDepthAttachment and pStencilAttachment name different image views",
            )?;
        }
        let none = vk::ResolveModeFlags::NONE;
        if d.resolve_mode != none
            && s.resolve_mode != none
            && d.resolve_image_view != s.resolve_image_view
        {
            refuse(
                "VUID-VkRenderingInfo-pDepthAttachment-06086",
                "pDepthAttachment and pStencilAttachment resolve into different image views",
            )?;
        }
        if d.image_view != null && s.image_view != null {
            let mut ds = vk::PhysicalDeviceDepthStencilResolveProperties::default();
            if super::ask_properties2(device, &mut ds) {
                if ds.independent_resolve_none == vk::FALSE && d.resolve_mode != s.resolve_mode {
                    refuse(
                        "VUID-VkRenderingInfo-pDepthAttachment-06104",
                        "the device resolves depth and stencil together (independentResolveNone is false), and their resolveModes differ",
                    )?;
                }
                if ds.independent_resolve == vk::FALSE
                    && d.resolve_mode != none
                    && s.resolve_mode != none
                    && d.resolve_mode != s.resolve_mode
                {
                    refuse(
                        "VUID-VkRenderingInfo-pDepthAttachment-06105",
                        "the device resolves depth and stencil by one mode (independentResolve is false), and their resolveModes differ",
                    )?;
                }
            }
        }
    }
    check_area(rendering_info, &slots, limits)?;
    if raw.view_mask != 0 {
        let top = 32 - raw.view_mask.leading_zeros();
        let max = super::render_pass::multiview_view_count(device).unwrap_or(0);
        if top > max {
            refuse(
                "VUID-VkRenderingInfo-viewMask-06128",
                format!(
                    "viewMask {:#x} names view {} and maxMultiviewViewCount is {max}",
                    raw.view_mask,
                    top - 1
                ),
            )?;
        }
    }
    Ok(())
}

/// The render area (or each device's, from a chained device group begin info)
/// inside every attachment's view, and (without device areas) at a non-negative
/// offset within the device's framebuffer limits.
fn check_area(
    rendering_info: &RenderingInfo<'_>,
    slots: &[Slot<'_>],
    limits: &vk::PhysicalDeviceLimits,
) -> Result<()> {
    let raw = rendering_info.as_raw();
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let group: Option<&vk::DeviceGroupRenderPassBeginInfo<'_>> = unsafe {
        super::chained(
            raw.p_next,
            vk::StructureType::DEVICE_GROUP_RENDER_PASS_BEGIN_INFO,
        )
    };
    // SAFETY: the safe setter stored the areas with their count.
    let areas = group.map_or(&[][..], |g| unsafe {
        crate::state::raw_slice(g.p_device_render_areas, g.device_render_area_count)
    });
    let (areas, rules) = if areas.is_empty() {
        let a = raw.render_area;
        if a.offset.x < 0 || a.offset.y < 0 {
            let vuid = if a.offset.x < 0 {
                "VUID-VkRenderingInfo-pNext-06077"
            } else {
                "VUID-VkRenderingInfo-pNext-06078"
            };
            refuse(
                vuid,
                format!(
                    "renderArea.offset ({}, {}) is negative",
                    a.offset.x, a.offset.y
                ),
            )?;
        }
        let right = i64::from(a.offset.x) + i64::from(a.extent.width);
        let bottom = i64::from(a.offset.y) + i64::from(a.extent.height);
        if right > i64::from(limits.max_framebuffer_width) {
            refuse(
                "VUID-VkRenderingInfo-pNext-07815",
                format!(
                    "renderArea ends at x = {right}, past maxFramebufferWidth ({})",
                    limits.max_framebuffer_width
                ),
            )?;
        }
        if bottom > i64::from(limits.max_framebuffer_height) {
            refuse(
                "VUID-VkRenderingInfo-pNext-07816",
                format!(
                    "renderArea ends at y = {bottom}, past maxFramebufferHeight ({})",
                    limits.max_framebuffer_height
                ),
            )?;
        }
        (
            vec![a],
            (
                "VUID-VkRenderingInfo-pNext-06079",
                "VUID-VkRenderingInfo-pNext-06080",
            ),
        )
    } else {
        (
            areas.to_vec(),
            (
                "VUID-VkRenderingInfo-pNext-06083",
                "VUID-VkRenderingInfo-pNext-06084",
            ),
        )
    };
    for s in slots {
        let Some((view, image)) = &s.view else {
            continue;
        };
        let (width, height) = level_size(image, view.base_level);
        for a in &areas {
            let right = i64::from(a.offset.x) + i64::from(a.extent.width);
            let bottom = i64::from(a.offset.y) + i64::from(a.extent.height);
            if right > i64::from(width) {
                refuse(
                    rules.0,
                    format!(
                        "{}.imageView is {width} wide, and the render area ends at x = {right}",
                        s.at
                    ),
                )?;
            }
            if bottom > i64::from(height) {
                refuse(
                    rules.1,
                    format!(
                        "{}.imageView is {height} high, and the render area ends at y = {bottom}",
                        s.at
                    ),
                )?;
            }
        }
    }
    Ok(())
}

/// The recorder enters dynamic rendering (one subpass, the info's view mask).
pub(crate) fn rendering_begun<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    rendering_info: &RenderingInfo<'_>,
) {
    let raw = rendering_info.as_raw();
    if raw
        .flags
        .intersects(vk::RenderingFlags::SUSPENDING | vk::RenderingFlags::RESUMING)
    {
        recorder.suspends = true;
    }
    // SAFETY: the safe setters stored the color attachments with their count and the
    // depth and stencil ones as references that outlive the info.
    let (color, depth, stencil) = unsafe {
        (
            crate::state::raw_slice(raw.p_color_attachments, raw.color_attachment_count),
            raw.p_depth_attachment.as_ref(),
            raw.p_stencil_attachment.as_ref(),
        )
    };
    let no_attachments = color
        .iter()
        .chain(depth)
        .chain(stencil)
        .all(|a| a.image_view == vk::ImageView::null());
    let live = recorder.device().live();
    let format = |a: Option<&vk::RenderingAttachmentInfo<'_>>| {
        a.and_then(|a| live.view(a.image_view))
            .map_or(vk::Format::UNDEFINED, |v| v.format)
    };
    let rendering = crate::state::RenderingFormats {
        view_mask: raw.view_mask,
        colors: color.iter().map(|a| format(Some(a))).collect(),
        depth: format(depth),
        stencil: format(stencil),
    };
    let layout = |a: Option<&vk::RenderingAttachmentInfo<'_>>| {
        a.filter(|a| a.image_view != vk::ImageView::null())
            .map(|a| a.image_layout)
    };
    // The sample count of the first attachment with a view (they must agree).
    let samples = color
        .iter()
        .chain(depth)
        .chain(stencil)
        .filter_map(|a| live.view(a.image_view))
        .find_map(|v| live.image(v.image))
        .map(|i| i.samples);
    let images = color
        .iter()
        .chain(depth)
        .chain(stencil)
        .flat_map(|a| [a.image_view, a.resolve_image_view])
        .filter_map(|v| live.view(v))
        .map(|v| v.image)
        .collect();
    recorder.instance = Some(crate::recorder::PassInstance {
        view_mask: raw.view_mask,
        no_attachments,
        dynamic: true,
        rendering_images: Some(images),
        rendering: Some(Vrc::new(rendering)),
        rendering_layouts: Some((layout(depth), layout(stencil))),
        rendering_samples: samples,
        area: Some((raw.render_area, raw.layer_count)),
        // SAFETY: the chain of a safe struct, and the type its sType names.
        device_mask: unsafe { super::pass_instance::group_device_mask(raw.p_next) },
        rendering_flags: raw.flags,
        ..Default::default()
    });
}

/// The rules of a set of dynamic rendering attachment formats and view mask (a
/// pipeline's `VkPipelineRenderingCreateInfo`, a secondary's
/// `VkCommandBufferInheritanceRenderingInfo`), by what each checks (`""`: the
/// struct has no such rule, or its implicit checks settle it).
pub(crate) struct FormatRules {
    /// A view mask without the multiview feature.
    pub multiview: &'static str,
    /// A view past `maxMultiviewViewCount`.
    pub view_count: &'static str,
    /// A color, depth or stencil format that is no value of the API (`""` where the
    /// struct's implicit checks refuse it before).
    pub values: [&'static str; 3],
    /// A color format without the color attachment feature.
    pub color_feature: &'static str,
    /// A depth (stencil) format without a depth (stencil) aspect, and without the
    /// depth/stencil attachment feature.
    pub depth: [&'static str; 2],
    pub stencil: [&'static str; 2],
    /// Depth and stencil formats that are both given and differ.
    pub same: &'static str,
}

/// Refuses formats and a view mask of dynamic rendering that break `rules`
/// (`at` says whose they are).
pub(crate) fn formats_checks(
    device: &Device,
    formats: &crate::state::RenderingFormats,
    rules: &FormatRules,
    at: &str,
) -> Result<()> {
    let multiview = device.live().with_features(|f| f.v11.multiview);
    let view_mask = formats.view_mask;
    if view_mask != 0 && multiview == vk::FALSE && !rules.multiview.is_empty() {
        refuse(
            rules.multiview,
            format!(
                "{at}'s viewMask is {view_mask:#x}, but the device was created without multiview"
            ),
        )?;
    }
    let highest = 32 - view_mask.leading_zeros();
    if let Some(max) = super::render_pass::multiview_view_count(device) {
        if highest > max {
            refuse(
                rules.view_count,
                format!("{at}'s viewMask ({view_mask:#x}) names view {}, past maxMultiviewViewCount ({max})", highest - 1),
            )?;
        }
    }
    let (depth, stencil) = (formats.depth, formats.stencil);
    // Values of the API first: the format queries below hand them to the driver.
    let scope = device.scope();
    let given = formats.colors.iter().map(|f| (*f, rules.values[0]));
    for (f, vuid) in given.chain([(depth, rules.values[1]), (stencil, rules.values[2])]) {
        if !vuid.is_empty() {
            crate::checks::enum_format(f, &scope, vuid)?;
        }
    }
    let defined = |f: vk::Format| f != vk::Format::UNDEFINED;
    for (k, &f) in formats
        .colors
        .iter()
        .enumerate()
        .filter(|(_, f)| defined(**f))
    {
        if !super::pipeline_fixed::features(device, f)?
            .contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT)
        {
            refuse(
                rules.color_feature,
                format!(
                    "{at}'s color attachment format {k} ({f:?}) has no color attachment feature"
                ),
            )?;
        }
    }
    let aspects = |f| crate::formats::aspects(f).unwrap_or_default();
    for (format, what, [aspect_vuid, feature_vuid], aspect) in [
        (depth, "depth", rules.depth, vk::ImageAspectFlags::DEPTH),
        (
            stencil,
            "stencil",
            rules.stencil,
            vk::ImageAspectFlags::STENCIL,
        ),
    ] {
        if !defined(format) {
            continue;
        }
        if !aspects(format).contains(aspect) {
            refuse(
                aspect_vuid,
                format!("{at}'s {what} attachment format ({format:?}) has no {aspect:?} aspect"),
            )?;
        }
        if !super::pipeline_fixed::features(device, format)?
            .contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT)
        {
            refuse(
                feature_vuid,
                format!("{at}'s {what} attachment format ({format:?}) has no depth/stencil attachment feature"),
            )?;
        }
    }
    if defined(depth) && defined(stencil) && depth != stencil {
        refuse(
            rules.same,
            format!("{at}'s depth attachment format ({depth:?}) and stencil attachment format ({stencil:?}) differ"),
        )?;
    }
    Ok(())
}
