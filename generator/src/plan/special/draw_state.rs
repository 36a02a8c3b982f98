//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/draw_state.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Commands that set draw state: pipeline, vertex, index and descriptor set binds, push
//! constants, viewports, scissors and the other dynamic states, each checked and recorded.

use super::{
    call, How, Special, BUFFER_USE, MULTI_VIEWPORT, NONE, RANGE, UNPROVEN_FAMILY, VIEWPORTS,
};

const SUBPASS_SAMPLES: &str = "checks the pipeline's sample count, kept from its creation, against the first one bound in a subpass without attachments (kept from the render pass's creation), where the physical device lacks variableMultisampleRate (the 1.3.239 layer does not check it at the bind: proven by the error alone)";
const VERTEX_LIMITS: &str = "checks the bindings against maxVertexInputBindings and the strides against maxVertexInputBindingStride, read once";
const STRIDE_EXTENT: &str = "checked at each draw, where the bound pipeline says which attributes the vertex shader fetches from each binding: a stride set for a pipeline with the stride dynamic is 0 or reaches the attributes' extent";
const INDEX_ALIGNED: &str = "checks the offset plus the buffer's offset in its memory (kept from the bind) is a multiple of the index size; allocations start aligned for any resource";
const PUSH: &str = "checks the range against the layout's push-constant ranges, kept from its creation, its alignment and the device's maxPushConstantsSize";
const SCISSORS: &str = "checks each scissor's offset is not negative and its ends do not overflow";
const SET_LAYOUTS_MATCH: &str = "checks each set's layout, recorded at its allocation, is the pipeline layout's layout at that set number or identically defined (bindings, their types, counts, stages, flags and immutable samplers, and the layout's flags, all recorded at creation)";
const BIND_POINT_FAMILY: &str = "checked by the safe methods in every build (the bind point against the queue flags of the pool's family, recorded when the pool was created), but no test breaks it: lavapipe's only queue family has graphics and compute";
const DYNAMIC_OFFSETS: &str = "checks each dynamic offset, in the order of sets, bindings and elements, against the alignment limit of its descriptor's type";
const DYNAMIC_RANGES: &str = "checks each dynamic offset against the offset and range its descriptor was written with and its buffer's size (the device records them from every write, copy and template update of a dynamic buffer descriptor)";
const BIND_POINT: &str =
    "checks the pipeline was created for the bind point, which the device remembers";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCmdBindVertexBuffers",
        check: call(
            "special::draw_state::cmd_bind_vertex_buffers_checks",
            &["self", "first_binding", "buffers", "offsets"],
        ),
        after: call(
            "special::draw_state::cmd_bind_vertex_buffers_done",
            &["self", "first_binding", "buffers", "offsets", "(&[], &[])"],
        ),
        settles: &[
            ("VUID-vkCmdBindVertexBuffers-pOffsets-00626", How::Dynamic(RANGE)),
            ("VUID-vkCmdBindVertexBuffers-pBuffers-00627", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindVertexBuffers-pBuffers-00628", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindVertexBuffers-firstBinding-00625", How::Dynamic(VERTEX_LIMITS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindVertexBuffers2",
        check: call(
            "special::draw_state::cmd_bind_vertex_buffers2_checks",
            &["self", "first_binding", "buffers", "offsets", "(sizes, strides)"],
        ),
        after: call(
            "special::draw_state::cmd_bind_vertex_buffers2_done",
            &["self", "first_binding", "buffers", "offsets", "(sizes, strides)"],
        ),
        settles: &[
            ("VUID-vkCmdBindVertexBuffers2-pOffsets-03357", How::Dynamic(RANGE)),
            ("VUID-vkCmdBindVertexBuffers2-pSizes-03358", How::Dynamic(RANGE)),
            ("VUID-vkCmdBindVertexBuffers2-pBuffers-03359", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindVertexBuffers2-pBuffers-03360", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindVertexBuffers2-firstBinding-03356", How::Dynamic(VERTEX_LIMITS)),
            ("VUID-vkCmdBindVertexBuffers2-pStrides-03362", How::Dynamic(VERTEX_LIMITS)),
            ("VUID-vkCmdBindVertexBuffers2-pStrides-06209", How::Dynamic(STRIDE_EXTENT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindIndexBuffer",
        after: call(
            "special::draw_state::cmd_bind_index_buffer_done",
            &["self", "buffer", "offset", "index_type"],
        ),
        check: call(
            "special::draw_state::cmd_bind_index_buffer_checks",
            &["self", "buffer", "offset", "index_type"],
        ),
        settles: &[
            ("VUID-vkCmdBindIndexBuffer-offset-00432", How::Dynamic(INDEX_ALIGNED)),
            ("VUID-vkCmdBindIndexBuffer-offset-00431", How::Dynamic(RANGE)),
            ("VUID-vkCmdBindIndexBuffer-buffer-00433", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindIndexBuffer-buffer-00434", How::Dynamic(BUFFER_USE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdPushConstants",
        check: call(
            "special::draw_state::cmd_push_constants_checks",
            &["self", "layout", "stage_flags", "offset", "values"],
        ),
        after: call(
            "special::draw_state::cmd_push_constants_done",
            &["self", "layout", "offset", "values"],
        ),
        settles: &[
            ("VUID-vkCmdPushConstants-offset-01795", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-offset-01796", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-offset-00368", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-size-00369", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-offset-00370", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-size-00371", How::Dynamic(PUSH)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindDescriptorSets",
        after: call(
            "special::draw_state::cmd_bind_descriptor_sets_done",
            &["self", "pipeline_bind_point", "first_set", "descriptor_sets"],
        ),
        check: call(
            "special::draw_state::cmd_bind_descriptor_sets_checks",
            &[
                "self",
                "pipeline_bind_point",
                "layout",
                "first_set",
                "descriptor_sets",
                "dynamic_offsets",
            ],
        ),
        settles: &[
            ("VUID-vkCmdBindDescriptorSets-pDescriptorSets-00358", How::Dynamic(SET_LAYOUTS_MATCH)),
            ("VUID-vkCmdBindDescriptorSets-pipelineBindPoint-00361", How::User(BIND_POINT_FAMILY)),
            ("VUID-vkCmdBindDescriptorSets-pDynamicOffsets-01971", How::Dynamic(DYNAMIC_OFFSETS)),
            ("VUID-vkCmdBindDescriptorSets-pDynamicOffsets-01972", How::Dynamic(DYNAMIC_OFFSETS)),
            ("VUID-vkCmdBindDescriptorSets-pDescriptorSets-01979", How::Dynamic(DYNAMIC_RANGES)),
            ("VUID-vkCmdBindDescriptorSets-pDescriptorSets-06715", How::Dynamic(DYNAMIC_RANGES)),
            (
                "VUID-vkCmdBindDescriptorSets-pDescriptorSets-06563",
                How::Static("taken as wrappers, which always hold valid descriptor sets"),
            ),
            (
                "VUID-vkCmdBindDescriptorSets-firstSet-00360",
                How::Dynamic("checks the sets against the layout's set count, kept from its creation"),
            ),
            (
                "VUID-vkCmdBindDescriptorSets-dynamicOffsetCount-00359",
                How::Dynamic("checks one dynamic offset per dynamic descriptor of the sets, counted from their layouts at creation"),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetLineWidth",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::LINE_WIDTH)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthBias",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::DEPTH_BIAS)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetBlendConstants",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::BLEND_CONSTANTS)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthBounds",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::DEPTH_BOUNDS)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilCompareMask",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::STENCIL_COMPARE_MASK)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilWriteMask",
        after: call("special::draw_state::depth_stencil_set", &["self", "crate::recorder::Set::WriteMask(face_mask, write_mask)", "crate::state::dynamic_bit(vk::DynamicState::STENCIL_WRITE_MASK)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilReference",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::STENCIL_REFERENCE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetCullMode",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::CULL_MODE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetFrontFace",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::FRONT_FACE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetPrimitiveTopology",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::PRIMITIVE_TOPOLOGY)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthTestEnable",
        after: call("special::draw_state::depth_stencil_set", &["self", "crate::recorder::Set::DepthTest(depth_test_enable)", "crate::state::dynamic_bit(vk::DynamicState::DEPTH_TEST_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthWriteEnable",
        after: call("special::draw_state::depth_stencil_set", &["self", "crate::recorder::Set::DepthWrite(depth_write_enable)", "crate::state::dynamic_bit(vk::DynamicState::DEPTH_WRITE_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthCompareOp",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::DEPTH_COMPARE_OP)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthBoundsTestEnable",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::DEPTH_BOUNDS_TEST_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilTestEnable",
        after: call("special::draw_state::depth_stencil_set", &["self", "crate::recorder::Set::StencilTest(stencil_test_enable)", "crate::state::dynamic_bit(vk::DynamicState::STENCIL_TEST_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilOp",
        after: call("special::draw_state::depth_stencil_set", &["self", "crate::recorder::Set::StencilOp(face_mask, [fail_op, pass_op, depth_fail_op])", "crate::state::dynamic_bit(vk::DynamicState::STENCIL_OP)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetRasterizerDiscardEnable",
        after: call("special::draw_state::depth_stencil_set", &["self", "crate::recorder::Set::Discard(rasterizer_discard_enable)", "crate::state::dynamic_bit(vk::DynamicState::RASTERIZER_DISCARD_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthBiasEnable",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::DEPTH_BIAS_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetPrimitiveRestartEnable",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::PRIMITIVE_RESTART_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetViewport",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::VIEWPORT)"]),
        check: call("special::draw_state::cmd_set_viewport_checks", &["self", "first_viewport", "viewports"]),
        settles: &[
            ("VUID-vkCmdSetViewport-firstViewport-01223", How::Dynamic(VIEWPORTS)),
            ("VUID-vkCmdSetViewport-firstViewport-01224", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-vkCmdSetViewport-viewportCount-01225", How::Dynamic(MULTI_VIEWPORT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetScissor",
        after: call("special::draw_state::dynamic_state_set", &["self", "crate::state::dynamic_bit(vk::DynamicState::SCISSOR)"]),
        check: call("special::draw_state::cmd_set_scissor_checks", &["self", "first_scissor", "scissors"]),
        settles: &[
            ("VUID-vkCmdSetScissor-firstScissor-00592", How::Dynamic(VIEWPORTS)),
            ("VUID-vkCmdSetScissor-firstScissor-00593", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-vkCmdSetScissor-scissorCount-00594", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-vkCmdSetScissor-x-00595", How::Dynamic(SCISSORS)),
            ("VUID-vkCmdSetScissor-offset-00596", How::Dynamic(SCISSORS)),
            ("VUID-vkCmdSetScissor-offset-00597", How::Dynamic(SCISSORS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetViewportWithCount",
        after: call("special::draw_state::viewport_count_set", &["self", "viewports.len()", "crate::state::dynamic_bit(vk::DynamicState::VIEWPORT_WITH_COUNT)"]),
        check: call("special::draw_state::cmd_set_viewport_with_count_checks", &["self", "viewports"]),
        settles: &[
            ("VUID-vkCmdSetViewportWithCount-viewportCount-03394", How::Dynamic(VIEWPORTS)),
            ("VUID-vkCmdSetViewportWithCount-viewportCount-03395", How::Dynamic(MULTI_VIEWPORT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetScissorWithCount",
        after: call("special::draw_state::viewport_count_set", &["self", "scissors.len()", "crate::state::dynamic_bit(vk::DynamicState::SCISSOR_WITH_COUNT)"]),
        check: call("special::draw_state::cmd_set_scissor_with_count_checks", &["self", "scissors"]),
        settles: &[
            ("VUID-vkCmdSetScissorWithCount-scissorCount-03397", How::Dynamic(VIEWPORTS)),
            ("VUID-vkCmdSetScissorWithCount-scissorCount-03398", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-vkCmdSetScissorWithCount-x-03399", How::Dynamic(SCISSORS)),
            ("VUID-vkCmdSetScissorWithCount-offset-03400", How::Dynamic(SCISSORS)),
            ("VUID-vkCmdSetScissorWithCount-offset-03401", How::Dynamic(SCISSORS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindPipeline",
        check: call(
            "special::draw_state::cmd_bind_pipeline_checks",
            &["self", "pipeline_bind_point", "pipeline"],
        ),
        settles: &[
            (
                "VUID-vkCmdBindPipeline-pipelineBindPoint-00779",
                How::Dynamic(BIND_POINT),
            ),
            (
                "VUID-vkCmdBindPipeline-pipelineBindPoint-00780",
                How::Dynamic(BIND_POINT),
            ),
            (
                "VUID-vkCmdBindPipeline-pipelineBindPoint-00777",
                How::User(UNPROVEN_FAMILY),
            ),
            ("VUID-vkCmdBindPipeline-pipeline-00781", How::Dynamic(SUBPASS_SAMPLES)),
            (
                "VUID-vkCmdBindPipeline-pipelineBindPoint-00778",
                How::User(UNPROVEN_FAMILY),
            ),
        ],
        after: call(
            "special::draw_state::cmd_bind_pipeline_done",
            &["self", "pipeline_bind_point", "pipeline"],
        ),
        ..NONE
    },
];
