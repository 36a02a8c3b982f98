//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/blits.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Blits: both images, the filter, and each region.

use super::{call, How, Special, LAYOUT, NONE};

const BLIT: &str = "checks both images' sample counts and formats, as the device recorded them at their creation, the filter against the source's format and its features, and each region's aspects, layers and offsets against the images' types";
const OVERLAP: &str = "checks, for a blit within one image, that no destination box meets a source box grown by the texel a filter may read beside it (mip level, layers and box), and, for two images, their bindings as the device recorded them: images bound to overlapping ranges of one memory are refused (the 1.3.239 layer does not check it: the error alone proves it)";
const SAME_AS_RANGES: &str = "checked by the safe methods in every build: the recognised checks of the offsets' x, y and z ranges (srcOffset-00243 to dstOffset-00251), which together are this rule and come first, name their own VUIDs";
const UNPROVEN_PROTECTED: &str = "checked by the safe methods in every build (the images' protected flags, recorded at their creation, against the command buffer's pool and protectedNoFault), but no test breaks it: lavapipe has no protectedMemory";
const UNPROVEN_FEATURES: &str = "checked by the safe methods in every build (the format features of the image's tiling, asked of the physical device once), but no test breaks it yet: every format lavapipe makes a transfer image of blits";
const UNPROVEN_YCBCR: &str = "checked by the safe methods in every build (the format's chroma subsampling, from the registry), but no test breaks it: lavapipe's formats that need a conversion lack BLIT_SRC and BLIT_DST";

/// The rows of a blit's two versions: `$info` names its rules, `$cmd` its
/// command's, `$region` its region struct's.
macro_rules! blit {
    ($command:literal, $check:literal, [$($arg:literal),*], $names:literal, $cmd:literal, $info:literal, $region:literal) => {
        Special {
            command: $command,
            check: call("special::image_layouts::image_layout_checks", &["self", $names]),
            check_last: call($check, &[$($arg),*]),
            after: call("special::image_layouts::image_layouts_named", &["self", $names]),
            settles: &[
                (concat!("VUID-", $info, "-srcImageLayout-00221"), How::Dynamic(LAYOUT)),
                (concat!("VUID-", $info, "-dstImageLayout-00226"), How::Dynamic(LAYOUT)),
                (concat!("VUID-", $cmd, "-commandBuffer-01834"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $cmd, "-commandBuffer-01835"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $cmd, "-commandBuffer-01836"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $info, "-pRegions-00215"), How::User(SAME_AS_RANGES)),
                (concat!("VUID-", $info, "-pRegions-00216"), How::User(SAME_AS_RANGES)),
                (concat!("VUID-", $info, "-pRegions-00217"), How::Dynamic(OVERLAP)),
                (concat!("VUID-", $info, "-srcImage-01999"), How::User(UNPROVEN_FEATURES)),
                (concat!("VUID-", $info, "-dstImage-02000"), How::User(UNPROVEN_FEATURES)),
                (concat!("VUID-", $info, "-srcImage-00229"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-srcImage-00230"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-srcImage-00231"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-srcImage-00232"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-srcImage-00233"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-dstImage-00234"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-filter-02001"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-srcImage-00240"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-srcImage-00245"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-srcImage-00247"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-dstImage-00250"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-dstImage-00252"), How::Dynamic(BLIT)),
                (concat!("VUID-", $info, "-srcImage-06421"), How::User(UNPROVEN_YCBCR)),
                (concat!("VUID-", $info, "-dstImage-06422"), How::User(UNPROVEN_YCBCR)),
                (concat!("VUID-", $region, "-aspectMask-00238"), How::Dynamic(BLIT)),
                (concat!("VUID-", $region, "-layerCount-00239"), How::Dynamic(BLIT)),
            ],
            ..NONE
        }
    };
}

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    blit!(
        "vkCmdBlitImage",
        "special::blits::cmd_blit_image_checks",
        ["self", "(src_image.raw(), dst_image.raw())", "regions", "filter"],
        "crate::special::image_layouts::Names::BlitImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)",
        "vkCmdBlitImage",
        "vkCmdBlitImage",
        "VkImageBlit"
    ),
    blit!(
        "vkCmdBlitImage2",
        "special::blits::cmd_blit_image2_checks",
        ["self", "blit_image_info"],
        "crate::special::image_layouts::Names::BlitImage2(blit_image_info)",
        "vkCmdBlitImage2",
        "VkBlitImageInfo2",
        "VkImageBlit2"
    ),
];
