//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/command_buffers.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Command pools and command buffers: their creation, allocation and resets (the
//! execution of secondaries is `secondaries.rs`).

use super::{call, How, Special, ACTIVE_QUERIES, NONE};

const POOL_FAMILY: &str =
    "checks the family against the queue create infos the device recorded at its creation";
const RECORDING: &str =
    "`Recorder::end` exists only on a recorder, which only `CommandBuffer::begin` makes";
const OUTSIDE: &str = "`Recorder::end` exists only on a recorder outside a render pass instance, or on a continuing secondary";
const POOL_PROTECTED: &str =
    "checks the protectedMemory feature the device recorded at its creation";

const INHERITED_QUERIES: &str = "`CommandBuffer::begin` checks a secondary's inheritance info against the inheritedQueries and pipelineStatisticsQuery features the device recorded at its creation (`special::secondaries::inheritance_checks`)";
const UNPROVEN_INHERITED_QUERIES: &str = "checked by the safe methods in every build (`CommandBuffer::begin`: the query control bits Vulkan defines), but no test breaks it: lavapipe has no inheritedQueries, whose absence makes any flag a breach of 02788 instead";
const UNPROVEN_STATISTICS_BITS: &str = "checked by the safe methods in every build (`CommandBuffer::begin`: the pipeline statistics bits of core Vulkan), but no test breaks it yet";
const ONE_SAMPLE_COUNT: &str = "the implicit check of rasterizationSamples (its -parameter rule, which the error names) refuses every value that is not one VkSampleCountFlagBits value, before `CommandBuffer::begin` records anything";
const INHERITED_FORMATS: &str = "`CommandBuffer::begin` checks a chained VkCommandBufferInheritanceRenderingInfo's formats (their aspects from vk.xml's formats, their features queried from the physical device) and view mask (against maxMultiviewViewCount), by the rules a pipeline's VkPipelineRenderingCreateInfo shares (`special::rendering::formats_checks`)";
const UNPROVEN_DEPTH_FEATURE: &str = "checked by the safe methods in every build (`CommandBuffer::begin`: the format's features, queried from the physical device), but no test breaks it: lavapipe supports every depth and stencil format as a depth/stencil attachment";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkResetCommandBuffer",
        check: call("special::command_buffers::reset_command_buffer_checks", &["self"]),
        after: call("special::command_buffers::reset_command_buffer_done", &["self"]),
        settles: &[
            (
                "VUID-vkResetCommandBuffer-commandBuffer-00045",
                How::Dynamic("refuses a buffer that a submission may still be executing"),
            ),
            (
                "VUID-vkResetCommandBuffer-commandBuffer-00046",
                How::Dynamic("refuses a buffer whose pool was created without RESET_COMMAND_BUFFER"),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkResetCommandPool",
        check: call("special::command_buffers::reset_command_pool_checks", &["self", "command_pool"]),
        after: call("special::command_buffers::reset_command_pool_done", &["command_pool"]),
        settles: &[(
            "VUID-vkResetCommandPool-commandPool-00040",
            How::Dynamic("refuses a pool one of whose buffers a submission may still be executing"),
        )],
        ..NONE
    },
    // `Recorder::end`, written by hand in `recorder.rs`.
    Special {
        command: "vkEndCommandBuffer",
        settles: &[
            ("VUID-vkEndCommandBuffer-commandBuffer-00059", How::Static(RECORDING)),
            ("VUID-vkEndCommandBuffer-commandBuffer-00060", How::Static(OUTSIDE)),
            ("VUID-vkEndCommandBuffer-commandBuffer-00061", How::Dynamic(ACTIVE_QUERIES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateCommandPool",
        check: call("special::command_buffers::create_command_pool_checks", &["self", "create_info"]),
        created: call("special::command_buffers::command_pool_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-vkCreateCommandPool-queueFamilyIndex-01937", How::Dynamic(POOL_FAMILY)),
            ("VUID-VkCommandPoolCreateInfo-flags-02860", How::Dynamic(POOL_PROTECTED)),
        ],
        ..NONE
    },
    Special {
        command: "vkAllocateCommandBuffers",
        created: call(
            "special::command_buffers::command_buffers_allocated",
            &["self", "created", "command_pool", "allocate_info"],
        ),
        ..NONE
    },
    // Rules settled by the hand-written parts of the crate that these commands
    // live in rather than by a generated method.
    Special {
        command: "vkBeginCommandBuffer",
        settles: &[
            (
                "VUID-vkBeginCommandBuffer-commandBuffer-00049",
                How::Dynamic("`CommandBuffer::begin` refuses a buffer that a submission may still be executing; a recording holds the buffer mutably, so none is under way"),
            ),
            (
                "VUID-vkBeginCommandBuffer-commandBuffer-00050",
                How::Dynamic("`CommandBuffer::begin` refuses a buffer begun before when its pool was created without RESET_COMMAND_BUFFER"),
            ),
            ("VUID-VkCommandBufferInheritanceInfo-queryFlags-02788", How::Dynamic(INHERITED_QUERIES)),
            ("VUID-VkCommandBufferInheritanceInfo-pipelineStatistics-00058", How::Dynamic(INHERITED_QUERIES)),
            ("VUID-VkCommandBufferInheritanceInfo-queryFlags-00057", How::User(UNPROVEN_INHERITED_QUERIES)),
            ("VUID-VkCommandBufferInheritanceInfo-pipelineStatistics-02789", How::User(UNPROVEN_STATISTICS_BITS)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-colorAttachmentCount-06004", How::Static(ONE_SAMPLE_COUNT)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-variableMultisampleRate-06005", How::Static(ONE_SAMPLE_COUNT)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-depthAttachmentFormat-06540", How::Dynamic(INHERITED_FORMATS)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-stencilAttachmentFormat-06541", How::Dynamic(INHERITED_FORMATS)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-depthAttachmentFormat-06200", How::Dynamic(INHERITED_FORMATS)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-pColorAttachmentFormats-06006", How::Dynamic(INHERITED_FORMATS)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-viewMask-06009", How::Dynamic(INHERITED_FORMATS)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-depthAttachmentFormat-06007", How::User(UNPROVEN_DEPTH_FEATURE)),
            ("VUID-VkCommandBufferInheritanceRenderingInfo-stencilAttachmentFormat-06199", How::User(UNPROVEN_DEPTH_FEATURE)),
        ],
        ..NONE
    },
];
