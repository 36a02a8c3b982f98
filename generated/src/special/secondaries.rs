//! Secondary command buffers executed from a primary: what each was recorded for
//! (its begin flags and inheritance info, which the device recorded when it was
//! begun: `state::Inheritance`) against where the primary executes it (outside or
//! inside a render pass instance, which one and which subpass, the queries active),
//! the lifecycle rules of executing one, and the image layouts, query and event
//! states it needs and leaves.

use super::image_layouts::execute_layout_checks;
use super::refuse;
use crate::handles::CommandBuffer;
use crate::recorder::{PassInstance, Recorder, Scope};
use crate::state::{Inheritance, Uses};
use crate::Result;
use ash::vk;
use tuff_runtime::Vrc;

/// Refuses secondaries that cannot run where the primary executes them: the
/// lifecycle of each (a secondary, executable or pending, not pending without
/// SIMULTANEOUS_USE, not executed twice without it, of the primary's queue family
/// and protection), what it was recorded for against the render pass instance and
/// the active queries, and the layouts, query and event states it needs.
pub(crate) fn cmd_execute_commands_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) -> Result<()> {
    let primary = recorder.command_buffer().uses();
    for (i, h) in command_buffers.iter().enumerate() {
        let uses = h.uses();
        let inherited = uses.inheritance().unwrap_or_default();
        let before = &command_buffers[..i];
        lifecycle_checks(recorder, primary, uses, &inherited, h.level(), before)?;
        match &recorder.instance {
            None => {
                if inherited
                    .flags
                    .contains(vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE)
                {
                    refuse(
                        "VUID-vkCmdExecuteCommands-pCommandBuffers-00100",
                        format!("secondary {i} was recorded with RENDER_PASS_CONTINUE, and the primary executes it outside a render pass instance"),
                    )?;
                }
            }
            Some(instance) if instance.dynamic => rendering_checks(instance, &inherited, i)?,
            Some(instance) => render_pass_checks(instance, &inherited, i)?,
        }
        query_checks(recorder, uses, &inherited, i)?;
        if uses.suspends() {
            refuse(
                "VUID-vkCmdExecuteCommands-pCommandBuffers-06021",
                format!("secondary {i} suspends or resumes a render pass instance (recorded through begin_rendering_unchecked): which commands run between a suspended instance and the one that resumes it is not followed, so the safe method does not execute it"),
            )?;
        }
    }
    execute_layout_checks(recorder, command_buffers)?;
    super::query::execute_queries_checks(recorder, command_buffers)?;
    super::sync::execute_events_checks(recorder, command_buffers)
}

/// A secondary, executable or pending (00088, 00089), not pending without
/// SIMULTANEOUS_USE (00091) nor executed twice by the recording without it (00092, 00093), from a pool of the primary's
/// queue family (00094) and protection (01820, 01821, unless protectedNoFault).
fn lifecycle_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    primary: &Vrc<Uses>,
    uses: &Vrc<Uses>,
    inherited: &Inheritance,
    level: vk::CommandBufferLevel,
    before: &[&CommandBuffer],
) -> Result<()> {
    let device = recorder.device();
    let simultaneous = inherited
        .flags
        .contains(vk::CommandBufferUsageFlags::SIMULTANEOUS_USE);
    // Polled once: a signalled fence retires the submissions it completes.
    let pending = uses.is_pending(device);
    if level != vk::CommandBufferLevel::SECONDARY {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00088",
            "a command buffer executed by a primary was allocated as a primary",
        )?;
    }
    if !uses.is_executable() && !pending {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00089",
            "a secondary is neither executable nor pending: it was never ended, a check refused one of its commands, or it was reset or recorded again",
        )?;
    }
    if !simultaneous && pending {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00091",
            "a secondary command buffer without SIMULTANEOUS_USE is pending: a submission that uses it may still be executing",
        )?;
    }
    if !simultaneous && primary.executes_already(uses) {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00092",
            "a secondary without SIMULTANEOUS_USE was already executed by this recording",
        )?;
    }
    if !simultaneous && before.iter().any(|b| Vrc::ptr_eq(b.uses(), uses)) {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00093",
            "a secondary without SIMULTANEOUS_USE is named twice",
        )?;
    }
    let (family, protected) = primary.pool().unzip();
    let (theirs, their_protection) = uses.pool().unzip();
    if family != theirs {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00094",
            format!(
                "a secondary's pool is of queue family {theirs:?}, the primary's of {family:?}"
            ),
        )?;
    }
    if protected != their_protection && !super::render_pass::protected_no_fault(device) {
        match protected {
            Some(true) => refuse(
                "VUID-vkCmdExecuteCommands-commandBuffer-01820",
                "a protected primary executes an unprotected secondary, and the device has no protectedNoFault",
            )?,
            _ => refuse(
                "VUID-vkCmdExecuteCommands-commandBuffer-01821",
                "an unprotected primary executes a protected secondary, and the device has no protectedNoFault",
            )?,
        }
    }
    Ok(())
}

/// Inside a render pass instance begun with `vkCmdBeginRenderPass`: the subpass's
/// contents are secondaries (06018), and each continues the instance (00096): the
/// current subpass (06019) of a compatible render pass (06020), and its framebuffer
/// if it names one (00099).
fn render_pass_checks(instance: &PassInstance, inherited: &Inheritance, i: usize) -> Result<()> {
    if instance.contents != vk::SubpassContents::SECONDARY_COMMAND_BUFFERS {
        refuse(
            "VUID-vkCmdExecuteCommands-contents-06018",
            format!(
                "the current subpass was begun with {:?} contents, not SECONDARY_COMMAND_BUFFERS",
                instance.contents
            ),
        )?;
    }
    continues(inherited, i)?;
    if inherited.subpass != instance.subpass {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-06019",
            format!("secondary {i} was recorded for subpass {}, and the primary executes it in subpass {}", inherited.subpass, instance.subpass),
        )?;
    }
    let compatible = match (&inherited.record, &instance.record) {
        (Some(theirs), Some(ours)) => theirs.compatible(ours),
        // A render pass the wrappers did not make: only itself is known compatible.
        _ => inherited.render_pass == instance.render_pass,
    };
    if !compatible {
        refuse(
            "VUID-vkCmdExecuteCommands-pBeginInfo-06020",
            format!("secondary {i} was recorded for a render pass that is not compatible with the instance's"),
        )?;
    }
    if inherited.framebuffer != vk::Framebuffer::null()
        && inherited.framebuffer != instance.framebuffer
    {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00099",
            format!("secondary {i} was recorded for another framebuffer than the instance's"),
        )?;
    }
    Ok(())
}

/// A secondary executed inside a render pass instance continues it (00096).
fn continues(inherited: &Inheritance, i: usize) -> Result<()> {
    if !inherited
        .flags
        .contains(vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE)
    {
        refuse(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00096",
            format!("secondary {i} was recorded without RENDER_PASS_CONTINUE, and the primary executes it inside a render pass instance"),
        )?;
    }
    Ok(())
}

/// Inside dynamic rendering: the instance takes secondaries (06024), and each
/// continues it (00096) with no render pass (06025), the instance's flags but for
/// the contents bit (06026), view mask (06031) and attachment formats, `UNDEFINED`
/// where the instance has no view (06027 to 06030, 07606, 06774, 06775).
fn rendering_checks(instance: &PassInstance, inherited: &Inheritance, i: usize) -> Result<()> {
    let contents = vk::RenderingFlags::CONTENTS_SECONDARY_COMMAND_BUFFERS;
    if !instance.rendering_flags.contains(contents) {
        refuse(
            "VUID-vkCmdExecuteCommands-flags-06024",
            "the dynamic rendering instance was begun without CONTENTS_SECONDARY_COMMAND_BUFFERS in its flags",
        )?;
    }
    continues(inherited, i)?;
    if inherited.render_pass != vk::RenderPass::null() {
        refuse(
            "VUID-vkCmdExecuteCommands-pBeginInfo-06025",
            format!("secondary {i} was recorded for a render pass, and the primary executes it in dynamic rendering"),
        )?;
    }
    let (Some(theirs), Some(ours)) = (&inherited.rendering, &instance.rendering) else {
        return Ok(());
    };
    if theirs.flags & !contents != instance.rendering_flags & !contents {
        refuse(
            "VUID-vkCmdExecuteCommands-flags-06026",
            format!(
                "secondary {i} was recorded for rendering flags {:?}, the instance's are {:?}",
                theirs.flags, instance.rendering_flags
            ),
        )?;
    }
    let formats = &theirs.formats;
    if formats.colors.len() != ours.colors.len() {
        refuse(
            "VUID-vkCmdExecuteCommands-colorAttachmentCount-06027",
            format!(
                "secondary {i} was recorded for {} color attachments, the instance has {}",
                formats.colors.len(),
                ours.colors.len()
            ),
        )?;
    }
    for (slot, (theirs, ours)) in formats.colors.iter().zip(&ours.colors).enumerate() {
        format_check(
            (*theirs, *ours),
            (
                "VUID-vkCmdExecuteCommands-imageView-06028",
                "VUID-vkCmdExecuteCommands-imageView-07606",
            ),
            &format!("color attachment {slot} of secondary {i}"),
        )?;
    }
    format_check(
        (formats.depth, ours.depth),
        (
            "VUID-vkCmdExecuteCommands-pDepthAttachment-06029",
            "VUID-vkCmdExecuteCommands-pDepthAttachment-06774",
        ),
        &format!("the depth attachment of secondary {i}"),
    )?;
    format_check(
        (formats.stencil, ours.stencil),
        (
            "VUID-vkCmdExecuteCommands-pStencilAttachment-06030",
            "VUID-vkCmdExecuteCommands-pStencilAttachment-06775",
        ),
        &format!("the stencil attachment of secondary {i}"),
    )?;
    if formats.view_mask != ours.view_mask {
        refuse(
            "VUID-vkCmdExecuteCommands-viewMask-06031",
            format!(
                "secondary {i} was recorded for view mask {:#x}, the instance's is {:#x}",
                formats.view_mask, ours.view_mask
            ),
        )?;
    }
    Ok(())
}

/// A format a secondary was recorded for against the instance's: the same where the
/// instance's attachment has a view (`rules.0`), `UNDEFINED` where it has none
/// (`rules.1`, the instance's format then being `UNDEFINED`).
fn format_check(
    (theirs, ours): (vk::Format, vk::Format),
    rules: (&'static str, &'static str),
    what: &str,
) -> Result<()> {
    if theirs == ours {
        return Ok(());
    }
    if ours == vk::Format::UNDEFINED {
        refuse(
            rules.1,
            format!(
                "{what} was recorded as {theirs:?}, and the instance has no view there (UNDEFINED)"
            ),
        )
    } else {
        refuse(
            rules.0,
            format!("{what} was recorded as {theirs:?}, the instance's view is {ours:?}"),
        )
    }
}

/// The queries active in the primary: none without inheritedQueries (00101), only
/// occlusion and pipeline statistics ones (07594), an occlusion query only for a
/// secondary recorded for it with its control flags (00102, 00103), pipeline
/// statistics only those the secondary was recorded for (00104), and none of a type
/// the secondary begins (00105).
fn query_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    uses: &Uses,
    inherited: &Inheritance,
    i: usize,
) -> Result<()> {
    if recorder.queries.is_empty() {
        return Ok(());
    }
    let device = recorder.device();
    let inherited_queries = device.live().with_features(|f| f.v10.inherited_queries);
    if inherited_queries == vk::FALSE {
        refuse(
            "VUID-vkCmdExecuteCommands-commandBuffer-00101",
            "a query is active, and the device did not enable the inheritedQueries feature",
        )?;
    }
    let begun = uses.query_types();
    for q in &recorder.queries {
        match q.ty {
            vk::QueryType::OCCLUSION => {
                if !inherited.occlusion_query_enable {
                    refuse(
                        "VUID-vkCmdExecuteCommands-commandBuffer-00102",
                        format!("an occlusion query is active, and secondary {i} was recorded without occlusionQueryEnable"),
                    )?;
                }
                if !inherited.query_flags.contains(q.flags) {
                    refuse(
                        "VUID-vkCmdExecuteCommands-commandBuffer-00103",
                        format!("an occlusion query is active with {:?}, and secondary {i} was recorded for {:?}", q.flags, inherited.query_flags),
                    )?;
                }
            }
            vk::QueryType::PIPELINE_STATISTICS => {
                let counted = device
                    .live()
                    .query_pool(q.pool)
                    .map_or(vk::QueryPipelineStatisticFlags::empty(), |p| p.statistics);
                if !inherited.pipeline_statistics.contains(counted) {
                    refuse(
                        "VUID-vkCmdExecuteCommands-commandBuffer-00104",
                        format!("a pipeline statistics query counting {counted:?} is active, and secondary {i} was recorded for {:?}", inherited.pipeline_statistics),
                    )?;
                }
            }
            ty => refuse(
                "VUID-vkCmdExecuteCommands-commandBuffer-07594",
                format!("a query of type {ty:?} is active: only occlusion and pipeline statistics queries may be while secondaries execute"),
            )?,
        }
        if begun.contains(&q.ty) {
            refuse(
                "VUID-vkCmdExecuteCommands-pCommandBuffers-00105",
                format!(
                    "a {:?} query is active, and secondary {i} begins one of that type",
                    q.ty
                ),
            )?;
        }
    }
    Ok(())
}

/// The recording executes the secondaries: the layouts, query and event states they
/// leave are the primary's.
pub(crate) fn cmd_execute_commands_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) {
    super::image_layouts::execute_layouts_done(recorder, command_buffers);
    super::query::execute_queries_done(recorder, command_buffers);
    super::sync::execute_events_done(recorder, command_buffers);
}

/// A primary is pending while it may run; so are the secondaries it executes.
pub(crate) fn cmd_execute_commands_before<S: Scope>(
    recorder: &Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) {
    for h in command_buffers {
        recorder.command_buffer().uses().executes(h.uses());
    }
}

/// The rules of a secondary's `VkCommandBufferInheritanceRenderingInfo` formats and
/// view mask (its formats' values are its implicit checks').
const INHERITED_FORMATS: super::rendering::FormatRules = super::rendering::FormatRules {
    multiview: "VUID-VkCommandBufferInheritanceRenderingInfo-multiview-06008",
    view_count: "VUID-VkCommandBufferInheritanceRenderingInfo-viewMask-06009",
    values: ["", "", ""],
    color_feature: "VUID-VkCommandBufferInheritanceRenderingInfo-pColorAttachmentFormats-06006",
    depth: [
        "VUID-VkCommandBufferInheritanceRenderingInfo-depthAttachmentFormat-06540",
        "VUID-VkCommandBufferInheritanceRenderingInfo-depthAttachmentFormat-06007",
    ],
    stencil: [
        "VUID-VkCommandBufferInheritanceRenderingInfo-stencilAttachmentFormat-06541",
        "VUID-VkCommandBufferInheritanceRenderingInfo-stencilAttachmentFormat-06199",
    ],
    same: "VUID-VkCommandBufferInheritanceRenderingInfo-depthAttachmentFormat-06200",
};

/// The query control and pipeline statistics flags of core Vulkan.
const CONTROL_BITS: vk::QueryControlFlags = vk::QueryControlFlags::PRECISE;
const STATISTICS_BITS: u32 = 0x7ff;

/// What a secondary is begun for, before it is: the queries its inheritance info
/// lets it run under against the inheritedQueries and pipelineStatisticsQuery
/// features (00057, 02788, 00058, 02789), and the formats and view mask of the
/// dynamic rendering a chained `VkCommandBufferInheritanceRenderingInfo` describes
/// ([`INHERITED_FORMATS`]; its rasterization samples are one sample count by its
/// implicit checks).
pub(crate) fn inheritance_checks(device: &crate::Device, inherited: &Inheritance) -> Result<()> {
    let (queries, statistics) = device
        .live()
        .with_features(|f| (f.v10.inherited_queries, f.v10.pipeline_statistics_query));
    let flags = inherited.query_flags;
    if queries == vk::FALSE && !flags.is_empty() {
        refuse(
            "VUID-VkCommandBufferInheritanceInfo-queryFlags-02788",
            format!("queryFlags is {flags:?}, and the device did not enable inheritedQueries"),
        )?;
    }
    if !(flags & !CONTROL_BITS).is_empty() {
        refuse(
            "VUID-VkCommandBufferInheritanceInfo-queryFlags-00057",
            format!("queryFlags ({flags:?}) holds bits that are no VkQueryControlFlagBits"),
        )?;
    }
    let counted = inherited.pipeline_statistics;
    if statistics == vk::FALSE && !counted.is_empty() {
        refuse(
            "VUID-VkCommandBufferInheritanceInfo-pipelineStatistics-00058",
            format!("pipelineStatistics is {counted:?}, and the device did not enable pipelineStatisticsQuery"),
        )?;
    }
    if counted.as_raw() & !STATISTICS_BITS != 0 {
        refuse(
            "VUID-VkCommandBufferInheritanceInfo-pipelineStatistics-02789",
            format!("pipelineStatistics ({counted:?}) holds bits that are no VkQueryPipelineStatisticFlagBits of core Vulkan"),
        )?;
    }
    let Some(rendering) = &inherited.rendering else {
        return Ok(());
    };
    super::rendering::formats_checks(
        device,
        &rendering.formats,
        &INHERITED_FORMATS,
        "the VkCommandBufferInheritanceRenderingInfo",
    )
}
