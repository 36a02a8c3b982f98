//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/image_copies.rs`, and a row here calls no other (but the image-layout
//! tracker).
//!
//! Copies between two images: each side's regions against its image, and the two
//! sides against each other.

use super::{call, How, Special, LAYOUT, NONE};

const PAIR: &str = "checks the two images' sample counts, types, formats, aspects and usage, as the device recorded them at their creation, and each region's layer counts and depth against them";
const OVERLAP: &str = "checks, for a copy within one image, that no source region shares a texel (mip level, aspect, layer and box) with a destination region, and, for two images, their bindings as the device recorded them: images bound to overlapping ranges of one memory are refused (where in its binding an optimally tiled region lies is the driver's)";
const ONE_D_DEPTH: &str = "checks the offset's z and the extent's depth of a 1D image";
const UNPROVEN_PROTECTED: &str = "checked by the safe methods in every build (the images' protected flags, recorded at their creation, against the command buffer's pool and protectedNoFault), but no test breaks it: lavapipe has no protectedMemory";
const UNPROVEN_FAMILY: &str = "checked by the safe methods in every build (the pool's queue family's image transfer granularity, recorded at the pool's creation), but no test breaks it: lavapipe's only queue family has a granularity of one texel";
const SAME_AS_Y: &str = "checked by the safe methods in every build: a 1D image is one texel high, so the recognised check of the y range (srcOffset-00145, dstOffset-00151), which comes first, names its own VUID";
const SAME_AS_LAYERS: &str = "checked by the safe methods in every build: a 3D image has one array layer, so the recognised check of the layer range (srcSubresource-01698, dstSubresource-01699), which comes first, names its own VUID";
const UNPROVEN_BLOCKS: &str = "checked by the safe methods in every build (the texel block extent of the image's format, from the registry), but no test breaks it yet: no test copies between images of a compressed format";
const UNPROVEN_FEATURES: &str = "checked by the safe methods in every build (the format features of the image's tiling, asked of the physical device once), but no test breaks it: an image whose format lacks the transfer feature cannot have the transfer usage the copy also needs on lavapipe";
const BOUND: &str = "checks memory was bound to the image, which the device records (the safe methods bind a non-sparse image whole to one memory, and cannot bind a disjoint image)";
const UNPROVEN_PLANES: &str = "checked by the safe methods in every build (the planes of the images' formats and each plane's format, from the registry), but no test breaks it yet: no test copies a multi-planar image";
const UNPROVEN_STENCIL_USAGE: &str = "checked by the safe methods in every build (the stencil usage chained at the image's creation), but no test breaks it yet";

/// The rows of a copy's two versions: `$info` names its rules, `$cmd` its command's.
macro_rules! copy_image {
    ($command:literal, $check:literal, [$($arg:literal),*], $names:literal, $cmd:literal, $info:literal) => {
        Special {
            command: $command,
            check: call("special::image_layouts::image_layout_checks", &["self", $names]),
            check_last: call($check, &[$($arg),*]),
            after: call("special::image_layouts::image_layouts_named", &["self", $names]),
            settles: &[
                (concat!("VUID-", $info, "-srcImageLayout-00128"), How::Dynamic(LAYOUT)),
                (concat!("VUID-", $info, "-dstImageLayout-00133"), How::Dynamic(LAYOUT)),
                (concat!("VUID-", $cmd, "-commandBuffer-01825"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $cmd, "-commandBuffer-01826"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $cmd, "-commandBuffer-01827"), How::User(UNPROVEN_PROTECTED)),
                (concat!("VUID-", $info, "-pRegions-00124"), How::Dynamic(OVERLAP)),
                (concat!("VUID-", $info, "-srcImage-00136"), How::Dynamic(PAIR)),
                (concat!("VUID-", $info, "-srcOffset-01783"), How::User(UNPROVEN_FAMILY)),
                (concat!("VUID-", $info, "-dstOffset-01784"), How::User(UNPROVEN_FAMILY)),
                (concat!("VUID-", $info, "-srcImage-00146"), How::User(SAME_AS_Y)),
                (concat!("VUID-", $info, "-dstImage-00152"), How::User(SAME_AS_Y)),
                (concat!("VUID-", $info, "-srcImage-01785"), How::Dynamic(ONE_D_DEPTH)),
                (concat!("VUID-", $info, "-dstImage-01786"), How::Dynamic(ONE_D_DEPTH)),
                (concat!("VUID-", $info, "-pRegions-07278"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-pRegions-07279"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-pRegions-07280"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-pRegions-07281"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-pRegions-07282"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-pRegions-07283"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-srcImage-01728"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-srcImage-01729"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-srcImage-01730"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-dstImage-01732"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-dstImage-01733"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-dstImage-01734"), How::User(UNPROVEN_BLOCKS)),
                (concat!("VUID-", $info, "-srcImage-01995"), How::User(UNPROVEN_FEATURES)),
                (concat!("VUID-", $info, "-dstImage-01996"), How::User(UNPROVEN_FEATURES)),
                (concat!("VUID-", $info, "-srcImage-04443"), How::User(SAME_AS_LAYERS)),
                (concat!("VUID-", $info, "-dstImage-04444"), How::User(SAME_AS_LAYERS)),
                (concat!("VUID-", $info, "-srcImage-07743"), How::Dynamic(PAIR)),
                (concat!("VUID-", $info, "-srcImage-07744"), How::Dynamic(PAIR)),
                (concat!("VUID-", $info, "-srcImage-01790"), How::Dynamic(PAIR)),
                (concat!("VUID-", $info, "-srcImage-01546"), How::Dynamic(BOUND)),
                (concat!("VUID-", $info, "-dstImage-01547"), How::Dynamic(BOUND)),
                (concat!("VUID-", $info, "-srcImage-01548"), How::Dynamic(PAIR)),
                (concat!("VUID-", $info, "-None-01549"), How::User(UNPROVEN_PLANES)),
                (concat!("VUID-", $info, "-srcImage-01551"), How::Dynamic(PAIR)),
                (concat!("VUID-", $info, "-srcImage-01552"), How::User(UNPROVEN_PLANES)),
                (concat!("VUID-", $info, "-srcImage-01553"), How::User(UNPROVEN_PLANES)),
                (concat!("VUID-", $info, "-dstImage-01554"), How::User(UNPROVEN_PLANES)),
                (concat!("VUID-", $info, "-dstImage-01555"), How::User(UNPROVEN_PLANES)),
                (concat!("VUID-", $info, "-srcImage-01556"), How::User(UNPROVEN_PLANES)),
                (concat!("VUID-", $info, "-dstImage-01557"), How::User(UNPROVEN_PLANES)),
                (concat!("VUID-", $info, "-aspect-06662"), How::Dynamic(PAIR)),
                (concat!("VUID-", $info, "-aspect-06663"), How::Dynamic(PAIR)),
                (concat!("VUID-", $info, "-aspect-06664"), How::User(UNPROVEN_STENCIL_USAGE)),
                (concat!("VUID-", $info, "-aspect-06665"), How::User(UNPROVEN_STENCIL_USAGE)),
            ],
            ..NONE
        }
    };
}

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    copy_image!(
        "vkCmdCopyImage",
        "special::image_copies::cmd_copy_image_checks",
        ["self", "(src_image.raw(), dst_image.raw())", "regions"],
        "crate::special::image_layouts::Names::CopyImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)",
        "vkCmdCopyImage",
        "vkCmdCopyImage"
    ),
    copy_image!(
        "vkCmdCopyImage2",
        "special::image_copies::cmd_copy_image2_checks",
        ["self", "copy_image_info"],
        "crate::special::image_layouts::Names::CopyImage2(copy_image_info)",
        "vkCmdCopyImage2",
        "VkCopyImageInfo2"
    ),
];
