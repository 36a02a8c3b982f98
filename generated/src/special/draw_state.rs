//! Commands that set draw state: pipeline, vertex, index and descriptor set binds, push
//! constants, viewports, scissors and the other dynamic states, each checked and recorded.

use super::buffer::used_buffer;
use super::{limits, refuse};
use crate::handles::*;
use crate::recorder::{Recorder, Scope};
use crate::state::{LayoutRecord, SetLayoutRecord};
use crate::{Handle, Result};
use ash::vk;
use ash::vk::Handle as _;
use smallvec::SmallVec;
use tuff_runtime::Vrc;

/// The rules a vertex-buffer binding breaks, one VUID each (empty where the command
/// has no such parameter).
struct VertexRules {
    /// The buffer has `VERTEX_BUFFER` usage.
    usage: &'static str,
    /// It is bound to memory.
    memory: &'static str,
    /// The offset lies inside it.
    offset: &'static str,
    /// The offset plus the size does too.
    size: &'static str,
    /// `firstBinding` + `bindingCount` is within `maxVertexInputBindings`.
    first_binding: &'static str,
    /// Each stride is within `maxVertexInputBindingStride`.
    stride: &'static str,
}

/// Each binding of `buffers` at `offsets` (and `sizes`, where given) lies inside its
/// buffer, which has vertex-buffer usage and memory.
fn check_vertex_bindings<S: Scope>(
    recorder: &Recorder<'_, S>,
    (first_binding, buffers): (u32, &[&Buffer]),
    offsets: &[vk::DeviceSize],
    (sizes, strides): (&[vk::DeviceSize], &[vk::DeviceSize]),
    rules: VertexRules,
) -> Result<()> {
    let device = recorder.device();
    let limits = limits(device);
    {
        let max = limits.max_vertex_input_bindings;
        if u64::from(first_binding) + buffers.len() as u64 > u64::from(max) {
            refuse(
                rules.first_binding,
                format!(
                    "`firstBinding` + `bindingCount` must be less than or equal to \
                     `VkPhysicalDeviceLimits::maxVertexInputBindings` (`firstBinding` = \
                     {first_binding}, `bindingCount` = {}, maxVertexInputBindings = {max})",
                    buffers.len()
                ),
            )?;
        }
        let max = limits.max_vertex_input_binding_stride;
        if let Some((i, stride)) = strides
            .iter()
            .enumerate()
            .find(|(_, &s)| s > u64::from(max))
        {
            refuse(
                rules.stride,
                format!(
                    "each element of `pStrides` must be less than or equal to \
                     `VkPhysicalDeviceLimits::maxVertexInputBindingStride` (`pStrides[{i}]` = \
                     {stride}, maxVertexInputBindingStride = {max})"
                ),
            )?;
        }
    }
    for (i, (b, &offset)) in buffers.iter().zip(offsets).enumerate() {
        let usage = vk::BufferUsageFlags::VERTEX_BUFFER;
        let record = used_buffer(
            recorder,
            b,
            usage,
            (rules.usage, rules.memory),
            &format_args!("pBuffers[{i}]"),
        )?;
        if offset >= record.size {
            refuse(rules.offset, format!("pOffsets[{i}] must be less than the size of pBuffers[{i}] (offset = {offset}, size = {})", record.size))?;
        }
        // VK_WHOLE_SIZE is the rest of the buffer.
        if let Some(&size) = sizes.get(i).filter(|&&s| s != vk::WHOLE_SIZE) {
            if size > record.size - offset {
                refuse(rules.size, format!("pOffsets[{i}] plus pSizes[{i}] must be at most the size of pBuffers[{i}] (offset = {offset}, size = {size}, size of the buffer = {})", record.size))?;
            }
        }
    }
    Ok(())
}

/// The checks of `vkCmdBindVertexBuffers` that keep each binding inside its buffer.
pub(crate) fn cmd_bind_vertex_buffers_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    first_binding: u32,
    buffers: &[&Buffer],
    offsets: &[vk::DeviceSize],
) -> Result<()> {
    let rules = VertexRules {
        usage: "VUID-vkCmdBindVertexBuffers-pBuffers-00627",
        memory: "VUID-vkCmdBindVertexBuffers-pBuffers-00628",
        offset: "VUID-vkCmdBindVertexBuffers-pOffsets-00626",
        size: "",
        first_binding: "VUID-vkCmdBindVertexBuffers-firstBinding-00625",
        stride: "",
    };
    check_vertex_bindings(
        recorder,
        (first_binding, buffers),
        offsets,
        (&[], &[]),
        rules,
    )
}

/// The checks of `vkCmdBindVertexBuffers2` that keep each binding inside its buffer.
pub(crate) fn cmd_bind_vertex_buffers2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    first_binding: u32,
    buffers: &[&Buffer],
    offsets: &[vk::DeviceSize],
    (sizes, strides): (&[vk::DeviceSize], &[vk::DeviceSize]),
) -> Result<()> {
    let rules = VertexRules {
        usage: "VUID-vkCmdBindVertexBuffers2-pBuffers-03359",
        memory: "VUID-vkCmdBindVertexBuffers2-pBuffers-03360",
        offset: "VUID-vkCmdBindVertexBuffers2-pOffsets-03357",
        size: "VUID-vkCmdBindVertexBuffers2-pSizes-03358",
        first_binding: "VUID-vkCmdBindVertexBuffers2-firstBinding-03356",
        stride: "VUID-vkCmdBindVertexBuffers2-pStrides-03362",
    };
    check_vertex_bindings(
        recorder,
        (first_binding, buffers),
        offsets,
        (sizes, strides),
        rules,
    )
}

/// The checks of `vkCmdBindIndexBuffer` that keep the binding inside the buffer.
///
/// Registries from 1.4 on (maintenance6) let the buffer be absent: then nothing is
/// read from it, and there is nothing to check.
pub(crate) fn cmd_bind_index_buffer_checks<'b, S: Scope>(
    recorder: &Recorder<'_, S>,
    buffer: impl Into<Option<&'b Buffer>>,
    offset: vk::DeviceSize,
    index_type: vk::IndexType,
) -> Result<()> {
    let Some(buffer) = buffer.into() else {
        return Ok(());
    };
    let record = used_buffer(
        recorder,
        buffer,
        vk::BufferUsageFlags::INDEX_BUFFER,
        (
            "VUID-vkCmdBindIndexBuffer-buffer-00433",
            "VUID-vkCmdBindIndexBuffer-buffer-00434",
        ),
        &"buffer",
    )?;
    // Every allocation starts aligned for any resource of the device, so the
    // address's alignment is that of the offset in memory plus the offset in the buffer.
    let size = match index_type {
        vk::IndexType::UINT16 => 2,
        vk::IndexType::UINT32 => 4,
        _ => 1,
    };
    if (record.memory_offset.wrapping_add(offset)) % size != 0 {
        refuse(
            "VUID-vkCmdBindIndexBuffer-offset-00432",
            format!(
                "The sum of `offset` and the address of the range of `VkDeviceMemory` object \
                 that is backing `buffer`, must be a multiple of the type indicated by \
                 `indexType` (`offset` = {offset}, offset in memory = {}, `indexType` = \
                 {index_type:?})",
                record.memory_offset
            ),
        )?;
    }
    if offset >= record.size {
        refuse(
            "VUID-vkCmdBindIndexBuffer-offset-00431",
            format!(
                "offset must be less than the size of buffer (offset = {offset}, size = {})",
                record.size
            ),
        )?;
    }
    Ok(())
}

/// The checks of `vkCmdPushConstants` that keep the write inside the layout's
/// ranges, which the drivers copy into arrays of `maxPushConstantsSize` bytes.
pub(crate) fn cmd_push_constants_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    layout: &PipelineLayout,
    stage_flags: vk::ShaderStageFlags,
    offset: u32,
    values: &[u8],
) -> Result<()> {
    let key = (layout.raw(), stage_flags, offset, values.len());
    if recorder.last_push == Some(key) {
        return Ok(());
    }
    let size = values.len() as u64;
    let offset = u64::from(offset);
    if offset % 4 != 0 {
        refuse(
            "VUID-vkCmdPushConstants-offset-00368",
            format!("offset must be a multiple of 4 (offset = {offset})"),
        )?;
    }
    if size % 4 != 0 {
        refuse(
            "VUID-vkCmdPushConstants-size-00369",
            format!("size must be a multiple of 4 (size = {size})"),
        )?;
    }
    let max = u64::from(limits(recorder.device()).max_push_constants_size);
    if offset >= max {
        refuse("VUID-vkCmdPushConstants-offset-00370", format!("offset must be less than maxPushConstantsSize (offset = {offset}, maxPushConstantsSize = {max})"))?;
    }
    if size > max - offset {
        refuse("VUID-vkCmdPushConstants-size-00371", format!("size must be at most maxPushConstantsSize minus offset (size = {size}, offset = {offset}, maxPushConstantsSize = {max})"))?;
    }
    let record = recorder.layout_record(layout)?;
    check_push_ranges(&record, stage_flags, offset, offset + size)?;
    recorder.last_push = Some(key);
    Ok(())
}

/// Every byte of `start..end` is in a range of each stage of `stages` (01795), and
/// every range that holds one of those bytes has only stages of `stages` (01796).
fn check_push_ranges(
    record: &LayoutRecord,
    stages: vk::ShaderStageFlags,
    start: u64,
    end: u64,
) -> Result<()> {
    for bit in (0..32).map(|i| vk::ShaderStageFlags::from_raw(1 << i)) {
        if !stages.contains(bit) {
            continue;
        }
        // Walk the bytes forward through the ranges of this stage.
        let mut at = start;
        while at < end {
            let next = record
                .push_ranges
                .iter()
                .filter(|r| r.stage_flags.contains(bit))
                .filter(|r| {
                    u64::from(r.offset) <= at && at < u64::from(r.offset) + u64::from(r.size)
                })
                .map(|r| u64::from(r.offset) + u64::from(r.size))
                .max();
            match next {
                Some(n) => at = n,
                None => {
                    return refuse(
                        "VUID-vkCmdPushConstants-offset-01795",
                        format!(
                        "byte {at} for stage {bit:?} is in no push-constant range of the layout"
                    ),
                    )
                }
            }
        }
    }
    for r in &record.push_ranges {
        let (r0, r1) = (u64::from(r.offset), u64::from(r.offset) + u64::from(r.size));
        if r0 < end && start < r1 && !stages.contains(r.stage_flags) {
            refuse(
                "VUID-vkCmdPushConstants-offset-01796",
                format!("stageFlags ({stages:?}) must include every stage ({:?}) of the range {r0}..{r1} the write overlaps", r.stage_flags),
            )?;
        }
    }
    Ok(())
}

/// The checks of `vkCmdBindDescriptorSets` that keep the driver inside the layout's
/// sets and the dynamic offsets.
pub(crate) fn cmd_bind_descriptor_sets_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    bind_point: vk::PipelineBindPoint,
    layout: &PipelineLayout,
    first_set: u32,
    descriptor_sets: &[&DescriptorSet],
    dynamic_offsets: &[u32],
) -> Result<()> {
    let record = recorder.layout_record(layout)?;
    let sets = record.set_dynamics.len() as u64;
    if u64::from(first_set) + descriptor_sets.len() as u64 > sets {
        refuse(
            "VUID-vkCmdBindDescriptorSets-firstSet-00360",
            format!("firstSet plus descriptorSetCount must be at most the layout's setLayoutCount (firstSet = {first_set}, descriptorSetCount = {}, setLayoutCount = {sets})", descriptor_sets.len()),
        )?;
    }
    let needs = if bind_point == vk::PipelineBindPoint::COMPUTE {
        vk::QueueFlags::COMPUTE
    } else {
        vk::QueueFlags::GRAPHICS
    };
    if !recorder.pool_queue_flags().contains(needs) {
        refuse(
            "VUID-vkCmdBindDescriptorSets-pipelineBindPoint-00361",
            format!("the command buffer's pool is of a queue family without {needs:?}, which {bind_point:?} needs"),
        )?;
    }
    let live = recorder.device().live();
    let layouts: SmallVec<[Option<Vrc<SetLayoutRecord>>; 4]> = descriptor_sets
        .iter()
        .map(|s| live.set_layout_of(s.raw()))
        .collect();
    for (i, got) in layouts.iter().enumerate() {
        let wanted = record.sets.get(first_set as usize + i);
        let matches = match (got, wanted) {
            (Some(got), Some(wanted)) => SetLayoutRecord::matches(got, wanted),
            _ => false,
        };
        if !matches {
            refuse(
                "VUID-vkCmdBindDescriptorSets-pDescriptorSets-00358",
                format!("pDescriptorSets[{i}] was allocated with a set layout that is not the layout's set {} (nor identically defined)", first_set as usize + i),
            )?;
        }
    }
    let dynamics: u64 = layouts
        .iter()
        .map(|l| u64::from(l.as_ref().map_or(0, |l| l.dynamics())))
        .sum();
    if dynamics != dynamic_offsets.len() as u64 {
        refuse(
            "VUID-vkCmdBindDescriptorSets-dynamicOffsetCount-00359",
            format!("dynamicOffsetCount must equal the number of dynamic descriptors in the sets (dynamicOffsetCount = {}, dynamic descriptors = {dynamics})", dynamic_offsets.len()),
        )?;
    }
    if !dynamic_offsets.is_empty() {
        dynamic_offset_checks(
            recorder.device(),
            descriptor_sets,
            &layouts,
            dynamic_offsets,
        )?;
    }
    Ok(())
}

/// Each dynamic offset, in the order of the sets, their bindings and array elements:
/// aligned for its descriptor's type, 0 for a descriptor written with
/// `VK_WHOLE_SIZE`, and keeping the written range inside its buffer.
fn dynamic_offset_checks(
    device: &Device,
    sets: &[&DescriptorSet],
    layouts: &[Option<Vrc<SetLayoutRecord>>],
    offsets: &[u32],
) -> Result<()> {
    let limits = limits(device);
    let live = device.live();
    let mut next = offsets.iter().copied().enumerate();
    for (set, layout) in sets.iter().zip(layouts) {
        let Some(layout) = layout else { continue };
        for b in &layout.bindings {
            let (alignment, vuid) = match b.ty {
                vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC => (
                    limits.min_uniform_buffer_offset_alignment,
                    "VUID-vkCmdBindDescriptorSets-pDynamicOffsets-01971",
                ),
                vk::DescriptorType::STORAGE_BUFFER_DYNAMIC => (
                    limits.min_storage_buffer_offset_alignment,
                    "VUID-vkCmdBindDescriptorSets-pDynamicOffsets-01972",
                ),
                _ => continue,
            };
            for element in 0..b.count {
                let Some((i, offset)) = next.next() else {
                    return Ok(());
                };
                if alignment != 0 && u64::from(offset) % alignment != 0 {
                    refuse(
                        vuid,
                        format!("pDynamicOffsets[{i}] ({offset}) is not a multiple of {alignment}, the alignment of a {:?} descriptor", b.ty),
                    )?;
                }
                let Some((at, range, size)) = live.dynamic_range(set.raw(), (b.binding, element))
                else {
                    continue;
                };
                if range == vk::WHOLE_SIZE {
                    if offset != 0 {
                        refuse(
                            "VUID-vkCmdBindDescriptorSets-pDescriptorSets-06715",
                            format!("pDynamicOffsets[{i}] ({offset}) is for binding {} element {element}, written with VK_WHOLE_SIZE, so it must be 0", b.binding),
                        )?;
                    }
                } else if at.saturating_add(u64::from(offset)).saturating_add(range) > size {
                    refuse(
                        "VUID-vkCmdBindDescriptorSets-pDescriptorSets-01979",
                        format!("binding {} element {element}: offset {at} plus pDynamicOffsets[{i}] ({offset}) plus range {range} is past the buffer's {size} bytes", b.binding),
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// `first + count` viewports or scissors within `1..=maxViewports`: drivers keep them
/// in arrays of that many.
fn check_viewport_range(
    device: &Device,
    first: u32,
    count: usize,
    vuid: &'static str,
    what: &str,
) -> Result<()> {
    let max = u64::from(limits(device).max_viewports);
    let end = u64::from(first) + count as u64;
    if end == 0 || end > max {
        refuse(
            vuid,
            format!("the first {what} plus their count must be between 1 and maxViewports (first = {first}, count = {count}, maxViewports = {max})"),
        )?;
    }
    Ok(())
}

/// Without the multiViewport feature, one viewport or scissor, the first.
fn check_single_viewport(
    device: &Device,
    first: u32,
    count: usize,
    (first_vuid, count_vuid): (Option<&'static str>, &'static str),
) -> Result<()> {
    if device.live().features().multi_viewport == vk::TRUE {
        return Ok(());
    }
    if let Some(vuid) = first_vuid.filter(|_| first != 0) {
        refuse(
            vuid,
            format!("without the multiViewport feature the first index must be 0 ({first})"),
        )?;
    }
    if count != 1 {
        refuse(
            count_vuid,
            format!("without the multiViewport feature the count must be 1 ({count})"),
        )?;
    }
    Ok(())
}

/// Scissor offsets are not negative and their ends do not overflow.
pub(super) fn check_scissors(
    scissors: &[vk::Rect2D],
    vuids: (&'static str, &'static str, &'static str),
) -> Result<()> {
    for (i, r) in scissors.iter().enumerate() {
        if r.offset.x < 0 || r.offset.y < 0 {
            refuse(
                vuids.0,
                format!(
                    "pScissors[{i}].offset must not be negative ({}, {})",
                    r.offset.x, r.offset.y
                ),
            )?;
        }
        if i64::from(r.offset.x) + i64::from(r.extent.width) > i64::from(i32::MAX) {
            refuse(
                vuids.1,
                format!(
                    "pScissors[{i}]: offset.x + extent.width overflows ({} + {})",
                    r.offset.x, r.extent.width
                ),
            )?;
        }
        if i64::from(r.offset.y) + i64::from(r.extent.height) > i64::from(i32::MAX) {
            refuse(
                vuids.2,
                format!(
                    "pScissors[{i}]: offset.y + extent.height overflows ({} + {})",
                    r.offset.y, r.extent.height
                ),
            )?;
        }
    }
    Ok(())
}

/// The checks of `vkCmdSetViewport` that keep the viewports inside the driver's array.
pub(crate) fn cmd_set_viewport_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    first_viewport: u32,
    viewports: &[vk::Viewport],
) -> Result<()> {
    let device = recorder.device();
    let rules = (
        Some("VUID-vkCmdSetViewport-firstViewport-01224"),
        "VUID-vkCmdSetViewport-viewportCount-01225",
    );
    check_single_viewport(device, first_viewport, viewports.len(), rules)?;
    let vuid = "VUID-vkCmdSetViewport-firstViewport-01223";
    check_viewport_range(device, first_viewport, viewports.len(), vuid, "viewport")
}

/// The checks of `vkCmdSetScissor` that keep the scissors inside the driver's array.
pub(crate) fn cmd_set_scissor_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    first_scissor: u32,
    scissors: &[vk::Rect2D],
) -> Result<()> {
    let device = recorder.device();
    let rules = (
        Some("VUID-vkCmdSetScissor-firstScissor-00593"),
        "VUID-vkCmdSetScissor-scissorCount-00594",
    );
    check_single_viewport(device, first_scissor, scissors.len(), rules)?;
    let vuid = "VUID-vkCmdSetScissor-firstScissor-00592";
    check_viewport_range(device, first_scissor, scissors.len(), vuid, "scissor")?;
    check_scissors(
        scissors,
        (
            "VUID-vkCmdSetScissor-x-00595",
            "VUID-vkCmdSetScissor-offset-00596",
            "VUID-vkCmdSetScissor-offset-00597",
        ),
    )
}

/// The checks of `vkCmdSetViewportWithCount` that keep the viewports inside the
/// driver's array.
pub(crate) fn cmd_set_viewport_with_count_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    viewports: &[vk::Viewport],
) -> Result<()> {
    let device = recorder.device();
    let rules = (None, "VUID-vkCmdSetViewportWithCount-viewportCount-03395");
    check_single_viewport(device, 0, viewports.len(), rules)?;
    let vuid = "VUID-vkCmdSetViewportWithCount-viewportCount-03394";
    check_viewport_range(device, 0, viewports.len(), vuid, "viewport")
}

/// The checks of `vkCmdSetScissorWithCount` that keep the scissors inside the
/// driver's array.
pub(crate) fn cmd_set_scissor_with_count_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    scissors: &[vk::Rect2D],
) -> Result<()> {
    let device = recorder.device();
    let rules = (None, "VUID-vkCmdSetScissorWithCount-scissorCount-03398");
    check_single_viewport(device, 0, scissors.len(), rules)?;
    let vuid = "VUID-vkCmdSetScissorWithCount-scissorCount-03397";
    check_viewport_range(device, 0, scissors.len(), vuid, "scissor")?;
    check_scissors(
        scissors,
        (
            "VUID-vkCmdSetScissorWithCount-x-03399",
            "VUID-vkCmdSetScissorWithCount-offset-03400",
            "VUID-vkCmdSetScissorWithCount-offset-03401",
        ),
    )
}

/// The recorder remembers the pipeline bound at its bind point.
pub(crate) fn cmd_bind_pipeline_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    pipeline_bind_point: vk::PipelineBindPoint,
    pipeline: &Pipeline,
) {
    if let Some(i) = crate::recorder::Bound::index(pipeline_bind_point) {
        recorder.bound[i].pipeline = recorder.device().live().pipeline(pipeline.raw());
    }
    if pipeline_bind_point == vk::PipelineBindPoint::COMPUTE {
        recorder.compute_dynamic = 0;
    }
    if pipeline_bind_point == vk::PipelineBindPoint::GRAPHICS {
        // A state static in the new pipeline must be set again before a later
        // pipeline that has it dynamic draws.
        let dynamic = recorder.bound[0].pipeline.as_ref().map_or(0, |p| p.dynamic);
        recorder.dynamic = (recorder.dynamic.0 & dynamic, 0);
        recorder.depth_stencil.forget_static(dynamic);
    }
    // The first graphics pipeline of a subpass sets its sample count.
    let samples = recorder.bound[0].pipeline.as_ref().map(|p| p.samples);
    if let (Some(instance), vk::PipelineBindPoint::GRAPHICS) =
        (recorder.instance.as_mut(), pipeline_bind_point)
    {
        instance.samples = instance.samples.or(samples);
    }
}

/// After `vkCmdBindVertexBuffers2`: the bindings bound, and with strides given, the
/// vertex input binding stride state set.
pub(crate) fn cmd_bind_vertex_buffers2_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    first_binding: u32,
    buffers: &[&Buffer],
    offsets: &[vk::DeviceSize],
    (sizes, strides): (&[vk::DeviceSize], &[vk::DeviceSize]),
) {
    cmd_bind_vertex_buffers_done(recorder, first_binding, buffers, offsets, (sizes, strides));
    if !strides.is_empty() {
        dynamic_state_set(
            recorder,
            crate::state::dynamic_bit(vk::DynamicState::VERTEX_INPUT_BINDING_STRIDE),
        );
    }
}

/// `vkCmdSetViewportWithCount` (`bits` its state) or `vkCmdSetScissorWithCount`:
/// the state is set, with `count` viewports or scissors.
pub(crate) fn viewport_count_set<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    count: usize,
    bits: u32,
) {
    let count = u32::try_from(count).unwrap_or(u32::MAX);
    if bits == crate::state::dynamic_bit(vk::DynamicState::VIEWPORT_WITH_COUNT) {
        recorder.counts.0 = Some(count);
    } else {
        recorder.counts.1 = Some(count);
    }
    dynamic_state_set(recorder, bits);
}

/// A command that sets a dynamic depth, stencil or rasterizer discard value (`bits`
/// its state): the value is kept for the checks of draws that write the
/// depth/stencil attachment.
pub(crate) fn depth_stencil_set<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    value: crate::recorder::Set,
    bits: u32,
) {
    recorder.depth_stencil.set(value);
    dynamic_state_set(recorder, bits);
}

/// A dynamic state setting command: the states of `bits` are set.
pub(crate) fn dynamic_state_set<S: Scope>(recorder: &mut Recorder<'_, S>, bits: u32) {
    recorder.dynamic.0 |= bits;
    recorder.dynamic.1 |= bits;
    recorder.compute_dynamic |= bits;
}

/// The recorder remembers the layouts of the sets bound at their numbers.
pub(crate) fn cmd_bind_descriptor_sets_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    pipeline_bind_point: vk::PipelineBindPoint,
    first_set: u32,
    descriptor_sets: &[&DescriptorSet],
) {
    let Some(i) = crate::recorder::Bound::index(pipeline_bind_point) else {
        return;
    };
    let last = recorder.sets.last().map(|(raw, _)| *raw);
    let bound: SmallVec<[_; 4]> = {
        let live = recorder.device().live();
        descriptor_sets
            .iter()
            .map(|s| {
                (
                    s.raw(),
                    live.set_layout_of(s.raw()),
                    live.set_bound(s.raw()),
                )
            })
            .collect()
    };
    let bound_points = &mut recorder.bound[i];
    for (n, (raw, layout, (generation, images, written))) in bound.into_iter().enumerate() {
        let n = first_set as usize + n;
        if bound_points.sets.len() <= n {
            bound_points.sets.resize(n + 1, None);
            bound_points.images.resize(n + 1, None);
            bound_points.written.resize(n + 1, None);
        }
        bound_points.sets[n] = layout;
        bound_points.images[n] = images;
        bound_points.written[n] = written;
        // A run of binds of one set (with new dynamic offsets) is remembered once.
        if descriptor_sets.len() > 1 || last != Some(raw.as_raw()) {
            recorder.sets.push((raw.as_raw(), generation));
        }
    }
}

/// After `vkCmdPushConstants`: its bytes are set, for the layouts compatible for
/// push constants with `layout`; a push with a layout of other ranges leaves the
/// earlier bytes undefined.
pub(crate) fn cmd_push_constants_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    layout: &PipelineLayout,
    offset: u32,
    values: &[u8],
) {
    let key = (layout.raw(), offset, values.len());
    if recorder.pushed.as_ref().is_some_and(|p| p.last == key) {
        return;
    }
    let Ok(record) = recorder.layout_record(layout) else {
        return;
    };
    let compatible = recorder
        .pushed
        .as_ref()
        .is_some_and(|p| Vrc::ptr_eq(&p.layout, &record) || p.layout.same_push_ranges(&record));
    if !compatible {
        recorder.pushed = Some(crate::recorder::Pushed::new(record));
        // Draws checked with the earlier bytes set are checked again.
        recorder.state_changed();
    }
    if let Some(p) = recorder.pushed.as_mut() {
        p.set(offset, values.len() as u32);
        p.last = key;
    }
}

/// The recorder remembers the vertex-buffer bindings bound (the first 64, the ones
/// a pipeline's record names).
pub(crate) fn cmd_bind_vertex_buffers_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    first_binding: u32,
    buffers: &[&Buffer],
    offsets: &[vk::DeviceSize],
    (sizes, strides): (&[vk::DeviceSize], &[vk::DeviceSize]),
) {
    let ranges: SmallVec<[_; 4]> = {
        let live = recorder.device().live();
        buffers
            .iter()
            .enumerate()
            .map(|(i, b)| {
                let size = live.buffer(b.raw()).map_or(0, |r| r.size);
                let offset = offsets.get(i).copied().unwrap_or(0);
                let bytes = match sizes.get(i) {
                    Some(&s) if s != vk::WHOLE_SIZE => s,
                    _ => size.saturating_sub(offset),
                };
                crate::recorder::VertexRange {
                    buffer: (b.raw(), offset),
                    bytes,
                    stride: strides.get(i).copied(),
                }
            })
            .collect()
    };
    let bound = &mut recorder.bound[0];
    for (i, mut range) in ranges.into_iter().enumerate() {
        let binding = first_binding as usize + i;
        if binding < 64 {
            bound.vertex |= 1 << binding;
        }
        if bound.vertex_ranges.len() <= binding {
            bound.vertex_ranges.resize(binding + 1, None);
        }
        // A bind without strides leaves the binding's dynamic stride as it was.
        if range.stride.is_none() {
            range.stride = bound.vertex_ranges[binding].and_then(|r| r.stride);
        }
        bound.vertex_ranges[binding] = Some(range);
    }
}

/// Refuses a pipeline bound at a bind point of another kind.
pub(crate) fn cmd_bind_pipeline_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    pipeline_bind_point: vk::PipelineBindPoint,
    pipeline: &Pipeline,
) -> Result<()> {
    let (needs, vuid) = match pipeline_bind_point {
        vk::PipelineBindPoint::COMPUTE => (
            vk::QueueFlags::COMPUTE,
            "VUID-vkCmdBindPipeline-pipelineBindPoint-00777",
        ),
        _ => (
            vk::QueueFlags::GRAPHICS,
            "VUID-vkCmdBindPipeline-pipelineBindPoint-00778",
        ),
    };
    if !recorder.pool_queue_flags().contains(needs) {
        refuse(
            vuid,
            format!(
                "the command buffer's pool is of a queue family without {needs:?} operations \
                 (its flags: {:?}), so it cannot bind a {pipeline_bind_point:?} pipeline",
                recorder.pool_queue_flags()
            ),
        )?;
    }
    let Some(record) = recorder.device().live().pipeline(pipeline.raw()) else {
        return Ok(());
    };
    // A subpass without attachments takes its sample count from its first graphics
    // pipeline, unless the device can vary it.
    let first = recorder
        .instance
        .as_ref()
        .filter(|i| i.no_attachments && record.bind_point == vk::PipelineBindPoint::GRAPHICS)
        .and_then(|i| i.samples);
    if let Some(samples) = first.filter(|&s| s != record.samples) {
        let physical = recorder.device().parent();
        // SAFETY: a live physical device of its instance.
        let variable = unsafe {
            physical
                .parent()
                .fns()
                .get_physical_device_features(physical.raw())
        }
        .variable_multisample_rate;
        if variable != vk::TRUE {
            refuse(
                "VUID-vkCmdBindPipeline-pipeline-00781",
                format!(
                    "the current subpass uses no attachments and the device does not support \
                     variableMultisampleRate, so the pipeline's sample count must match that \
                     of the subpass's first graphics pipeline ({:?} against {samples:?})",
                    record.samples
                ),
            )?;
        }
    }
    let vuid = match pipeline_bind_point {
        vk::PipelineBindPoint::COMPUTE => "VUID-vkCmdBindPipeline-pipelineBindPoint-00779",
        vk::PipelineBindPoint::GRAPHICS => "VUID-vkCmdBindPipeline-pipelineBindPoint-00780",
        _ => return Ok(()),
    };
    if record.bind_point != pipeline_bind_point {
        refuse(
            vuid,
            format!(
                "a {:?} pipeline is bound at the {pipeline_bind_point:?} bind point",
                record.bind_point
            ),
        )?;
    }
    Ok(())
}

/// The recorder remembers the index buffer bound: its size, the offset and the index
/// type, which indexed draws are checked against.
pub(crate) fn cmd_bind_index_buffer_done<'b, S: Scope>(
    recorder: &mut Recorder<'_, S>,
    buffer: impl Into<Option<&'b Buffer>>,
    offset: vk::DeviceSize,
    index_type: vk::IndexType,
) {
    let buffer = buffer.into();
    let size = buffer
        .and_then(|b| recorder.device().live().buffer(b.raw()))
        .map(|r| r.size);
    recorder.bound[0].index = size.map(|size| (size, offset, index_type));
    recorder.bound[0].index_buffer = buffer.map_or(vk::Buffer::null(), |b| b.raw());
}
