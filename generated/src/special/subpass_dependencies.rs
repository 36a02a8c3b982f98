//! The checks of render pass creation over its subpass dependencies: stages,
//! accesses, self-dependencies and view offsets.

use super::refuse;
use super::render_pass::{multiview_view_count, Pass, Rule};
use crate::handles::*;
use crate::Result;
use ash::vk;

/// The dependencies of either render pass creation, and its view masks, offsets
/// and correlation masks, each rule under the version's VUID.
pub(super) fn subpass_dependency_checks(device: &Device, pass: &Pass) -> Result<()> {
    let external = vk::SUBPASS_EXTERNAL;
    let sync2 = device.live().with_features(|f| f.v13.synchronization2) != vk::FALSE;
    let masks = pass.view_masks();
    let graphics = super::stages::GRAPHICS
        | vk::PipelineStageFlags::ALL_GRAPHICS
        | vk::PipelineStageFlags::ALL_COMMANDS;
    let fb = super::stages::FRAMEBUFFER_SPACE;
    for (i, d) in pass.dependencies.iter().enumerate() {
        let at = format!("pDependencies[{i}]");
        let (src_subpass, dst_subpass) = d.subpasses;
        let (src_stage, dst_stage) = d.stages;
        let (src_access, dst_access) = d.access;
        if src_subpass == external && dst_subpass == external {
            refuse(
                pass.vuid(BOTH_EXTERNAL),
                format!("{at} has VK_SUBPASS_EXTERNAL at both ends"),
            )?;
        }
        if src_subpass != external && dst_subpass != external && src_subpass > dst_subpass {
            refuse(
                pass.vuid(ORDER),
                format!(
                    "{at}'s srcSubpass ({src_subpass}) is after its dstSubpass ({dst_subpass})"
                ),
            )?;
        }
        if !sync2 && src_stage.is_empty() {
            refuse(
                pass.vuid(SRC_ZERO),
                format!("{at}'s srcStageMask is 0, and synchronization2 is not enabled"),
            )?;
        }
        if !sync2 && dst_stage.is_empty() {
            refuse(
                pass.vuid(DST_ZERO),
                format!("{at}'s dstStageMask is 0, and synchronization2 is not enabled"),
            )?;
        }
        if src_subpass != external && !graphics.contains(src_stage) {
            refuse(
                pass.vuid(SRC_GRAPHICS),
                format!(
                    "{at}'s srcStageMask ({src_stage:?}) names a stage a graphics pipeline has not"
                ),
            )?;
        }
        if dst_subpass != external && !graphics.contains(dst_stage) {
            refuse(
                pass.vuid(DST_GRAPHICS),
                format!(
                    "{at}'s dstStageMask ({dst_stage:?}) names a stage a graphics pipeline has not"
                ),
            )?;
        }
        if let Some(a) = super::stages::unsupported_access(src_access, src_stage) {
            refuse(
                pass.vuid(SRC_ACCESS),
                format!("{at}'s srcAccessMask has {a:?}, which no stage of its srcStageMask ({src_stage:?}) supports"),
            )?;
        }
        if let Some(a) = super::stages::unsupported_access(dst_access, dst_stage) {
            refuse(
                pass.vuid(DST_ACCESS),
                format!("{at}'s dstAccessMask has {a:?}, which no stage of its dstStageMask ({dst_stage:?}) supports"),
            )?;
        }
        if src_subpass == dst_subpass && src_subpass != external {
            let (src, dst) = (
                super::stages::expand(src_stage),
                super::stages::expand(dst_stage),
            );
            let logical =
                vk::PipelineStageFlags::TOP_OF_PIPE | vk::PipelineStageFlags::BOTTOM_OF_PIPE;
            if src.intersects(fb) && !fb.contains(dst & !logical) {
                refuse(
                    pass.vuid(SELF_FRAMEBUFFER),
                    format!("{at} is a self-dependency whose srcStageMask has a framebuffer-space stage, but its dstStageMask ({dst_stage:?}) has others"),
                )?;
            }
            if src.intersects(fb)
                && dst.intersects(fb)
                && !d.flags.contains(vk::DependencyFlags::BY_REGION)
            {
                refuse(
                    pass.vuid(SELF_BY_REGION),
                    format!("{at} is a self-dependency between framebuffer-space stages without VK_DEPENDENCY_BY_REGION_BIT"),
                )?;
            }
            let views = masks
                .get(src_subpass as usize)
                .map_or(0, |m| m.count_ones());
            if views > 1 && !d.flags.contains(vk::DependencyFlags::VIEW_LOCAL) {
                refuse(
                    pass.vuid(SELF_VIEW_LOCAL),
                    format!("{at} is a self-dependency of a subpass of {views} views without VK_DEPENDENCY_VIEW_LOCAL_BIT"),
                )?;
            }
        }
        if let Some(offset) = d.view_offset.filter(|o| *o != 0) {
            if src_subpass == dst_subpass {
                refuse(
                    pass.vuid(OFFSET_SELF),
                    format!("{at} has view offset {offset} but the same subpass at both ends"),
                )?;
            }
            // The second version's rule for this is its struct's own (checked by
            // the emitted checks).
            if !pass.second && !d.flags.contains(vk::DependencyFlags::VIEW_LOCAL) {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-02512",
                    format!("{at} has view offset {offset} but is not view-local"),
                )?;
            }
        }
    }
    // The second version's view masks are checked with its subpasses' references.
    if !pass.second {
        let multiview_on = device.live().with_features(|f| f.v11.multiview) != vk::FALSE;
        let max = if masks.iter().any(|m| *m != 0) {
            multiview_view_count(device)
        } else {
            None
        };
        for (i, m) in masks.iter().enumerate() {
            if *m != 0 && !multiview_on {
                refuse(
                    "VUID-VkRenderPassMultiviewCreateInfo-multiview-06555",
                    format!("pViewMasks[{i}] is {m:#x}, but the multiview feature is not enabled"),
                )?;
            }
            let highest = 32 - m.leading_zeros();
            if let Some(max) = max.filter(|max| *m != 0 && highest > *max) {
                refuse(
                    "VUID-VkRenderPassMultiviewCreateInfo-pViewMasks-06697",
                    format!(
                        "pViewMasks[{i}] ({m:#x}) names view {}, past maxMultiviewViewCount ({max})",
                        highest - 1
                    ),
                )?;
            }
        }
    }
    let mut seen = 0u32;
    for (i, c) in pass.correlations.iter().enumerate() {
        if seen & c != 0 {
            refuse(
                pass.vuid(CORRELATION),
                format!("the correlation mask {i} ({c:#x}) shares a view with an earlier mask"),
            )?;
        }
        seen |= c;
    }
    Ok(())
}

const BOTH_EXTERNAL: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-00865",
    "VUID-VkSubpassDependency2-srcSubpass-03085",
);
const ORDER: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-00864",
    "VUID-VkSubpassDependency2-srcSubpass-03084",
);
const SRC_ZERO: Rule = (
    "VUID-VkSubpassDependency-srcStageMask-03937",
    "VUID-VkSubpassDependency2-srcStageMask-03937",
);
const DST_ZERO: Rule = (
    "VUID-VkSubpassDependency-dstStageMask-03937",
    "VUID-VkSubpassDependency2-dstStageMask-03937",
);
const SRC_GRAPHICS: Rule = (
    "VUID-VkRenderPassCreateInfo-pDependencies-00837",
    "VUID-VkRenderPassCreateInfo2-pDependencies-03054",
);
const DST_GRAPHICS: Rule = (
    "VUID-VkRenderPassCreateInfo-pDependencies-00838",
    "VUID-VkRenderPassCreateInfo2-pDependencies-03055",
);
const SRC_ACCESS: Rule = (
    "VUID-VkSubpassDependency-srcAccessMask-00868",
    "VUID-VkSubpassDependency2-srcAccessMask-03088",
);
const DST_ACCESS: Rule = (
    "VUID-VkSubpassDependency-dstAccessMask-00869",
    "VUID-VkSubpassDependency2-dstAccessMask-03089",
);
const SELF_FRAMEBUFFER: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-06809",
    "VUID-VkSubpassDependency2-srcSubpass-06810",
);
const SELF_BY_REGION: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-02243",
    "VUID-VkSubpassDependency2-srcSubpass-02245",
);
const SELF_VIEW_LOCAL: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-00872",
    "VUID-VkRenderPassCreateInfo2-pDependencies-03060",
);
const OFFSET_SELF: Rule = (
    "VUID-VkRenderPassCreateInfo-pNext-01930",
    "VUID-VkSubpassDependency2-viewOffset-02530",
);
const CORRELATION: Rule = (
    "VUID-VkRenderPassMultiviewCreateInfo-pCorrelationMasks-00841",
    "VUID-VkRenderPassCreateInfo2-pCorrelatedViewMasks-03056",
);
