//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/rendering.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Dynamic rendering: `vkCmdBeginRendering`'s attachments, each read into one slot
//! whose rules are written once, and its render area.

use super::{call, How, Special, NONE};

const NO_SUSPENSION: &str = "checked by the safe methods in every build: the safe `begin_rendering` refuses the SUSPENDING and RESUMING flags (tuff does not follow suspended render pass instances across commands and command buffers yet), so no recording made through the safe methods holds a suspended or resumed instance";
const ATTACHMENT: &str = "checks each attachment's layouts, resolve mode and resolve view against its view, the view's image and format, as the device recorded them";
const SLOTS: &str = "checks each attachment against its slot (color, depth, stencil: the view's usage and aspects, the layouts the slot may not be in, the device's resolve modes), the views' sample counts, the depth and stencil slots against each other, the color attachment count and the view mask against the device's limits, and the command buffer's level";
const AREA: &str = "checks the render area (or each device's, from a chained VkDeviceGroupRenderPassBeginInfo) against the size of every attachment's view at its base level, and against maxFramebufferWidth and maxFramebufferHeight";
const SLOTS_ALONE: &str = "checks each depth or stencil attachment's layouts against the aspect its slot renders (the 1.3.239 layer does not check it: the error alone proves it)";
const AREA_ALONE: &str = "checks the render area's end against maxFramebufferWidth and maxFramebufferHeight (the 1.3.239 layer does not check it: the error alone proves it)";
const UNPROVEN_DEPTH_MODES: &str = "checked by the safe methods in every build (against VkPhysicalDeviceDepthStencilResolveProperties::supportedDepthResolveModes), but no test breaks it: lavapipe resolves depth by every mode";
const UNPROVEN_INDEPENDENT: &str = "checked by the safe methods in every build (against VkPhysicalDeviceDepthStencilResolveProperties), but no test breaks it: lavapipe resolves depth and stencil independently";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[Special {
    command: "vkCmdBeginRendering",
    check: call(
        "special::rendering::begin_rendering_checks",
        &["&self", "rendering_info"],
    ),
    check_last: call(
        "special::rendering::rendering_attachment_checks",
        &["&self", "rendering_info"],
    ),
    after: call(
        "special::rendering::rendering_begun",
        &["&mut self", "rendering_info"],
    ),
    settles: &[
        (
            "VUID-vkCmdBeginRendering-commandBuffer-06068",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06129",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06130",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06864",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06865",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06135",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06136",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06132",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06860",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06137",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06142",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06145",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06146",
            How::Dynamic(ATTACHMENT),
        ),
        (
            "VUID-VkRenderingInfo-multisampledRenderToSingleSampled-06857",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06087",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06547",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06088",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06548",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06089",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06090",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06091",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06092",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06093",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06094",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06095",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06102",
            How::User(UNPROVEN_DEPTH_MODES),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06103",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06104",
            How::User(UNPROVEN_INDEPENDENT),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06105",
            How::User(UNPROVEN_INDEPENDENT),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06106",
            How::Dynamic(SLOTS),
        ),
        ("VUID-VkRenderingInfo-pNext-06077", How::Dynamic(AREA)),
        ("VUID-VkRenderingInfo-pNext-06078", How::Dynamic(AREA)),
        ("VUID-VkRenderingInfo-pNext-07815", How::Dynamic(AREA_ALONE)),
        ("VUID-VkRenderingInfo-pNext-07816", How::Dynamic(AREA_ALONE)),
        ("VUID-VkRenderingInfo-pNext-06079", How::Dynamic(AREA)),
        ("VUID-VkRenderingInfo-pNext-06080", How::Dynamic(AREA)),
        ("VUID-VkRenderingInfo-pNext-06083", How::Dynamic(AREA)),
        ("VUID-VkRenderingInfo-pNext-06084", How::Dynamic(AREA)),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06085",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06086",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06096",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06097",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06098",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06099",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06100",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06101",
            How::Dynamic(SLOTS),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-07732",
            How::Dynamic(SLOTS_ALONE),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-07733",
            How::Dynamic(SLOTS_ALONE),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-07734",
            How::Dynamic(SLOTS_ALONE),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-07735",
            How::Dynamic(SLOTS_ALONE),
        ),
        ("VUID-VkRenderingInfo-viewMask-06128", How::Dynamic(SLOTS)),
        (
            "VUID-VkSubmitInfo-pCommandBuffers-06193",
            How::User(NO_SUSPENSION),
        ),
        (
            "VUID-VkSubmitInfo-pCommandBuffers-06014",
            How::User(NO_SUSPENSION),
        ),
        (
            "VUID-VkSubmitInfo-pCommandBuffers-06015",
            How::User(NO_SUSPENSION),
        ),
        (
            "VUID-VkSubmitInfo-pCommandBuffers-06016",
            How::User(NO_SUSPENSION),
        ),
        (
            "VUID-VkSubmitInfo2KHR-commandBuffer-06192",
            How::User(NO_SUSPENSION),
        ),
        (
            "VUID-VkSubmitInfo2KHR-commandBuffer-06010",
            How::User(NO_SUSPENSION),
        ),
        (
            "VUID-VkSubmitInfo2KHR-commandBuffer-06011",
            How::User(NO_SUSPENSION),
        ),
        (
            "VUID-VkSubmitInfo2KHR-commandBuffer-06012",
            How::User(NO_SUSPENSION),
        ),
    ],
    ..NONE
}];
