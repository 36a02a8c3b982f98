//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/descriptors.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Descriptor pools and sets: allocation, updates (each write and copy against its
//! set's layout), resets, update templates and descriptor-buffer capture data.

use super::{call, unsafe_call, How, Special, CHAINED_COUNT, NONE};

const UNPROVEN_CAPTURE: &str = "checked by the safe methods in every build (the slice against the device's descriptor-buffer capture data size), but no test breaks it: lavapipe 22.3 has no VK_EXT_descriptor_buffer";
const UNPROVEN_UAB: &str = "checked by the safe methods in every build (the layouts' and the pool's create flags are kept from their creation), but no test breaks it: lavapipe 22.3 has no update-after-bind descriptors";
const UNPROVEN_VARIABLE: &str = "checked by the safe methods in every build (the variable-count binding is kept from the layout's creation, and each set's writes are checked against the count it was allocated with), but no test breaks it: lavapipe 22.3 has no variable descriptor counts";
const IMAGE_INFO_WRAPPERS: &str = "a descriptor image info takes its sampler and image view as wrappers or none, so each is a valid handle or null";
const IMAGE_INFO_SAMPLER: &str = "refuses a SAMPLER or COMBINED_IMAGE_SAMPLER write into a binding without immutable samplers whose image info has no sampler";
const IMAGE_INFO_VIEW: &str = "refuses a write of an image descriptor type other than SAMPLER whose image info has no image view (the nullDescriptor feature is not followed: a null view is refused even where it is enabled)";
const TEXEL_VIEW_WRAPPERS: &str =
    "texel buffer views are taken as a slice of wrappers, which always hold valid handles";
const OTHER_DEVICE_DESCRIPTOR: &str = "checks each object a descriptor names is one the device recorded (the 1.3.239 layer names the structs' commonparent rule, or for a sampler its validity rule, which the same handle breaks)";
const OTHER_DEVICE_BUFFER_DESCRIPTOR: &str = "checks each buffer a descriptor names is one the device recorded (the 1.3.239 layer crashes looking up a buffer of another device: proven by the error alone)";
const NULL_DESCRIPTOR: &str =
    "refuses a null buffer: the emitted API has no nullDescriptor feature";
const BUFFER_DESCRIPTOR: &str = "checks each buffer descriptor's buffer (recorded usage, size and binding; for a texel buffer view, its buffer's usage) and its offset and range against the device's limits";
const IMAGE_DESCRIPTOR: &str = "checks each image descriptor's view (its recorded type, aspects, usage and swizzle, and its image's type) and the layout against the lists its descriptor type allows";
const BOTH_ASPECTS: &str = "checks a view of a depth/stencil image names one of its aspects (the 1.3.239 layer reports it as UNASSIGNED-CoreValidation-DrawState-InvalidImageView, both aspects set)";
const AFTER_BIND_POOLS: &str = "checks the two sets' pools were created alike with or without UPDATE_AFTER_BIND (recorded at each set's allocation)";
const UNPROVEN_INLINE_COPIES: &str = "checked by the safe methods in every build (an inline uniform block's offset and size against 4), but no test breaks it: the safe copy takes its count as a number, and no test has two inline uniform block bindings to copy between yet";
const UNPROVEN_STORAGE_RANGE: &str = "checked by the safe methods in every build (the range against maxStorageBufferRange), but no test breaks it: lavapipe's limit is larger than a test can allocate";
const UNPROVEN_PLANE_SAMPLER: &str = "checked by the safe methods in every build (the image's recorded format and flags, the view's aspect), but no test breaks it: lavapipe 22.3 supports no multi-planar format";
const UNPROVEN_AFTER_BIND_LAYOUTS: &str = "checked by the safe methods in every build (the layouts' UPDATE_AFTER_BIND_POOL flags, recorded at their creation), but no test breaks it: lavapipe 22.3 offers update-after-bind for no descriptor type";
const SET_BINDINGS: &str = "checks the binding, type and array elements against the set's layout, kept from its creation, consecutive bindings included";

const TEMPLATE_LAYOUT: &str = "the safe create info's constructor takes the descriptor set layout (a wrapper, so a valid handle) whatever the template type";
const TEMPLATE_BINDINGS: &str = "checks each entry against the bindings of the set layout the template updates (the pipeline layout's set `set` for push descriptors), recorded at their creation, as a write to a set is checked (the 1.3.239 layer does not check it at the template's creation: the error alone proves it)";
const TEMPLATE_ENTRIES: &str = "checks each entry against the bindings of the set layout the template updates (the pipeline layout's set `set` for push descriptors), recorded at their creation, as a write to a set is checked";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkResetDescriptorPool",
        check: call("special::descriptors::reset_descriptor_pool_checks", &["descriptor_pool"]),
        after: call("special::descriptors::reset_descriptor_pool_done", &["descriptor_pool"]),
        settles: &[(
            "VUID-vkResetDescriptorPool-descriptorPool-00313",
            How::Dynamic("refuses a pool whose sets are still alive (held by the program, a command buffer or a submission)"),
        )],
        ..NONE
    },
    Special {
        command: "vkUpdateDescriptorSets",
        check: call(
            "special::descriptors::update_descriptor_sets_checks",
            &["self", "descriptor_writes", "descriptor_copies"],
        ),
        hold: call(
            "special::descriptors::update_descriptor_sets_hold",
            &["self", "descriptor_writes", "descriptor_copies"],
        ),
        after: call(
            "special::descriptors::update_descriptor_sets_done",
            &["self", "descriptor_writes", "descriptor_copies"],
        ),
        settles: &[
            (
                "VUID-VkWriteDescriptorSet-descriptorType-00324",
                How::Dynamic("refuses a write whose descriptor type selects an array that is not set"),
            ),
            ("VUID-VkWriteDescriptorSet-dstBinding-00315", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-dstBinding-00316", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00319", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-dstArrayElement-00321", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-descriptorCount-00317", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-srcBinding-00345", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-srcArrayElement-00346", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-dstBinding-00347", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-dstArrayElement-00348", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-dstBinding-02632", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-descriptorCount-00318", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02752", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-dstBinding-02753", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-srcBinding-02223", How::User(UNPROVEN_INLINE_COPIES)),
            ("VUID-VkCopyDescriptorSet-dstBinding-02224", How::User(UNPROVEN_INLINE_COPIES)),
            ("VUID-VkCopyDescriptorSet-srcBinding-02225", How::User(UNPROVEN_INLINE_COPIES)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06493", How::Dynamic("refuses a write whose descriptor type selects an array that is not set")),
            ("VUID-VkWriteDescriptorSet-descriptorType-00325", How::Dynamic(IMAGE_INFO_SAMPLER)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02996", How::Static(IMAGE_INFO_WRAPPERS)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02997", How::Dynamic(IMAGE_INFO_VIEW)),
            ("VUID-VkWriteDescriptorSet-descriptorType-07683", How::Dynamic(IMAGE_INFO_VIEW)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02994", How::Static(TEXEL_VIEW_WRAPPERS)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02995", How::Static(TEXEL_VIEW_WRAPPERS)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06236", How::Dynamic(OTHER_DEVICE_DESCRIPTOR)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06237", How::Dynamic(OTHER_DEVICE_BUFFER_DESCRIPTOR)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06238", How::Dynamic(OTHER_DEVICE_DESCRIPTOR)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06239", How::Dynamic(OTHER_DEVICE_DESCRIPTOR)),
            ("VUID-VkDescriptorBufferInfo-buffer-02998", How::Dynamic(NULL_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00327", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00328", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00329", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00330", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00331", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00332", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00333", How::User(UNPROVEN_STORAGE_RANGE)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00334", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00335", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00336", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00337", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00338", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00339", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-04149", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-04150", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-04151", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-04152", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-07729", How::Dynamic(BOTH_ASPECTS)),
            ("VUID-VkDescriptorImageInfo-imageView-01976", How::Dynamic(BOTH_ASPECTS)),
            ("VUID-VkDescriptorImageInfo-imageView-06711", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkDescriptorImageInfo-imageView-06712", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkDescriptorImageInfo-sampler-01564", How::User(UNPROVEN_PLANE_SAMPLER)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02221", How::Dynamic("checks an inline uniform block write chains a VkWriteDescriptorSetInlineUniformBlock whose dataSize is the write's count")),
            ("VUID-VkCopyDescriptorSet-srcSet-00349", How::Dynamic("checks the two ranges of a copy inside one set, as positions among the set's elements in binding order, do not overlap (the 1.3.239 layer does not check it: proven by the error alone)")),
            ("VUID-VkCopyDescriptorSet-srcSet-01918", How::User(UNPROVEN_AFTER_BIND_LAYOUTS)),
            ("VUID-VkCopyDescriptorSet-srcSet-04886", How::User(UNPROVEN_AFTER_BIND_LAYOUTS)),
            ("VUID-VkCopyDescriptorSet-srcSet-01920", How::Dynamic(AFTER_BIND_POOLS)),
            ("VUID-VkCopyDescriptorSet-srcSet-04888", How::Dynamic(AFTER_BIND_POOLS)),
            ("VUID-vkUpdateDescriptorSets-None-03047", How::Dynamic("checks the submissions of the command buffers that bound each set the update writes (recorded at each submission, dropped once known complete) when it rewrites a binding without UPDATE_AFTER_BIND or UPDATE_UNUSED_WHILE_PENDING, or one of image descriptors (whose layouts the submission checked); an update also leaves the command buffers that bound the set invalid, and what it replaces stays alive until those submissions complete")),
            ("VUID-VkDescriptorImageInfo-imageLayout-00344", How::Dynamic("checked where each draw and dispatch reads the sets bound at its pipeline layout's set numbers (the image descriptors each set held when it was bound; an update after that leaves the recording invalid): each descriptor's layout against what the recording's earlier commands leave its view's subresources in, and otherwise needed at the recording's start, which its submission checks against what the earlier submissions leave; a descriptor naming an attachment of the render pass instance is refused, as the recorder does not follow subpass layouts (across command buffers the 1.3.239 layer states the mismatch as UNASSIGNED-CoreValidation-DrawState-InvalidImageLayout)")),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06993", How::Static("every descriptor update and every submission holds the device's descriptor gate, so no two of them touch a set at once")),
        ],
        ..NONE
    },
    Special {
        command: "vkUpdateDescriptorSetWithTemplate",
        after: unsafe_call(
            "special::descriptors::update_descriptor_set_with_template_done",
            &["self", "descriptor_set", "descriptor_update_template", "data"],
            "the caller of this unsafe method vouches that `data` is laid out as the template's entries describe.",
        ),
        ..NONE
    },
    Special {
        command: "vkGetBufferOpaqueCaptureDescriptorDataEXT",
        check: call(
            "special::descriptors::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.buffer_capture_replay_descriptor_data_size",
                "\"VUID-vkGetBufferOpaqueCaptureDescriptorDataEXT-pData-08073\"",
            ],
        ),
        settles: &[("VUID-vkGetBufferOpaqueCaptureDescriptorDataEXT-pData-08073", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkGetImageOpaqueCaptureDescriptorDataEXT",
        check: call(
            "special::descriptors::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.image_capture_replay_descriptor_data_size",
                "\"VUID-vkGetImageOpaqueCaptureDescriptorDataEXT-pData-08077\"",
            ],
        ),
        settles: &[("VUID-vkGetImageOpaqueCaptureDescriptorDataEXT-pData-08077", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkGetImageViewOpaqueCaptureDescriptorDataEXT",
        check: call(
            "special::descriptors::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.image_view_capture_replay_descriptor_data_size",
                "\"VUID-vkGetImageViewOpaqueCaptureDescriptorDataEXT-pData-08081\"",
            ],
        ),
        settles: &[("VUID-vkGetImageViewOpaqueCaptureDescriptorDataEXT-pData-08081", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkGetSamplerOpaqueCaptureDescriptorDataEXT",
        check: call(
            "special::descriptors::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.sampler_capture_replay_descriptor_data_size",
                "\"VUID-vkGetSamplerOpaqueCaptureDescriptorDataEXT-pData-08085\"",
            ],
        ),
        settles: &[("VUID-vkGetSamplerOpaqueCaptureDescriptorDataEXT-pData-08085", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkGetAccelerationStructureOpaqueCaptureDescriptorDataEXT",
        check: call(
            "special::descriptors::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.acceleration_structure_capture_replay_descriptor_data_size",
                "\"VUID-vkGetAccelerationStructureOpaqueCaptureDescriptorDataEXT-pData-08089\"",
            ],
        ),
        settles: &[("VUID-vkGetAccelerationStructureOpaqueCaptureDescriptorDataEXT-pData-08089", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkCreateDescriptorPool",
        created: call("special::descriptors::descriptor_pool_created", &["created", "create_info"]),
        ..NONE
    },
    Special {
        command: "vkCreateDescriptorUpdateTemplate",
        check_last: call("special::descriptors::descriptor_update_template_checks", &["self", "create_info"]),
        settles: &[
            ("VUID-VkDescriptorUpdateTemplateCreateInfo-templateType-00350", How::Static(TEMPLATE_LAYOUT)),
            ("VUID-VkDescriptorUpdateTemplateEntry-dstBinding-00354", How::Dynamic(TEMPLATE_BINDINGS)),
            ("VUID-VkDescriptorUpdateTemplateEntry-dstArrayElement-00355", How::Dynamic(TEMPLATE_BINDINGS)),
            ("VUID-VkDescriptorUpdateTemplateEntry-descriptor-02226", How::Dynamic(TEMPLATE_ENTRIES)),
            ("VUID-VkDescriptorUpdateTemplateEntry-descriptor-02227", How::Dynamic(TEMPLATE_ENTRIES)),
        ],
        created: call("special::descriptors::descriptor_update_template_created", &["created", "create_info"]),
        ..NONE
    },
    Special {
        command: "vkAllocateDescriptorSets",
        check: call("special::descriptors::allocate_descriptor_sets_checks", &["allocate_info"]),
        check_last: call(
            "special::descriptors::allocate_descriptor_sets_layouts",
            &["self", "descriptor_pool", "allocate_info"],
        ),
        settles: &[
            (
                "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-descriptorSetCount-03045",
                How::Dynamic(CHAINED_COUNT),
            ),
            (
                "VUID-VkDescriptorSetAllocateInfo-pSetLayouts-03044",
                How::User(UNPROVEN_UAB),
            ),
            (
                "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-pSetLayouts-03046",
                How::User(UNPROVEN_VARIABLE),
            ),
        ],
        created: call(
            "special::descriptors::descriptor_sets_allocated",
            &["self", "created", "descriptor_pool", "allocate_info"],
        ),
        ..NONE
    },
];
