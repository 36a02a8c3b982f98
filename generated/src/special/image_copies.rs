//! Copies between two images (`vkCmdCopyImage`, `vkCmdCopyImage2`): each side's
//! regions against its image as a buffer-image copy's are (texel blocks, 1D and 3D
//! shapes, planes, format features, the queue family's granularity, read by
//! `copies::check_regions`), and the two sides against each other (sample counts,
//! types, layer counts, compatible formats and aspects, usage, binding, protection
//! and overlap). Both versions' regions are read into one shape and each rule is
//! written once, named by the version's VUID.

use super::copies::{check_protected, check_regions, Protection, Region, Rules, NO_RULES};
use super::image::bindings_overlap;
use super::{check, pool_family, refuse};
use crate::recorder::{Recorder, Scope};
use crate::state::ImageRecord;
use crate::structs::CopyImageInfo2;
use crate::Result;
use ash::vk;

/// The rules of an image-to-image copy, by what they check.
pub(crate) struct ImageCopyRules {
    /// Each source region against the source image.
    pub src: Rules,
    /// Each destination region against the destination image.
    pub dst: Rules,
    pub protected: Protection,
    /// The source regions and the destination regions do not overlap in memory.
    pub overlap: &'static str,
    /// Both images have one sample count.
    pub samples: &'static str,
    /// Images of two types are one 2D and one 3D.
    pub types: &'static str,
    /// Images of one type: each region's two layer counts match.
    pub layer_counts: &'static str,
    /// Two 2D images: each region's depth is 1.
    pub depth_2d: &'static str,
    /// A 1D source: `srcOffset.z` 0 and `extent.depth` 1.
    pub src_1d_z: &'static str,
    /// A 1D destination: `dstOffset.z` 0 and `extent.depth` 1.
    pub dst_1d_z: &'static str,
    /// The source is bound to memory.
    pub src_bound: &'static str,
    /// The destination is bound to memory.
    pub dst_bound: &'static str,
    /// Neither format multi-planar: the formats are size-compatible.
    pub size_compatible: &'static str,
    /// A plane copied: its format is compatible with the other image's.
    pub plane_compatible: &'static str,
    /// Neither format multi-planar: each region's two aspects match.
    pub same_aspects: &'static str,
    /// A multi-planar source and a destination that is not: the destination aspect
    /// is COLOR.
    pub src_planar: &'static str,
    /// A multi-planar destination and a source that is not: the source aspect is
    /// COLOR.
    pub dst_planar: &'static str,
    /// The source's usage (its stencil usage, for a stencil aspect of an image
    /// with one) holds TRANSFER_SRC: (other aspects, stencil).
    pub src_usage: (&'static str, &'static str),
    /// The destination's usage holds TRANSFER_DST: (other aspects, stencil).
    pub dst_usage: (&'static str, &'static str),
}

/// The rules of both versions, whose VUIDs differ in their prefix: `$p` names the
/// command's (or the info struct's) rules, `$c` the command's protection rules.
macro_rules! image_copy_rules {
    ($p:literal, $c:literal) => {
        ImageCopyRules {
            src: Rules {
                one_d: concat!($p, "srcImage-00146"),
                layers_3d: concat!($p, "srcImage-04443"),
                offset_block: [
                    concat!($p, "pRegions-07278"),
                    concat!($p, "pRegions-07279"),
                    concat!($p, "pRegions-07280"),
                ],
                extent_block: [
                    concat!($p, "srcImage-01728"),
                    concat!($p, "srcImage-01729"),
                    concat!($p, "srcImage-01730"),
                ],
                two_planes: concat!($p, "srcImage-01552"),
                three_planes: concat!($p, "srcImage-01553"),
                features: (
                    concat!($p, "srcImage-01995"),
                    vk::FormatFeatureFlags::TRANSFER_SRC,
                ),
                granularity: concat!($p, "srcOffset-01783"),
                ..NO_RULES
            },
            dst: Rules {
                one_d: concat!($p, "dstImage-00152"),
                layers_3d: concat!($p, "dstImage-04444"),
                offset_block: [
                    concat!($p, "pRegions-07281"),
                    concat!($p, "pRegions-07282"),
                    concat!($p, "pRegions-07283"),
                ],
                extent_block: [
                    concat!($p, "dstImage-01732"),
                    concat!($p, "dstImage-01733"),
                    concat!($p, "dstImage-01734"),
                ],
                two_planes: concat!($p, "dstImage-01554"),
                three_planes: concat!($p, "dstImage-01555"),
                features: (
                    concat!($p, "dstImage-01996"),
                    vk::FormatFeatureFlags::TRANSFER_DST,
                ),
                granularity: concat!($p, "dstOffset-01784"),
                to_image: true,
                ..NO_RULES
            },
            protected: Protection {
                protected_src: concat!($c, "commandBuffer-01825"),
                protected_dst: concat!($c, "commandBuffer-01826"),
                unprotected_dst: concat!($c, "commandBuffer-01827"),
            },
            overlap: concat!($p, "pRegions-00124"),
            samples: concat!($p, "srcImage-00136"),
            types: concat!($p, "srcImage-07743"),
            layer_counts: concat!($p, "srcImage-07744"),
            depth_2d: concat!($p, "srcImage-01790"),
            src_1d_z: concat!($p, "srcImage-01785"),
            dst_1d_z: concat!($p, "dstImage-01786"),
            src_bound: concat!($p, "srcImage-01546"),
            dst_bound: concat!($p, "dstImage-01547"),
            size_compatible: concat!($p, "srcImage-01548"),
            plane_compatible: concat!($p, "None-01549"),
            same_aspects: concat!($p, "srcImage-01551"),
            src_planar: concat!($p, "srcImage-01556"),
            dst_planar: concat!($p, "dstImage-01557"),
            src_usage: (concat!($p, "aspect-06662"), concat!($p, "aspect-06664")),
            dst_usage: (concat!($p, "aspect-06663"), concat!($p, "aspect-06665")),
        }
    };
}

/// `vkCmdCopyImage`.
const COPY_IMAGE: ImageCopyRules =
    image_copy_rules!("VUID-vkCmdCopyImage-", "VUID-vkCmdCopyImage-");

/// `vkCmdCopyImage2`.
const COPY_IMAGE2: ImageCopyRules =
    image_copy_rules!("VUID-VkCopyImageInfo2-", "VUID-vkCmdCopyImage2-");

/// One region of an image copy, of either version.
#[derive(Clone, Copy)]
struct Copy {
    src: vk::ImageSubresourceLayers,
    src_offset: vk::Offset3D,
    dst: vk::ImageSubresourceLayers,
    dst_offset: vk::Offset3D,
    extent: vk::Extent3D,
}

/// Refuses a copy between images (`vkCmdCopyImage`) that breaks a rule of its
/// images or regions (after the recognised checks of each region's ranges).
pub(crate) fn cmd_copy_image_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    (src_image, dst_image): (vk::Image, vk::Image),
    regions: &[vk::ImageCopy],
) -> Result<()> {
    let read: Vec<Copy> = regions
        .iter()
        .map(|r| Copy {
            src: r.src_subresource,
            src_offset: r.src_offset,
            dst: r.dst_subresource,
            dst_offset: r.dst_offset,
            extent: r.extent,
        })
        .collect();
    check_image_copy(recorder, (src_image, dst_image), &read, &COPY_IMAGE)
}

/// As [`cmd_copy_image_checks`], for `vkCmdCopyImage2`.
pub(crate) fn cmd_copy_image2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    copy_image_info: &CopyImageInfo2<'_>,
) -> Result<()> {
    let raw = copy_image_info.as_raw();
    // SAFETY: the safe setter stored the regions with their count.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    let read: Vec<Copy> = regions
        .iter()
        .map(|r| Copy {
            src: r.src_subresource,
            src_offset: r.src_offset,
            dst: r.dst_subresource,
            dst_offset: r.dst_offset,
            extent: r.extent,
        })
        .collect();
    check_image_copy(
        recorder,
        (raw.src_image, raw.dst_image),
        &read,
        &COPY_IMAGE2,
    )
}

/// How many planes an image's format has (0: not multi-planar).
fn planes(image: &ImageRecord) -> usize {
    let has = crate::formats::aspects(image.format).unwrap_or(vk::ImageAspectFlags::COLOR);
    [
        vk::ImageAspectFlags::PLANE_0,
        vk::ImageAspectFlags::PLANE_1,
        vk::ImageAspectFlags::PLANE_2,
    ]
    .iter()
    .filter(|p| has.contains(**p))
    .count()
}

/// The format a region copies of an image: the plane's, for a plane aspect of a
/// multi-planar image, else the image's.
fn copied_format(image: &ImageRecord, aspect: vk::ImageAspectFlags) -> vk::Format {
    let plane = [
        vk::ImageAspectFlags::PLANE_0,
        vk::ImageAspectFlags::PLANE_1,
        vk::ImageAspectFlags::PLANE_2,
    ]
    .iter()
    .position(|p| *p == aspect);
    plane
        .and_then(|p| crate::formats::plane_format(image.format, p))
        .unwrap_or(image.format)
}

/// Whether two formats are size-compatible: a depth/stencil format only with
/// itself, two others when their texel blocks have one size in bytes.
fn size_compatible(a: vk::Format, b: vk::Format) -> bool {
    let depth_stencil = |f: vk::Format| {
        crate::formats::aspects(f).is_some_and(|a| {
            a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL)
        })
    };
    if depth_stencil(a) || depth_stencil(b) {
        return a == b;
    }
    let color = vk::ImageAspectFlags::COLOR;
    match (
        crate::formats::block(a, color),
        crate::formats::block(b, color),
    ) {
        (Some((sa, _)), Some((sb, _))) => sa == sb,
        _ => a == b,
    }
}

/// Refuses usage without `usage` for the aspects a region names: the stencil usage
/// for a stencil aspect of an image created with one, the usage otherwise.
fn check_usage(
    image: &ImageRecord,
    aspect: vk::ImageAspectFlags,
    usage: vk::ImageUsageFlags,
    (main, stencil): (&'static str, &'static str),
    at: &str,
) -> Result<()> {
    let others =
        !(aspect & !vk::ImageAspectFlags::STENCIL).is_empty() || image.stencil_usage.is_none();
    check(main, !others || image.usage.contains(usage), || {
        format!("{at}: the image's usage {:?} lacks {usage:?}", image.usage)
    })?;
    if let Some(s) = image.stencil_usage {
        if aspect.contains(vk::ImageAspectFlags::STENCIL) {
            check(stencil, s.contains(usage), || {
                format!("{at}: the image's stencil usage {s:?} lacks {usage:?}")
            })?;
        }
    }
    Ok(())
}

/// A region's side: its subresource, offset and extent.
type Side = (vk::ImageSubresourceLayers, vk::Offset3D, vk::Extent3D);

/// Whether two regions of one image share a texel: one mip level, overlapping
/// aspects and layers, and overlapping boxes.
fn regions_meet((a, ao, ae): Side, (b, bo, be): Side) -> bool {
    let span = |o: i32, e: u32| (i64::from(o), i64::from(o) + i64::from(e));
    let meet = |(a0, a1): (i64, i64), (b0, b1): (i64, i64)| a0 < b1 && b0 < a1;
    let color = vk::ImageAspectFlags::COLOR;
    let aspects = a.aspect_mask.intersects(b.aspect_mask)
        || a.aspect_mask.contains(color)
        || b.aspect_mask.contains(color);
    let layers = |s: vk::ImageSubresourceLayers| {
        (
            i64::from(s.base_array_layer),
            i64::from(s.base_array_layer) + i64::from(s.layer_count),
        )
    };
    a.mip_level == b.mip_level
        && aspects
        && meet(layers(a), layers(b))
        && meet(span(ao.x, ae.width), span(bo.x, be.width))
        && meet(span(ao.y, ae.height), span(bo.y, be.height))
        && meet(span(ao.z, ae.depth), span(bo.z, be.depth))
}

fn check_image_copy<S: Scope>(
    recorder: &Recorder<'_, S>,
    (src_image, dst_image): (vk::Image, vk::Image),
    regions: &[Copy],
    rules: &ImageCopyRules,
) -> Result<()> {
    let device = recorder.device();
    let live = device.live();
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
    check(rules.src_bound, src.bound, || {
        "the source image has no memory bound".into()
    })?;
    check(rules.dst_bound, dst.bound, || {
        "the destination image has no memory bound".into()
    })?;
    check(rules.samples, src.samples == dst.samples, || {
        format!(
            "the source has {:?} samples and the destination {:?}",
            src.samples, dst.samples
        )
    })?;
    let (src_type, dst_type) = (src.image_type, dst.image_type);
    let two_three = [vk::ImageType::TYPE_2D, vk::ImageType::TYPE_3D];
    check(
        rules.types,
        src_type == dst_type || (two_three.contains(&src_type) && two_three.contains(&dst_type)),
        || format!("a {src_type:?} image copied to a {dst_type:?} image"),
    )?;
    let family = pool_family(recorder);
    let side = |r: &Copy, sub: vk::ImageSubresourceLayers, offset: vk::Offset3D| Region {
        offset: 0,
        row_length: 0,
        image_height: 0,
        subresource: sub,
        image_offset: offset,
        extent: r.extent,
    };
    check_regions(
        device,
        &src,
        family,
        regions.iter().map(|r| side(r, r.src, r.src_offset)),
        &rules.src,
    )?;
    check_regions(
        device,
        &dst,
        family,
        regions.iter().map(|r| side(r, r.dst, r.dst_offset)),
        &rules.dst,
    )?;
    let (src_planes, dst_planes) = (planes(&src), planes(&dst));
    for (n, r) in regions.iter().enumerate() {
        let at = format!("pRegions[{n}]");
        let e = r.extent;
        if src_type == dst_type {
            check(
                rules.layer_counts,
                r.src.layer_count == r.dst.layer_count,
                || {
                    format!(
                        "{at} copies {} layers into {}",
                        r.src.layer_count, r.dst.layer_count
                    )
                },
            )?;
        }
        if src_type == vk::ImageType::TYPE_2D && dst_type == vk::ImageType::TYPE_2D {
            check(rules.depth_2d, e.depth == 1, || {
                format!("{at} has depth {} between 2D images", e.depth)
            })?;
        }
        for (image, offset, vuid) in [
            (&src, r.src_offset, rules.src_1d_z),
            (&dst, r.dst_offset, rules.dst_1d_z),
        ] {
            if image.image_type == vk::ImageType::TYPE_1D {
                check(vuid, offset.z == 0 && e.depth == 1, || {
                    format!(
                        "{at} has offset z {} and depth {} in a 1D image",
                        offset.z, e.depth
                    )
                })?;
            }
        }
        let (sa, da) = (r.src.aspect_mask, r.dst.aspect_mask);
        let color = vk::ImageAspectFlags::COLOR;
        match (src_planes > 0, dst_planes > 0) {
            (false, false) => {
                check(rules.same_aspects, sa == da, || {
                    format!("{at} copies aspects {sa:?} into {da:?}")
                })?;
                check(
                    rules.size_compatible,
                    size_compatible(src.format, dst.format),
                    || {
                        format!(
                            "{:?} and {:?} are not size-compatible",
                            src.format, dst.format
                        )
                    },
                )?;
            }
            (true, false) => {
                check(rules.src_planar, da == color, || {
                    format!("{at} copies a plane of a multi-planar image into aspects {da:?}, not COLOR")
                })?
            }
            (false, true) => {
                check(rules.dst_planar, sa == color, || {
                    format!("{at} copies aspects {sa:?}, not COLOR, into a plane of a multi-planar image")
                })?
            }
            (true, true) => {}
        }
        if src_planes > 0 || dst_planes > 0 {
            let (sf, df) = (copied_format(&src, sa), copied_format(&dst, da));
            check(rules.plane_compatible, size_compatible(sf, df), || {
                format!("{at} copies {sf:?} into {df:?}, which are not compatible")
            })?;
        }
        check_usage(
            &src,
            sa,
            vk::ImageUsageFlags::TRANSFER_SRC,
            rules.src_usage,
            &at,
        )?;
        check_usage(
            &dst,
            da,
            vk::ImageUsageFlags::TRANSFER_DST,
            rules.dst_usage,
            &at,
        )?;
    }
    // Regions of one image must not meet; two images that share memory may meet
    // wherever their bindings do (where a region of an optimally tiled image lies
    // in its binding is the driver's).
    if src_image == dst_image {
        for (i, a) in regions.iter().enumerate() {
            for (j, b) in regions.iter().enumerate() {
                check(
                    rules.overlap,
                    !regions_meet(
                        (a.src, a.src_offset, a.extent),
                        (b.dst, b.dst_offset, b.extent),
                    ),
                    || {
                        format!("the source of pRegions[{i}] and the destination of pRegions[{j}] share texels of the image")
                    },
                )?;
            }
        }
    } else if let Some(m) = bindings_overlap(live, src_image, dst_image) {
        refuse(rules.overlap, m)?;
    }
    Ok(())
}
