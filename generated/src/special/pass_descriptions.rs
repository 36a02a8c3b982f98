//! Render pass creation over its attachment descriptions: each attachment's format
//! and layouts, the layouts its subpasses reference it in and those of its first
//! use, and the second version's stencil layouts and depth/stencil resolves, read
//! from the [`Pass`] both create infos fill, each rule named by the version's VUID.

use super::refuse;
use super::render_pass::{Pass, Ref, Rule};
use crate::handles::*;
use crate::Result;
use ash::vk;

const FORMAT_UNDEFINED: Rule = (
    "VUID-VkAttachmentDescription-format-06698",
    "VUID-VkAttachmentDescription2-format-06698",
);
const INITIAL_STENCIL_LAYOUT: Rule = (
    "VUID-VkAttachmentDescription-format-06906",
    "VUID-VkAttachmentDescription2-format-06906",
);
const FINAL_STENCIL_LAYOUT: Rule = (
    "VUID-VkAttachmentDescription-format-06907",
    "VUID-VkAttachmentDescription2-format-06907",
);
/// The second version allows these with a chained stencil layout struct.
const INITIAL_DEPTH_LAYOUT: Rule = (
    "VUID-VkAttachmentDescription-format-06242",
    "VUID-VkAttachmentDescription2-format-06249",
);
const FINAL_DEPTH_LAYOUT: Rule = (
    "VUID-VkAttachmentDescription-format-06243",
    "VUID-VkAttachmentDescription2-format-06250",
);
const DEPTH_REFERENCE_LAYOUT: Rule = (
    "VUID-VkSubpassDescription-attachment-06915",
    "VUID-VkSubpassDescription2-attachment-06915",
);
const CLEARED_READ: Rule = (
    "VUID-VkRenderPassCreateInfo-pAttachments-00836",
    "VUID-VkRenderPassCreateInfo2-pAttachments-02522",
);
const STENCIL_CLEARED_READ: Rule = (
    "VUID-VkRenderPassCreateInfo-pAttachments-02511",
    "VUID-VkRenderPassCreateInfo2-pAttachments-02523",
);
/// The second version states these in its two rules above.
const CLEARED_DEPTH_READ: Rule = (
    "VUID-VkRenderPassCreateInfo-pAttachments-01566",
    "VUID-VkRenderPassCreateInfo2-pAttachments-02522",
);
const STENCIL_CLEARED_STENCIL_READ: Rule = (
    "VUID-VkRenderPassCreateInfo-pAttachments-01567",
    "VUID-VkRenderPassCreateInfo2-pAttachments-02523",
);
const INPUT_FIRST_CLEARED: Rule = (
    "VUID-VkSubpassDescription-loadOp-00846",
    "VUID-VkSubpassDescription2-loadOp-03064",
);

/// The depth component of a depth format: its bits and whether it is a float.
fn depth_kind(format: vk::Format) -> Option<(u32, bool)> {
    type F = vk::Format;
    match format {
        F::D16_UNORM | F::D16_UNORM_S8_UINT => Some((16, false)),
        F::X8_D24_UNORM_PACK32 | F::D24_UNORM_S8_UINT => Some((24, false)),
        F::D32_SFLOAT | F::D32_SFLOAT_S8_UINT => Some((32, true)),
        _ => None,
    }
}

impl Pass {
    /// Every rule of the attachment descriptions and the layouts the subpasses
    /// reference them in, of either version (the indices are in range: checked
    /// first), and the second version's stencil layouts and depth/stencil resolves.
    pub(super) fn check_descriptions(&self, device: &Device) -> Result<()> {
        type L = vk::ImageLayout;
        let depth_only = [L::DEPTH_ATTACHMENT_OPTIMAL, L::DEPTH_READ_ONLY_OPTIMAL];
        let stencil_only = [L::STENCIL_ATTACHMENT_OPTIMAL, L::STENCIL_READ_ONLY_OPTIMAL];
        let aspects = |f: vk::Format| crate::formats::aspects(f).unwrap_or_default();
        let (depth, stencil) = (vk::ImageAspectFlags::DEPTH, vk::ImageAspectFlags::STENCIL);
        for (i, ((format, _), d)) in self.attachments.iter().zip(&self.described).enumerate() {
            let at = format!("pAttachments[{i}]");
            if *format == vk::Format::UNDEFINED {
                refuse(
                    self.vuid(FORMAT_UNDEFINED),
                    format!("{at}.format is VK_FORMAT_UNDEFINED"),
                )?;
            }
            let has = aspects(*format);
            let (initial, last) = (d.layouts.initial, d.layouts.last);
            if has.contains(depth | stencil) {
                for (layouts, allowed, rules) in [
                    (
                        &stencil_only,
                        false,
                        (INITIAL_STENCIL_LAYOUT, FINAL_STENCIL_LAYOUT),
                    ),
                    // The second version takes them with the stencil aspect's own.
                    (
                        &depth_only,
                        self.second && d.stencil_chained,
                        (INITIAL_DEPTH_LAYOUT, FINAL_DEPTH_LAYOUT),
                    ),
                ] {
                    if allowed {
                        continue;
                    }
                    if layouts.contains(&initial) {
                        refuse(self.vuid(rules.0), format!("{at} ({format:?}, with depth and stencil) starts in {initial:?}, which names one aspect"))?;
                    }
                    if layouts.contains(&last) {
                        refuse(self.vuid(rules.1), format!("{at} ({format:?}, with depth and stencil) ends in {last:?}, which names one aspect"))?;
                    }
                }
            }
            if !self.second {
                continue;
            }
            if has.contains(stencil) && d.load.1 == vk::AttachmentLoadOp::LOAD {
                if !d.stencil_chained && initial == L::UNDEFINED {
                    refuse(
                        "VUID-VkAttachmentDescription2-pNext-06704",
                        format!(
                            "{at} loads its stencil, so its initialLayout must not be UNDEFINED"
                        ),
                    )?;
                }
                if d.stencil_chained && d.layouts.stencil_initial == L::UNDEFINED {
                    refuse("VUID-VkAttachmentDescription2-pNext-06705", format!("{at} loads its stencil, so its stencilInitialLayout must not be UNDEFINED"))?;
                }
            }
            if has == stencil && !d.stencil_chained {
                if depth_only.contains(&initial) {
                    refuse(
                        "VUID-VkAttachmentDescription2-format-06247",
                        format!(
                            "{at} ({format:?}) has only a stencil aspect and starts in {initial:?}"
                        ),
                    )?;
                }
                if depth_only.contains(&last) {
                    refuse(
                        "VUID-VkAttachmentDescription2-format-06248",
                        format!("{at} ({format:?}) has only a stencil aspect and ends in {last:?}"),
                    )?;
                }
            }
        }
        for (i, s) in self.subpasses.iter().enumerate() {
            let Some(d) = s.depth.filter(|d| d.used()) else {
                continue;
            };
            let at = format!("pSubpasses[{i}].pDepthStencilAttachment");
            if matches!(
                d.layout,
                L::COLOR_ATTACHMENT_OPTIMAL | L::SHADER_READ_ONLY_OPTIMAL
            ) {
                refuse(
                    self.vuid(DEPTH_REFERENCE_LAYOUT),
                    format!("{at} is in {:?}", d.layout),
                )?;
            }
            if !self.second {
                continue;
            }
            let has = aspects(self.attachments[d.attachment as usize].0);
            if depth_only.contains(&d.layout) && !d.stencil_chained && has.contains(depth | stencil)
            {
                refuse("VUID-VkRenderPassCreateInfo2-attachment-06244", format!("{at} is in {:?}, names attachment {} of depth and stencil, and chains no stencil layout", d.layout, d.attachment))?;
            }
            if stencil_only.contains(&d.layout) && has != stencil {
                refuse("VUID-VkRenderPassCreateInfo2-attachment-06245", format!("{at} is in {:?}, and attachment {}'s format has other aspects than stencil", d.layout, d.attachment))?;
            }
            if depth_only.contains(&d.layout) && has == stencil {
                refuse(
                    "VUID-VkRenderPassCreateInfo2-attachment-06246",
                    format!(
                        "{at} is in {:?}, and attachment {} has only a stencil aspect",
                        d.layout, d.attachment
                    ),
                )?;
            }
            if d.stencil_chained && stencil_only.contains(&d.layout) {
                refuse(
                    "VUID-VkSubpassDescription2-attachment-06251",
                    format!("{at} chains a stencil layout and is in {:?}", d.layout),
                )?;
            }
        }
        self.check_first_uses()?;
        if self.second {
            self.check_depth_resolves(device)?;
        }
        Ok(())
    }

    /// The layout of each attachment's first use (the first subpass that
    /// references it) against its load operations.
    fn check_first_uses(&self) -> Result<()> {
        type L = vk::ImageLayout;
        let clear = vk::AttachmentLoadOp::CLEAR;
        for (n, d) in self.described.iter().enumerate() {
            let n = n as u32;
            let first = self.subpasses.iter().enumerate().find_map(|(i, s)| {
                let refs: Vec<(&Ref, bool)> = s
                    .inputs
                    .iter()
                    .map(|r| (r, true))
                    .chain(s.colors.iter().map(|r| (r, false)))
                    .chain(s.resolves.iter().flatten().map(|r| (r, false)))
                    .chain(s.depth.iter().map(|r| (r, false)))
                    .filter(|(r, _)| r.attachment == n)
                    .collect();
                (!refs.is_empty()).then_some((i, refs))
            });
            let Some((i, refs)) = first else {
                continue;
            };
            for (r, _) in &refs {
                let read_only = matches!(
                    r.layout,
                    L::SHADER_READ_ONLY_OPTIMAL | L::DEPTH_STENCIL_READ_ONLY_OPTIMAL
                );
                if d.load.0 == clear && read_only {
                    refuse(self.vuid(CLEARED_READ), format!("pAttachments[{n}] is cleared, but its first use (subpass {i}) is in {:?}", r.layout))?;
                }
                if d.load.1 == clear && read_only {
                    refuse(self.vuid(STENCIL_CLEARED_READ), format!("pAttachments[{n}]'s stencil is cleared, but its first use (subpass {i}) is in {:?}", r.layout))?;
                }
                if d.load.0 == clear && r.layout == L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL {
                    refuse(self.vuid(CLEARED_DEPTH_READ), format!("pAttachments[{n}] is cleared, but its first use (subpass {i}) reads its depth only"))?;
                }
                if d.load.1 == clear && r.layout == L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL {
                    refuse(self.vuid(STENCIL_CLEARED_STENCIL_READ), format!("pAttachments[{n}]'s stencil is cleared, but its first use (subpass {i}) reads its stencil only"))?;
                }
            }
            if refs.iter().all(|(_, input)| *input) && d.load.0 == clear {
                refuse(self.vuid(INPUT_FIRST_CLEARED), format!("pAttachments[{n}] is first used as an input attachment only (subpass {i}), so it must not be cleared"))?;
            }
        }
        Ok(())
    }

    /// The second version's depth/stencil resolves: a multisampled depth/stencil
    /// attachment into a single-sampled one of a matching format, by modes the
    /// device supports.
    fn check_depth_resolves(&self, device: &Device) -> Result<()> {
        let none = vk::ResolveModeFlags::NONE;
        let mut props = vk::PhysicalDeviceDepthStencilResolveProperties::default();
        let known = crate::special::ask_properties2(device, &mut props);
        for (i, s) in self.subpasses.iter().enumerate() {
            let Some(r) = s.depth_resolve.filter(|a| *a != vk::ATTACHMENT_UNUSED) else {
                continue;
            };
            let at = format!("pSubpasses[{i}]'s VkSubpassDescriptionDepthStencilResolve");
            let Some(d) = s.depth.filter(|d| d.used()) else {
                refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03177", format!("{at} resolves into attachment {r}, and the subpass has no depth/stencil attachment"))?;
                continue;
            };
            let (ds_format, ds_samples) = self.attachments[d.attachment as usize];
            let (format, samples) = self.attachments[r as usize];
            if ds_samples == vk::SampleCountFlags::TYPE_1 {
                refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03179", format!("{at} resolves attachment {}, which has one sample", d.attachment))?;
            }
            if samples != vk::SampleCountFlags::TYPE_1 {
                refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03180", format!("{at} resolves into attachment {r}, of {samples:?} samples"))?;
            }
            let features = device
                .parent()
                .get_format_properties(format)
                .map(|p| p.linear_tiling_features | p.optimal_tiling_features)
                .unwrap_or_default();
            if !features.contains(vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT) {
                refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-02651", format!("{at} resolves into attachment {r}, whose format {format:?} cannot be a depth/stencil attachment"))?;
            }
            let has = crate::formats::aspects(format).unwrap_or_default();
            let ds_has = crate::formats::aspects(ds_format).unwrap_or_default();
            let (has_depth, has_stencil) = (
                has.contains(vk::ImageAspectFlags::DEPTH),
                has.contains(vk::ImageAspectFlags::STENCIL),
            );
            if has_depth && depth_kind(format) != depth_kind(ds_format) {
                refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03181", format!("{at} resolves {ds_format:?} into {format:?}, whose depth components differ"))?;
            }
            // Every stencil component is 8 bits of UINT.
            if has_stencil && !ds_has.contains(vk::ImageAspectFlags::STENCIL) {
                refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03182", format!("{at} resolves {ds_format:?}, which has no stencil, into {format:?}"))?;
            }
            let (depth_mode, stencil_mode) = s.depth_resolve_modes;
            if depth_mode == none && stencil_mode == none {
                refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03178", format!("{at} resolves into attachment {r} by no mode"))?;
            }
            if !known {
                continue;
            }
            if has_depth
                && depth_mode != none
                && !props.supported_depth_resolve_modes.contains(depth_mode)
            {
                refuse(
                    "VUID-VkSubpassDescriptionDepthStencilResolve-depthResolveMode-03183",
                    format!(
                        "{at}'s depthResolveMode {depth_mode:?} is not among the device's ({:?})",
                        props.supported_depth_resolve_modes
                    ),
                )?;
            }
            if has_stencil
                && stencil_mode != none
                && !props.supported_stencil_resolve_modes.contains(stencil_mode)
            {
                refuse("VUID-VkSubpassDescriptionDepthStencilResolve-stencilResolveMode-03184", format!("{at}'s stencilResolveMode {stencil_mode:?} is not among the device's ({:?})", props.supported_stencil_resolve_modes))?;
            }
            if has_depth
                && has_stencil
                && props.independent_resolve == vk::FALSE
                && depth_mode != stencil_mode
            {
                if props.independent_resolve_none == vk::FALSE {
                    refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03185", format!("{at}'s modes differ ({depth_mode:?}, {stencil_mode:?}), and the device resolves both aspects by one"))?;
                } else if depth_mode != none && stencil_mode != none {
                    refuse("VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03186", format!("{at}'s modes differ ({depth_mode:?}, {stencil_mode:?}), and the device resolves both aspects by one or one of them not at all"))?;
                }
            }
        }
        Ok(())
    }
}
