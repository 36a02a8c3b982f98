//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/image_layouts.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! The image layouts recorded commands name, checked against those the recording
//! and the device's submissions leave.

use super::{call, How, Special, LAYOUT, NONE};

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCmdBlitImage",
        check: call("special::image_layouts::image_layout_checks", &["self", "crate::special::image_layouts::Names::BlitImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)"]),
        after: call("special::image_layouts::image_layouts_named", &["self", "crate::special::image_layouts::Names::BlitImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)"]),
        settles: &[
            ("VUID-vkCmdBlitImage-srcImageLayout-00221", How::Dynamic(LAYOUT)),
            ("VUID-vkCmdBlitImage-dstImageLayout-00226", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBlitImage2",
        check: call("special::image_layouts::image_layout_checks", &["self", "crate::special::image_layouts::Names::BlitImage2(blit_image_info)"]),
        after: call("special::image_layouts::image_layouts_named", &["self", "crate::special::image_layouts::Names::BlitImage2(blit_image_info)"]),
        settles: &[
            ("VUID-VkBlitImageInfo2-srcImageLayout-00221", How::Dynamic(LAYOUT)),
            ("VUID-VkBlitImageInfo2-dstImageLayout-00226", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
];
