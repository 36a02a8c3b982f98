//! The checks of render pass creation over what each subpass references: the
//! attachments' formats, sample counts and layouts, preserved attachments, and the
//! view masks. Both create infos are first read into one shape ([`Pass`]), so each
//! rule is written once with its two VUIDs (`VkSubpassDescription` and
//! `VkSubpassDescription2`, or the two create infos).

use super::*;

/// One attachment reference: the attachment, its layout, and (for
/// `VkAttachmentReference2`) the aspects an input attachment reads.
#[derive(Clone, Copy)]
struct Ref {
    attachment: u32,
    layout: vk::ImageLayout,
    aspect_mask: vk::ImageAspectFlags,
}

impl Ref {
    fn used(&self) -> bool {
        self.attachment != vk::ATTACHMENT_UNUSED
    }
}

/// One subpass's references.
struct Subpass {
    inputs: Vec<Ref>,
    colors: Vec<Ref>,
    resolves: Option<Vec<Ref>>,
    depth: Option<Ref>,
    preserve: Vec<u32>,
}

impl Subpass {
    /// Every reference, with where it comes from.
    fn refs(&self) -> impl Iterator<Item = (&'static str, &Ref)> {
        let inputs = self.inputs.iter().map(|r| ("pInputAttachments", r));
        let colors = self.colors.iter().map(|r| ("pColorAttachments", r));
        let resolves = self
            .resolves
            .iter()
            .flatten()
            .map(|r| ("pResolveAttachments", r));
        let depth = self.depth.iter().map(|r| ("pDepthStencilAttachment", r));
        inputs.chain(colors).chain(resolves).chain(depth)
    }
}

/// A render pass, as either create info gives it.
struct Pass {
    /// Each attachment's format and sample count.
    attachments: Vec<(vk::Format, vk::SampleCountFlags)>,
    subpasses: Vec<Subpass>,
    /// Read from `vkCreateRenderPass2`: the VUIDs of its rules are the second ones.
    second: bool,
}

/// A rule's VUIDs through `vkCreateRenderPass` and `vkCreateRenderPass2` (empty where
/// one of them has no such rule).
type Rule = (&'static str, &'static str);

const PRESERVE_UNUSED: Rule = (
    "VUID-VkSubpassDescription-attachment-00853",
    "VUID-VkSubpassDescription2-attachment-03073",
);
const PRESERVE_USED: Rule = (
    "VUID-VkSubpassDescription-pPreserveAttachments-00854",
    "VUID-VkSubpassDescription2-pPreserveAttachments-03074",
);
const RESOLVE_COLOR_UNUSED: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-00847",
    "VUID-VkSubpassDescription2-pResolveAttachments-03065",
);
const RESOLVE_COLOR_SINGLE: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-00848",
    "VUID-VkSubpassDescription2-pResolveAttachments-03066",
);
const RESOLVE_MULTI: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-00849",
    "VUID-VkSubpassDescription2-pResolveAttachments-03067",
);
const RESOLVE_FORMAT: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-00850",
    "VUID-VkSubpassDescription2-pResolveAttachments-03068",
);
const INPUT_FEATURES: Rule = (
    "VUID-VkSubpassDescription-pInputAttachments-02647",
    "VUID-VkSubpassDescription2-pInputAttachments-02897",
);
const COLOR_FEATURES: Rule = (
    "VUID-VkSubpassDescription-pColorAttachments-02648",
    "VUID-VkSubpassDescription2-pColorAttachments-02898",
);
const RESOLVE_FEATURES: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-02649",
    "VUID-VkSubpassDescription2-pResolveAttachments-02899",
);
const DEPTH_FEATURES: Rule = (
    "VUID-VkSubpassDescription-pDepthStencilAttachment-02650",
    "VUID-VkSubpassDescription2-pDepthStencilAttachment-02900",
);
const COLOR_SAMPLES: Rule = (
    "VUID-VkSubpassDescription-pColorAttachments-06868",
    "VUID-VkSubpassDescription2-multisampledRenderToSingleSampled-06872",
);
const DEPTH_SAMPLES: Rule = (
    "VUID-VkSubpassDescription-pDepthStencilAttachment-01418",
    "VUID-VkSubpassDescription2-multisampledRenderToSingleSampled-06872",
);
const SAME_LAYOUT: Rule = (
    "VUID-VkSubpassDescription-layout-02519",
    "VUID-VkSubpassDescription2-layout-02528",
);
const DEPTH_IS_COLOR: Rule = (
    "VUID-VkSubpassDescription-pDepthStencilAttachment-04438",
    "VUID-VkSubpassDescription2-pDepthStencilAttachment-04440",
);

impl Pass {
    /// Reads `vkCreateRenderPass`'s create info.
    fn of(create_info: &RenderPassCreateInfo<'_>) -> Pass {
        let raw = create_info.as_raw();
        // SAFETY: the safe setters store each array with its count, resolve
        // attachments one per color attachment; a depth/stencil reference outlives
        // the create info.
        unsafe {
            let attachments = crate::retention::raw_slice(raw.p_attachments, raw.attachment_count)
                .iter()
                .map(|a| (a.format, a.samples))
                .collect();
            let plain = |r: &vk::AttachmentReference| Ref {
                attachment: r.attachment,
                layout: r.layout,
                aspect_mask: vk::ImageAspectFlags::empty(),
            };
            let subpasses = crate::retention::raw_slice(raw.p_subpasses, raw.subpass_count)
                .iter()
                .map(|s| {
                    let list = |p, n| {
                        crate::retention::raw_slice(p, n)
                            .iter()
                            .map(plain)
                            .collect::<Vec<_>>()
                    };
                    Subpass {
                        inputs: list(s.p_input_attachments, s.input_attachment_count),
                        colors: list(s.p_color_attachments, s.color_attachment_count),
                        resolves: (!s.p_resolve_attachments.is_null())
                            .then(|| list(s.p_resolve_attachments, s.color_attachment_count)),
                        depth: s.p_depth_stencil_attachment.as_ref().map(plain),
                        preserve: crate::retention::raw_slice(
                            s.p_preserve_attachments,
                            s.preserve_attachment_count,
                        )
                        .to_vec(),
                    }
                })
                .collect();
            Pass {
                attachments,
                subpasses,
                second: false,
            }
        }
    }

    /// Reads `vkCreateRenderPass2`'s create info.
    fn of2(create_info: &RenderPassCreateInfo2<'_>) -> Pass {
        let raw = create_info.as_raw();
        // SAFETY: as in `of`.
        unsafe {
            let attachments = crate::retention::raw_slice(raw.p_attachments, raw.attachment_count)
                .iter()
                .map(|a| (a.format, a.samples))
                .collect();
            let plain = |r: &vk::AttachmentReference2<'_>| Ref {
                attachment: r.attachment,
                layout: r.layout,
                aspect_mask: r.aspect_mask,
            };
            let subpasses = crate::retention::raw_slice(raw.p_subpasses, raw.subpass_count)
                .iter()
                .map(|s| {
                    let list = |p, n| {
                        crate::retention::raw_slice(p, n)
                            .iter()
                            .map(plain)
                            .collect::<Vec<_>>()
                    };
                    Subpass {
                        inputs: list(s.p_input_attachments, s.input_attachment_count),
                        colors: list(s.p_color_attachments, s.color_attachment_count),
                        resolves: (!s.p_resolve_attachments.is_null())
                            .then(|| list(s.p_resolve_attachments, s.color_attachment_count)),
                        depth: s.p_depth_stencil_attachment.as_ref().map(plain),
                        preserve: crate::retention::raw_slice(
                            s.p_preserve_attachments,
                            s.preserve_attachment_count,
                        )
                        .to_vec(),
                    }
                })
                .collect();
            Pass {
                attachments,
                subpasses,
                second: true,
            }
        }
    }

    /// Each subpass's color attachments' formats and depth/stencil attachment's
    /// format, for the render pass's record. An index past the attachments (which
    /// only the unchecked path lets through) reads as `UNDEFINED`.
    fn formats(&self) -> (Vec<Vec<vk::Format>>, Vec<Option<vk::Format>>) {
        let format = |r: &Ref| {
            self.attachments
                .get(r.attachment as usize)
                .map_or(vk::Format::UNDEFINED, |a| a.0)
        };
        let colors = self
            .subpasses
            .iter()
            .map(|s| {
                s.colors
                    .iter()
                    .map(|r| {
                        if r.used() {
                            format(r)
                        } else {
                            vk::Format::UNDEFINED
                        }
                    })
                    .collect()
            })
            .collect();
        let depths = self
            .subpasses
            .iter()
            .map(|s| s.depth.filter(Ref::used).map(|r| format(&r)))
            .collect();
        (colors, depths)
    }

    fn vuid(&self, rule: Rule) -> &'static str {
        if self.second {
            rule.1
        } else {
            rule.0
        }
    }

    /// The first reference past the attachments, for `vkCreateRenderPass2`
    /// (`vkCreateRenderPass` checks it before the other checks, as 00834).
    fn check_indices(&self) -> Result<()> {
        let count = self.attachments.len() as u32;
        for (i, s) in self.subpasses.iter().enumerate() {
            let refs = s.refs().map(|(_, r)| r.attachment);
            if let Some(a) = refs
                .chain(s.preserve.iter().copied())
                .find(|&a| a != vk::ATTACHMENT_UNUSED && a >= count)
            {
                refuse(
                    "VUID-VkRenderPassCreateInfo2-attachment-03051",
                    format!(
                        "pSubpasses[{i}] names attachment {a}, but the render pass has {count}"
                    ),
                )?;
            }
        }
        Ok(())
    }

    /// Every rule of the subpasses' references. The indices are in range (checked
    /// first).
    fn check_references(&self, device: &Device) -> Result<()> {
        let format_of = |r: &Ref| self.attachments[r.attachment as usize].0;
        let samples_of = |r: &Ref| self.attachments[r.attachment as usize].1;
        let physical = device.parent();
        // What an image of the format can do with either tiling.
        let features = |format: vk::Format| {
            physical
                .get_physical_device_format_properties(format)
                .map(|p| p.linear_tiling_features | p.optimal_tiling_features)
        };
        for (i, s) in self.subpasses.iter().enumerate() {
            for (k, &p) in s.preserve.iter().enumerate() {
                if p == vk::ATTACHMENT_UNUSED {
                    refuse(
                        self.vuid(PRESERVE_UNUSED),
                        format!(
                            "pSubpasses[{i}].pPreserveAttachments[{k}] is VK_ATTACHMENT_UNUSED"
                        ),
                    )?;
                }
                if let Some((what, _)) = s.refs().find(|(_, r)| r.attachment == p) {
                    refuse(
                        self.vuid(PRESERVE_USED),
                        format!("pSubpasses[{i}] preserves attachment {p}, which its {what} uses"),
                    )?;
                }
            }
            if let Some(resolves) = &s.resolves {
                for (k, (r, c)) in resolves.iter().zip(&s.colors).enumerate() {
                    if !r.used() {
                        continue;
                    }
                    let at = format!("pSubpasses[{i}].pResolveAttachments[{k}]");
                    if !c.used() {
                        refuse(
                            self.vuid(RESOLVE_COLOR_UNUSED),
                            format!("{at} resolves an unused color attachment"),
                        )?;
                        continue;
                    }
                    if samples_of(c) == vk::SampleCountFlags::TYPE_1 {
                        refuse(
                            self.vuid(RESOLVE_COLOR_SINGLE),
                            format!(
                                "{at} resolves attachment {}, which has one sample",
                                c.attachment
                            ),
                        )?;
                    }
                    if samples_of(r) != vk::SampleCountFlags::TYPE_1 {
                        refuse(
                            self.vuid(RESOLVE_MULTI),
                            format!("{at} names attachment {}, of {:?} samples: a resolve attachment has one", r.attachment, samples_of(r)),
                        )?;
                    }
                    if format_of(r) != format_of(c) {
                        refuse(
                            self.vuid(RESOLVE_FORMAT),
                            format!(
                                "{at} has format {:?}, its color attachment {:?}",
                                format_of(r),
                                format_of(c)
                            ),
                        )?;
                    }
                }
            }
            if let Some(d) = s.depth.filter(|d| d.used()) {
                if s.colors.iter().any(|c| c.attachment == d.attachment) {
                    refuse(
                        self.vuid(DEPTH_IS_COLOR),
                        format!("pSubpasses[{i}] uses attachment {} as a color and the depth/stencil attachment", d.attachment),
                    )?;
                }
            }
            let attachment = vk::FormatFeatureFlags::COLOR_ATTACHMENT;
            let depth = vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT;
            for (what, rule, need) in [
                ("pInputAttachments", INPUT_FEATURES, attachment | depth),
                ("pColorAttachments", COLOR_FEATURES, attachment),
                ("pResolveAttachments", RESOLVE_FEATURES, attachment),
                ("pDepthStencilAttachment", DEPTH_FEATURES, depth),
            ] {
                for (_, r) in s.refs().filter(|(w, r)| *w == what && r.used()) {
                    let format = format_of(r);
                    if !features(format)?.intersects(need) {
                        refuse(
                            self.vuid(rule),
                            format!("pSubpasses[{i}].{what} names attachment {}, whose format {format:?} supports none of {need:?}", r.attachment),
                        )?;
                    }
                }
            }
            let mut colors = s.colors.iter().filter(|r| r.used());
            if let Some(first) = colors.next() {
                let samples = samples_of(first);
                if let Some(other) = colors.find(|r| samples_of(r) != samples) {
                    refuse(
                        self.vuid(COLOR_SAMPLES),
                        format!("pSubpasses[{i}]'s color attachments {} and {} have {samples:?} and {:?} samples", first.attachment, other.attachment, samples_of(other)),
                    )?;
                }
                if let Some(d) = s.depth.filter(|d| d.used() && samples_of(d) != samples) {
                    refuse(
                        self.vuid(DEPTH_SAMPLES),
                        format!("pSubpasses[{i}]'s depth/stencil attachment {} has {:?} samples, its color attachments {samples:?}", d.attachment, samples_of(&d)),
                    )?;
                }
            }
            let refs: Vec<_> = s.refs().filter(|(_, r)| r.used()).collect();
            for (n, (what, r)) in refs.iter().enumerate() {
                if let Some((other, o)) = refs[n + 1..]
                    .iter()
                    .find(|(_, o)| o.attachment == r.attachment && o.layout != r.layout)
                {
                    refuse(
                        self.vuid(SAME_LAYOUT),
                        format!("pSubpasses[{i}] uses attachment {} in {what} as {:?} and in {other} as {:?}", r.attachment, r.layout, o.layout),
                    )?;
                }
            }
            if self.second {
                for (k, r) in s.inputs.iter().enumerate().filter(|(_, r)| r.used()) {
                    check_input_aspects(i, k, r, format_of(r))?;
                }
            }
        }
        Ok(())
    }
}

/// The aspects of an input attachment of `vkCreateRenderPass2`.
fn check_input_aspects(i: usize, k: usize, r: &Ref, format: vk::Format) -> Result<()> {
    let at = format!("pSubpasses[{i}].pInputAttachments[{k}].aspectMask");
    if r.aspect_mask.is_empty() {
        refuse(
            "VUID-VkSubpassDescription2-attachment-02800",
            format!("{at} is 0"),
        )?;
    }
    if r.aspect_mask.contains(vk::ImageAspectFlags::METADATA) {
        refuse(
            "VUID-VkSubpassDescription2-attachment-02801",
            format!("{at} includes VK_IMAGE_ASPECT_METADATA_BIT"),
        )?;
    }
    if let Some(present) = crate::formats::aspects(format) {
        if !present.contains(r.aspect_mask) {
            refuse(
                "VUID-VkRenderPassCreateInfo2-attachment-02525",
                format!(
                    "{at} ({:?}) names aspects that format {format:?} has not ({present:?})",
                    r.aspect_mask
                ),
            )?;
        }
    }
    Ok(())
}

/// The view masks of a render pass's subpasses: all zero or none
/// (`VkRenderPassCreateInfo2-viewMask-03058`, `VkRenderPassCreateInfo-pNext-02513`),
/// and with multiview off, no correlation masks and no view-local dependency.
fn check_view_masks(
    device: &Device,
    masks: &[u32],
    correlations: u32,
    dependencies: &[vk::DependencyFlags],
    second: bool,
) -> Result<()> {
    let pick = |a, b| if second { b } else { a };
    let zero = masks.iter().filter(|&&m| m == 0).count();
    if zero != 0 && zero != masks.len() {
        refuse(
            pick(
                "VUID-VkRenderPassCreateInfo-pNext-02513",
                "VUID-VkRenderPassCreateInfo2-viewMask-03058",
            ),
            format!(
                "{zero} of the {} view masks are 0: all or none must be",
                masks.len()
            ),
        )?;
    }
    if zero == masks.len() {
        if correlations != 0 {
            refuse(
                pick(
                    "VUID-VkRenderPassCreateInfo-pNext-02515",
                    "VUID-VkRenderPassCreateInfo2-viewMask-03057",
                ),
                format!("every view mask is 0, but {correlations} correlation masks are given"),
            )?;
        }
        if let Some(i) = dependencies
            .iter()
            .position(|f| f.contains(vk::DependencyFlags::VIEW_LOCAL))
        {
            refuse(
                pick(
                    "VUID-VkRenderPassCreateInfo-pNext-02514",
                    "VUID-VkRenderPassCreateInfo2-viewMask-03059",
                ),
                format!("every view mask is 0, but pDependencies[{i}] is view-local"),
            )?;
        }
    }
    if second {
        let max = multiview_view_count(device);
        for (i, m) in masks.iter().enumerate() {
            let highest = 32 - m.leading_zeros();
            if *m != 0 && max.is_some_and(|max| highest > max) {
                refuse(
                    "VUID-VkSubpassDescription2-viewMask-06706",
                    format!("pSubpasses[{i}].viewMask ({m:#x}) names view {}, past maxMultiviewViewCount ({})", highest - 1, max.unwrap_or(0)),
                )?;
            }
        }
    }
    Ok(())
}

/// The device's `maxMultiviewViewCount`, where the instance can ask for it.
pub(super) fn multiview_view_count(device: &Device) -> Option<u32> {
    let physical = device.parent();
    let instance = physical.parent();
    if !instance.exts().version(1) {
        return None;
    }
    let mut multiview = vk::PhysicalDeviceMultiviewProperties::default();
    let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(&mut multiview);
    // SAFETY: a live physical device of a Vulkan 1.1 instance; the chain is local.
    unsafe {
        instance
            .fns()
            .get_physical_device_properties2(physical.raw(), &mut p2)
    };
    Some(multiview.max_multiview_view_count)
}

/// The checks of `vkCreateRenderPass` that read the attachments its subpasses
/// reference, and a chained `VkRenderPassMultiviewCreateInfo`. They query the
/// attachments' format features, so they run after the checks of the values.
pub(crate) fn render_pass_reference_checks(
    device: &Device,
    create_info: &RenderPassCreateInfo<'_>,
) -> Result<()> {
    Pass::of(create_info).check_references(device)?;
    let raw = create_info.as_raw();
    // SAFETY: `raw` is a safe struct's.
    let multiview: Option<&vk::RenderPassMultiviewCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_MULTIVIEW_CREATE_INFO,
        )
    };
    let Some(m) = multiview else {
        return Ok(());
    };
    if m.dependency_count != 0 && m.dependency_count != raw.dependency_count {
        refuse(
            "VUID-VkRenderPassCreateInfo-pNext-01929",
            format!("the chained VkRenderPassMultiviewCreateInfo's dependencyCount ({}) must be 0 or the render pass's ({})", m.dependency_count, raw.dependency_count),
        )?;
    }
    // SAFETY: the safe setters store each array with its count.
    let (masks, dependencies) = unsafe {
        (
            crate::retention::raw_slice(m.p_view_masks, m.subpass_count),
            crate::retention::raw_slice(raw.p_dependencies, raw.dependency_count),
        )
    };
    let flags: Vec<_> = dependencies.iter().map(|d| d.dependency_flags).collect();
    check_view_masks(device, masks, m.correlation_mask_count, &flags, false)
}

/// The checks of `vkCreateRenderPass2` that keep its reads inside the attachments:
/// each reference names one of them.
pub(crate) fn create_render_pass2_checks(create_info: &RenderPassCreateInfo2<'_>) -> Result<()> {
    Pass::of2(create_info).check_indices()
}

/// The checks of `vkCreateRenderPass2` over the attachments its subpasses
/// reference and their view masks, as for `vkCreateRenderPass`.
pub(crate) fn render_pass2_reference_checks(
    device: &Device,
    create_info: &RenderPassCreateInfo2<'_>,
) -> Result<()> {
    Pass::of2(create_info).check_references(device)?;
    let raw = create_info.as_raw();
    // SAFETY: the safe setters store each array with its count.
    let (subpasses, dependencies) = unsafe {
        (
            crate::retention::raw_slice(raw.p_subpasses, raw.subpass_count),
            crate::retention::raw_slice(raw.p_dependencies, raw.dependency_count),
        )
    };
    let masks: Vec<_> = subpasses.iter().map(|s| s.view_mask).collect();
    let flags: Vec<_> = dependencies.iter().map(|d| d.dependency_flags).collect();
    check_view_masks(device, &masks, raw.correlated_view_mask_count, &flags, true)
}

/// Each subpass's color and depth/stencil formats, for `vkCreateRenderPass`'s record.
pub(crate) fn subpass_formats(
    create_info: &RenderPassCreateInfo<'_>,
) -> (Vec<Vec<vk::Format>>, Vec<Option<vk::Format>>) {
    Pass::of(create_info).formats()
}

/// [`subpass_formats`] for `vkCreateRenderPass2`.
pub(crate) fn subpass_formats2(
    create_info: &RenderPassCreateInfo2<'_>,
) -> (Vec<Vec<vk::Format>>, Vec<Option<vk::Format>>) {
    Pass::of2(create_info).formats()
}
