//! Blits (`vkCmdBlitImage`, `vkCmdBlitImage2`): both images' sample counts,
//! formats, format features and protection, the filter against the source's
//! format, and each region's aspects, layers, offsets and overlap. Both versions'
//! regions are read into one shape and each rule is written once, named by the
//! version's VUID.

use super::copies::{check_protected, Protection};
use super::image::{bindings_overlap, tiling_features};
use super::{check, refuse};
use crate::recorder::{Recorder, Scope};
use crate::state::ImageRecord;
use crate::structs::BlitImageInfo2;
use crate::Result;
use ash::vk;

/// The rules of a blit, by what they check.
pub(crate) struct BlitRules {
    pub protected: Protection,
    /// Each source region inside the source's level.
    pub src_contained: &'static str,
    /// Each destination region inside the destination's level.
    pub dst_contained: &'static str,
    /// No destination texel is one the blit may sample.
    pub overlap: &'static str,
    /// The source's format features hold BLIT_SRC.
    pub src_blit: &'static str,
    /// The destination's format features hold BLIT_DST.
    pub dst_blit: &'static str,
    /// A signed integer format on one side needs one on the other.
    pub signed: &'static str,
    /// An unsigned integer format on one side needs one on the other.
    pub unsigned: &'static str,
    /// A depth/stencil format on one side needs the same format on the other.
    pub depth_stencil: &'static str,
    /// A depth/stencil source needs the NEAREST filter.
    pub depth_nearest: &'static str,
    /// The source has one sample.
    pub src_samples: &'static str,
    /// The destination has one sample.
    pub dst_samples: &'static str,
    /// The LINEAR filter needs the source's SAMPLED_IMAGE_FILTER_LINEAR feature.
    pub linear: &'static str,
    /// With a 3D image, each subresource is layer 0 alone.
    pub layers_3d: &'static str,
    /// A 1D source: `srcOffsets[0].y` 0 and `srcOffsets[1].y` 1.
    pub src_1d: &'static str,
    /// A 1D or 2D source: `srcOffsets[0].z` 0 and `srcOffsets[1].z` 1.
    pub src_flat: &'static str,
    /// A 1D destination: `dstOffsets[0].y` 0 and `dstOffsets[1].y` 1.
    pub dst_1d: &'static str,
    /// A 1D or 2D destination: `dstOffsets[0].z` 0 and `dstOffsets[1].z` 1.
    pub dst_flat: &'static str,
    /// The source's format needs no sampler Y'CbCr conversion.
    pub src_ycbcr: &'static str,
    /// The destination's format needs no sampler Y'CbCr conversion.
    pub dst_ycbcr: &'static str,
    /// Each region's two aspect masks match.
    pub aspects: &'static str,
    /// Each region's two layer counts match.
    pub layer_count: &'static str,
}

/// The rules of both versions: `$p` prefixes the command's (or the info struct's)
/// rules, `$c` the command's protection rules, `$r` the region struct's.
macro_rules! blit_rules {
    ($p:literal, $c:literal, $r:literal) => {
        BlitRules {
            protected: Protection {
                protected_src: concat!($c, "commandBuffer-01834"),
                protected_dst: concat!($c, "commandBuffer-01835"),
                unprotected_dst: concat!($c, "commandBuffer-01836"),
            },
            src_contained: concat!($p, "pRegions-00215"),
            dst_contained: concat!($p, "pRegions-00216"),
            overlap: concat!($p, "pRegions-00217"),
            src_blit: concat!($p, "srcImage-01999"),
            dst_blit: concat!($p, "dstImage-02000"),
            signed: concat!($p, "srcImage-00229"),
            unsigned: concat!($p, "srcImage-00230"),
            depth_stencil: concat!($p, "srcImage-00231"),
            depth_nearest: concat!($p, "srcImage-00232"),
            src_samples: concat!($p, "srcImage-00233"),
            dst_samples: concat!($p, "dstImage-00234"),
            linear: concat!($p, "filter-02001"),
            layers_3d: concat!($p, "srcImage-00240"),
            src_1d: concat!($p, "srcImage-00245"),
            src_flat: concat!($p, "srcImage-00247"),
            dst_1d: concat!($p, "dstImage-00250"),
            dst_flat: concat!($p, "dstImage-00252"),
            src_ycbcr: concat!($p, "srcImage-06421"),
            dst_ycbcr: concat!($p, "dstImage-06422"),
            aspects: concat!($r, "aspectMask-00238"),
            layer_count: concat!($r, "layerCount-00239"),
        }
    };
}

/// `vkCmdBlitImage`.
const BLIT: BlitRules = blit_rules!(
    "VUID-vkCmdBlitImage-",
    "VUID-vkCmdBlitImage-",
    "VUID-VkImageBlit-"
);

/// `vkCmdBlitImage2`.
const BLIT2: BlitRules = blit_rules!(
    "VUID-VkBlitImageInfo2-",
    "VUID-vkCmdBlitImage2-",
    "VUID-VkImageBlit2-"
);

/// One region of a blit, of either version.
#[derive(Clone, Copy)]
struct Blit {
    src: vk::ImageSubresourceLayers,
    src_offsets: [vk::Offset3D; 2],
    dst: vk::ImageSubresourceLayers,
    dst_offsets: [vk::Offset3D; 2],
}

/// Refuses a blit (`vkCmdBlitImage`) that breaks a rule of its images, filter or
/// regions (after the recognised checks of each region's ranges).
pub(crate) fn cmd_blit_image_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    (src_image, dst_image): (vk::Image, vk::Image),
    regions: &[vk::ImageBlit],
    filter: vk::Filter,
) -> Result<()> {
    let read: Vec<Blit> = regions
        .iter()
        .map(|r| Blit {
            src: r.src_subresource,
            src_offsets: r.src_offsets,
            dst: r.dst_subresource,
            dst_offsets: r.dst_offsets,
        })
        .collect();
    check_blit(recorder, (src_image, dst_image), &read, filter, &BLIT)
}

/// As [`cmd_blit_image_checks`], for `vkCmdBlitImage2`.
pub(crate) fn cmd_blit_image2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    blit_image_info: &BlitImageInfo2<'_>,
) -> Result<()> {
    let raw = blit_image_info.as_raw();
    // SAFETY: the safe setter stored the regions with their count.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    let read: Vec<Blit> = regions
        .iter()
        .map(|r| Blit {
            src: r.src_subresource,
            src_offsets: r.src_offsets,
            dst: r.dst_subresource,
            dst_offsets: r.dst_offsets,
        })
        .collect();
    check_blit(
        recorder,
        (raw.src_image, raw.dst_image),
        &read,
        raw.filter,
        &BLIT2,
    )
}

/// The size of mip level `mip` of an image.
fn level(image: &ImageRecord, mip: u32) -> [i64; 3] {
    let e = image.extent;
    let shrink = |v: u32| i64::from((v >> mip.min(31)).max(1));
    [shrink(e.width), shrink(e.height), shrink(e.depth)]
}

/// A region's box on one side, as `[min, max)` per axis (a blit may mirror, so its
/// two offsets come in either order).
fn boxed(offsets: [vk::Offset3D; 2]) -> [(i64, i64); 3] {
    let [a, b] = offsets;
    let span = |p: i32, q: i32| (i64::from(p.min(q)), i64::from(p.max(q)));
    [span(a.x, b.x), span(a.y, b.y), span(a.z, b.z)]
}

fn check_blit<S: Scope>(
    recorder: &Recorder<'_, S>,
    (src_image, dst_image): (vk::Image, vk::Image),
    regions: &[Blit],
    filter: vk::Filter,
    rules: &BlitRules,
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
    let one = vk::SampleCountFlags::TYPE_1;
    check(rules.src_samples, src.samples == one, || {
        format!("the source has {:?} samples", src.samples)
    })?;
    check(rules.dst_samples, dst.samples == one, || {
        format!("the destination has {:?} samples", dst.samples)
    })?;
    let (sf, df) = (src.format, dst.format);
    check(
        rules.src_ycbcr,
        crate::formats::chroma(sf).is_none(),
        || format!("the source's format {sf:?} needs a sampler Y'CbCr conversion"),
    )?;
    check(
        rules.dst_ycbcr,
        crate::formats::chroma(df).is_none(),
        || format!("the destination's format {df:?} needs a sampler Y'CbCr conversion"),
    )?;
    let (ss, ds) = (
        crate::formats::integer_signed(sf),
        crate::formats::integer_signed(df),
    );
    check(
        rules.signed,
        (ss == Some(true)) == (ds == Some(true)),
        || format!("{sf:?} blitted into {df:?}: one is a signed integer format and the other not"),
    )?;
    check(
        rules.unsigned,
        (ss == Some(false)) == (ds == Some(false)),
        || {
            format!(
                "{sf:?} blitted into {df:?}: one is an unsigned integer format and the other not"
            )
        },
    )?;
    let depth_stencil = |f: vk::Format| {
        crate::formats::aspects(f).is_some_and(|a| {
            a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL)
        })
    };
    check(
        rules.depth_stencil,
        !(depth_stencil(sf) || depth_stencil(df)) || sf == df,
        || format!("{sf:?} blitted into {df:?}: a depth/stencil format blits only into itself"),
    )?;
    check(
        rules.depth_nearest,
        !depth_stencil(sf) || filter == vk::Filter::NEAREST,
        || format!("a depth/stencil source ({sf:?}) blitted with filter {filter:?}, not NEAREST"),
    )?;
    type F = vk::FormatFeatureFlags;
    let (src_features, dst_features) = (
        tiling_features(recorder.device(), &src)?,
        tiling_features(recorder.device(), &dst)?,
    );
    check(rules.src_blit, src_features.contains(F::BLIT_SRC), || {
        format!("the source's features {src_features:?} lack BLIT_SRC")
    })?;
    check(rules.dst_blit, dst_features.contains(F::BLIT_DST), || {
        format!("the destination's features {dst_features:?} lack BLIT_DST")
    })?;
    check(
        rules.linear,
        filter != vk::Filter::LINEAR || src_features.contains(F::SAMPLED_IMAGE_FILTER_LINEAR),
        || {
            format!("filter LINEAR, and the source's features {src_features:?} lack SAMPLED_IMAGE_FILTER_LINEAR")
        },
    )?;
    let any_3d =
        src.image_type == vk::ImageType::TYPE_3D || dst.image_type == vk::ImageType::TYPE_3D;
    for (n, r) in regions.iter().enumerate() {
        let at = format!("pRegions[{n}]");
        check(
            rules.aspects,
            r.src.aspect_mask == r.dst.aspect_mask,
            || {
                format!(
                    "{at} blits aspects {:?} into {:?}",
                    r.src.aspect_mask, r.dst.aspect_mask
                )
            },
        )?;
        check(
            rules.layer_count,
            r.src.layer_count == r.dst.layer_count,
            || {
                format!(
                    "{at} blits {} layers into {}",
                    r.src.layer_count, r.dst.layer_count
                )
            },
        )?;
        for sub in [r.src, r.dst] {
            check(
                rules.layers_3d,
                !any_3d || (sub.base_array_layer == 0 && sub.layer_count == 1),
                || {
                    format!(
                        "{at} names layers {}..+{} with a 3D image",
                        sub.base_array_layer, sub.layer_count
                    )
                },
            )?;
        }
        for (image, offsets, sub, one_d, flat, contained) in [
            (
                &src,
                r.src_offsets,
                r.src,
                rules.src_1d,
                rules.src_flat,
                rules.src_contained,
            ),
            (
                &dst,
                r.dst_offsets,
                r.dst,
                rules.dst_1d,
                rules.dst_flat,
                rules.dst_contained,
            ),
        ] {
            let [a, b] = offsets;
            if image.image_type == vk::ImageType::TYPE_1D {
                check(one_d, a.y == 0 && b.y == 1, || {
                    format!("{at} has offsets y {} and {} in a 1D image", a.y, b.y)
                })?;
            }
            if image.image_type != vk::ImageType::TYPE_3D {
                check(flat, a.z == 0 && b.z == 1, || {
                    format!(
                        "{at} has offsets z {} and {} in a {:?} image",
                        a.z, b.z, image.image_type
                    )
                })?;
            }
            let size = level(image, sub.mip_level);
            let inside = boxed(offsets)
                .iter()
                .zip(size)
                .all(|(&(lo, hi), s)| lo >= 0 && hi <= s);
            check(contained, inside, || {
                format!("{at} reaches past level {} ({size:?})", sub.mip_level)
            })?;
        }
    }
    // Destination texels must not be ones the blit samples: within one image, no
    // destination box meets a source box grown by the texel a filter may read
    // beside it; two images that share memory, wherever their bindings meet.
    if src_image == dst_image {
        let meets = |a: &Blit, b: &Blit| {
            let same_layers = a.src.mip_level == b.dst.mip_level
                && a.src.base_array_layer
                    < b.dst.base_array_layer.saturating_add(b.dst.layer_count)
                && b.dst.base_array_layer
                    < a.src.base_array_layer.saturating_add(a.src.layer_count);
            same_layers
                && boxed(a.src_offsets)
                    .iter()
                    .zip(boxed(b.dst_offsets))
                    .all(|(&(slo, shi), (dlo, dhi))| slo - 1 < dhi && dlo < shi + 1)
        };
        for (i, a) in regions.iter().enumerate() {
            for (j, b) in regions.iter().enumerate() {
                check(rules.overlap, !meets(a, b), || {
                    format!("the destination of pRegions[{j}] meets texels the source of pRegions[{i}] may sample")
                })?;
            }
        }
    } else if let Some(m) = bindings_overlap(live, src_image, dst_image) {
        refuse(rules.overlap, m)?;
    }
    Ok(())
}
