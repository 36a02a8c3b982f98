//! Fences, semaphores and events: their creation, host waits and signals, timeline
//! values, and events set, reset and waited on in recordings.

use super::barriers::{check_barrier_structs, Barriers};
use super::image_layouts::{cmd_pipeline_barrier_done, dependency_done};
use super::{chained, refuse, vulkan12_properties};
use crate::handles::*;
use crate::recorder::{Recorder, Scope};
use crate::structs::{BufferMemoryBarrier, ImageMemoryBarrier, *};
use crate::submission::{self};
use crate::{Error, Handle, Result};
use ash::vk;
use ash::vk::Handle as _;

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

/// As [`set_event_checks`], for `vkCmdResetEvent`.
pub(crate) fn reset_event_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    stage_mask: vk::PipelineStageFlags,
) -> Result<()> {
    event_stage_checks(recorder, stage_mask, &RESET_EVENT)
}

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

/// After `vkCmdWaitEvents`: the events it names, and the layouts its barriers leave.
pub(crate) fn wait_events_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    events: &[&Event],
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) {
    for e in events {
        event_recorded(recorder, e);
    }
    cmd_pipeline_barrier_done(recorder, image_memory_barriers);
}

/// After `vkCmdWaitEvents2`: the events it names, and the layouts its dependencies
/// leave.
pub(crate) fn wait_events2_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    events: &[&Event],
    dependency_infos: &[DependencyInfo<'_>],
) {
    for e in events {
        event_recorded(recorder, e);
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
        check_barrier_structs(recorder, &Barriers::of2(info))?;
    }
    super::image_layouts::dependency_checks(recorder, dependency_infos)
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

/// The checks of an event wait's barriers, and the layouts its image barriers move
/// from.
pub(crate) fn wait_events_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    buffer_memory_barriers: &[BufferMemoryBarrier<'_>],
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) -> Result<()> {
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
