//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/copies.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Transfer commands: buffer and image copies, fills and updates, each region against
//! the resources it names, their usage, formats and protection.

use super::{call, How, Special, BUFFER_USE, LAYOUT, NONE, RANGE};

const COPY_REGION: &str = "checks each region against the image's type, format and texel blocks and the subresource it names, as the device recorded them at the image's creation";
const COPY_ROW_PITCH: &str = "checks each region's row length in bytes against 2^31-1 (the 1.3.239 layer does not check it: the error alone proves it)";
const COPY_OVERLAP: &str = "checks each region's bytes of the buffer against the whole binding of the image when both are bound to one memory, as the device recorded their bindings (the 1.3.239 layer does not check it: the error alone proves it)";
const COPY_SAME_AS_SIZE: &str = "checked by the safe methods in every build, by the check of the texel block size (pRegions-07273), whose condition it is for these formats and whose VUID the error names";
const COPY_SAME_AS_RANGES: &str = "checked by the safe methods in every build: the checks of the x, y and z ranges, which together are this rule and come first, name their own VUIDs";
const COPY_SAME_AS_Y: &str = "checked by the safe methods in every build: a 1D image is one texel high, so the check of the y range, which comes first, names its own VUID";
const COPY_SAME_AS_Z: &str = "checked by the safe methods in every build: the image is one texel deep, so the check of the z range, which comes first, names its own VUID";
const COPY_SAME_AS_LAYERS: &str = "checked by the safe methods in every build: a 3D image has one array layer, so the check of the layer range, which comes first, names its own VUID";
const COPY_BLOCK_DEPTH: &str = "checked by the safe methods in every build, but no test breaks it: no format of the emitted API has a texel block deeper than one texel";
const COPY_PLANES: &str = "checked by the safe methods in every build, but no test breaks it: no test copies a multi-planar image yet";
const COPY_FEATURES: &str = "checked by the safe methods in every build, but no test breaks it: an image whose format lacks the transfer feature cannot have the transfer usage the copy also needs";
const COPY_FAMILY: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe's only queue family has graphics and compute and an image transfer granularity of one texel";
const COPY_PROTECTED: &str = "checked by the safe methods in every build (the pool's protected flag and the resources' create flags, recorded at their creation, against the device's protectedNoFault), but no test breaks it: lavapipe has no protected memory";
const COPY_BUFFER_OVERLAP: &str =
    "checks, when both buffers are one, that no source range overlaps a destination range";
const COPY_DEPTH_VALUES: &str = "refuses every region into the depth aspect of a floating-point depth format (D32_SFLOAT, D32_SFLOAT_S8_UINT), whose values come from the buffer's contents, which tuff cannot see; a unorm depth format holds [0,1] by its encoding (the 1.3.239 layer does not check it: proven by the error alone)";
const CLEAR_IMAGE: &str = "checks the image's format, aspects, levels, layers and usage, recorded at its creation, and the layout named, against each range";
const CLEAR_FEATURES: &str = "checked by the safe methods in every build (the format features of the image's tiling, asked of the physical device once), but no test breaks it: a format without TRANSFER_DST cannot have the transfer usage the clear also needs on lavapipe";
const CLEAR_YCBCR: &str = "checked by the safe methods in every build (the format's chroma subsampling, from the registry), but no test breaks it: lavapipe's formats that need a conversion lack TRANSFER_DST, which is refused first";
const CLEAR_STENCIL_USAGE: &str = "checked by the safe methods in every build (the stencil usage chained at the image's creation), but no test breaks it yet";
const CLEAR_VALUE: &str = "the value is a reference to the union, 16 bytes that every bit pattern fills with a value of each of its members";
const COPY_RANGE: &str = "checks each region against the buffers' sizes, kept from their creation";
const BUFFER_IMAGE_RANGE: &str = "checks each region's bytes, by Buffer and Image Addressing over the image's recorded format (the texel block of the region's aspect, from the registry's formats), lie inside the buffer's recorded size";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCmdFillBuffer",
        check: call(
            "special::copies::cmd_fill_buffer_checks",
            &["self", "dst_buffer", "dst_offset", "size"],
        ),
        settles: &[
            ("VUID-vkCmdFillBuffer-dstOffset-00024", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-dstOffset-00025", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-size-00026", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-size-00027", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-size-00028", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-dstBuffer-00029", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdFillBuffer-dstBuffer-00031", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdFillBuffer-commandBuffer-01811", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdFillBuffer-commandBuffer-01812", How::User(COPY_PROTECTED)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdUpdateBuffer",
        check: call(
            "special::copies::cmd_update_buffer_checks",
            &["self", "dst_buffer", "dst_offset", "data"],
        ),
        settles: &[
            ("VUID-vkCmdUpdateBuffer-dstOffset-00032", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-dataSize-00033", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-dstBuffer-00034", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdUpdateBuffer-dstBuffer-00035", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdUpdateBuffer-dstOffset-00036", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-dataSize-00037", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-dataSize-00038", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-commandBuffer-01813", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdUpdateBuffer-commandBuffer-01814", How::User(COPY_PROTECTED)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdCopyBufferToImage",
        check: call("special::image_layouts::image_layout_checks", &["self", "crate::special::image_layouts::Names::BufferToImage(dst_image.raw(), dst_image_layout, regions)"]),
        after: call("special::image_layouts::image_layouts_named", &["self", "crate::special::image_layouts::Names::BufferToImage(dst_image.raw(), dst_image_layout, regions)"]),
        check_last: call(
            "special::copies::cmd_copy_buffer_to_image_checks",
            &["self", "src_buffer", "dst_image", "regions"],
        ),
        settles: &[
            ("VUID-vkCmdCopyBufferToImage-bufferRowLength-00203", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-bufferImageHeight-00204", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07274", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07275", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-imageExtent-00207", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-imageExtent-00208", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07273", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-srcImage-04053", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07277", How::Dynamic(COPY_ROW_PITCH)),
            ("VUID-vkCmdCopyBufferToImage-None-00214", How::Dynamic(COPY_DEPTH_VALUES)),
            ("VUID-vkCmdCopyBufferToImage-dstImage-00179", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-00173", How::Dynamic(COPY_OVERLAP)),
            ("VUID-vkCmdCopyBufferToImage-srcImage-00201", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-imageOffset-00200", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-aspectMask-00211", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-srcImage-00199", How::User(COPY_SAME_AS_Y)),
            ("VUID-vkCmdCopyBufferToImage-baseArrayLayer-00213", How::User(COPY_SAME_AS_LAYERS)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-06217", How::User(COPY_SAME_AS_RANGES)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07276", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-vkCmdCopyBufferToImage-imageExtent-00209", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07740", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07741", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyBufferToImage-bufferOffset-01559", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyBufferToImage-bufferOffset-01558", How::User(COPY_SAME_AS_SIZE)),
            ("VUID-vkCmdCopyBufferToImage-dstImage-01997", How::User(COPY_FEATURES)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-07737", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage-imageOffset-07738", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-07739", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-01828", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-01829", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-01830", How::User(COPY_PROTECTED)),
            ("VUID-VkBufferImageCopy-bufferRowLength-00195", How::Dynamic(COPY_REGION)),
            ("VUID-VkBufferImageCopy-bufferImageHeight-00196", How::Dynamic(COPY_REGION)),
            ("VUID-VkBufferImageCopy-aspectMask-00212", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-dstImageLayout-00180", How::Dynamic(LAYOUT)),(
            "VUID-vkCmdCopyBufferToImage-pRegions-00171",
            How::Dynamic(BUFFER_IMAGE_RANGE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdCopyImageToBuffer",
        check: call("special::image_layouts::image_layout_checks", &["self", "crate::special::image_layouts::Names::ImageToBuffer(src_image.raw(), src_image_layout, regions)"]),
        after: call("special::image_layouts::image_layouts_named", &["self", "crate::special::image_layouts::Names::ImageToBuffer(src_image.raw(), src_image_layout, regions)"]),
        check_last: call(
            "special::copies::cmd_copy_image_to_buffer_checks",
            &["self", "src_image", "dst_buffer", "regions"],
        ),
        settles: &[
            ("VUID-vkCmdCopyImageToBuffer-bufferRowLength-00203", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-bufferImageHeight-00204", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07274", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07275", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-imageExtent-00207", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-imageExtent-00208", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07273", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-04053", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07277", How::Dynamic(COPY_ROW_PITCH)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-00188", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-00184", How::Dynamic(COPY_OVERLAP)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-00201", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-imageOffset-00200", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-aspectMask-00211", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-00199", How::User(COPY_SAME_AS_Y)),
            ("VUID-vkCmdCopyImageToBuffer-baseArrayLayer-00213", How::User(COPY_SAME_AS_LAYERS)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-06220", How::User(COPY_SAME_AS_RANGES)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07276", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-vkCmdCopyImageToBuffer-imageExtent-00209", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07740", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07741", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyImageToBuffer-bufferOffset-01559", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyImageToBuffer-bufferOffset-01558", How::User(COPY_SAME_AS_SIZE)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-01998", How::User(COPY_FEATURES)),
            ("VUID-vkCmdCopyImageToBuffer-commandBuffer-07746", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyImageToBuffer-imageOffset-07747", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyImageToBuffer-commandBuffer-01831", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyImageToBuffer-commandBuffer-01832", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyImageToBuffer-commandBuffer-01833", How::User(COPY_PROTECTED)),
            ("VUID-VkImageSubresourceLayers-aspectMask-00167", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-srcImageLayout-00189", How::Dynamic(LAYOUT)),(
            "VUID-vkCmdCopyImageToBuffer-pRegions-00183",
            How::Dynamic(BUFFER_IMAGE_RANGE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdCopyBufferToImage2",
        check: call("special::image_layouts::image_layout_checks", &["self", "crate::special::image_layouts::Names::BufferToImage2(copy_buffer_to_image_info)"]),
        after: call("special::image_layouts::image_layouts_named", &["self", "crate::special::image_layouts::Names::BufferToImage2(copy_buffer_to_image_info)"]),
        check_last: call(
            "special::copies::cmd_copy_buffer_to_image2_checks",
            &["self", "copy_buffer_to_image_info"],
        ),
        settles: &[
            ("VUID-VkCopyBufferToImageInfo2-bufferRowLength-00203", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-bufferImageHeight-00204", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07274", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07275", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-imageExtent-00207", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-imageExtent-00208", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07273", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-srcImage-04053", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07277", How::Dynamic(COPY_ROW_PITCH)),
            ("VUID-VkCopyBufferToImageInfo2-None-00214", How::Dynamic(COPY_DEPTH_VALUES)),
            ("VUID-VkCopyBufferToImageInfo2-dstImage-00179", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-00173", How::Dynamic(COPY_OVERLAP)),
            ("VUID-VkCopyBufferToImageInfo2-srcImage-00199", How::User(COPY_SAME_AS_Y)),
            ("VUID-VkCopyBufferToImageInfo2-srcImage-00201", How::User(COPY_SAME_AS_Z)),
            ("VUID-VkCopyBufferToImageInfo2-baseArrayLayer-00213", How::User(COPY_SAME_AS_LAYERS)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-00172", How::User(COPY_SAME_AS_RANGES)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07276", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-VkCopyBufferToImageInfo2-imageExtent-00209", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07740", How::User(COPY_PLANES)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07741", How::User(COPY_PLANES)),
            ("VUID-VkCopyBufferToImageInfo2-bufferOffset-01559", How::User(COPY_PLANES)),
            ("VUID-VkCopyBufferToImageInfo2-bufferOffset-01558", How::User(COPY_SAME_AS_SIZE)),
            ("VUID-VkCopyBufferToImageInfo2-dstImage-01997", How::User(COPY_FEATURES)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-07737", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage2-imageOffset-07738", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-07739", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-01828", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-01829", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-01830", How::User(COPY_PROTECTED)),
            ("VUID-VkBufferImageCopy2-bufferRowLength-00195", How::Dynamic(COPY_REGION)),
            ("VUID-VkBufferImageCopy2-bufferImageHeight-00196", How::Dynamic(COPY_REGION)),
            ("VUID-VkBufferImageCopy2-aspectMask-00212", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-dstImageLayout-00180", How::Dynamic(LAYOUT)),(
            "VUID-VkCopyBufferToImageInfo2-pRegions-00171",
            How::Dynamic(BUFFER_IMAGE_RANGE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdCopyImageToBuffer2",
        check: call("special::image_layouts::image_layout_checks", &["self", "crate::special::image_layouts::Names::ImageToBuffer2(copy_image_to_buffer_info)"]),
        after: call("special::image_layouts::image_layouts_named", &["self", "crate::special::image_layouts::Names::ImageToBuffer2(copy_image_to_buffer_info)"]),
        check_last: call(
            "special::copies::cmd_copy_image_to_buffer2_checks",
            &["self", "copy_image_to_buffer_info"],
        ),
        settles: &[
            ("VUID-VkCopyImageToBufferInfo2-bufferRowLength-00203", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-bufferImageHeight-00204", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07274", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07275", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-imageExtent-00207", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-imageExtent-00208", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07273", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-04053", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07277", How::Dynamic(COPY_ROW_PITCH)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-00188", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-00184", How::Dynamic(COPY_OVERLAP)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-00199", How::User(COPY_SAME_AS_Y)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-00201", How::User(COPY_SAME_AS_Z)),
            ("VUID-VkCopyImageToBufferInfo2-baseArrayLayer-00213", How::User(COPY_SAME_AS_LAYERS)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-00182", How::User(COPY_SAME_AS_RANGES)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07276", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-VkCopyImageToBufferInfo2-imageExtent-00209", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07740", How::User(COPY_PLANES)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07741", How::User(COPY_PLANES)),
            ("VUID-VkCopyImageToBufferInfo2-bufferOffset-01559", How::User(COPY_PLANES)),
            ("VUID-VkCopyImageToBufferInfo2-bufferOffset-01558", How::User(COPY_SAME_AS_SIZE)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-01998", How::User(COPY_FEATURES)),
            ("VUID-vkCmdCopyImageToBuffer2-commandBuffer-07746", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyImageToBuffer2-imageOffset-07747", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyImageToBuffer2-commandBuffer-01831", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyImageToBuffer2-commandBuffer-01832", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyImageToBuffer2-commandBuffer-01833", How::User(COPY_PROTECTED)),
            ("VUID-VkCopyImageToBufferInfo2-srcImageLayout-00189", How::Dynamic(LAYOUT)),(
            "VUID-VkCopyImageToBufferInfo2-pRegions-00183",
            How::Dynamic(BUFFER_IMAGE_RANGE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdCopyBuffer",
        check: call(
            "special::copies::cmd_copy_buffer_checks",
            &["self", "src_buffer", "dst_buffer", "regions"],
        ),
        settles: &[
            ("VUID-vkCmdCopyBuffer-srcOffset-00113", How::Dynamic(COPY_RANGE)),
            ("VUID-vkCmdCopyBuffer-dstOffset-00114", How::Dynamic(COPY_RANGE)),
            ("VUID-vkCmdCopyBuffer-size-00115", How::Dynamic(COPY_RANGE)),
            ("VUID-vkCmdCopyBuffer-size-00116", How::Dynamic(COPY_RANGE)),
            ("VUID-VkBufferCopy-size-01988", How::Dynamic(COPY_RANGE)),
            (
                "VUID-vkCmdCopyBuffer-pRegions-00117",
                How::Dynamic(COPY_BUFFER_OVERLAP),
            ),
            ("VUID-vkCmdCopyBuffer-srcBuffer-00118", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdCopyBuffer-srcBuffer-00119", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdCopyBuffer-dstBuffer-00120", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdCopyBuffer-dstBuffer-00121", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdCopyBuffer-commandBuffer-01822", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBuffer-commandBuffer-01823", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBuffer-commandBuffer-01824", How::User(COPY_PROTECTED)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdClearColorImage",
        check: call("special::image_layouts::image_layout_checks", &["self", "crate::special::image_layouts::Names::ClearColor(image.raw(), image_layout, ranges)"]),
        check_last: call(
            "special::copies::cmd_clear_color_image_checks",
            &["self", "image", "ranges"],
        ),
        after: call("special::image_layouts::image_layouts_named", &["self", "crate::special::image_layouts::Names::ClearColor(image.raw(), image_layout, ranges)"]),
        settles: &[
            ("VUID-vkCmdClearColorImage-imageLayout-00004", How::Dynamic(LAYOUT)),
            ("VUID-vkCmdClearColorImage-image-01993", How::User(CLEAR_FEATURES)),
            ("VUID-vkCmdClearColorImage-image-00007", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearColorImage-image-01545", How::User(CLEAR_YCBCR)),
            ("VUID-vkCmdClearColorImage-aspectMask-02498", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearColorImage-baseMipLevel-01470", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearColorImage-baseArrayLayer-01472", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearColorImage-pColor-04961", How::Static(CLEAR_VALUE)),
            ("VUID-vkCmdClearColorImage-commandBuffer-01805", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdClearColorImage-commandBuffer-01806", How::User(COPY_PROTECTED)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdClearDepthStencilImage",
        check: call("special::image_layouts::image_layout_checks", &["self", "crate::special::image_layouts::Names::ClearDepthStencil(image.raw(), image_layout, ranges)"]),
        check_last: call(
            "special::copies::cmd_clear_depth_stencil_image_checks",
            &["self", "image", "image_layout", "ranges"],
        ),
        after: call("special::image_layouts::image_layouts_named", &["self", "crate::special::image_layouts::Names::ClearDepthStencil(image.raw(), image_layout, ranges)"]),
        settles: &[
            ("VUID-vkCmdClearDepthStencilImage-imageLayout-00011", How::Dynamic(LAYOUT)),
            ("VUID-vkCmdClearDepthStencilImage-imageLayout-00012", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-image-01994", How::User(CLEAR_FEATURES)),
            ("VUID-vkCmdClearDepthStencilImage-image-00014", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-aspectMask-02824", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-image-02825", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-image-02826", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-pRanges-02658", How::User(CLEAR_STENCIL_USAGE)),
            ("VUID-vkCmdClearDepthStencilImage-pRanges-02659", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-pRanges-02660", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-baseMipLevel-01474", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-baseArrayLayer-01476", How::Dynamic(CLEAR_IMAGE)),
            ("VUID-vkCmdClearDepthStencilImage-commandBuffer-01807", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdClearDepthStencilImage-commandBuffer-01808", How::User(COPY_PROTECTED)),
        ],
        ..NONE
    },
    // The recognised checks of the info's ranges and usages run first; the row adds
    // the rules no recogniser reads, by the same function as `vkCmdCopyBuffer`.
    Special {
        command: "vkCmdCopyBuffer2",
        check_last: call(
            "special::copies::cmd_copy_buffer2_checks",
            &["self", "copy_buffer_info"],
        ),
        settles: &[
            ("VUID-VkBufferCopy2-size-01988", How::Dynamic(COPY_RANGE)),
            ("VUID-VkCopyBufferInfo2-pRegions-00117", How::Dynamic(COPY_BUFFER_OVERLAP)),
            ("VUID-vkCmdCopyBuffer2-commandBuffer-01822", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBuffer2-commandBuffer-01823", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBuffer2-commandBuffer-01824", How::User(COPY_PROTECTED)),
        ],
        ..NONE
    },
];
