//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/secondaries.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Secondary command buffers executed from a primary: what each was recorded for
//! (its begin flags and inheritance info, recorded when it was begun) against where
//! the primary executes it, and the lifecycle rules of executing one.

use super::{call, How, Special, NONE};

const SECONDARY: &str = "checks the command buffer's level, recorded at its allocation";
const LIFECYCLE: &str = "checks the secondary's lifecycle state, which the device follows through every begin, end, reset and submission (a recording a check refused is not executable)";
const ONCE: &str = "checks, for a secondary begun without SIMULTANEOUS_USE (its begin flags, recorded), the secondaries the recording executed so far and those named before it in the call";
const UNPROVEN_FAMILY: &str = "checked by the safe methods in every build (the queue family of the secondary's pool against the primary's, as the pools' creation recorded them), but no test breaks it: lavapipe has one queue family";
const UNPROVEN_PROTECTED: &str = "checked by the safe methods in every build (the protection of the secondary's pool against the primary's, as the pools' creation recorded them, unless the device has protectedNoFault), but no test breaks it: lavapipe has no protectedMemory, so no pool is protected";
const CONTINUE: &str = "checks the secondary's begin flags, recorded when it was begun, against whether the primary is inside a render pass instance";
const CONTENTS: &str = "checks the contents the current subpass was begun with (vkCmdBeginRenderPass or vkCmdNextSubpass), which the recorder keeps";
const CONTENTS_OLD: &str = "the rule 06018 states for vkCmdBeginRenderPass and 06024 for dynamic rendering, whose checks refuse the case (their VUIDs name it)";
const INHERITED_PASS: &str = "checks the inheritance info the secondary was begun with (recorded then: its render pass's record, subpass and framebuffer) against the render pass instance the recorder is inside";
const RENDERING: &str = "checks the inheritance info the secondary was begun with (its chained VkCommandBufferInheritanceRenderingInfo, recorded then) against the flags, view mask and attachment formats of the dynamic rendering instance the recorder is inside (UNDEFINED where an attachment has no view)";
const UNPROVEN_QUERY_TYPE: &str = "checked by the safe methods in every build (the type of each query the recorder has begun and not ended), but no test breaks it yet: the core API begins only occlusion and pipeline statistics queries, and no test begins one of an extension's type";
const UNPROVEN_QUERIES: &str = "checked by the safe methods in every build (the queries the recorder has begun and not ended, their type, control flags and pool's pipeline statistics, against the inheritance info the secondary was begun with and the query types its recording begins), but no test breaks it: lavapipe has no inheritedQueries, so no query is active while a secondary runs";
const QUERIES: &str = "checks the queries the recorder has begun and not ended (their type, control flags and pool's pipeline statistics, recorded) against the inheritance info the secondary was begun with, the query types its recording begins and the inheritedQueries feature";
const ATTACHMENTS: &str = "every draw checks that no descriptor its shaders declare reaches the memory of an attachment of the current subpass (06537, 06538): in the primary against the instance's attachments, in a secondary against those of the framebuffer its inheritance names, which must be the instance's (00099), and where it names none, a draw whose shaders declare a descriptor of memory is refused; nothing else reads memory inside a render pass instance";
const NONE_SUSPENDED: &str = "the safe method refuses every secondary whose recording suspends or resumes a render pass instance (the error names 06021), so no instance lies between a suspended one and the one that resumes it";
const SUSPENDED: &str = "checks whether the secondary's recording suspends or resumes a render pass instance (only `begin_rendering_unchecked` begins one that does, and the recorder notes it), and refuses it: which commands run between a suspended instance and the one that resumes it is not followed (the 1.3.239 layer does not check it at this call: the error alone proves it)";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[Special {
    command: "vkCmdExecuteCommands",
    check: call(
        "special::secondaries::cmd_execute_commands_checks",
        &["self", "command_buffers"],
    ),
    before: call(
        "special::secondaries::cmd_execute_commands_before",
        &["self", "command_buffers"],
    ),
    after: call(
        "special::secondaries::cmd_execute_commands_done",
        &["self", "command_buffers"],
    ),
    settles: &[
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00088", How::Dynamic(SECONDARY)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00089", How::Dynamic(LIFECYCLE)),
        (
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00091",
            How::Dynamic("refuses a secondary without SIMULTANEOUS_USE that a submission may still be executing"),
        ),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00092", How::Dynamic(ONCE)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00093", How::Dynamic(ONCE)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00094", How::User(UNPROVEN_FAMILY)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-01820", How::User(UNPROVEN_PROTECTED)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-01821", How::User(UNPROVEN_PROTECTED)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00096", How::Dynamic(CONTINUE)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00100", How::Dynamic(CONTINUE)),
        ("VUID-vkCmdExecuteCommands-contents-06018", How::Dynamic(CONTENTS)),
        ("VUID-vkCmdExecuteCommands-contents-00095", How::Static(CONTENTS_OLD)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-06019", How::Dynamic(INHERITED_PASS)),
        ("VUID-vkCmdExecuteCommands-pBeginInfo-06020", How::Dynamic(INHERITED_PASS)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00099", How::Dynamic(INHERITED_PASS)),
        ("VUID-vkCmdExecuteCommands-flags-06024", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-pBeginInfo-06025", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-flags-06026", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-colorAttachmentCount-06027", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-imageView-06028", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-imageView-07606", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-pDepthAttachment-06029", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-pStencilAttachment-06030", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-pDepthAttachment-06774", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-pStencilAttachment-06775", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-viewMask-06031", How::Dynamic(RENDERING)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-00101", How::Dynamic(QUERIES)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-00102", How::User(UNPROVEN_QUERIES)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-00103", How::User(UNPROVEN_QUERIES)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-00104", How::User(UNPROVEN_QUERIES)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-00105", How::User(UNPROVEN_QUERIES)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-07594", How::User(UNPROVEN_QUERY_TYPE)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-06533", How::Static(ATTACHMENTS)),
        ("VUID-vkCmdExecuteCommands-commandBuffer-06534", How::Static(ATTACHMENTS)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-06535", How::Static(ATTACHMENTS)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-06536", How::Static(ATTACHMENTS)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-06021", How::Dynamic(SUSPENDED)),
        ("VUID-vkCmdExecuteCommands-pCommandBuffers-06022", How::Static(NONE_SUSPENDED)),
    ],
    ..NONE
}];
