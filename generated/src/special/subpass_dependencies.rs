//! The checks of render pass creation over its subpass dependencies: stages,
//! accesses, self-dependencies and view offsets.

use super::render_pass::multiview_view_count;
use super::{chained, refuse};
use crate::handles::*;
use crate::Result;
use ash::vk;

/// The dependencies of `vkCreateRenderPass`, and a chained
/// `VkRenderPassMultiviewCreateInfo`'s masks and offsets.
pub(super) fn subpass_dependency_checks(
    device: &Device,
    raw: &vk::RenderPassCreateInfo<'_>,
    dependencies: &[vk::SubpassDependency],
) -> Result<()> {
    let external = vk::SUBPASS_EXTERNAL;
    let sync2 = device.live().with_features(|f| f.v13.synchronization2) != vk::FALSE;
    // SAFETY: `raw` is a safe struct's.
    let multiview: Option<&vk::RenderPassMultiviewCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_MULTIVIEW_CREATE_INFO,
        )
    };
    // SAFETY: the safe setters store each array with its count.
    let (masks, offsets, correlations) =
        multiview.map_or((&[][..], &[][..], &[][..]), |m| unsafe {
            (
                crate::state::raw_slice(m.p_view_masks, m.subpass_count),
                crate::state::raw_slice(m.p_view_offsets, m.dependency_count),
                crate::state::raw_slice(m.p_correlation_masks, m.correlation_mask_count),
            )
        });
    let graphics = super::stages::GRAPHICS
        | vk::PipelineStageFlags::ALL_GRAPHICS
        | vk::PipelineStageFlags::ALL_COMMANDS;
    let fb = super::stages::FRAMEBUFFER_SPACE;
    for (i, d) in dependencies.iter().enumerate() {
        let at = format!("pDependencies[{i}]");
        if d.src_subpass == external && d.dst_subpass == external {
            refuse(
                "VUID-VkSubpassDependency-srcSubpass-00865",
                format!("{at} has VK_SUBPASS_EXTERNAL at both ends"),
            )?;
        }
        if d.src_subpass != external && d.dst_subpass != external && d.src_subpass > d.dst_subpass {
            refuse(
                "VUID-VkSubpassDependency-srcSubpass-00864",
                format!(
                    "{at}'s srcSubpass ({}) is after its dstSubpass ({})",
                    d.src_subpass, d.dst_subpass
                ),
            )?;
        }
        if !sync2 && d.src_stage_mask.is_empty() {
            refuse(
                "VUID-VkSubpassDependency-srcStageMask-03937",
                format!("{at}'s srcStageMask is 0, and synchronization2 is not enabled"),
            )?;
        }
        if !sync2 && d.dst_stage_mask.is_empty() {
            refuse(
                "VUID-VkSubpassDependency-dstStageMask-03937",
                format!("{at}'s dstStageMask is 0, and synchronization2 is not enabled"),
            )?;
        }
        if d.src_subpass != external && !graphics.contains(d.src_stage_mask) {
            refuse(
                "VUID-VkRenderPassCreateInfo-pDependencies-00837",
                format!(
                    "{at}'s srcStageMask ({:?}) names a stage a graphics pipeline has not",
                    d.src_stage_mask
                ),
            )?;
        }
        if d.dst_subpass != external && !graphics.contains(d.dst_stage_mask) {
            refuse(
                "VUID-VkRenderPassCreateInfo-pDependencies-00838",
                format!(
                    "{at}'s dstStageMask ({:?}) names a stage a graphics pipeline has not",
                    d.dst_stage_mask
                ),
            )?;
        }
        if let Some(a) = super::stages::unsupported_access(d.src_access_mask, d.src_stage_mask) {
            refuse(
                "VUID-VkSubpassDependency-srcAccessMask-00868",
                format!("{at}'s srcAccessMask has {a:?}, which no stage of its srcStageMask ({:?}) supports", d.src_stage_mask),
            )?;
        }
        if let Some(a) = super::stages::unsupported_access(d.dst_access_mask, d.dst_stage_mask) {
            refuse(
                "VUID-VkSubpassDependency-dstAccessMask-00869",
                format!("{at}'s dstAccessMask has {a:?}, which no stage of its dstStageMask ({:?}) supports", d.dst_stage_mask),
            )?;
        }
        if d.src_subpass == d.dst_subpass && d.src_subpass != external {
            let (src, dst) = (
                super::stages::expand(d.src_stage_mask),
                super::stages::expand(d.dst_stage_mask),
            );
            let logical =
                vk::PipelineStageFlags::TOP_OF_PIPE | vk::PipelineStageFlags::BOTTOM_OF_PIPE;
            if src.intersects(fb) && !fb.contains(dst & !logical) {
                refuse(
                    "VUID-VkSubpassDependency-srcSubpass-06809",
                    format!("{at} is a self-dependency whose srcStageMask has a framebuffer-space stage, but its dstStageMask ({:?}) has others", d.dst_stage_mask),
                )?;
            }
            if src.intersects(fb)
                && dst.intersects(fb)
                && !d.dependency_flags.contains(vk::DependencyFlags::BY_REGION)
            {
                refuse(
                    "VUID-VkSubpassDependency-srcSubpass-02243",
                    format!("{at} is a self-dependency between framebuffer-space stages without VK_DEPENDENCY_BY_REGION_BIT"),
                )?;
            }
            let views = masks
                .get(d.src_subpass as usize)
                .map_or(0, |m| m.count_ones());
            if views > 1 && !d.dependency_flags.contains(vk::DependencyFlags::VIEW_LOCAL) {
                refuse(
                    "VUID-VkSubpassDependency-srcSubpass-00872",
                    format!("{at} is a self-dependency of a subpass of {views} views without VK_DEPENDENCY_VIEW_LOCAL_BIT"),
                )?;
            }
        }
        if let Some(&offset) = offsets.get(i) {
            if offset != 0 && d.src_subpass == d.dst_subpass {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-01930",
                    format!("{at} has view offset {offset} but the same subpass at both ends"),
                )?;
            }
            if offset != 0 && !d.dependency_flags.contains(vk::DependencyFlags::VIEW_LOCAL) {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-02512",
                    format!("{at} has view offset {offset} but is not view-local"),
                )?;
            }
        }
    }
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
    let mut seen = 0u32;
    for (i, c) in correlations.iter().enumerate() {
        if seen & c != 0 {
            refuse(
                "VUID-VkRenderPassMultiviewCreateInfo-pCorrelationMasks-00841",
                format!("pCorrelationMasks[{i}] ({c:#x}) shares a view with an earlier mask"),
            )?;
        }
        seen |= c;
    }
    Ok(())
}
