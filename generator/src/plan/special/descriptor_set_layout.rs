//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/descriptor_set_layout.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Descriptor set layouts: their creation checks (binding flags, immutable samplers,
//! limits) and the record the device keeps of each.

use super::{call, How, Special, NONE};

const UNPROVEN_INLINE_AFTER_BIND: &str = "checked by the safe methods in every build, but no test breaks it: the tests' only device with inlineUniformBlock enables every feature lavapipe has, update-after-bind of inline uniform blocks included";
const STAGE_BITS: &str = "checks the stages are of the emitted API (the graphics stages and compute) or VK_SHADER_STAGE_ALL (the 1.3.239 layer does not check bits no extension defines: proven by the error alone)";
const IMMUTABLE_SAMPLERS: &str = "the safe binding's `immutable_samplers` setter stores the sampler wrappers with their count as descriptorCount, and `descriptor_count` clears them when it sets another count; the walk over what the create info reaches checks each sampler is the device's before any other check or driver call";
const UNPROVEN_AFTER_BIND: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe 22.3 has no update-after-bind descriptors, so a binding updated after bind is refused for the missing feature first";
const UNPROVEN_VARIABLE_COUNT: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe 22.3 has no variable descriptor counts, so a variable-sized binding is refused for the missing feature first";
const LAYOUT_BINDINGS: &str = "checks the bindings against each other (each number once), input attachments' stages, inline uniform blocks against maxInlineUniformBlockSize, and a chained binding-flags struct's count and flags against the device's descriptor-indexing features";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCreateDescriptorSetLayout",
        check_last: call("special::descriptor_set_layout::descriptor_set_layout_checks", &["self", "create_info"]),
        created: call(
            "special::descriptor_set_layout::descriptor_set_layout_created",
            &["self", "created", "create_info"],
        ),
        settles: &[
            ("VUID-VkDescriptorSetLayoutBinding-descriptorCount-00283", How::Dynamic(STAGE_BITS)),
            ("VUID-VkDescriptorSetLayoutBinding-descriptorType-00282", How::Dynamic(IMMUTABLE_SAMPLERS)),
            ("VUID-VkDescriptorSetLayoutCreateInfo-flags-03000", How::User(UNPROVEN_AFTER_BIND)),
            ("VUID-VkDescriptorSetLayoutCreateInfo-descriptorType-03001", How::User(UNPROVEN_AFTER_BIND)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-pBindingFlags-03004", How::User(UNPROVEN_VARIABLE_COUNT)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-pBindingFlags-03015", How::User(UNPROVEN_VARIABLE_COUNT)),
            ("VUID-VkDescriptorSetLayoutCreateInfo-binding-00279", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBinding-descriptorType-01510", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBinding-descriptorType-02210", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-bindingCount-03002", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformBufferUpdateAfterBind-03005", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingSampledImageUpdateAfterBind-03006", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageImageUpdateAfterBind-03007", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageBufferUpdateAfterBind-03008", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformTexelBufferUpdateAfterBind-03009", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageTexelBufferUpdateAfterBind-03010", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingInlineUniformBlockUpdateAfterBind-02211", How::User(UNPROVEN_INLINE_AFTER_BIND)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-None-03011", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUpdateUnusedWhilePending-03012", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingPartiallyBound-03013", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingVariableDescriptorCount-03014", How::Dynamic(LAYOUT_BINDINGS)),
        ],
        ..NONE
    },
];
