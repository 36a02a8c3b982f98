//! Fences, semaphores and events: their creation, host waits and signals, timeline
//! values, and events set, reset and waited on in recordings.

use super::barriers::{
    check_barrier_scopes, check_barrier_structs, every_stage, every_stage1, stage_pairs, Barriers,
    PipelineBarrierRules,
};
use super::image_layouts::{cmd_pipeline_barrier_done, dependency_done};
use super::{chained, refuse, vulkan12_properties};
use crate::handles::*;
use crate::recorder::{Recorder, Scope};
use crate::state::events::{judge1, judge2, Need, Signal};
use crate::structs::{BufferMemoryBarrier, ImageMemoryBarrier, *};
use crate::submission::{self};
use crate::{Error, Handle, Result};
use ash::vk;
use ash::vk::Handle as _;
use std::sync::Arc;

/// Refuses a fence whose queue operation may still be executing.
pub(crate) fn reset_fences_checks(device: &Device, fences: &[&Fence]) -> Result<()> {
    for f in fences {
        if f.submission().is_some_and(|sub| !sub.poll(device)) {
            return Err(Error::Validation {
                vuid: "VUID-vkResetFences-pFences-01123",
                message: "a fence is reset while the queue operation that signals it may still be executing".into(),
            });
        }
    }
    Ok(())
}

/// Refuses a binary semaphore.
pub(crate) fn get_semaphore_counter_value_checks(
    device: &Device,
    semaphore: &Semaphore,
) -> Result<()> {
    submission::check_semaphore_type(
        device.live(),
        &[semaphore.raw()],
        true,
        "VUID-vkGetSemaphoreCounterValue-semaphore-03255",
    )
}

/// A timeline value seen on the host: the batches that signal it are done.
pub(crate) fn semaphore_value_seen(device: &Device, semaphore: &Semaphore, value: u64) {
    timeline_seen(device, semaphore.raw(), value, false);
}

/// The host saw (or set) a timeline semaphore's value: the batches that signal it
/// are done, and the device knows the semaphore reached it.
fn timeline_seen(device: &Device, semaphore: vk::Semaphore, value: u64, host_signal: bool) {
    if let Some(t) = device.live().timelines().get_mut(&semaphore.as_raw()) {
        t.seen(value, host_signal);
    }
    device.live().ledger().reached(semaphore, value);
}

/// After `vkSignalSemaphore`: the semaphore has the value.
pub(crate) fn signal_semaphore_done(device: &Device, signal_info: &SemaphoreSignalInfo<'_>) {
    timeline_seen(device, signal_info.semaphore, signal_info.value, true);
}

/// The physical device's `maxTimelineSemaphoreValueDifference`, read once per device
/// (no limit is known below Vulkan 1.2, where the device has no timeline semaphores).
pub(super) fn timeline_difference(device: &Device) -> u64 {
    device.live().timeline_difference(|| {
        vulkan12_properties(device).map_or(u64::MAX, |p| p.max_timeline_semaphore_value_difference)
    })
}

/// Refuses binary semaphores.
pub(crate) fn wait_semaphores_checks(
    device: &Device,
    wait_info: &SemaphoreWaitInfo<'_>,
) -> Result<()> {
    // SAFETY: the safe struct stores the array with its length.
    let semaphores =
        unsafe { crate::state::raw_slice(wait_info.p_semaphores, wait_info.semaphore_count) };
    submission::check_semaphore_type(
        device.live(),
        semaphores,
        true,
        "VUID-VkSemaphoreWaitInfo-pSemaphores-03256",
    )
}

/// After `vkWaitSemaphores`: only a wait for all of them says each reached its value.
pub(crate) fn wait_semaphores_done(
    device: &Device,
    wait_info: &SemaphoreWaitInfo<'_>,
    r: vk::Result,
) {
    if r != vk::Result::SUCCESS || wait_info.flags.contains(vk::SemaphoreWaitFlags::ANY) {
        return;
    }
    // SAFETY: the safe struct stores both arrays with their one length.
    let semaphores =
        unsafe { crate::state::raw_slice(wait_info.p_semaphores, wait_info.semaphore_count) };
    // SAFETY: the same length, from the same safe struct.
    let values = unsafe { crate::state::raw_slice(wait_info.p_values, wait_info.semaphore_count) };
    for (s, v) in semaphores.iter().zip(values) {
        timeline_seen(device, *s, *v, false);
    }
}

/// Takes the device's submission gate for a host signal of a timeline semaphore
/// (held until the call and its bookkeeping are done, so that no submission or other
/// host signal changes the semaphore meanwhile) and checks the value under it: above
/// the semaphore's value, read from the driver (03258), below every pending signal
/// (03259) and within `maxTimelineSemaphoreValueDifference` of the value and of the
/// pending operations (03260).
///
/// A signal below a pending one is valid only if the host's runs first. The safe
/// method signals only where it must: each pending signal's batch waits on the same
/// semaphore for a value above the one it has and no more than the host's (the
/// wait-before-signal pattern), so no signal can run before the host's, and the
/// value read holds until the call. Otherwise it is refused (`Error::Misuse`).
pub(crate) fn signal_semaphore_hold<'d>(
    device: &'d Device,
    signal_info: &SemaphoreSignalInfo<'_>,
) -> Result<tuff_runtime::VutexGuard<'d, ()>> {
    let gate = device.live().descriptor_gate();
    let semaphore = signal_info.semaphore;
    let value = signal_info.value;
    type Op = (
        u64,
        bool,
        tuff_runtime::Vweak<crate::state::Submission>,
        usize,
    );
    let pending: Vec<Op> = {
        let mut timelines = device.live().timelines();
        let Some(t) = timelines.get_mut(&semaphore.as_raw()) else {
            return Ok(gate);
        };
        t.prune();
        t.pending.clone()
    };
    if let Some((below, ..)) = pending
        .iter()
        .find(|(v, signal, ..)| *signal && *v <= value)
    {
        refuse(
            "VUID-VkSemaphoreSignalInfo-value-03259",
            format!("a submitted signal of the semaphore to {below}, not known complete, is not above {value}"),
        )?;
    }
    let mut current = 0;
    // SAFETY: a live timeline semaphore of this device (its type was checked) and a
    // pointer to a local.
    let r = unsafe {
        (device.fns().fp_v1_2().get_semaphore_counter_value)(device.raw(), semaphore, &mut current)
    };
    if r != vk::Result::SUCCESS {
        return Err(Error::Vk(r));
    }
    if value <= current {
        refuse(
            "VUID-VkSemaphoreSignalInfo-value-03258",
            format!("the semaphore's value is {current}, and the signal's {value} is not above it"),
        )?;
    }
    // A pending signal waits, in its batch, for a value only the host's signal
    // reaches: every other signal that could reach it is pending and waits too.
    let blocked = |(_, _, sub, batch): &Op| {
        pending.iter().any(|(w, signal, other, other_batch)| {
            !*signal && other.ptr_eq(sub) && other_batch == batch && *w > current && *w <= value
        })
    };
    if pending.iter().any(|op| op.1 && !blocked(op)) {
        return Err(Error::Misuse(
            "the safe signal_semaphore signals a timeline semaphore only where no submitted signal of it can run first (each pending signal's batch waits on it for a value above the current one, at most the host's); wait for the submission's fence, or use signal_semaphore_unchecked",
        ));
    }
    let difference = timeline_difference(device);
    let far = pending
        .iter()
        .map(|(v, ..)| *v)
        .chain([current])
        .find(|v| v.abs_diff(value) > difference);
    if let Some(far) = far {
        refuse(
            "VUID-VkSemaphoreSignalInfo-value-03260",
            format!("{value} differs from {far}, the semaphore's value or a pending operation's, by more than maxTimelineSemaphoreValueDifference ({difference})"),
        )?;
    }
    Ok(gate)
}

/// Refuses a binary semaphore.
pub(crate) fn signal_semaphore_checks(
    device: &Device,
    signal_info: &SemaphoreSignalInfo<'_>,
) -> Result<()> {
    submission::check_semaphore_type(
        device.live(),
        &[signal_info.semaphore],
        true,
        "VUID-VkSemaphoreSignalInfo-semaphore-03257",
    )
}

/// A signalled fence's queue operation is complete.
pub(crate) fn get_fence_status_done(fence: &Fence, r: vk::Result) {
    if r == vk::Result::SUCCESS {
        fence.completed();
    }
}

/// After a successful wait, the fences known signalled are complete.
pub(crate) fn wait_for_fences_done(
    device: &Device,
    fences: &[&Fence],
    wait_all: vk::Bool32,
    r: vk::Result,
) {
    if r != vk::Result::SUCCESS {
        return;
    }
    if wait_all == vk::TRUE || fences.len() == 1 {
        for f in fences {
            f.completed();
        }
    } else {
        // One fence at least is signalled; ask each which.
        for f in fences {
            if let Some(sub) = f.submission() {
                sub.poll(device);
            }
        }
    }
}

/// The device remembers which semaphores are timeline semaphores.
pub(crate) fn semaphore_created(
    device: &Device,
    semaphore: Semaphore,
    create_info: &SemaphoreCreateInfo<'_>,
) -> Semaphore {
    if let Some(initial) = submission::timeline_initial(create_info) {
        device.live().set_timeline(semaphore.raw(), initial);
    }
    semaphore
}

/// The recording names `event` in an event command: its submission is checked
/// against pending submissions to other queues that name it too.
/// The rules of a command that sets or resets an event from a stage mask, by field:
/// `vkCmdSetEvent`'s and `vkCmdResetEvent`'s differ only in their names.
pub(crate) struct EventStageRules {
    /// Each stage is supported by the queue family of the command buffer's pool.
    pub family: &'static str,
    /// The mask is not 0 unless synchronization2 is enabled.
    pub empty: &'static str,
    /// The command buffer's current device mask names exactly one physical device.
    pub one_device: &'static str,
}

const SET_EVENT: EventStageRules = EventStageRules {
    family: "VUID-vkCmdSetEvent-stageMask-06457",
    empty: "VUID-vkCmdSetEvent-stageMask-03937",
    one_device: "VUID-vkCmdSetEvent-commandBuffer-01152",
};

const RESET_EVENT: EventStageRules = EventStageRules {
    family: "VUID-vkCmdResetEvent-stageMask-06458",
    empty: "VUID-vkCmdResetEvent-stageMask-03937",
    one_device: "VUID-vkCmdResetEvent-commandBuffer-01157",
};

/// Refuses a `vkCmdSetEvent` whose stage mask the pool's queue family cannot run
/// or is empty without synchronization2, or that runs on other than one physical
/// device.
pub(crate) fn set_event_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    stage_mask: vk::PipelineStageFlags,
) -> Result<()> {
    event_stage_checks(recorder, stage_mask, &SET_EVENT)
}

/// As [`set_event_checks`], for `vkCmdResetEvent`, and no wait on the event that
/// the recording made without a barrier ordering the reset after it.
pub(crate) fn reset_event_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    event: &Event,
    stage_mask: vk::PipelineStageFlags,
) -> Result<()> {
    event_stage_checks(recorder, stage_mask, &RESET_EVENT)?;
    recorder
        .event_states
        .check_reset(event.raw().as_raw(), every_stage1(stage_mask), false)
}

/// `vkCmdResetEvent2`: no wait on the event that the recording made without a
/// barrier ordering the reset after it, on one physical device.
pub(crate) fn reset_event2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    event: &Event,
    stage_mask: vk::PipelineStageFlags2,
) -> Result<()> {
    one_device(recorder, "VUID-vkCmdResetEvent2-commandBuffer-03833")?;
    recorder
        .event_states
        .check_reset(event.raw().as_raw(), every_stage(stage_mask), true)
}

/// The command buffer's current device mask names one physical device.
fn one_device<S: Scope>(recorder: &Recorder<'_, S>, vuid: &'static str) -> Result<()> {
    let mask = recorder.current_device_mask;
    if mask.count_ones() != 1 {
        refuse(
            vuid,
            format!("the command buffer's current device mask {mask:#x} names other than one physical device"),
        )?;
    }
    Ok(())
}

/// After `vkCmdSetEvent`: the event is set with `stage_mask`.
pub(crate) fn set_event_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    event: &Event,
    stage_mask: vk::PipelineStageFlags,
) {
    event_recorded(recorder, event);
    recorder
        .event_states
        .set(event.raw().as_raw(), Signal::Set1(stage_mask));
}

/// After `vkCmdSetEvent2`: the event is set with the dependency info.
pub(crate) fn set_event2_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    event: &Event,
    dependency_info: &DependencyInfo<'_>,
) {
    event_recorded(recorder, event);
    let digest = digest(dependency_info.as_raw());
    recorder
        .event_states
        .set(event.raw().as_raw(), Signal::Set2(digest));
}

/// After `vkCmdResetEvent`: the event is unsignaled.
pub(crate) fn reset_event_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    event: &Event,
    stage_mask: vk::PipelineStageFlags,
) {
    event_reset(recorder, event, every_stage1(stage_mask), false);
}

/// After `vkCmdResetEvent2`: the event is unsignaled.
pub(crate) fn reset_event2_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    event: &Event,
    stage_mask: vk::PipelineStageFlags2,
) {
    event_reset(recorder, event, every_stage(stage_mask), true);
}

/// A reset of either version at `stages` (every stage spelled out).
fn event_reset<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    event: &Event,
    stages: vk::PipelineStageFlags2,
    v2: bool,
) {
    event_recorded(recorder, event);
    recorder
        .event_states
        .reset(event.raw().as_raw(), stages, v2);
}

/// A dependency info as `vkCmdWaitEvents2` compares it with the one `vkCmdSetEvent2`
/// gave (they must be exactly equal): each member of it and of its barriers, a
/// chained struct by its address.
fn digest(info: &vk::DependencyInfo<'_>) -> Arc<[u64]> {
    let (memory, buffers, images) = super::barriers::arrays(info);
    let mut d = vec![
        u64::from(info.dependency_flags.as_raw()),
        info.p_next as usize as u64,
        memory.len() as u64,
        buffers.len() as u64,
        images.len() as u64,
    ];
    for b in memory {
        d.extend([
            b.p_next as usize as u64,
            b.src_stage_mask.as_raw(),
            b.src_access_mask.as_raw(),
            b.dst_stage_mask.as_raw(),
            b.dst_access_mask.as_raw(),
        ]);
    }
    for b in buffers {
        d.extend([
            b.p_next as usize as u64,
            b.src_stage_mask.as_raw(),
            b.src_access_mask.as_raw(),
            b.dst_stage_mask.as_raw(),
            b.dst_access_mask.as_raw(),
            u64::from(b.src_queue_family_index),
            u64::from(b.dst_queue_family_index),
            b.buffer.as_raw(),
            b.offset,
            b.size,
        ]);
    }
    for b in images {
        let r = b.subresource_range;
        d.extend([
            b.p_next as usize as u64,
            b.src_stage_mask.as_raw(),
            b.src_access_mask.as_raw(),
            b.dst_stage_mask.as_raw(),
            b.dst_access_mask.as_raw(),
            b.old_layout.as_raw() as u64,
            b.new_layout.as_raw() as u64,
            u64::from(b.src_queue_family_index),
            u64::from(b.dst_queue_family_index),
            b.image.as_raw(),
            u64::from(r.aspect_mask.as_raw()),
            u64::from(r.base_mip_level),
            u64::from(r.level_count),
            u64::from(r.base_array_layer),
            u64::from(r.layer_count),
        ]);
    }
    d.into()
}

/// Whether each barrier of a dependency info holds only host operations in its
/// first scope, and whether it has any barrier.
fn host_scope(info: &vk::DependencyInfo<'_>) -> (bool, bool) {
    let pairs = stage_pairs(info);
    (
        pairs
            .iter()
            .all(|(src, _)| *src == vk::PipelineStageFlags2::HOST),
        !pairs.is_empty(),
    )
}

/// The rules a first-version wait on events shares with a pipeline barrier (those
/// of a barrier inside a render pass instance are the pipeline barrier's alone).
const WAIT_EVENTS: PipelineBarrierRules = PipelineBarrierRules {
    src_zero: "VUID-vkCmdWaitEvents-srcStageMask-03937",
    dst_zero: "VUID-vkCmdWaitEvents-dstStageMask-03937",
    src_unsupported: "VUID-vkCmdWaitEvents-srcStageMask-06459",
    dst_unsupported: "VUID-vkCmdWaitEvents-dstStageMask-06460",
    memory_src_access: "VUID-vkCmdWaitEvents-srcAccessMask-02815",
    memory_dst_access: "VUID-vkCmdWaitEvents-dstAccessMask-02816",
    buffer_src_access: "VUID-vkCmdWaitEvents-pBufferMemoryBarriers-02817",
    buffer_dst_access: "VUID-vkCmdWaitEvents-pBufferMemoryBarriers-02818",
    image_src_access: "VUID-vkCmdWaitEvents-pImageMemoryBarriers-02819",
    image_dst_access: "VUID-vkCmdWaitEvents-pImageMemoryBarriers-02820",
    view_local: "",
    dynamic_rendering: "",
    self_dependency: "",
    image_attachment: "",
    buffer_in_pass: "",
    layout_in_pass: "",
    transfer_in_pass: "",
};

/// The rules the second version's wait shares with a pipeline barrier.
const WAIT_EVENTS2: PipelineBarrierRules = PipelineBarrierRules {
    src_zero: "",
    dst_zero: "",
    src_unsupported: "VUID-vkCmdWaitEvents2-srcStageMask-03842",
    dst_unsupported: "VUID-vkCmdWaitEvents2-dstStageMask-03843",
    memory_src_access: "",
    memory_dst_access: "",
    buffer_src_access: "",
    buffer_dst_access: "",
    image_src_access: "",
    image_dst_access: "",
    ..WAIT_EVENTS
};

fn event_stage_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    stage_mask: vk::PipelineStageFlags,
    rules: &EventStageRules,
) -> Result<()> {
    let flags = recorder.pool_queue_flags();
    if let Some(s) = super::stages::unsupported_stage(stage_mask, flags) {
        refuse(
            rules.family,
            format!("stageMask includes {s:?}, which the pool's queue family ({flags:?}) does not support"),
        )?;
    }
    let sync2 = recorder
        .device()
        .live()
        .with_features(|f| f.v13.synchronization2);
    if stage_mask.is_empty() && sync2 != vk::TRUE {
        refuse(
            rules.empty,
            "stageMask is 0, and synchronization2 is not enabled",
        )?;
    }
    let mask = recorder.current_device_mask;
    if mask.count_ones() != 1 {
        refuse(
            rules.one_device,
            format!("the command buffer's current device mask {mask:#x} names other than one physical device"),
        )?;
    }
    Ok(())
}

/// A new current device mask names only physical devices of the device (00108),
/// of the command buffer's initial mask (00110) and, inside a render pass instance,
/// of the instance's mask (00111).
pub(crate) fn set_device_mask_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    device_mask: u32,
) -> Result<()> {
    let count = recorder.device().live().physical_count().min(32);
    let all = ((1u64 << count) - 1) as u32;
    if device_mask & !all != 0 {
        refuse(
            "VUID-vkCmdSetDeviceMask-deviceMask-00108",
            format!(
                "deviceMask {device_mask:#x} names a physical device the device has not ({count})"
            ),
        )?;
    }
    let initial = recorder.device_mask;
    if device_mask & !initial != 0 {
        refuse(
            "VUID-vkCmdSetDeviceMask-deviceMask-00110",
            format!("deviceMask {device_mask:#x} is not within the command buffer's initial device mask {initial:#x}"),
        )?;
    }
    if let Some(pass) = recorder.instance.as_ref().and_then(|i| i.device_mask) {
        if device_mask & !pass != 0 {
            refuse(
                "VUID-vkCmdSetDeviceMask-deviceMask-00111",
                format!("deviceMask {device_mask:#x} is not within the render pass instance's device mask {pass:#x}"),
            )?;
        }
    }
    Ok(())
}

/// The recorder follows the command buffer's current device mask, which event
/// commands read.
pub(crate) fn device_mask_set<S: Scope>(recorder: &mut Recorder<'_, S>, device_mask: u32) {
    recorder.current_device_mask = device_mask;
}

pub(crate) fn event_recorded<S: Scope>(recorder: &mut Recorder<'_, S>, event: &Event) {
    let raw = event.raw().as_raw();
    if !recorder.events.contains(&raw) {
        recorder.events.push(raw);
    }
}

/// After `vkCmdWaitEvents`: the events it names and waits on (what the recording
/// does not know of them, each submission checks), and the layouts its barriers
/// leave.
pub(crate) fn wait_events_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    events: &[&Event],
    src_stage_mask: vk::PipelineStageFlags,
    dst_stage_mask: vk::PipelineStageFlags,
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) {
    for e in events {
        event_recorded(recorder, e);
    }
    let raw: Vec<u64> = events.iter().map(|e| e.raw().as_raw()).collect();
    let known = recorder.event_states.known(&raw);
    let need = known
        .iter()
        .any(|(_, s)| s.is_none())
        .then_some(Need::Wait1 {
            src: src_stage_mask,
            events: known,
        });
    recorder
        .event_states
        .waited(&raw, every_stage1(dst_stage_mask), false, need);
    cmd_pipeline_barrier_done(recorder, image_memory_barriers);
}

/// After `vkCmdWaitEvents2`: the events it names, and the layouts its dependencies
/// leave.
pub(crate) fn wait_events2_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    events: &[&Event],
    dependency_infos: &[DependencyInfo<'_>],
) {
    for (e, info) in events.iter().zip(dependency_infos) {
        event_recorded(recorder, e);
        let raw = e.raw().as_raw();
        let info = info.as_raw();
        let need = recorder.event_states.signal(raw).is_none().then(|| {
            let (host_scope, barriers) = host_scope(info);
            Need::Wait2 {
                event: raw,
                digest: digest(info),
                host_scope,
                barriers,
            }
        });
        let stages = stage_pairs(info)
            .iter()
            .fold(vk::PipelineStageFlags2::empty(), |a, (_, dst)| {
                a | every_stage(*dst)
            });
        recorder.event_states.waited(&[raw], stages, true, need);
    }
    dependency_done(recorder, dependency_infos);
}

/// Exportable handle types a fence's creation asks for: each one the physical device
/// The first handle type of `wanted` that the physical device cannot export, or
/// whose compatible types leave out one of `wanted`, as `query` reports a type:
/// (exportable, compatible types). `None` when every one can be exported together.
fn unexportable(wanted: u32, query: impl Fn(u32) -> (bool, u32)) -> Option<(u32, bool, u32)> {
    (0..32)
        .map(|i| 1u32 << i)
        .filter(|b| wanted & b != 0)
        .map(|bit| {
            let (exportable, compatible) = query(bit);
            (bit, exportable, compatible)
        })
        .find(|&(_, exportable, compatible)| !exportable || compatible & wanted != wanted)
}

/// Exportable handle types a fence's creation asks for: each one the physical device
/// can export, and all of them compatible with each other.
pub(crate) fn create_fence_checks(
    device: &Device,
    create_info: &FenceCreateInfo<'_>,
) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let Some(export) = (unsafe {
        chained::<vk::ExportFenceCreateInfo<'_>>(
            create_info.as_raw().p_next,
            vk::StructureType::EXPORT_FENCE_CREATE_INFO,
        )
    }) else {
        return Ok(());
    };
    let physical = device.parent();
    let wanted = export.handle_types;
    let failed = unexportable(wanted.as_raw(), |bit| {
        let info = vk::PhysicalDeviceExternalFenceInfo::default()
            .handle_type(vk::ExternalFenceHandleTypeFlags::from_raw(bit));
        let mut props = vk::ExternalFenceProperties::default();
        // SAFETY: a live physical device of its instance, a valid info and an output
        // it owns; the fence struct is core 1.1, which the implicit checks required.
        unsafe {
            physical
                .parent()
                .fns()
                .get_physical_device_external_fence_properties(physical.raw(), &info, &mut props)
        };
        (
            props
                .external_fence_features
                .contains(vk::ExternalFenceFeatureFlags::EXPORTABLE),
            props.compatible_handle_types.as_raw(),
        )
    });
    match failed {
        Some(f) => refuse(
            "VUID-VkExportFenceCreateInfo-handleTypes-01446",
            unexportable_message("VkExternalFenceProperties", wanted.as_raw(), f),
        ),
        None => Ok(()),
    }
}

/// The refusal of [`unexportable`]'s finding.
fn unexportable_message(
    what: &str,
    wanted: u32,
    (bit, exportable, compatible): (u32, bool, u32),
) -> String {
    format!(
        "The bits in `handleTypes` must be supported and compatible, as reported by {what} \
         (`handleTypes` = {wanted:#x}; handle type {bit:#x} is {}exportable, compatible with \
         {compatible:#x})",
        if exportable { "" } else { "not " }
    )
}

/// As [`create_fence_checks`], for a semaphore (of the type it is created with).
pub(crate) fn create_semaphore_checks(
    device: &Device,
    create_info: &SemaphoreCreateInfo<'_>,
) -> Result<()> {
    let next = create_info.as_raw().p_next;
    // SAFETY: the `pNext` of a safe struct, and the types their sTypes name.
    let (export, ty) = unsafe {
        (
            chained::<vk::ExportSemaphoreCreateInfo<'_>>(
                next,
                vk::StructureType::EXPORT_SEMAPHORE_CREATE_INFO,
            ),
            chained::<vk::SemaphoreTypeCreateInfo<'_>>(
                next,
                vk::StructureType::SEMAPHORE_TYPE_CREATE_INFO,
            ),
        )
    };
    let Some(export) = export else {
        return Ok(());
    };
    let semaphore_type = ty.map(|t| t.semaphore_type);
    let physical = device.parent();
    let wanted = export.handle_types;
    let failed = unexportable(wanted.as_raw(), |bit| {
        let mut ty =
            semaphore_type.map(|t| vk::SemaphoreTypeCreateInfo::default().semaphore_type(t));
        let mut info = vk::PhysicalDeviceExternalSemaphoreInfo::default()
            .handle_type(vk::ExternalSemaphoreHandleTypeFlags::from_raw(bit));
        if let Some(t) = ty.as_mut() {
            info = info.push_next(t);
        }
        let mut props = vk::ExternalSemaphoreProperties::default();
        // SAFETY: as in `create_fence_checks`; the type struct chained is a local copy.
        unsafe {
            physical
                .parent()
                .fns()
                .get_physical_device_external_semaphore_properties(
                    physical.raw(),
                    &info,
                    &mut props,
                )
        };
        (
            props
                .external_semaphore_features
                .contains(vk::ExternalSemaphoreFeatureFlags::EXPORTABLE),
            props.compatible_handle_types.as_raw(),
        )
    });
    match failed {
        Some(f) => refuse(
            "VUID-VkExportSemaphoreCreateInfo-handleTypes-01124",
            unexportable_message("VkExternalSemaphoreProperties", wanted.as_raw(), f),
        ),
        None => Ok(()),
    }
}

/// An event the host sets, resets or reads was not created device-only.
pub(crate) fn host_event(device: &Device, event: &Event, vuid: &'static str) -> Result<()> {
    if device.live().is_device_only(event.raw()) {
        refuse(
            vuid,
            "`event` must not have been created with `VK_EVENT_CREATE_DEVICE_ONLY_BIT`",
        )?;
    }
    Ok(())
}

/// The device remembers a device-only event, which the host may not touch.
pub(crate) fn event_created(
    device: &Device,
    event: Event,
    create_info: &EventCreateInfo<'_>,
) -> Event {
    if create_info
        .flags
        .contains(vk::EventCreateFlags::DEVICE_ONLY)
    {
        device.live().set_device_only(event.raw());
    }
    event
}

/// The checks of the second version's event wait: each dependency info's barriers
/// against the resources they name, as a pipeline barrier's, and the layouts its
/// image barriers move from.
pub(crate) fn wait_events2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    dependency_infos: &[DependencyInfo<'_>],
) -> Result<()> {
    for info in dependency_infos {
        let barriers = Barriers::of2(info);
        check_barrier_scopes(recorder, None, &barriers, &WAIT_EVENTS2)?;
        if recorder.instance.is_some()
            && barriers
                .scopes()
                .any(|b| b.src_stage.contains(vk::PipelineStageFlags2::HOST))
        {
            refuse(
                "VUID-vkCmdWaitEvents2-dependencyFlags-03844",
                "a barrier's srcStageMask includes the host stage inside a render pass instance",
            )?;
        }
        check_barrier_structs(recorder, &barriers)?;
    }
    one_device(recorder, "VUID-vkCmdWaitEvents2-commandBuffer-03846")?;
    super::image_layouts::dependency_checks(recorder, dependency_infos)
}

/// The events of a second-version wait, as far as the recording set or reset them,
/// are signaled as each dependency info says (after the command's other checks).
pub(crate) fn wait_events2_signals<S: Scope>(
    recorder: &Recorder<'_, S>,
    events: &[&Event],
    dependency_infos: &[DependencyInfo<'_>],
) -> Result<()> {
    for (e, info) in events.iter().zip(dependency_infos) {
        let raw = e.raw().as_raw();
        if let Some(state) = recorder.event_states.signal(raw) {
            let info = info.as_raw();
            let (host, barriers) = host_scope(info);
            judge2(raw, &digest(info), host, barriers, state)?;
        }
    }
    Ok(())
}

/// The checks of the second version's event signal: its barriers against the
/// resources they name, as a pipeline barrier's.
pub(crate) fn set_event2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    dependency_info: &DependencyInfo<'_>,
) -> Result<()> {
    let flags = dependency_info.dependency_flags;
    if !flags.is_empty() {
        refuse(
            "VUID-vkCmdSetEvent2-dependencyFlags-03825",
            format!(
                "The `dependencyFlags` member of `pDependencyInfo` must be `0` (it is {flags:?})"
            ),
        )?;
    }
    let barriers = Barriers::of2(dependency_info);
    let family = recorder.pool_queue_flags();
    for (n, b) in barriers.scopes().enumerate() {
        for (mask, vuid) in [
            (b.src_stage, "VUID-vkCmdSetEvent2-srcStageMask-03827"),
            (b.dst_stage, "VUID-vkCmdSetEvent2-dstStageMask-03828"),
        ] {
            if let Some(s) = super::stages::unsupported_stage2(mask, family) {
                refuse(
                    vuid,
                    format!("barrier {n}'s stage mask includes {s:?}, which the pool's queue family ({family:?}) does not support"),
                )?;
            }
        }
    }
    let mask = recorder.current_device_mask;
    if mask.count_ones() != 1 {
        refuse(
            "VUID-vkCmdSetEvent2-commandBuffer-03826",
            format!("the command buffer's current device mask {mask:#x} names other than one physical device"),
        )?;
    }
    check_barrier_structs(recorder, &barriers)
}

/// Held through a host reset of an event: refuses it while a submission whose
/// command buffers name the event may still be executing (a wait there needs an
/// execution dependency with the reset, which the host gives only by waiting for
/// the submission), under the device's submission gate, so that no submission
/// comes between the check and the reset.
pub(crate) fn reset_event_hold<'d>(
    device: &'d Device,
    event: &Event,
) -> Result<tuff_runtime::VutexGuard<'d, ()>> {
    let gate = device.live().descriptor_gate();
    // No queue of the device has the null handle: the submissions to every queue.
    let pending = device
        .live()
        .event_submissions(event.raw().as_raw(), vk::Queue::null());
    for sub in pending {
        if !sub.poll(device) {
            refuse(
                "VUID-vkResetEvent-event-03821",
                "a submission whose command buffers name the event (and may wait on it) may still be executing: wait for its fence before the host resets the event",
            )?;
        }
    }
    Ok(gate)
}

/// Held through the host's set of an event: the device's submission gate, so that
/// no submission's check of the event's state comes between the set and its record.
pub(crate) fn set_event_hold(device: &Device) -> Result<tuff_runtime::VutexGuard<'_, ()>> {
    Ok(device.live().descriptor_gate())
}

/// After the host's `vkSetEvent`: the event is set by the host; or, where a
/// submission that sets or resets it may still be executing, its state is not
/// known (which comes last is timing).
pub(crate) fn host_event_set(device: &Device, event: &Event) {
    let raw = event.raw().as_raw();
    let racing = device
        .live()
        .event_writer(raw)
        .is_some_and(|s| !s.poll(device));
    let signal = if racing {
        Signal::Unknown
    } else {
        Signal::Host
    };
    device.live().event_signaled_on_host(raw, signal);
}

/// After the host's `vkResetEvent` (which no pending submission names): unsignaled.
pub(crate) fn host_event_reset(device: &Device, event: &Event) {
    device
        .live()
        .event_signaled_on_host(event.raw().as_raw(), Signal::Unset);
}

/// The checks of an event wait's barriers, and the layouts its image barriers move
/// from.
pub(crate) fn wait_events_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_stage_mask: vk::PipelineStageFlags,
    dst_stage_mask: vk::PipelineStageFlags,
    memory_barriers: &[MemoryBarrier<'_>],
    buffer_memory_barriers: &[BufferMemoryBarrier<'_>],
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) -> Result<()> {
    let masks = (src_stage_mask, dst_stage_mask);
    let scoped = Barriers::of(
        masks,
        memory_barriers,
        buffer_memory_barriers,
        image_memory_barriers,
    );
    check_barrier_scopes(recorder, Some(masks), &scoped, &WAIT_EVENTS)?;
    if recorder.instance.is_some() && src_stage_mask.contains(vk::PipelineStageFlags::HOST) {
        refuse(
            "VUID-vkCmdWaitEvents-srcStageMask-07308",
            "srcStageMask includes the host stage inside a render pass instance",
        )?;
    }
    let families = scoped
        .buffers
        .iter()
        .map(|b| b.families)
        .chain(scoped.images.iter().map(|b| b.families));
    for (src, dst) in families {
        if src != dst {
            refuse(
                "VUID-vkCmdWaitEvents-srcQueueFamilyIndex-02803",
                format!("a barrier transfers queue family ownership ({src} to {dst}), which an event wait cannot"),
            )?;
        }
    }
    one_device(recorder, "VUID-vkCmdWaitEvents-commandBuffer-01167")?;
    // The structs' rules of the first version read no stage mask.
    let none = vk::PipelineStageFlags::empty();
    let barriers = Barriers::of(
        (none, none),
        &[],
        buffer_memory_barriers,
        image_memory_barriers,
    );
    check_barrier_structs(recorder, &barriers)?;
    super::image_layouts::cmd_pipeline_barrier_checks(recorder, image_memory_barriers)
}

/// Refuses secondaries whose event waits break on the states the recording leaves
/// them, or whose resets race its waits.
pub(crate) fn execute_events_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) -> Result<()> {
    let mut so_far = recorder.event_states.clone();
    for cb in command_buffers {
        if let Some(theirs) = cb.uses().event_states() {
            so_far.check_then(&theirs)?;
            so_far.then(&theirs);
        }
    }
    Ok(())
}

/// The recording executes the secondaries' event commands.
pub(crate) fn execute_events_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) {
    for cb in command_buffers {
        if let Some(theirs) = cb.uses().event_states() {
            recorder.event_states.then(&theirs);
        }
    }
}

/// The events of a first-version wait, where the recording set or reset them all,
/// were set with the stage masks `src_stage_mask` ORs (after the command's other
/// checks; where one's state comes from before the recording, the submission checks).
pub(crate) fn wait_events_signals<S: Scope>(
    recorder: &Recorder<'_, S>,
    events: &[&Event],
    src_stage_mask: vk::PipelineStageFlags,
) -> Result<()> {
    let raw: Vec<u64> = events.iter().map(|e| e.raw().as_raw()).collect();
    let known = recorder.event_states.known(&raw);
    if known.iter().all(|(_, s)| s.is_some()) {
        judge1(
            src_stage_mask,
            known.iter().filter_map(|(e, s)| Some((*e, s.as_ref()?))),
        )?;
    }
    Ok(())
}
