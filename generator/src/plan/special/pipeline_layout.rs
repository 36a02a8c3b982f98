//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/pipeline_layout.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Pipeline layouts: their creation, against the device's per-stage and total
//! descriptor limits and push constant ranges.

use super::{call, How, Special, NONE, UNPROVEN};

const UNPROVEN_BLOCKS: &str = "checked by the safe methods in every build (the set layouts' inline uniform block bindings, per stage and in all, against the device's Vulkan 1.3 limits), but no test breaks it yet: the tests' device does not enable inlineUniformBlock";
const LAYOUT_LIMITS: &str = "checks the set layouts' recorded bindings, counted per kind in each stage and across all stages, against the device's limits (the update-after-bind ones from its Vulkan 1.2 properties), the set count against maxBoundDescriptorSets, and the push-constant ranges for a stage named twice";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[Special {
    command: "vkCreatePipelineLayout",
    check_last: call(
        "special::pipeline_layout::create_pipeline_layout_checks",
        &["self", "create_info"],
    ),
    created: call(
        "special::pipeline_layout::pipeline_layout_created",
        &["self", "created", "create_info"],
    ),
    // The update-after-bind limits are larger than the others on lavapipe, so a
    // layout past one is past a set-wide limit first, and no test breaks them
    // alone (but the two dynamic-buffer ones, which are smaller there).
    settles: &[
        (
            "VUID-VkPipelineLayoutCreateInfo-setLayoutCount-00286",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02214",
            How::User(UNPROVEN_BLOCKS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02215",
            How::User(UNPROVEN_BLOCKS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02216",
            How::User(UNPROVEN_BLOCKS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02217",
            How::User(UNPROVEN_BLOCKS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pPushConstantRanges-00292",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03016",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03017",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03018",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03019",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03020",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03021",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03022",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03023",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03024",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03025",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03026",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03027",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03028",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03029",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03030",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03031",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03032",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03033",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03034",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03035",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03036",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03037",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03038",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03039",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03040",
            How::Dynamic(LAYOUT_LIMITS),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03041",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03042",
            How::User(UNPROVEN),
        ),
        (
            "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03043",
            How::User(UNPROVEN),
        ),
    ],
    ..NONE
}];
