//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/render_pass.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Render passes: `vkCreateRenderPass` and `vkCreateRenderPass2` read into one `Pass`,
//! whose rules are each written once.

use super::{call, How, Special, CHAINED_COUNT, NONE};

const RENDER_PASS_INDICES: &str =
    "checks each attachment, subpass and input attachment index against the render pass's counts";
const ATTACHMENT_DESCRIPTIONS: &str = "checks each attachment's format and layouts, a depth/stencil reference's layout, and a chained input-attachment-aspect struct's aspects against the attachments' formats";
const FIRST_USE: &str = "checks the layout of each attachment's first use (the first subpass that references it) against its load operations";
const DEPENDENCIES: &str = "checks each dependency's subpasses, its stage masks against the stages of a graphics pipeline and the synchronization2 feature, its access masks against the accesses each stage supports (the specification's table, checked in as hooks/stages.rs: the pinned registry has no <sync> block), and a self-dependency's framebuffer-space stages against BY_REGION";
const MULTIVIEW_MASKS: &str = "checks a chained VkRenderPassMultiviewCreateInfo's view masks against the multiview feature and maxMultiviewViewCount, its correlation masks against each other, its view offsets against the dependencies, and multi-view self-dependencies against VIEW_LOCAL";
const SUBPASS_REFERENCES: &str = "checks what each subpass references against the render pass's attachments (formats, their format features as the physical device reports them, sample counts, layouts) and its view masks against each other and maxMultiviewViewCount (the 1.3.239 layer does not check that an attachment keeps one layout within a subpass: that rule is proven by the error alone)";
const UNPROVEN_RESOLVE_FEATURES: &str = "checked by the safe methods in every build, but no test breaks it: a resolve attachment has its color attachment's format, whose features a color attachment needs as well, so a format without them is refused for the color attachment first";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCreateRenderPass2",
        check: call(
            "special::render_pass::create_render_pass2_checks",
            &["create_info"],
        ),
        check_last: call(
            "special::render_pass::render_pass2_reference_checks",
            &["self", "create_info"],
        ),
        created: call(
            "special::render_pass::render_pass2_created",
            &["self", "created", "create_info"],
        ),
        settles: &[
            (
                "VUID-VkRenderPassCreateInfo2-attachment-03051",
                How::Dynamic(RENDER_PASS_INDICES),
            ),
            (
                "VUID-VkSubpassDescription2-attachment-03073",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pPreserveAttachments-03074",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pResolveAttachments-03065",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pResolveAttachments-03066",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pResolveAttachments-03067",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pResolveAttachments-03068",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pInputAttachments-02897",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pColorAttachments-02898",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pResolveAttachments-02899",
                How::User(UNPROVEN_RESOLVE_FEATURES),
            ),
            (
                "VUID-VkSubpassDescription2-pDepthStencilAttachment-02900",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-multisampledRenderToSingleSampled-06872",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-layout-02528",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-pDepthStencilAttachment-04440",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-attachment-02800",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-attachment-02801",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo2-attachment-02525",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription2-viewMask-06706",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo2-viewMask-03057",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo2-viewMask-03058",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo2-viewMask-03059",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateRenderPass",
        check: call(
            "special::render_pass::create_render_pass_checks",
            &["create_info"],
        ),
        check_last: call(
            "special::render_pass::render_pass_reference_checks",
            &["self", "create_info"],
        ),
        created: call(
            "special::render_pass::render_pass_created",
            &["self", "created", "create_info"],
        ),
        settles: &[
            (
                "VUID-VkAttachmentDescription-format-06698",
                How::Dynamic(ATTACHMENT_DESCRIPTIONS),
            ),
            (
                "VUID-VkAttachmentDescription-format-06242",
                How::Dynamic(ATTACHMENT_DESCRIPTIONS),
            ),
            (
                "VUID-VkAttachmentDescription-format-06243",
                How::Dynamic(ATTACHMENT_DESCRIPTIONS),
            ),
            (
                "VUID-VkAttachmentDescription-format-06906",
                How::Dynamic(ATTACHMENT_DESCRIPTIONS),
            ),
            (
                "VUID-VkAttachmentDescription-format-06907",
                How::Dynamic(ATTACHMENT_DESCRIPTIONS),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pAttachments-00836",
                How::Dynamic(FIRST_USE),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pAttachments-02511",
                How::Dynamic(FIRST_USE),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pAttachments-01566",
                How::Dynamic(FIRST_USE),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pAttachments-01567",
                How::Dynamic(FIRST_USE),
            ),
            (
                "VUID-VkSubpassDescription-loadOp-00846",
                How::Dynamic(FIRST_USE),
            ),
            (
                "VUID-VkSubpassDescription-attachment-06915",
                How::Dynamic(ATTACHMENT_DESCRIPTIONS),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pDependencies-00837",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pDependencies-00838",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-srcSubpass-00864",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-srcSubpass-00865",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-srcSubpass-06809",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-srcSubpass-02243",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-srcAccessMask-00868",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-dstAccessMask-00869",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-srcStageMask-03937",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-dstStageMask-03937",
                How::Dynamic(DEPENDENCIES),
            ),
            (
                "VUID-VkSubpassDependency-srcSubpass-00872",
                How::Dynamic(MULTIVIEW_MASKS),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-01930",
                How::Dynamic(MULTIVIEW_MASKS),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-02512",
                How::Dynamic(MULTIVIEW_MASKS),
            ),
            (
                "VUID-VkRenderPassMultiviewCreateInfo-pCorrelationMasks-00841",
                How::Dynamic(MULTIVIEW_MASKS),
            ),
            (
                "VUID-VkRenderPassMultiviewCreateInfo-multiview-06555",
                How::Dynamic(MULTIVIEW_MASKS),
            ),
            (
                "VUID-VkRenderPassMultiviewCreateInfo-pViewMasks-06697",
                How::Dynamic(MULTIVIEW_MASKS),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-01963",
                How::Dynamic(ATTACHMENT_DESCRIPTIONS),
            ),
            (
                "VUID-VkSubpassDescription-attachment-00853",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pPreserveAttachments-00854",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pResolveAttachments-00847",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pResolveAttachments-00848",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pResolveAttachments-00849",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pResolveAttachments-00850",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pInputAttachments-02647",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pColorAttachments-02648",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pResolveAttachments-02649",
                How::User(UNPROVEN_RESOLVE_FEATURES),
            ),
            (
                "VUID-VkSubpassDescription-pDepthStencilAttachment-02650",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pColorAttachments-06868",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pDepthStencilAttachment-01418",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-layout-02519",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkSubpassDescription-pDepthStencilAttachment-04438",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-01929",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-02513",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-02514",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-02515",
                How::Dynamic(SUBPASS_REFERENCES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-attachment-00834",
                How::Dynamic(RENDER_PASS_INDICES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pDependencies-06866",
                How::Dynamic(RENDER_PASS_INDICES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pDependencies-06867",
                How::Dynamic(RENDER_PASS_INDICES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-01926",
                How::Dynamic(RENDER_PASS_INDICES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-01927",
                How::Dynamic(RENDER_PASS_INDICES),
            ),
            (
                "VUID-VkRenderPassCreateInfo-pNext-01928",
                How::Dynamic(CHAINED_COUNT),
            ),
        ],
        ..NONE
    },
];
