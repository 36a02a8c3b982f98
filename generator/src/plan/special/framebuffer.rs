//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/framebuffer.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Framebuffers: each attachment view against the render pass and the framebuffer's
//! size, and the views imageless framebuffers take at begin.

use super::{call, How, Special, NONE};

const UNPROVEN_OTHER_DEVICE_VIEW: &str = "checked by the safe methods in every build (each view must be one the device recorded), but no test breaks it: a view of another device is refused by the common-parent check first";
const UNPROVEN_FRAMEBUFFER_ROLES: &str = "checked by the safe methods in every build (the roles the render pass's subpasses give each attachment, recorded at its creation), but no test breaks it: the framebuffer test's render pass has no input or depth/stencil resolve attachment";
const UNPROVEN_FRAMEBUFFER_MULTIVIEW: &str = "checked by the safe methods in every build (against the render pass's recorded view masks), but no test breaks it: the framebuffer test's device does not enable multiview";
const UNPROVEN_DEPTH_3D: &str = "checked by the safe methods in every build (the view's format and its image's recorded type), but no test breaks it: no depth/stencil format can make a 3D image";
const FRAMEBUFFER_ATTACHMENTS: &str = "checks each attachment (the view's recorded format, range, swizzle, derived usage and its image's samples and extent, or an imageless framebuffer's chained attachment info) against the roles the render pass's subpasses give it, its format and samples, the framebuffer's size and layers, and the view masks, all recorded at creation";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[Special {
    command: "vkCreateFramebuffer",
    check_last: call(
        "special::framebuffer::create_framebuffer_checks",
        &["self", "create_info"],
    ),
    created: call(
        "special::framebuffer::framebuffer_created",
        &["self", "created", "create_info"],
    ),
    settles: &[
        (
            "VUID-vkCreateFramebuffer-pCreateInfo-02777",
            How::User(UNPROVEN_OTHER_DEVICE_VIEW),
        ),
        (
            "VUID-VkFramebufferCreateInfo-attachmentCount-00876",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00877",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-02633",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00879",
            How::User(UNPROVEN_FRAMEBUFFER_ROLES),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00880",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00881",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04533",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04534",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04535",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00883",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00884",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04113",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-02634",
            How::User(UNPROVEN_FRAMEBUFFER_ROLES),
        ),
        (
            "VUID-VkFramebufferCreateInfo-renderPass-04536",
            How::User(UNPROVEN_FRAMEBUFFER_MULTIVIEW),
        ),
        (
            "VUID-VkFramebufferCreateInfo-renderPass-02531",
            How::User(UNPROVEN_FRAMEBUFFER_MULTIVIEW),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00891",
            How::User(UNPROVEN_DEPTH_3D),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03190",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03191",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04541",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04542",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03201",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03202",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03204",
            How::User(UNPROVEN_FRAMEBUFFER_ROLES),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03205",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-renderPass-03198",
            How::User(UNPROVEN_FRAMEBUFFER_MULTIVIEW),
        ),
        (
            "VUID-VkFramebufferCreateInfo-renderPass-04546",
            How::Dynamic(FRAMEBUFFER_ATTACHMENTS),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-02778",
            How::Static("set from wrappers, which always hold valid image views"),
        ),
    ],
    ..NONE
}];
