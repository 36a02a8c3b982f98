//! Resolves of a multisampled image into a single-sampled one outside a render pass:
//! both images' sample counts, formats, features, types and protection, and each
//! region's subresources. Both versions' regions are read into one shape and each
//! rule is written once, named by the version's VUID.

use super::copies::{check_protected, Protection};
use super::image::{bindings_overlap, tiling_features};
use super::{check, refuse};
use crate::recorder::{Recorder, Scope};
use crate::state::ImageRecord;
use crate::structs::ResolveImageInfo2;
use crate::Result;
use ash::vk;

/// The rules of a resolve command, by what they check.
pub(crate) struct ResolveRules {
    pub protected: Protection,
    /// The two images' memory does not overlap.
    pub overlap: &'static str,
    /// The source has more than one sample.
    pub src_samples: &'static str,
    /// The destination has one sample.
    pub dst_samples: &'static str,
    /// The destination's format features hold COLOR_ATTACHMENT.
    pub dst_color_attachment: &'static str,
    /// Both images have one format.
    pub same_format: &'static str,
    /// With a 3D image, the source subresource is layer 0 alone.
    pub src_3d_layers: &'static str,
    /// With a 3D image, the destination subresource is layer 0 alone.
    pub dst_3d_layers: &'static str,
    /// A 1D source: `srcOffset.y` 0 and `extent.height` 1.
    pub src_1d: &'static str,
    /// A 1D or 2D source: `srcOffset.z` 0 and `extent.depth` 1.
    pub src_flat: &'static str,
    /// A 1D destination: `dstOffset.y` 0 and `extent.height` 1.
    pub dst_1d: &'static str,
    /// A 1D or 2D destination: `dstOffset.z` 0 and `extent.depth` 1.
    pub dst_flat: &'static str,
    /// The source's format features hold TRANSFER_SRC.
    pub src_transfer: &'static str,
    /// The destination's format features hold TRANSFER_DST.
    pub dst_transfer: &'static str,
    /// Both subresources' aspects are COLOR alone.
    pub aspect_color: &'static str,
    /// Both subresources have one layer count.
    pub layer_count: &'static str,
}

/// `vkCmdResolveImage`.
const RESOLVE: ResolveRules = ResolveRules {
    protected: Protection {
        protected_src: "VUID-vkCmdResolveImage-commandBuffer-01837",
        protected_dst: "VUID-vkCmdResolveImage-commandBuffer-01838",
        unprotected_dst: "VUID-vkCmdResolveImage-commandBuffer-01839",
    },
    overlap: "VUID-vkCmdResolveImage-pRegions-00255",
    src_samples: "VUID-vkCmdResolveImage-srcImage-00257",
    dst_samples: "VUID-vkCmdResolveImage-dstImage-00259",
    dst_color_attachment: "VUID-vkCmdResolveImage-dstImage-02003",
    same_format: "VUID-vkCmdResolveImage-srcImage-01386",
    src_3d_layers: "VUID-vkCmdResolveImage-srcImage-04446",
    dst_3d_layers: "VUID-vkCmdResolveImage-srcImage-04447",
    src_1d: "VUID-vkCmdResolveImage-srcImage-00271",
    src_flat: "VUID-vkCmdResolveImage-srcImage-00273",
    dst_1d: "VUID-vkCmdResolveImage-dstImage-00276",
    dst_flat: "VUID-vkCmdResolveImage-dstImage-00278",
    src_transfer: "VUID-vkCmdResolveImage-srcImage-06763",
    dst_transfer: "VUID-vkCmdResolveImage-dstImage-06765",
    aspect_color: "VUID-VkImageResolve-aspectMask-00266",
    layer_count: "VUID-VkImageResolve-layerCount-00267",
};

/// `vkCmdResolveImage2`.
const RESOLVE2: ResolveRules = ResolveRules {
    protected: Protection {
        protected_src: "VUID-vkCmdResolveImage2-commandBuffer-01837",
        protected_dst: "VUID-vkCmdResolveImage2-commandBuffer-01838",
        unprotected_dst: "VUID-vkCmdResolveImage2-commandBuffer-01839",
    },
    overlap: "VUID-VkResolveImageInfo2-pRegions-00255",
    src_samples: "VUID-VkResolveImageInfo2-srcImage-00257",
    dst_samples: "VUID-VkResolveImageInfo2-dstImage-00259",
    dst_color_attachment: "VUID-VkResolveImageInfo2-dstImage-02003",
    same_format: "VUID-VkResolveImageInfo2-srcImage-01386",
    src_3d_layers: "VUID-VkResolveImageInfo2-srcImage-04446",
    dst_3d_layers: "VUID-VkResolveImageInfo2-srcImage-04447",
    src_1d: "VUID-VkResolveImageInfo2-srcImage-00271",
    src_flat: "VUID-VkResolveImageInfo2-srcImage-00273",
    dst_1d: "VUID-VkResolveImageInfo2-dstImage-00276",
    dst_flat: "VUID-VkResolveImageInfo2-dstImage-00278",
    src_transfer: "VUID-VkResolveImageInfo2-srcImage-06763",
    dst_transfer: "VUID-VkResolveImageInfo2-dstImage-06765",
    aspect_color: "VUID-VkImageResolve2-aspectMask-00266",
    layer_count: "VUID-VkImageResolve2-layerCount-00267",
};

/// One region of a resolve, of either version.
#[derive(Clone, Copy)]
struct Region {
    src: vk::ImageSubresourceLayers,
    src_offset: vk::Offset3D,
    dst: vk::ImageSubresourceLayers,
    dst_offset: vk::Offset3D,
    extent: vk::Extent3D,
}

/// Refuses a resolve (`vkCmdResolveImage`) that breaks a rule of its images or
/// regions (after the recognised checks of each region's ranges).
pub(crate) fn cmd_resolve_image_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    (src_image, dst_image): (vk::Image, vk::Image),
    regions: &[vk::ImageResolve],
) -> Result<()> {
    let read = regions.iter().map(|r| Region {
        src: r.src_subresource,
        src_offset: r.src_offset,
        dst: r.dst_subresource,
        dst_offset: r.dst_offset,
        extent: r.extent,
    });
    check_resolve(recorder, (src_image, dst_image), read, &RESOLVE)
}

/// As [`cmd_resolve_image_checks`], for `vkCmdResolveImage2`.
pub(crate) fn cmd_resolve_image2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    resolve_image_info: &ResolveImageInfo2<'_>,
) -> Result<()> {
    let raw = resolve_image_info.as_raw();
    // SAFETY: the safe setter stored the regions with their count.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    let read = regions.iter().map(|r| Region {
        src: r.src_subresource,
        src_offset: r.src_offset,
        dst: r.dst_subresource,
        dst_offset: r.dst_offset,
        extent: r.extent,
    });
    check_resolve(recorder, (raw.src_image, raw.dst_image), read, &RESOLVE2)
}

fn check_resolve<S: Scope>(
    recorder: &Recorder<'_, S>,
    (src_image, dst_image): (vk::Image, vk::Image),
    regions: impl Iterator<Item = Region>,
    rules: &ResolveRules,
) -> Result<()> {
    let live = recorder.device().live();
    let (Some(src), Some(dst)) = (live.image(src_image), live.image(dst_image)) else {
        return Ok(());
    };
    let protected = |i: &ImageRecord| i.flags.contains(vk::ImageCreateFlags::PROTECTED);
    check_protected(
        recorder,
        Some(protected(&src)),
        protected(&dst),
        &rules.protected,
    )?;
    check(
        rules.src_samples,
        src.samples != vk::SampleCountFlags::TYPE_1,
        || "the source image has one sample".into(),
    )?;
    check(
        rules.dst_samples,
        dst.samples == vk::SampleCountFlags::TYPE_1,
        || format!("the destination image has {:?} samples", dst.samples),
    )?;
    check(rules.same_format, src.format == dst.format, || {
        format!(
            "the source is {:?} and the destination {:?}",
            src.format, dst.format
        )
    })?;
    type F = vk::FormatFeatureFlags;
    let (src_features, dst_features) = (
        tiling_features(recorder.device(), &src)?,
        tiling_features(recorder.device(), &dst)?,
    );
    check(
        rules.dst_color_attachment,
        dst_features.contains(F::COLOR_ATTACHMENT),
        || format!("the destination's features {dst_features:?} lack COLOR_ATTACHMENT"),
    )?;
    check(
        rules.src_transfer,
        src_features.contains(F::TRANSFER_SRC),
        || format!("the source's features {src_features:?} lack TRANSFER_SRC"),
    )?;
    check(
        rules.dst_transfer,
        dst_features.contains(F::TRANSFER_DST),
        || format!("the destination's features {dst_features:?} lack TRANSFER_DST"),
    )?;
    // The images' bindings: regions of two images that share memory may overlap
    // there (where in its binding an optimally tiled region lies is the driver's).
    if let Some(m) = bindings_overlap(live, src_image, dst_image) {
        refuse(rules.overlap, m)?;
    }
    let any_3d =
        src.image_type == vk::ImageType::TYPE_3D || dst.image_type == vk::ImageType::TYPE_3D;
    for (n, r) in regions.enumerate() {
        let at = format!("pRegions[{n}]");
        for (sub, vuid) in [(r.src, rules.src_3d_layers), (r.dst, rules.dst_3d_layers)] {
            check(
                vuid,
                !any_3d || (sub.base_array_layer == 0 && sub.layer_count == 1),
                || {
                    format!(
                        "{at} names layers {}..+{} with a 3D image",
                        sub.base_array_layer, sub.layer_count
                    )
                },
            )?;
        }
        for (image, offset, one_d, flat) in [
            (&src, r.src_offset, rules.src_1d, rules.src_flat),
            (&dst, r.dst_offset, rules.dst_1d, rules.dst_flat),
        ] {
            if image.image_type == vk::ImageType::TYPE_1D {
                check(one_d, offset.y == 0 && r.extent.height == 1, || {
                    format!(
                        "{at} has offset y {} and height {} in a 1D image",
                        offset.y, r.extent.height
                    )
                })?;
            }
            if image.image_type != vk::ImageType::TYPE_3D {
                check(flat, offset.z == 0 && r.extent.depth == 1, || {
                    format!(
                        "{at} has offset z {} and depth {} in a {:?} image",
                        offset.z, r.extent.depth, image.image_type
                    )
                })?;
            }
        }
        let color = vk::ImageAspectFlags::COLOR;
        check(
            rules.aspect_color,
            r.src.aspect_mask == color && r.dst.aspect_mask == color,
            || {
                format!(
                    "{at} resolves aspects {:?} into {:?}, not COLOR alone",
                    r.src.aspect_mask, r.dst.aspect_mask
                )
            },
        )?;
        check(
            rules.layer_count,
            r.src.layer_count == r.dst.layer_count,
            || {
                format!(
                    "{at} resolves {} layers into {}",
                    r.src.layer_count, r.dst.layer_count
                )
            },
        )?;
    }
    Ok(())
}
