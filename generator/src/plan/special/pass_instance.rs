//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/pass_instance.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Render pass instances: beginning a render pass or dynamic rendering (attachments,
//! views, clear values, device groups), moving to the next subpass, and ending.

use super::{call, How, Special, ACTIVE_QUERIES_ALONE, NONE};

const LAYOUT_PASS: &str = "checks each attachment's initial layout against the one the recording's earlier commands leave its view's subresources in, and, for subresources the recording has not touched before, at submission against the one the device's earlier submissions leave (the 1.3.239 layer reports the rule as UNASSIGNED-CoreValidation-DrawState-InvalidRenderpass, \"the render pass initial layout ... and the previous known layout of the attachment ... must match\")";
const PASS_BEGIN: &str = "checks the render area against the framebuffer's size, the clear values against the largest attachment the render pass clears, and each layout the render pass gives an attachment against the usage of the framebuffer's view, as the device recorded them";
const PASS_BEGIN_UNPROVEN: &str = "checked by the safe methods in every build, but no test breaks it: the framebuffer's creation already needs the usage each attachment's role in the render pass implies, and no test begins an instance of another render pass that gives the attachment these layouts";
const PASS_GROUP: &str = "checks the chained struct's device mask against the device's physical devices, its render areas' count, and each area against the framebuffer's size and the device's limits";
const PASS_GROUP_LIMIT: &str = "checks each device render area against the device's limits (an area past them is past every framebuffer, and the 1.3.239 layer names only that rule: the error alone proves this one)";
const PASS_GROUP_MASK: &str = "checked by the safe methods in every build, but no test breaks it: in a group of one physical device, the only valid masks are the initial mask";
const PASS_VIEWS: &str = "checks the views a chained VkRenderPassAttachmentBeginInfo gives against the imageless framebuffer's attachment image infos and the render pass's attachments, and the render pass against the one the framebuffer was created with (attachment formats and sample counts, each subpass's attachments and view mask), as the device recorded them";
const PASS_FORMATS: &str = "checks the view formats the view's image lists against the attachment image info's (an image that lists none is judged by its view's format alone, as the 1.3.239 layer judges it)";
const CLEAR_ATTACHMENTS: &str = "checks each attachment against the current subpass's (or dynamic rendering's) color count and depth/stencil format, and each rectangle against the render area and layer count the instance was begun with (in a continuing secondary, whose area is not known, a clear is refused)";
const CLEAR_DEPTH_ASPECTS: &str = "checked by the safe methods in every build (the aspects cleared against the current depth/stencil attachment's format, kept from the render pass's creation), but no test breaks it yet";
const CLEAR_MULTIVIEW: &str = "checked by the safe methods in every build (the current subpass's view mask, kept from the render pass's creation), but no test breaks it yet";
const CLEAR_PROTECTED: &str = "checked by the safe methods in every build (the attachments' images' protected flags against the pool's, recorded at their creation, and the device's protectedNoFault), but no test breaks it: lavapipe has no protected memory";
const CLEAR_VALUE: &str = "the value is a `vk::ClearValue`, 16 bytes that every bit pattern fills with a value of each of its members";
const PASS_UNPROVEN: &str = "checked by the safe methods in every build, but no test breaks it yet";
const PASS_FAMILY: &str = "checked by the safe methods in every build (each dependency's stages against the pool's queue family), but no test breaks it: lavapipe's only queue family supports every stage";
const SUBPASSES: &str = "checks the subpass against the render pass's subpass count, which the device records at its creation and the recorder follows (a refused end first records the remaining subpasses, so the driver sees a valid end of an unsubmittable buffer)";
const IN_RENDER_PASS: &str = "the method exists only on a recorder inside a render pass begun with `begin_render_pass` (its state type), not dynamic rendering nor a continuing secondary";
const IN_RENDERING: &str = "the method exists only on a recorder inside dynamic rendering it began itself (its state type)";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCmdBeginRenderPass",
        check: call(
            "special::pass_instance::begin_render_pass_checks",
            &["&self", "render_pass_begin", "&crate::special::pass_instance::BEGIN"],
        ),
        after: call(
            "special::pass_instance::render_pass_begun",
            &["&mut self", "render_pass_begin", "contents", "\"VUID-vkCmdBeginRenderPass-initialLayout-00900\""],
        ),
        settles: &[
            ("VUID-VkRenderPassBeginInfo-framebuffer-03207", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03208", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03209", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-04627", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03211", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03212", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03213", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03214", How::Dynamic(PASS_FORMATS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03216", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03217", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-renderPass-00904", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassAttachmentBeginInfo-pAttachments-03218", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassAttachmentBeginInfo-pAttachments-03219", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-02780", How::User(PASS_UNPROVEN)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03215", How::User(PASS_UNPROVEN)),
            ("VUID-VkRenderPassAttachmentBeginInfo-pAttachments-04114", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-framebuffer-02532", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-stencilInitialLayout-02843", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-srcStageMask-06451", How::User(PASS_FAMILY)),
            ("VUID-vkCmdBeginRenderPass-dstStageMask-06452", How::User(PASS_FAMILY)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-deviceMask-00905", How::Dynamic(PASS_GROUP)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-deviceRenderAreaCount-00908", How::Dynamic(PASS_GROUP)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-offset-06166", How::Dynamic(PASS_GROUP)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-offset-06167", How::Dynamic(PASS_GROUP)),
            ("VUID-VkRenderPassBeginInfo-pNext-02856", How::Dynamic(PASS_GROUP)),
            ("VUID-VkRenderPassBeginInfo-pNext-02857", How::Dynamic(PASS_GROUP)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-offset-06168", How::Dynamic(PASS_GROUP_LIMIT)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-offset-06169", How::Dynamic(PASS_GROUP_LIMIT)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-deviceMask-00907", How::User(PASS_GROUP_MASK)),
            ("VUID-VkRenderPassBeginInfo-clearValueCount-04962", How::Static("set from a slice by the safe setter, which stores its pointer with its count")),
            ("VUID-vkCmdBeginRenderPass-initialLayout-00897", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-00898", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-00899", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-00895", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-01758", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-02842", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-VkRenderPassBeginInfo-pNext-02850", How::Dynamic(PASS_BEGIN)),
            ("VUID-VkRenderPassBeginInfo-pNext-02851", How::Dynamic(PASS_BEGIN)),
            ("VUID-VkRenderPassBeginInfo-pNext-02852", How::Dynamic(PASS_BEGIN)),
            ("VUID-VkRenderPassBeginInfo-pNext-02853", How::Dynamic(PASS_BEGIN)),
            ("VUID-VkRenderPassBeginInfo-clearValueCount-00902", How::Dynamic(PASS_BEGIN)),("VUID-vkCmdBeginRenderPass-initialLayout-00900", How::Dynamic(LAYOUT_PASS))],
        ..NONE
    },
    Special {
        command: "vkCmdBeginRenderPass2",
        check: call(
            "special::pass_instance::begin_render_pass_checks",
            &["&self", "render_pass_begin", "&crate::special::pass_instance::BEGIN2"],
        ),
        after: call(
            "special::pass_instance::render_pass_begun",
            &["&mut self", "render_pass_begin", "subpass_begin_info.contents", "\"VUID-vkCmdBeginRenderPass2-initialLayout-03100\""],
        ),
        settles: &[
            (
                "VUID-vkCmdBeginRenderPass2-framebuffer-02779",
                How::Dynamic("checks the framebuffer and the render pass are listed on the command buffer's device, as every one made through the wrappers is on its own (the 1.3.239 layer names only the begin info's commonparent rule, which the same objects break: the error alone proves this one)"),
            ),
            ("VUID-vkCmdBeginRenderPass2-framebuffer-02533", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass2-stencilInitialLayout-02845", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass2-srcStageMask-06453", How::User(PASS_FAMILY)),
            ("VUID-vkCmdBeginRenderPass2-dstStageMask-06454", How::User(PASS_FAMILY)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03097", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03098", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03099", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03094", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03096", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-02844", How::User(PASS_BEGIN_UNPROVEN)),("VUID-vkCmdBeginRenderPass2-initialLayout-03100", How::Dynamic(LAYOUT_PASS))],
        ..NONE
    },
    Special {
        command: "vkCmdClearAttachments",
        check_last: call(
            "special::pass_instance::clear_attachments_checks",
            &["self", "attachments", "rects"],
        ),
        settles: &[
            ("VUID-vkCmdClearAttachments-aspectMask-07271", How::Dynamic(CLEAR_ATTACHMENTS)),
            ("VUID-vkCmdClearAttachments-pAttachments-07270", How::User(CLEAR_DEPTH_ASPECTS)),
            ("VUID-vkCmdClearAttachments-rect-02682", How::Dynamic(CLEAR_ATTACHMENTS)),
            ("VUID-vkCmdClearAttachments-rect-02683", How::Dynamic(CLEAR_ATTACHMENTS)),
            ("VUID-vkCmdClearAttachments-pRects-00016", How::Dynamic(CLEAR_ATTACHMENTS)),
            ("VUID-vkCmdClearAttachments-pRects-06937", How::Dynamic(CLEAR_ATTACHMENTS)),
            ("VUID-vkCmdClearAttachments-baseArrayLayer-00018", How::User(CLEAR_MULTIVIEW)),
            ("VUID-VkClearAttachment-clearValue-00021", How::Static(CLEAR_VALUE)),
            ("VUID-vkCmdClearAttachments-commandBuffer-02504", How::User(CLEAR_PROTECTED)),
            ("VUID-vkCmdClearAttachments-commandBuffer-02505", How::User(CLEAR_PROTECTED)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdNextSubpass",
        check: call(
            "special::pass_instance::next_subpass_checks",
            &["self", "\"VUID-vkCmdNextSubpass-None-00909\""],
        ),
        after: call("special::pass_instance::next_subpass_done", &["self", "contents"]),
        settles: &[("VUID-vkCmdNextSubpass-None-00909", How::Dynamic(SUBPASSES))],
        ..NONE
    },
    Special {
        command: "vkCmdNextSubpass2",
        check: call(
            "special::pass_instance::next_subpass_checks",
            &["self", "\"VUID-vkCmdNextSubpass2-None-03102\""],
        ),
        after: call("special::pass_instance::next_subpass_done", &["self", "subpass_begin_info.contents"]),
        settles: &[("VUID-vkCmdNextSubpass2-None-03102", How::Dynamic(SUBPASSES))],
        ..NONE
    },
    Special {
        command: "vkCmdEndRenderPass",
        check: call(
            "special::pass_instance::end_render_pass_checks",
            &[
                "&mut self",
                "(\"VUID-vkCmdEndRenderPass-None-00910\", \"VUID-vkCmdEndRenderPass-None-07004\")",
            ],
        ),
        after: call("special::pass_instance::instance_ended", &["&mut self"]),
        settles: &[
            ("VUID-vkCmdEndRenderPass-None-00910", How::Dynamic(SUBPASSES)),
            ("VUID-vkCmdEndRenderPass-None-07004", How::Dynamic(ACTIVE_QUERIES_ALONE)),
            ("VUID-vkCmdEndRenderPass-None-06170", How::Static(IN_RENDER_PASS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdEndRenderPass2",
        check: call(
            "special::pass_instance::end_render_pass_checks",
            &[
                "&mut self",
                "(\"VUID-vkCmdEndRenderPass2-None-03103\", \"VUID-vkCmdEndRenderPass2-None-07005\")",
            ],
        ),
        after: call("special::pass_instance::instance_ended", &["&mut self"]),
        settles: &[
            ("VUID-vkCmdEndRenderPass2-None-03103", How::Dynamic(SUBPASSES)),
            ("VUID-vkCmdEndRenderPass2-None-07005", How::Dynamic(ACTIVE_QUERIES_ALONE)),
            ("VUID-vkCmdEndRenderPass2-None-06171", How::Static(IN_RENDER_PASS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdEndRendering",
        check: call("special::pass_instance::end_rendering_checks", &["&mut self"]),
        after: call("special::pass_instance::instance_ended", &["&mut self"]),
        settles: &[
            ("VUID-vkCmdEndRendering-None-06999", How::Dynamic(ACTIVE_QUERIES_ALONE)),
            ("VUID-vkCmdEndRendering-None-06161", How::Static(IN_RENDERING)),
            ("VUID-vkCmdEndRendering-commandBuffer-06162", How::Static(IN_RENDERING)),
        ],
        ..NONE
    },
];
