//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/resolves.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Resolves of a multisampled image outside a render pass: both images' sample
//! counts, formats, features, types, protection and memory, and each region.

use super::{call, How, Special, LAYOUT, NONE};

const RESOLVE: &str = "checks both images' sample counts, formats, format features for their tiling and types, as the device recorded them at their creation, and each region's subresources against them";
const RESOLVE_OVERLAP: &str = "checks the two images' bindings, as the device recorded them: images bound to overlapping ranges of one memory are refused (where in its binding an optimally tiled region lies is the driver's), whatever the regions (the 1.3.239 layer does not check it: the error alone proves it)";
const UNPROVEN_PROTECTED: &str = "checked by the safe methods in every build (the images' protected flags, recorded at their creation, against the command buffer's pool and protectedNoFault), but no test breaks it: lavapipe has no protectedMemory";
const RESOLVE_FLAT: &str = "checks the offset's z and the extent's depth of a 1D or 2D image, whose levels are one deep, so that the recognised range rules of the region (srcOffset-00272, dstOffset-00277) refuse any other before this check runs (the oracle breaks those)";
const UNPROVEN_RESOLVE_FEATURES: &str = "checked by the safe methods in every build (the format features the physical device reports for each image's format and tiling), but no test breaks it: every format lavapipe multisamples is a colour attachment and a transfer source and destination in both tilings";
const UNPROVEN_RESOLVE_TYPES: &str = "checked by the safe methods in every build (the images' types, recorded at their creation), but no test breaks it: lavapipe makes no multisampled 1D or 3D image, which a resolve's source must be";

/// The rows of a resolve's two versions: `$v1` names its rules, `$v2` its struct's.
macro_rules! resolve {
    ($command:literal, $check:literal, [$($arg:literal),*], $names:literal, $cmd:literal, $info:literal, $region:literal) => {
        Special {
            command: $command,
            check: call("special::image_layouts::image_layout_checks", &["self", $names]),
            check_last: call($check, &[$($arg),*]),
            after: call("special::image_layouts::image_layouts_named", &["self", $names]),
            settles: &[
                (concat!("VUID-", $info, "-srcImageLayout-00260"), How::Dynamic(LAYOUT)),
                (concat!("VUID-", $info, "-dstImageLayout-00262"), How::Dynamic(LAYOUT)),
                (concat!("VUID-", $cmd, "-commandBuffer-01837"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $cmd, "-commandBuffer-01838"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $cmd, "-commandBuffer-01839"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $info, "-pRegions-00255"), How::Dynamic(RESOLVE_OVERLAP)),
                (concat!("VUID-", $info, "-srcImage-00257"), How::Dynamic(RESOLVE)),
                (concat!("VUID-", $info, "-dstImage-00259"), How::Dynamic(RESOLVE)),
                (concat!("VUID-", $info, "-dstImage-02003"), How::User(UNPROVEN_RESOLVE_FEATURES)),
                (concat!("VUID-", $info, "-srcImage-01386"), How::Dynamic(RESOLVE)),
                (concat!("VUID-", $info, "-srcImage-04446"), How::User(UNPROVEN_RESOLVE_TYPES)),
                (concat!("VUID-", $info, "-srcImage-04447"), How::User(UNPROVEN_RESOLVE_TYPES)),
                (concat!("VUID-", $info, "-srcImage-00271"), How::User(UNPROVEN_RESOLVE_TYPES)),
                (concat!("VUID-", $info, "-srcImage-00273"), How::Dynamic(RESOLVE_FLAT)),
                (concat!("VUID-", $info, "-dstImage-00276"), How::User(UNPROVEN_RESOLVE_TYPES)),
                (concat!("VUID-", $info, "-dstImage-00278"), How::Dynamic(RESOLVE_FLAT)),
                (concat!("VUID-", $info, "-srcImage-06763"), How::User(UNPROVEN_RESOLVE_FEATURES)),
                (concat!("VUID-", $info, "-dstImage-06765"), How::User(UNPROVEN_RESOLVE_FEATURES)),
                (concat!("VUID-", $region, "-aspectMask-00266"), How::Dynamic(RESOLVE)),
                (concat!("VUID-", $region, "-layerCount-00267"), How::Dynamic(RESOLVE)),
            ],
            ..NONE
        }
    };
}

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    resolve!(
        "vkCmdResolveImage",
        "special::resolves::cmd_resolve_image_checks",
        ["self", "(src_image.raw(), dst_image.raw())", "regions"],
        "crate::special::image_layouts::Names::ResolveImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)",
        "vkCmdResolveImage",
        "vkCmdResolveImage",
        "VkImageResolve"
    ),
    resolve!(
        "vkCmdResolveImage2",
        "special::resolves::cmd_resolve_image2_checks",
        ["self", "resolve_image_info"],
        "crate::special::image_layouts::Names::ResolveImage2(resolve_image_info)",
        "vkCmdResolveImage2",
        "VkResolveImageInfo2",
        "VkImageResolve2"
    ),
];
