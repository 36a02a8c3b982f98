//! The hand-written parts of generated commands: what the generator's special-case
//! table (`generator/src/plan/hooks.rs`) says a command calls beyond its parameters.
//!
//! Each function is named in one row of that table, which also lists the rules it
//! settles, so the report counts exactly what these functions check. `*_checks` run in
//! every build before the call (after the checks of implicit rules);
//! `*_before` and `*_done` are the bookkeeping around a successful call; `*_created`,
//! `*_allocated` and `*_got` finish the wrapper a command returns.

use crate::handles::*;
use crate::recorder::{Recorder, Scope};
use crate::retention::{
    BindingRecord, BufferRecord, ImageRecord, LayoutRecord, PipelineRecord, QueryPoolRecord,
    RenderPassRecord, SetLayoutRecord,
};
use crate::structs::*;
use crate::submission::{self, SubmitRules};
use crate::{Error, Handle, Result};
use ash::vk;
use ash::vk::Handle as _;
use smallvec::SmallVec;
use tuff_runtime::Vrc;

mod barriers;
mod copies;
mod creation;
mod descriptors;
mod layouts;
mod pass_begin;
mod pipeline;
mod render_pass;
mod stages;
#[cfg(feature = "khr_swapchain")]
mod swapchain;
mod view;
pub(crate) use barriers::{pipeline_barrier_checks, wait_events_checks};
use creation::image_create_rules;
pub(crate) use creation::{
    allocate_memory_checks, allocate_memory_gate, create_device_checks,
    descriptor_set_layout_checks, sampler_checks,
};
pub(crate) use descriptors::{
    update_descriptor_sets_checks, update_descriptor_sets_done, update_descriptor_sets_gate,
};
pub(crate) use layouts::{
    cmd_pipeline_barrier_checks, cmd_pipeline_barrier_done, dependency_checks, dependency_done,
    execute_layout_checks, execute_layouts_done, framebuffer_created, image_layout_checks,
    image_layouts_named, render_pass_layout_checks, Names,
};
pub(crate) use pass_begin::{begin_render_pass_checks, BEGIN, BEGIN2};
pub(crate) use pipeline::{compute_pipeline_state_checks, graphics_pipeline_state_checks};
pub(crate) use render_pass::{
    create_render_pass2_checks, render_pass2_reference_checks, render_pass_reference_checks,
};
#[cfg(feature = "khr_swapchain")]
pub(crate) use swapchain::{
    acquire_next_image2_khr_checks, acquire_next_image2_khr_done, acquire_next_image_khr_checks,
    acquire_next_image_khr_done, create_swapchain_checks, swapchain_retires,
};
pub(crate) use view::{
    conversion_created, create_framebuffer_checks, image_view_checks, image_view_created,
};

/// The raw command buffers of `vkQueueSubmit` batches.
fn submit_command_buffers(submits: &[SubmitInfo<'_>]) -> SmallVec<[vk::CommandBuffer; 8]> {
    submits
        .iter()
        // SAFETY: the safe structs store every array with its length.
        .flat_map(|s| unsafe {
            crate::retention::raw_slice(s.p_command_buffers, s.command_buffer_count)
        })
        .copied()
        .collect()
}

/// The raw command buffers of `vkQueueSubmit2` batches.
fn submit2_command_buffers(submits: &[SubmitInfo2<'_>]) -> SmallVec<[vk::CommandBuffer; 8]> {
    submits
        .iter()
        // SAFETY: the safe structs store every array with its length.
        .flat_map(|s| unsafe {
            crate::retention::raw_slice(s.p_command_buffer_infos, s.command_buffer_info_count)
        })
        .map(|i| i.command_buffer)
        .collect()
}

/// Refuses timeline semaphores of a batch without one value each.
///
/// # Safety
///
/// The arrays and chain come from a safe struct: each array stored with its length,
/// and only structs pushed through `push_next` chained.
unsafe fn check_batch(
    queue: &Queue,
    waits: *const vk::Semaphore,
    wait_count: u32,
    signals: *const vk::Semaphore,
    signal_count: u32,
    next: *const core::ffi::c_void,
    rules: &submission::TimelineRules,
) -> Result<()> {
    // SAFETY: the caller's promise, passed on.
    unsafe {
        submission::check_timeline_batch(
            queue.parent().live(),
            crate::retention::raw_slice(waits, wait_count),
            crate::retention::raw_slice(signals, signal_count),
            next,
            rules,
        )
    }
}

/// The checks of `vkQueueSubmit` that memory safety needs: the fence, the command
/// buffers' states and the batches' timeline values.
pub(crate) fn queue_submit_checks(
    queue: &Queue,
    submits: &[SubmitInfo<'_>],
    fence: Option<&Fence>,
) -> Result<()> {
    submit_checks(
        queue,
        fence,
        &submit_command_buffers(submits),
        &submission::SUBMIT,
    )?;
    for (i, b) in submits.iter().enumerate() {
        check_device_group_submit(i, b)?;
        check_group_indices(queue.parent(), i, b)?;
        check_wait_stages(queue, i, b)?;
        check_pools(queue, i, b)?;
    }
    for b in submits {
        // SAFETY: `b` is a safe struct.
        unsafe {
            check_batch(
                queue,
                b.p_wait_semaphores,
                b.wait_semaphore_count,
                b.p_signal_semaphores,
                b.signal_semaphore_count,
                b.p_next,
                &submission::SUBMIT_TIMELINE,
            )
        }?;
    }
    Ok(())
}

/// Refuses a batch whose command buffers come from a pool of another queue family
/// than the queue's (00074), a protected batch on a queue that is not protected
/// (06448), and command buffers whose pool's protection differs from the batch's
/// (04120, 04148).
fn check_pools(queue: &Queue, i: usize, batch: &SubmitInfo<'_>) -> Result<()> {
    let device = queue.parent();
    let live = device.live();
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let protected_info: Option<&vk::ProtectedSubmitInfo<'_>> =
        unsafe { chained(batch.p_next, vk::StructureType::PROTECTED_SUBMIT_INFO) };
    let protected = protected_info.is_some_and(|p| p.protected_submit == vk::TRUE);
    if protected && !live.is_protected_queue(queue.raw()) {
        refuse(
            "VUID-vkQueueSubmit-queue-06448",
            format!(
                "pSubmits[{i}] is a protected submission, and the queue was not created protected"
            ),
        )?;
    }
    let family = live.queue_family(queue.raw());
    // SAFETY: the safe struct stores the array with its length.
    let cbs =
        unsafe { crate::retention::raw_slice(batch.p_command_buffers, batch.command_buffer_count) };
    for (j, raw) in cbs.iter().enumerate() {
        let Some((pool_family, pool_protected)) =
            device.command_buffer_uses(*raw).and_then(|u| u.pool())
        else {
            continue;
        };
        if family.is_some_and(|f| f != pool_family) {
            refuse(
                "VUID-vkQueueSubmit-pCommandBuffers-00074",
                format!("pSubmits[{i}].pCommandBuffers[{j}] comes from a pool of queue family {pool_family}, not the queue's"),
            )?;
        }
        if protected && !pool_protected {
            refuse(
                "VUID-VkSubmitInfo-pNext-04148",
                format!("pSubmits[{i}] is protected, and pCommandBuffers[{j}] is not a protected command buffer"),
            )?;
        }
        if !protected && pool_protected {
            refuse(
                "VUID-VkSubmitInfo-pNext-04120",
                format!("pSubmits[{i}] is not protected, and pCommandBuffers[{j}] is a protected command buffer"),
            )?;
        }
    }
    Ok(())
}

/// Takes the device's descriptor gate for `vkQueueSubmit` and refuses command
/// buffers that an update of a set they bind left invalid.
pub(crate) fn queue_submit_gate<'q>(
    queue: &'q Queue,
    submits: &[SubmitInfo<'_>],
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    let device = queue.parent();
    let cbs = submit_command_buffers(submits);
    let gate = submission::sets_gate(device, &cbs, submission::SUBMIT.executable)?;
    // What other queues' submissions use and leave (events, semaphores) is checked
    // under the gate, which every submission holds until it has recorded its own.
    submission::check_events(
        device,
        queue.raw(),
        &cbs,
        "VUID-vkQueueSubmit-pCommandBuffers-00065",
    )?;
    submission::check_binary_ops(
        device,
        queue.raw(),
        &submit_semaphore_ops(submits),
        &submission::SUBMIT_BINARY,
    )?;
    submission::check_timeline_values(
        device.live(),
        &submission::submit_timeline_ops(device.live(), submits),
        timeline_difference(device),
        submission::SUBMIT_TIMELINE_VALUES,
    )?;
    Ok(gate)
}

/// As [`queue_submit_gate`], for `vkQueueSubmit2`.
pub(crate) fn queue_submit2_gate<'q>(
    queue: &'q Queue,
    submits: &[SubmitInfo2<'_>],
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    let device = queue.parent();
    let gate = submission::sets_gate(
        device,
        &submit2_command_buffers(submits),
        submission::SUBMIT2.executable,
    )?;
    submission::check_binary_ops(
        device,
        queue.raw(),
        &submit2_semaphore_ops(submits),
        &submission::SUBMIT2_BINARY,
    )?;
    Ok(gate)
}

/// Takes the device's gate for `vkQueueBindSparse` and checks its binary semaphore
/// operations again under it, so no submission on another queue changes their
/// states between this check and the bookkeeping of the call.
pub(crate) fn queue_bind_sparse_gate<'q>(
    queue: &'q Queue,
    bind_info: &[BindSparseInfo<'_>],
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    let gate = queue.parent().live().descriptor_gate();
    submission::check_binary_ops(
        queue.parent(),
        queue.raw(),
        &bind_sparse_semaphore_ops(bind_info),
        &submission::BIND_SPARSE_BINARY,
    )?;
    Ok(gate)
}

/// As [`queue_bind_sparse_gate`], for `vkQueuePresentKHR`'s waits.
#[cfg(feature = "khr_swapchain")]
pub(crate) fn queue_present_khr_gate<'q>(
    queue: &'q Queue,
    present_info: &PresentInfoKHR<'_>,
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    let gate = queue.parent().live().descriptor_gate();
    // SAFETY: the safe struct stores the array with its length.
    let waits = unsafe {
        crate::retention::raw_slice(
            present_info.p_wait_semaphores,
            present_info.wait_semaphore_count,
        )
    };
    let ops: Vec<submission::SemOp> = waits.iter().map(|s| submission::SemOp::Wait(*s)).collect();
    submission::check_binary_ops(
        queue.parent(),
        queue.raw(),
        &ops,
        &submission::PRESENT_BINARY,
    )?;
    Ok(gate)
}

/// The device remembers the buffer and format of a new buffer view.
pub(crate) fn buffer_view_created(
    device: &Device,
    view: BufferView,
    create_info: &BufferViewCreateInfo<'_>,
) -> BufferView {
    let info = create_info.as_raw();
    device
        .live()
        .buffer_view_created(view.raw(), info.buffer, info.format);
    view
}

/// The device remembers what a new sampler does (its filters, mipmap mode,
/// unnormalized coordinates and Y'CbCr conversion), which draws and dispatches check
/// the image views it samples against.
pub(crate) fn sampler_created(
    device: &Device,
    sampler: Sampler,
    create_info: &SamplerCreateInfo<'_>,
) -> Sampler {
    let info = create_info.as_raw();
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let conversion: Option<&vk::SamplerYcbcrConversionInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::SAMPLER_YCBCR_CONVERSION_INFO,
        )
    };
    device.live().sampler_created(
        sampler.raw(),
        crate::retention::sampler_bits(info, conversion.is_some()),
    );
    sampler
}

/// The checks of `vkQueueSubmit2`: the fence and the command buffers' states.
pub(crate) fn queue_submit2_checks(
    queue: &Queue,
    submits: &[SubmitInfo2<'_>],
    fence: Option<&Fence>,
) -> Result<()> {
    submit_checks(
        queue,
        fence,
        &submit2_command_buffers(submits),
        &submission::SUBMIT2,
    )
}

/// The semaphore operations of `vkQueueSubmit`'s batches, in order.
fn submit_semaphore_ops(submits: &[SubmitInfo<'_>]) -> Vec<submission::SemOp> {
    submission::batch_ops(submits.iter().map(|b| {
        // SAFETY: the safe struct stores each array with its length.
        unsafe {
            (
                crate::retention::raw_slice(b.p_wait_semaphores, b.wait_semaphore_count),
                crate::retention::raw_slice(b.p_signal_semaphores, b.signal_semaphore_count),
            )
        }
    }))
}

/// The semaphore operations of `vkQueueSubmit2`'s batches, in order.
fn submit2_semaphore_ops(submits: &[SubmitInfo2<'_>]) -> Vec<submission::SemOp> {
    let mut ops = Vec::new();
    for b in submits {
        // SAFETY: the safe struct stores each array with its length.
        let (waits, signals) = unsafe {
            (
                crate::retention::raw_slice(b.p_wait_semaphore_infos, b.wait_semaphore_info_count),
                crate::retention::raw_slice(
                    b.p_signal_semaphore_infos,
                    b.signal_semaphore_info_count,
                ),
            )
        };
        ops.extend(waits.iter().map(|w| submission::SemOp::Wait(w.semaphore)));
        ops.extend(
            signals
                .iter()
                .map(|s| submission::SemOp::Signal(s.semaphore)),
        );
    }
    ops
}

/// The semaphore operations of `vkQueueBindSparse`'s batches, in order.
fn bind_sparse_semaphore_ops(bind_info: &[BindSparseInfo<'_>]) -> Vec<submission::SemOp> {
    submission::batch_ops(bind_info.iter().map(|b| {
        // SAFETY: the safe struct stores each array with its length.
        unsafe {
            (
                crate::retention::raw_slice(b.p_wait_semaphores, b.wait_semaphore_count),
                crate::retention::raw_slice(b.p_signal_semaphores, b.signal_semaphore_count),
            )
        }
    }))
}

/// The checks of `vkQueueBindSparse`: the fence and the batches' timeline values.
pub(crate) fn queue_bind_sparse_checks(
    queue: &Queue,
    bind_info: &[BindSparseInfo<'_>],
    fence: &Fence,
) -> Result<()> {
    submission::check_fence(fence, &submission::BIND_SPARSE)?;
    submission::check_binary_ops(
        queue.parent(),
        queue.raw(),
        &bind_sparse_semaphore_ops(bind_info),
        &submission::BIND_SPARSE_BINARY,
    )?;
    for b in bind_info {
        // SAFETY: `b` is a safe struct.
        unsafe {
            check_batch(
                queue,
                b.p_wait_semaphores,
                b.wait_semaphore_count,
                b.p_signal_semaphores,
                b.signal_semaphore_count,
                b.p_next,
                &submission::BIND_SPARSE_TIMELINE,
            )
        }?;
    }
    Ok(())
}

fn submit_checks(
    queue: &Queue,
    fence: Option<&Fence>,
    cbs: &[vk::CommandBuffer],
    rules: &SubmitRules,
) -> Result<()> {
    if let Some(fence) = fence {
        submission::check_fence(fence, rules)?;
    }
    submission::check_command_buffers(queue.parent(), cbs, rules)?;
    submission::check_layouts(queue.parent(), cbs)
}

/// After `vkQueueSubmit`: the fence holds everything the submission names (its
/// command buffers, which keep what their recordings use, its semaphores, and whatever
/// else its structs reach) until the submission is known complete; without a fence,
/// the queue does, until a later fence of the queue or an idle wait shows it complete.
pub(crate) fn queue_submit_done(queue: &Queue, submits: &[SubmitInfo<'_>], fence: Option<&Fence>) {
    let device = queue.parent();
    let mut kept = Vec::new();
    for s in submits {
        // SAFETY: the safe structs store every array with its length.
        unsafe { crate::reach::submit_info(s.as_raw(), device.live(), &mut kept) };
    }
    let batches = submission::submit_timeline_batches(device.live(), submits);
    let cbs = submit_command_buffers(submits);
    let sub = submission::submitted(device, queue.raw(), fence, &cbs, kept, batches);
    let ops = submit_semaphore_ops(submits);
    submission::record_binary_ops(device, queue.raw(), &ops, Some(&sub));
    let values = submission::submit_timeline_ops(device.live(), submits);
    submission::record_timeline_values(device.live(), &values, &sub);
    if fence.is_none() {
        queue.hold(sub);
    }
}

/// After `vkQueueSubmit2`, as after `vkQueueSubmit`.
pub(crate) fn queue_submit2_done(
    queue: &Queue,
    submits: &[SubmitInfo2<'_>],
    fence: Option<&Fence>,
) {
    let device = queue.parent();
    let mut kept = Vec::new();
    for s in submits {
        // SAFETY: the safe structs store every array with its length.
        unsafe { crate::reach::submit_info2(s.as_raw(), device.live(), &mut kept) };
    }
    let batches = submission::submit2_timeline_batches(device.live(), submits);
    let cbs = submit2_command_buffers(submits);
    let sub = submission::submitted(device, queue.raw(), fence, &cbs, kept, batches);
    let ops = submit2_semaphore_ops(submits);
    submission::record_binary_ops(device, queue.raw(), &ops, Some(&sub));
    let live = device.live();
    let mut values = Vec::new();
    for b in submits {
        // SAFETY: the safe struct stores each array with its length.
        let (waits, signals) = unsafe {
            (
                crate::retention::raw_slice(b.p_wait_semaphore_infos, b.wait_semaphore_info_count),
                crate::retention::raw_slice(
                    b.p_signal_semaphore_infos,
                    b.signal_semaphore_info_count,
                ),
            )
        };
        let ops = waits
            .iter()
            .map(|w| (w, false))
            .chain(signals.iter().map(|s| (s, true)))
            .filter(|(i, _)| live.is_timeline(i.semaphore))
            .map(|(i, signal)| (i.semaphore, i.value, signal));
        values.extend(ops);
    }
    submission::record_timeline_values(live, &values, &sub);
    if fence.is_none() {
        queue.hold(sub);
    }
}

/// After `vkQueueBindSparse`: the fence holds what the binds name (a timeline signal
/// tells nothing of sparse binds yet).
pub(crate) fn queue_bind_sparse_done(
    queue: &Queue,
    bind_info: &[BindSparseInfo<'_>],
    fence: &Fence,
) {
    let device = queue.parent();
    let mut kept = Vec::new();
    for s in bind_info {
        // SAFETY: the safe structs store every array with its length.
        unsafe { crate::reach::bind_sparse_info(s.as_raw(), device.live(), &mut kept) };
    }
    let sub = submission::submitted(device, queue.raw(), Some(fence), &[], kept, Vec::new());
    let ops = bind_sparse_semaphore_ops(bind_info);
    submission::record_binary_ops(device, queue.raw(), &ops, Some(&sub));
    let mut values = Vec::new();
    for b in bind_info {
        // SAFETY: a safe struct's arrays and chain.
        unsafe {
            submission::timeline_ops(
                device.live(),
                b.p_wait_semaphores,
                b.wait_semaphore_count,
                b.p_signal_semaphores,
                b.signal_semaphore_count,
                b.p_next,
                &mut values,
            )
        };
    }
    submission::record_timeline_values(device.live(), &values, &sub);
}

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

/// Refuses a pending secondary that may not run twice at once.
pub(crate) fn cmd_execute_commands_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) -> Result<()> {
    for h in command_buffers {
        if h.uses().is_pending_exclusive(recorder.device()) {
            return Err(Error::Validation {
                vuid: "VUID-vkCmdExecuteCommands-pCommandBuffers-00091",
                message: "a secondary command buffer without SIMULTANEOUS_USE is pending: a submission that uses it may still be executing".into(),
            });
        }
    }
    execute_layout_checks(recorder, command_buffers)
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
fn timeline_difference(device: &Device) -> u64 {
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
        unsafe { crate::retention::raw_slice(wait_info.p_semaphores, wait_info.semaphore_count) };
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
        unsafe { crate::retention::raw_slice(wait_info.p_semaphores, wait_info.semaphore_count) };
    // SAFETY: the same length, from the same safe struct.
    let values =
        unsafe { crate::retention::raw_slice(wait_info.p_values, wait_info.semaphore_count) };
    for (s, v) in semaphores.iter().zip(values) {
        timeline_seen(device, *s, *v, false);
    }
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

/// Refuses timeline semaphores.
#[cfg(feature = "khr_swapchain")]
pub(crate) fn queue_present_khr_checks(
    queue: &Queue,
    present_info: &PresentInfoKHR<'_>,
) -> Result<()> {
    // SAFETY: the safe struct stores the array with its length.
    let waits = unsafe {
        crate::retention::raw_slice(
            present_info.p_wait_semaphores,
            present_info.wait_semaphore_count,
        )
    };
    submission::check_semaphore_type(
        queue.parent().live(),
        waits,
        false,
        "VUID-vkQueuePresentKHR-pWaitSemaphores-03267",
    )?;
    let ops: Vec<submission::SemOp> = waits.iter().map(|s| submission::SemOp::Wait(*s)).collect();
    submission::check_binary_ops(
        queue.parent(),
        queue.raw(),
        &ops,
        &submission::PRESENT_BINARY,
    )?;
    check_presented_images(queue.parent(), present_info)?;
    check_surface_support(queue, present_info)?;
    check_device_group_present(queue.parent(), present_info)
}

/// Refuses a swapchain whose surface the queue's family cannot present to, as
/// `vkGetPhysicalDeviceSurfaceSupportKHR` says (asked once per swapchain and family).
#[cfg(feature = "khr_swapchain")]
fn check_surface_support(queue: &Queue, present_info: &PresentInfoKHR<'_>) -> Result<()> {
    let device = queue.parent();
    let Some(family) = device.live().queue_family(queue.raw()) else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the array with its count.
    let swapchains = unsafe {
        crate::retention::raw_slice(present_info.p_swapchains, present_info.swapchain_count)
    };
    for (n, swapchain) in swapchains.iter().enumerate() {
        if device.live().presents_from(*swapchain, family) {
            continue;
        }
        let Some(surface) = device.live().swapchain_surface(*swapchain) else {
            continue;
        };
        let fp = device
            .parent()
            .parent()
            .ext()
            .khr_surface
            .as_ref()
            .ok_or(Error::ExtensionNotEnabled("VK_KHR_surface"))?
            .get_physical_device_surface_support_khr;
        let mut supported = vk::FALSE;
        // SAFETY: the physical device of the device, a family the device has a queue
        // of, and the live surface of a live swapchain (its wrapper keeps it alive).
        let r = unsafe { fp(device.parent().raw(), family, surface, &mut supported) };
        if r.as_raw() < 0 {
            return Err(Error::Vk(r));
        }
        if supported != vk::TRUE {
            return refuse(
                "VUID-vkQueuePresentKHR-pSwapchains-01292",
                format!("the surface of pSwapchains[{n}] does not support presentation from the queue's family {family}"),
            );
        }
        device.live().set_presents_from(*swapchain, family);
    }
    Ok(())
}

/// `VkDeviceGroupPresentCapabilitiesKHR::presentMask`, read once (a device of one
/// physical device that cannot ask presents from it alone).
#[cfg(feature = "khr_swapchain")]
fn present_masks(device: &Device) -> Result<[u32; vk::MAX_DEVICE_GROUP_SIZE]> {
    if let Some(masks) = device.live().present_masks() {
        return Ok(masks);
    }
    let mut masks = [0; vk::MAX_DEVICE_GROUP_SIZE];
    masks[0] = 1;
    if device.exts().version(1) {
        let mut caps = DeviceGroupPresentCapabilitiesKHR::new();
        device.get_group_present_capabilities_khr(&mut caps)?;
        masks = caps.present_mask;
    }
    device.live().set_present_masks(masks);
    Ok(masks)
}

/// The rules of a chained `VkDeviceGroupPresentInfoKHR`: its count, each device
/// mask against the mode and the devices that can present, against the mask its
/// image was acquired with, and the mode against the swapchain's modes.
#[cfg(feature = "khr_swapchain")]
fn check_device_group_present(device: &Device, present_info: &PresentInfoKHR<'_>) -> Result<()> {
    let info = present_info.as_raw();
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let Some(group) = (unsafe {
        chained::<vk::DeviceGroupPresentInfoKHR<'_>>(
            info.p_next,
            vk::StructureType::DEVICE_GROUP_PRESENT_INFO_KHR,
        )
    }) else {
        return Ok(());
    };
    if group.swapchain_count != 0 && group.swapchain_count != info.swapchain_count {
        return refuse(
            "VUID-VkDeviceGroupPresentInfoKHR-swapchainCount-01297",
            format!(
                "swapchainCount is {}, and VkPresentInfoKHR::swapchainCount is {}",
                group.swapchain_count, info.swapchain_count
            ),
        );
    }
    // SAFETY: the safe setters store each array with its count.
    let (masks, swapchains, indices) = unsafe {
        (
            crate::retention::raw_slice(group.p_device_masks, group.swapchain_count),
            crate::retention::raw_slice(info.p_swapchains, info.swapchain_count),
            crate::retention::raw_slice(info.p_image_indices, info.swapchain_count),
        )
    };
    let present = present_masks(device)?;
    let can_present = |bit: u32| present.get(bit as usize).is_some_and(|m| *m != 0);
    let bits = |mask: u32| (0..32).filter(move |b| mask & (1 << b) != 0);
    type Mode = vk::DeviceGroupPresentModeFlagsKHR;
    for (n, mask) in masks.iter().enumerate() {
        let one_bit = mask.count_ones() == 1;
        let (vuid, ok) = match group.mode {
            Mode::LOCAL => (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01298",
                one_bit && bits(*mask).all(can_present),
            ),
            Mode::REMOTE => (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01299",
                one_bit && present.iter().any(|p| p & mask != 0),
            ),
            Mode::SUM => (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01300",
                present.iter().any(|p| p & mask == *mask),
            ),
            Mode::LOCAL_MULTI_DEVICE => (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01301",
                bits(*mask).all(can_present),
            ),
            _ => ("", true),
        };
        if !ok {
            return refuse(
                vuid,
                format!(
                    "pDeviceMasks[{n}] = {mask:#x} does not suit mode {:?} with the device group's presentMask {:x?}",
                    group.mode, &present[..device.live().physical_count().clamp(1, 32) as usize]
                ),
            );
        }
        let acquired = swapchains
            .get(n)
            .zip(indices.get(n))
            .and_then(|(s, i)| device.live().acquired_image(*s, *i).ok());
        if let Some((_, acquired_mask)) = acquired {
            if acquired_mask != *mask {
                return refuse(
                    "VUID-VkDeviceGroupPresentInfoKHR-pDeviceMasks-01302",
                    format!("pDeviceMasks[{n}] = {mask:#x}, and the image was acquired with device mask {acquired_mask:#x}"),
                );
            }
        }
    }
    for (n, swapchain) in swapchains.iter().enumerate() {
        let modes = device.live().swapchain_modes(*swapchain);
        if group.mode.as_raw().count_ones() != 1 || !modes.contains(group.mode) {
            return refuse(
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01303",
                format!(
                    "mode is {:?}, and pSwapchains[{n}] was created for modes {modes:?}",
                    group.mode
                ),
            );
        }
    }
    Ok(())
}

/// Refuses an image index that is not acquired, or whose image the submissions so
/// far leave in a layout other than `PRESENT_SRC_KHR` (or `SHARED_PRESENT_KHR`).
#[cfg(feature = "khr_swapchain")]
fn check_presented_images(device: &Device, present_info: &PresentInfoKHR<'_>) -> Result<()> {
    const VUID: &str = "VUID-VkPresentInfoKHR-pImageIndices-01296";
    let info = present_info.as_raw();
    // SAFETY: the safe setter stores both arrays with the one count.
    let (swapchains, indices) = unsafe {
        (
            crate::retention::raw_slice(info.p_swapchains, info.swapchain_count),
            crate::retention::raw_slice(info.p_image_indices, info.swapchain_count),
        )
    };
    for (n, (swapchain, index)) in swapchains.iter().zip(indices).enumerate() {
        match device.live().acquired_image(*swapchain, *index) {
            Ok((image, _)) => crate::layouts::check_device_layout(
                device.live(),
                image,
                &[
                    vk::ImageLayout::PRESENT_SRC_KHR,
                    vk::ImageLayout::SHARED_PRESENT_KHR,
                ],
                VUID,
            )?,
            Err(false) => refuse(
                VUID,
                format!("pImageIndices[{n}] = {index} is not an image acquired from pSwapchains[{n}] and not presented since"),
            )?,
            Err(true) => refuse(
                VUID,
                format!("image {index} of pSwapchains[{n}] was never returned by get_swapchain_images_khr, so no command made its layout PRESENT_SRC_KHR"),
            )?,
        }
    }
    Ok(())
}

/// Held before the call: a presentation the engine rejects still waits on its
/// semaphores. The queue holds it until it is known complete.
#[cfg(feature = "khr_swapchain")]
pub(crate) fn queue_present_khr_before(queue: &Queue, present_info: &PresentInfoKHR<'_>) {
    let device = queue.parent();
    let mut kept = Vec::new();
    // SAFETY: the safe struct stores every array with its length.
    unsafe { crate::reach::present_info_khr(present_info.as_raw(), device.live(), &mut kept) };
    let sub = submission::submitted(device, queue.raw(), None, &[], kept, Vec::new());
    // SAFETY: the safe struct stores the array with its length.
    let waits = unsafe {
        crate::retention::raw_slice(
            present_info.p_wait_semaphores,
            present_info.wait_semaphore_count,
        )
    };
    let ops: Vec<submission::SemOp> = waits.iter().map(|s| submission::SemOp::Wait(*s)).collect();
    submission::record_binary_ops(device, queue.raw(), &ops, Some(&sub));
    queue.hold(sub);
    let info = present_info.as_raw();
    // SAFETY: the safe setter stores both arrays with the one count.
    let (swapchains, indices) = unsafe {
        (
            crate::retention::raw_slice(info.p_swapchains, info.swapchain_count),
            crate::retention::raw_slice(info.p_image_indices, info.swapchain_count),
        )
    };
    for (swapchain, index) in swapchains.iter().zip(indices) {
        device.live().image_presented(*swapchain, *index);
    }
}

/// Refuses a buffer that may still be executing, or whose pool does not reset buffers.
pub(crate) fn reset_command_buffer_checks(command_buffer: &CommandBuffer) -> Result<()> {
    command_buffer.uses().check_reset(
        command_buffer.device(),
        command_buffer.parent().resets_buffers(),
    )
}

/// Initial state; the last recording's objects go, as no submission uses the buffer
/// (checked).
pub(crate) fn reset_command_buffer_done(command_buffer: &CommandBuffer) {
    command_buffer.uses().reset();
    command_buffer.keep_alive(Vec::new());
}

/// Refuses a pool one of whose buffers may still be executing or is being recorded.
pub(crate) fn reset_command_pool_checks(device: &Device, command_pool: &CommandPool) -> Result<()> {
    submission::check_pool_reset(device, &command_pool.buffer_uses())
}

/// Every buffer of the pool is back in the initial state.
pub(crate) fn reset_command_pool_done(command_pool: &CommandPool) {
    for u in command_pool.buffer_uses() {
        u.reset();
    }
}

/// Refuses a pool whose sets are still alive.
pub(crate) fn reset_descriptor_pool_checks(descriptor_pool: &DescriptorPool) -> Result<()> {
    if descriptor_pool.has_sets() {
        return Err(Error::Validation {
            vuid: "VUID-vkResetDescriptorPool-descriptorPool-00313",
            message: "sets allocated from the pool are still alive (held by the program, or by a command buffer or submission that uses them); drop them before the pool is reset".into(),
        });
    }
    Ok(())
}

/// The pool's sets are gone: it forgets those whose free it deferred.
pub(crate) fn reset_descriptor_pool_done(descriptor_pool: &DescriptorPool) {
    descriptor_pool.forget_deferred();
}

/// The set remembers what the template wrote into it.
///
/// # Safety
///
/// `data` is laid out as the template's entries describe (the promise of the
/// `unsafe` method that calls this).
pub(crate) unsafe fn update_descriptor_set_with_template_done(
    device: &Device,
    descriptor_set: &DescriptorSet,
    descriptor_update_template: &DescriptorUpdateTemplate,
    data: *const core::ffi::c_void,
) {
    // Which bindings the template writes is not looked at: the update counts as one
    // that invalidates the command buffers that bound the set.
    device.live().set_invalidated(descriptor_set.raw());
    // SAFETY: the caller's promise, passed on.
    unsafe {
        device.live().write_template(
            descriptor_set.raw(),
            descriptor_update_template.entries(),
            data,
        )
    };
}

/// The buffer keeps its memory alive; commands that use it may now read it.
pub(crate) fn bind_buffer_memory_done(
    device: &Device,
    buffer: &Buffer,
    memory: &DeviceMemory,
    memory_offset: vk::DeviceSize,
) {
    buffer.retain_memory(memory.retained());
    device
        .live()
        .buffer_bound(buffer.raw(), memory.raw(), memory_offset);
}

/// Each buffer keeps its memory alive (the safe infos name both by wrappers); commands
/// that use it may now read it.
pub(crate) fn bind_buffer_memory2_done(device: &Device, bind_infos: &[BindBufferMemoryInfo<'_>]) {
    for info in bind_infos {
        device.live().bound2(info.buffer, info.memory);
        device
            .live()
            .buffer_bound(info.buffer, info.memory, info.memory_offset);
    }
}

/// Each image keeps its memory alive; commands that use it may now read it.
pub(crate) fn bind_image_memory2_done(device: &Device, bind_infos: &[BindImageMemoryInfo<'_>]) {
    for info in bind_infos {
        device.live().bound2(info.image, info.memory);
        let size = image_size(device, info.image);
        device
            .live()
            .image_bound(info.image, info.memory, info.memory_offset, size);
    }
}

/// The device remembers the image's creation parameters for the checks of the
/// commands and structs that name it.
pub(crate) fn image_created(
    device: &Device,
    image: Image,
    create_info: &ImageCreateInfo<'_>,
) -> Image {
    if create_info
        .flags
        .contains(vk::ImageCreateFlags::SPARSE_BINDING)
    {
        // What the creation's check counted, so the total stays what it checks.
        let required = sparse_image_requirement(device, create_info.as_raw());
        device.live().sparse_created(image.raw(), required);
    }
    let next = create_info.as_raw().p_next;
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (stencil, list) = unsafe {
        (
            chained::<vk::ImageStencilUsageCreateInfo<'_>>(
                next,
                vk::StructureType::IMAGE_STENCIL_USAGE_CREATE_INFO,
            ),
            chained::<vk::ImageFormatListCreateInfo<'_>>(
                next,
                vk::StructureType::IMAGE_FORMAT_LIST_CREATE_INFO,
            ),
        )
    };
    // SAFETY: the safe setter stores the formats with their count.
    let views = list.map_or(&[][..], |l| unsafe {
        crate::retention::raw_slice(l.p_view_formats, l.view_format_count)
    });
    device.live().image_created(
        image.raw(),
        ImageRecord {
            flags: create_info.flags,
            image_type: create_info.image_type,
            format: create_info.format,
            extent: create_info.extent,
            mip_levels: create_info.mip_levels,
            array_layers: create_info.array_layers,
            usage: create_info.usage,
            tiling: create_info.tiling,
            samples: create_info.samples,
            stencil_usage: stencil.map(|s| s.stencil_usage),
            sharing: create_info.sharing_mode,
            families: family_bits(create_info.sharing_mode, create_info.as_raw()),
            bound: false,
            external: external_handle_types(next),
        },
        views,
    );
    if create_info.initial_layout == vk::ImageLayout::PREINITIALIZED {
        device.live().image_preinitialized(image.raw());
    }
    image
}

/// The queue families of a concurrent resource as bits (see `ImageRecord::families`).
fn family_bits(sharing: vk::SharingMode, info: &vk::ImageCreateInfo<'_>) -> u64 {
    if sharing != vk::SharingMode::CONCURRENT {
        return 0;
    }
    // SAFETY: the safe setter stores the indices with their count.
    let families = unsafe {
        crate::retention::raw_slice(info.p_queue_family_indices, info.queue_family_index_count)
    };
    families
        .iter()
        .fold(0, |bits, &f| match 1u64.checked_shl(f) {
            Some(bit) => bits | bit,
            None => u64::MAX,
        })
}

/// The handle types a chained `VkExternalMemoryBufferCreateInfo` or
/// `VkExternalMemoryImageCreateInfo` names (none without one).
fn external_handle_types(next: *const core::ffi::c_void) -> vk::ExternalMemoryHandleTypeFlags {
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name (the two
    // structs have the same layout).
    let (buffer, image) = unsafe {
        (
            chained::<vk::ExternalMemoryBufferCreateInfo<'_>>(
                next,
                vk::StructureType::EXTERNAL_MEMORY_BUFFER_CREATE_INFO,
            ),
            chained::<vk::ExternalMemoryImageCreateInfo<'_>>(
                next,
                vk::StructureType::EXTERNAL_MEMORY_IMAGE_CREATE_INFO,
            ),
        )
    };
    buffer
        .map(|b| b.handle_types)
        .or(image.map(|i| i.handle_types))
        .unwrap_or_default()
}

/// The image creation flags a swapchain's flags imply for its images (the
/// specification's implied image creation parameters).
#[cfg(feature = "khr_swapchain")]
fn swapchain_image_flags(flags: vk::SwapchainCreateFlagsKHR) -> vk::ImageCreateFlags {
    let mut image = vk::ImageCreateFlags::empty();
    if flags.contains(vk::SwapchainCreateFlagsKHR::SPLIT_INSTANCE_BIND_REGIONS) {
        image |= vk::ImageCreateFlags::SPLIT_INSTANCE_BIND_REGIONS;
    }
    if flags.contains(vk::SwapchainCreateFlagsKHR::PROTECTED) {
        image |= vk::ImageCreateFlags::PROTECTED;
    }
    if flags.contains(vk::SwapchainCreateFlagsKHR::MUTABLE_FORMAT) {
        image |= vk::ImageCreateFlags::MUTABLE_FORMAT | vk::ImageCreateFlags::EXTENDED_USAGE;
    }
    image
}

/// The device remembers what the swapchain's images are, as the images a
/// `VkImageCreateInfo` of its parameters would make (2D, one level, its extent,
/// layers and usage, bound), for [`swapchain_images`].
#[cfg(feature = "khr_swapchain")]
pub(crate) fn swapchain_created(
    device: &Device,
    swapchain: SwapchainKHR,
    surface: &SurfaceKHR,
    create_info: &SwapchainCreateInfoKHR<'_>,
) -> SwapchainKHR {
    device.live().swapchain_created(
        swapchain.raw(),
        surface.raw(),
        ImageRecord {
            flags: swapchain_image_flags(create_info.flags),
            image_type: vk::ImageType::TYPE_2D,
            format: create_info.image_format,
            extent: vk::Extent3D {
                width: create_info.image_extent.width,
                height: create_info.image_extent.height,
                depth: 1,
            },
            mip_levels: 1,
            array_layers: create_info.image_array_layers,
            usage: create_info.image_usage,
            tiling: vk::ImageTiling::OPTIMAL,
            samples: vk::SampleCountFlags::TYPE_1,
            stencil_usage: None,
            sharing: create_info.image_sharing_mode,
            families: family_bits(
                create_info.image_sharing_mode,
                &vk::ImageCreateInfo::default().queue_family_indices(
                    // SAFETY: the safe setter stores the indices with their count.
                    unsafe {
                        crate::retention::raw_slice(
                            create_info.p_queue_family_indices,
                            create_info.queue_family_index_count,
                        )
                    },
                ),
            ),
            bound: true,
            external: vk::ExternalMemoryHandleTypeFlags::empty(),
        },
        // SAFETY: the chain of a safe struct, and the type its sType names.
        unsafe {
            chained::<vk::DeviceGroupSwapchainCreateInfoKHR<'_>>(
                create_info.p_next,
                vk::StructureType::DEVICE_GROUP_SWAPCHAIN_CREATE_INFO_KHR,
            )
        }
        .map_or(vk::DeviceGroupPresentModeFlagsKHR::LOCAL, |g| g.modes),
    );
    swapchain
}

/// The swapchain's images get its record, so the checks of the commands that name
/// one read its size and usage as for any image.
#[cfg(feature = "khr_swapchain")]
pub(crate) fn swapchain_images(
    device: &Device,
    images: Vec<Image>,
    swapchain: &SwapchainKHR,
) -> Vec<Image> {
    let raw: SmallVec<[vk::Image; 8]> = images.iter().map(|i| i.raw()).collect();
    device.live().swapchain_images(swapchain.raw(), &raw);
    images
}

/// The device remembers the buffer's size, usage and flags for the checks of the
/// commands that use it.
pub(crate) fn buffer_created(
    device: &Device,
    buffer: Buffer,
    create_info: &BufferCreateInfo<'_>,
) -> Buffer {
    if create_info
        .flags
        .contains(vk::BufferCreateFlags::SPARSE_BINDING)
    {
        let required = sparse_requirement(device, create_info);
        device.live().sparse_created(buffer.raw(), required);
    }
    device.live().buffer_created(
        buffer.raw(),
        BufferRecord {
            size: create_info.size,
            usage: create_info.usage,
            flags: create_info.flags,
            sharing: create_info.sharing_mode,
            bound: false,
            memory_offset: 0,
            external: external_handle_types(create_info.as_raw().p_next),
        },
    );
    buffer
}

/// The record of a buffer wrapper, which every buffer made through the wrappers has.
fn buffer_record(device: &Device, buffer: &Buffer) -> Result<BufferRecord> {
    device.live().buffer(buffer.raw()).ok_or(Error::Misuse(
        "the buffer was not created through the wrappers, so its size is unknown",
    ))
}

/// A refusal naming the rule, what it says, and the values that break it.
fn refuse(vuid: &'static str, message: String) -> Result<()> {
    Err(Error::Validation { vuid, message })
}

/// Checks that a buffer a command reads or writes has memory (or is sparse) and the
/// usage the command needs.
fn check_buffer_use(
    record: &BufferRecord,
    usage: vk::BufferUsageFlags,
    (usage_vuid, bound_vuid): (&'static str, &'static str),
    name: &dyn core::fmt::Display,
) -> Result<()> {
    if !record.usage.contains(usage) {
        refuse(
            usage_vuid,
            format!(
                "{name} must have been created with {usage:?} usage (usage = {:?})",
                record.usage
            ),
        )?;
    }
    let sparse = record.flags.contains(vk::BufferCreateFlags::SPARSE_BINDING);
    if !sparse && !record.bound {
        refuse(
            bound_vuid,
            format!("{name} is not sparse, so memory must be bound to it before a command uses it"),
        )?;
    }
    Ok(())
}

/// The records of buffers a recorded command uses, with their usage and binding
/// checked.
fn used_buffer<S: Scope>(
    recorder: &Recorder<'_, S>,
    buffer: &Buffer,
    usage: vk::BufferUsageFlags,
    vuids: (&'static str, &'static str),
    name: &dyn core::fmt::Display,
) -> Result<BufferRecord> {
    let record = buffer_record(recorder.device(), buffer)?;
    check_buffer_use(&record, usage, vuids, name)?;
    Ok(record)
}

/// The checks of `vkCmdFillBuffer` that keep the fill inside the buffer.
pub(crate) fn cmd_fill_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    dst_buffer: &Buffer,
    dst_offset: vk::DeviceSize,
    size: vk::DeviceSize,
) -> Result<()> {
    let dst = used_buffer(
        recorder,
        dst_buffer,
        vk::BufferUsageFlags::TRANSFER_DST,
        (
            "VUID-vkCmdFillBuffer-dstBuffer-00029",
            "VUID-vkCmdFillBuffer-dstBuffer-00031",
        ),
        &"dstBuffer",
    )?;
    if dst_offset >= dst.size {
        refuse("VUID-vkCmdFillBuffer-dstOffset-00024", format!("dstOffset must be less than the size of dstBuffer (dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size))?;
    }
    if dst_offset % 4 != 0 {
        refuse(
            "VUID-vkCmdFillBuffer-dstOffset-00025",
            format!("dstOffset must be a multiple of 4 (dstOffset = {dst_offset})"),
        )?;
    }
    if size != vk::WHOLE_SIZE {
        if size == 0 {
            refuse(
                "VUID-vkCmdFillBuffer-size-00026",
                "size must be greater than 0 (size = 0)".into(),
            )?;
        }
        if size > dst.size - dst_offset {
            refuse("VUID-vkCmdFillBuffer-size-00027", format!("size must be at most the size of dstBuffer minus dstOffset (size = {size}, dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size))?;
        }
        if size % 4 != 0 {
            refuse(
                "VUID-vkCmdFillBuffer-size-00028",
                format!("size must be a multiple of 4 (size = {size})"),
            )?;
        }
    }
    Ok(())
}

/// The checks of `vkCmdUpdateBuffer` that keep the update inside the buffer.
pub(crate) fn cmd_update_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    dst_buffer: &Buffer,
    dst_offset: vk::DeviceSize,
    data: &[u8],
) -> Result<()> {
    let dst = used_buffer(
        recorder,
        dst_buffer,
        vk::BufferUsageFlags::TRANSFER_DST,
        (
            "VUID-vkCmdUpdateBuffer-dstBuffer-00034",
            "VUID-vkCmdUpdateBuffer-dstBuffer-00035",
        ),
        &"dstBuffer",
    )?;
    let len = data.len() as u64;
    if dst_offset >= dst.size {
        refuse("VUID-vkCmdUpdateBuffer-dstOffset-00032", format!("dstOffset must be less than the size of dstBuffer (dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size))?;
    }
    if len > dst.size - dst_offset {
        refuse("VUID-vkCmdUpdateBuffer-dataSize-00033", format!("dataSize must be at most the size of dstBuffer minus dstOffset (dataSize = {len}, dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size))?;
    }
    if dst_offset % 4 != 0 {
        refuse(
            "VUID-vkCmdUpdateBuffer-dstOffset-00036",
            format!("dstOffset must be a multiple of 4 (dstOffset = {dst_offset})"),
        )?;
    }
    if len > 65536 {
        refuse(
            "VUID-vkCmdUpdateBuffer-dataSize-00037",
            format!("dataSize must be at most 65536 (dataSize = {len})"),
        )?;
    }
    if len % 4 != 0 {
        refuse(
            "VUID-vkCmdUpdateBuffer-dataSize-00038",
            format!("dataSize must be a multiple of 4 (dataSize = {len})"),
        )?;
    }
    Ok(())
}

/// The rules a vertex-buffer binding breaks: (usage, memory, offset, offset plus size).
type VertexRules = [&'static str; 6];

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
    let limits = device
        .live()
        .limits(|| device.parent().get_properties().limits);
    {
        let max = limits.max_vertex_input_bindings;
        if u64::from(first_binding) + buffers.len() as u64 > u64::from(max) {
            refuse(
                rules[4],
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
                rules[5],
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
            (rules[0], rules[1]),
            &format_args!("pBuffers[{i}]"),
        )?;
        if offset >= record.size {
            refuse(rules[2], format!("pOffsets[{i}] must be less than the size of pBuffers[{i}] (offset = {offset}, size = {})", record.size))?;
        }
        // VK_WHOLE_SIZE is the rest of the buffer.
        if let Some(&size) = sizes.get(i).filter(|&&s| s != vk::WHOLE_SIZE) {
            if size > record.size - offset {
                refuse(rules[3], format!("pOffsets[{i}] plus pSizes[{i}] must be at most the size of pBuffers[{i}] (offset = {offset}, size = {size}, size of the buffer = {})", record.size))?;
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
    let rules = [
        "VUID-vkCmdBindVertexBuffers-pBuffers-00627",
        "VUID-vkCmdBindVertexBuffers-pBuffers-00628",
        "VUID-vkCmdBindVertexBuffers-pOffsets-00626",
        "",
        "VUID-vkCmdBindVertexBuffers-firstBinding-00625",
        "",
    ];
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
    let rules = [
        "VUID-vkCmdBindVertexBuffers2-pBuffers-03359",
        "VUID-vkCmdBindVertexBuffers2-pBuffers-03360",
        "VUID-vkCmdBindVertexBuffers2-pOffsets-03357",
        "VUID-vkCmdBindVertexBuffers2-pSizes-03358",
        "VUID-vkCmdBindVertexBuffers2-firstBinding-03356",
        "VUID-vkCmdBindVertexBuffers2-pStrides-03362",
    ];
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

/// The checks of `vkCmdCopyBuffer` that keep the copy inside both buffers: a copy out
/// of range reads or writes memory the buffers do not own.
pub(crate) fn cmd_copy_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_buffer: &Buffer,
    dst_buffer: &Buffer,
    regions: &[vk::BufferCopy],
) -> Result<()> {
    let device = recorder.device();
    let src = buffer_record(device, src_buffer)?;
    let dst = buffer_record(device, dst_buffer)?;
    check_buffer_use(
        &src,
        vk::BufferUsageFlags::TRANSFER_SRC,
        (
            "VUID-vkCmdCopyBuffer-srcBuffer-00118",
            "VUID-vkCmdCopyBuffer-srcBuffer-00119",
        ),
        &"srcBuffer",
    )?;
    check_buffer_use(
        &dst,
        vk::BufferUsageFlags::TRANSFER_DST,
        (
            "VUID-vkCmdCopyBuffer-dstBuffer-00120",
            "VUID-vkCmdCopyBuffer-dstBuffer-00121",
        ),
        &"dstBuffer",
    )?;
    for (i, r) in regions.iter().enumerate() {
        if r.size == 0 {
            refuse(
                "VUID-VkBufferCopy-size-01988",
                format!("pRegions[{i}].size must be greater than 0 (size = 0)"),
            )?;
        }
        if r.src_offset >= src.size {
            refuse(
                "VUID-vkCmdCopyBuffer-srcOffset-00113",
                format!("pRegions[{i}].srcOffset must be less than the size of srcBuffer (srcOffset = {}, size of srcBuffer = {})", r.src_offset, src.size),
            )?;
        }
        if r.dst_offset >= dst.size {
            refuse(
                "VUID-vkCmdCopyBuffer-dstOffset-00114",
                format!("pRegions[{i}].dstOffset must be less than the size of dstBuffer (dstOffset = {}, size of dstBuffer = {})", r.dst_offset, dst.size),
            )?;
        }
        if r.size > src.size - r.src_offset {
            refuse(
                "VUID-vkCmdCopyBuffer-size-00115",
                format!("pRegions[{i}].size must be at most the size of srcBuffer minus srcOffset (size = {}, srcOffset = {}, size of srcBuffer = {})", r.size, r.src_offset, src.size),
            )?;
        }
        if r.size > dst.size - r.dst_offset {
            refuse(
                "VUID-vkCmdCopyBuffer-size-00116",
                format!("pRegions[{i}].size must be at most the size of dstBuffer minus dstOffset (size = {}, dstOffset = {}, size of dstBuffer = {})", r.size, r.dst_offset, dst.size),
            )?;
        }
    }
    if src_buffer.raw() == dst_buffer.raw() {
        // Every source range against every destination range, the region's own
        // included; the offsets and sizes are in range, so the ends do not overflow.
        for (i, a) in regions.iter().enumerate() {
            for (j, b) in regions.iter().enumerate() {
                let (a0, a1) = (a.src_offset, a.src_offset + a.size);
                let (b0, b1) = (b.dst_offset, b.dst_offset + b.size);
                if a0 < b1 && b0 < a1 {
                    refuse(
                        "VUID-vkCmdCopyBuffer-pRegions-00117",
                        format!("the source of pRegions[{i}] ({a0}..{a1}) overlaps the destination of pRegions[{j}] ({b0}..{b1}) in the same buffer"),
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// The image keeps its memory alive.
pub(crate) fn bind_image_memory_done(
    device: &Device,
    image: &Image,
    memory: &DeviceMemory,
    memory_offset: vk::DeviceSize,
) {
    image.retain_memory(memory.retained());
    let size = image_size(device, image.raw());
    device
        .live()
        .image_bound(image.raw(), memory.raw(), memory_offset, size);
}

/// The bytes a live image of the device takes in the memory it is bound to.
fn image_size(device: &Device, image: vk::Image) -> vk::DeviceSize {
    // SAFETY: `image` is a live image of `device` (a wrapper's, just bound).
    unsafe { device.fns().get_image_memory_requirements(image) }.size
}

/// What the checks of recorded commands need of a command pool's queue family.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PoolFamily {
    /// The family's index.
    pub index: u32,
    /// Its queue flags.
    pub flags: vk::QueueFlags,
    /// Its `minImageTransferGranularity`.
    pub granularity: vk::Extent3D,
    /// Whether the pool was created with `VK_COMMAND_POOL_CREATE_PROTECTED_BIT`.
    pub protected: bool,
}

/// The queue family of the recorder's command pool, as its pool's creation
/// recorded it (all capabilities, for a pool the wrappers did not record).
pub(crate) fn pool_family<S: Scope>(recorder: &Recorder<'_, S>) -> PoolFamily {
    let pool = recorder.command_buffer().parent().raw();
    recorder
        .device()
        .live()
        .pool_family(pool)
        .unwrap_or(PoolFamily {
            index: vk::QUEUE_FAMILY_IGNORED,
            flags: recorder.pool_queue_flags(),
            granularity: vk::Extent3D {
                width: 1,
                height: 1,
                depth: 1,
            },
            protected: false,
        })
}

/// Every queue operation of the queue is complete.
pub(crate) fn queue_wait_idle_done(queue: &Queue) {
    queue.parent().live().ledger().retire_queue(queue.raw());
}

/// Every queue operation of the device is complete.
pub(crate) fn device_wait_idle_done(device: &Device) {
    device.live().ledger().retire_all();
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

/// The instance remembers its enabled extensions and API version.
pub(crate) fn instance_created(
    entry: &crate::Entry,
    raw: vk::Instance,
    create_info: &InstanceCreateInfo<'_>,
) -> Instance {
    Instance::from_created(
        entry,
        raw,
        &create_info.enabled_extensions(),
        create_info.api_version(),
    )
}

/// The device remembers its enabled extensions and core features (given directly,
/// in a chained `VkPhysicalDeviceFeatures2`, a core version's features struct, or
/// the struct of the extension a core feature came from).
pub(crate) fn device_created(
    physical: &PhysicalDevice,
    raw: vk::Device,
    create_info: &DeviceCreateInfo<'_>,
) -> Device {
    let device = Device::from_created(physical, raw, &create_info.enabled_extensions());
    let info = create_info.as_raw();
    device
        .live()
        .set_features(creation::enabled_features(create_info));
    let queues = if info.p_queue_create_infos.is_null() {
        &[][..]
    } else {
        // SAFETY: the safe setter stores a slice, with its length, that outlives the
        // create info.
        unsafe {
            core::slice::from_raw_parts(
                info.p_queue_create_infos,
                info.queue_create_info_count as usize,
            )
        }
    };
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let group: Option<&vk::DeviceGroupDeviceCreateInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::DEVICE_GROUP_DEVICE_CREATE_INFO,
        )
    };
    device
        .live()
        .set_physical_count(group.map_or(1, |g| g.physical_device_count).max(1));
    device.live().set_queue_infos(
        queues
            .iter()
            .map(|q| (q.queue_family_index, q.queue_count, q.flags))
            .collect(),
    );
    device
}

/// A command pool is made for a queue family the device has queues of, and is
/// protected only where the protectedMemory feature is enabled.
pub(crate) fn create_command_pool_checks(
    device: &Device,
    create_info: &CommandPoolCreateInfo<'_>,
) -> Result<()> {
    let family = create_info.queue_family_index;
    if !device.live().queue_infos().iter().any(|q| q.0 == family) {
        refuse(
            "VUID-vkCreateCommandPool-queueFamilyIndex-01937",
            format!("the device was created with no queue of family {family}"),
        )?;
    }
    let protected = create_info
        .flags
        .contains(vk::CommandPoolCreateFlags::PROTECTED);
    if protected && device.live().with_features(|f| f.v11.protected_memory) != vk::TRUE {
        refuse(
            "VUID-VkCommandPoolCreateInfo-flags-02860",
            "a protected command pool needs the protectedMemory feature, which the device \
             did not enable"
                .into(),
        )?;
    }
    Ok(())
}

/// The pool remembers its flags (whether its sets may be freed one by one).
pub(crate) fn descriptor_pool_created(
    pool: DescriptorPool,
    create_info: &DescriptorPoolCreateInfo<'_>,
) -> DescriptorPool {
    pool.with_flags(create_info.flags)
}

/// The pool remembers its flags, and its family's queue flags for the `cmdpool` checks.
pub(crate) fn command_pool_created(
    device: &Device,
    pool: CommandPool,
    create_info: &CommandPoolCreateInfo<'_>,
) -> CommandPool {
    let physical = device.parent();
    // SAFETY: the physical device is a live wrapper of its instance.
    let families = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_queue_family_properties(physical.raw())
    };
    // The family's flags and granularity, from one query (an index past the families
    // has neither).
    let (flags, granularity) = families
        .get(create_info.queue_family_index as usize)
        .map_or(Default::default(), |f| {
            (f.queue_flags, f.min_image_transfer_granularity)
        });
    device.live().pool_created(
        pool.raw(),
        PoolFamily {
            index: create_info.queue_family_index,
            flags,
            granularity,
            protected: create_info
                .flags
                .contains(vk::CommandPoolCreateFlags::PROTECTED),
        },
    );
    pool.with_create_flags(create_info.flags)
        .with_queue_flags(flags)
}

/// The device remembers the allocation's size and memory type, which mapping needs.
pub(crate) fn memory_allocated(
    device: &Device,
    memory: DeviceMemory,
    raw: vk::DeviceMemory,
    allocate_info: &MemoryAllocateInfo<'_>,
) -> DeviceMemory {
    let next = allocate_info.as_raw().p_next;
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (dedicated, export, flags) = unsafe {
        (
            chained::<vk::MemoryDedicatedAllocateInfo<'_>>(
                next,
                vk::StructureType::MEMORY_DEDICATED_ALLOCATE_INFO,
            ),
            chained::<vk::ExportMemoryAllocateInfo<'_>>(
                next,
                vk::StructureType::EXPORT_MEMORY_ALLOCATE_INFO,
            ),
            chained::<vk::MemoryAllocateFlagsInfo<'_>>(
                next,
                vk::StructureType::MEMORY_ALLOCATE_FLAGS_INFO,
            ),
        )
    };
    let dedicated = dedicated.and_then(|d| {
        if d.buffer != vk::Buffer::null() {
            Some((vk::ObjectType::BUFFER, d.buffer.as_raw()))
        } else if d.image != vk::Image::null() {
            Some((vk::ObjectType::IMAGE, d.image.as_raw()))
        } else {
            None
        }
    });
    let asked = crate::retention::MemoryAsked {
        dedicated,
        export: export.map_or(vk::ExternalMemoryHandleTypeFlags::empty(), |e| {
            e.handle_types
        }),
        device_address: flags
            .is_some_and(|f| f.flags.contains(vk::MemoryAllocateFlags::DEVICE_ADDRESS)),
    };
    device.live().allocated(
        raw,
        allocate_info.allocation_size,
        allocate_info.memory_type_index,
        asked,
    );
    memory
}

/// The queue remembers its family's flags for the `queuetype` checks.
pub(crate) fn queue_got(device: &Device, queue: Queue, queue_family_index: u32) -> Queue {
    device
        .live()
        .queue_family_of(queue.raw(), queue_family_index);
    queue.with_queue_flags(crate::validation::family_flags(device, queue_family_index))
}

/// As [`queue_got`], for `vkGetDeviceQueue2`.
pub(crate) fn queue2_got(
    device: &Device,
    queue: Queue,
    queue_info: &DeviceQueueInfo2<'_>,
) -> Queue {
    if queue_info
        .flags
        .contains(vk::DeviceQueueCreateFlags::PROTECTED)
    {
        device.live().queue_protected(queue.raw());
    }
    queue_got(device, queue, queue_info.queue_family_index)
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

/// The template remembers its entries, which say how to read the data of an update.
pub(crate) fn descriptor_update_template_created(
    template: DescriptorUpdateTemplate,
    create_info: &DescriptorUpdateTemplateCreateInfo<'_>,
) -> DescriptorUpdateTemplate {
    let raw = create_info.as_raw();
    // SAFETY: the safe setter stored the entries with their count.
    template.with_entries(unsafe {
        crate::retention::raw_slice(
            raw.p_descriptor_update_entries,
            raw.descriptor_update_entry_count,
        )
    })
}

/// Each set holds a token of its pool, which counts the sets alive, and the device
/// remembers its layout, which writes to it are checked against.
pub(crate) fn descriptor_sets_allocated(
    device: &Device,
    sets: Vec<DescriptorSet>,
    descriptor_pool: &DescriptorPool,
    allocate_info: &DescriptorSetAllocateInfo<'_>,
) -> Vec<DescriptorSet> {
    let raw = allocate_info.as_raw();
    // SAFETY: the safe setter stored the layouts with their count.
    let layouts =
        unsafe { crate::retention::raw_slice(raw.p_set_layouts, raw.descriptor_set_count) };
    let counts = variable_counts(allocate_info);
    for (i, (set, layout)) in sets.iter().zip(layouts).enumerate() {
        let mut record = device.live().set_layout(*layout).unwrap_or_default();
        // A variable-count binding has, in this set, the count the allocation gave
        // it (0 without one), which writes to the set are checked against.
        if let Some(variable) = record.variable {
            let count = counts.get(i).copied().unwrap_or(0);
            let mut own = (*record).clone();
            if let Some(b) = own.bindings.iter_mut().find(|b| b.binding == variable) {
                b.count = count;
            }
            record = Vrc::new(own);
        }
        device.live().set_allocated(set.raw(), record);
        device.live().set_pool_update_after_bind(
            set.raw(),
            descriptor_pool
                .pool_flags()
                .contains(vk::DescriptorPoolCreateFlags::UPDATE_AFTER_BIND),
        );
    }
    sets.into_iter()
        .map(|set| set.with_token(descriptor_pool.set_token()))
        .collect()
}

/// The device remembers the layout's bindings.
pub(crate) fn descriptor_set_layout_created(
    device: &Device,
    layout: DescriptorSetLayout,
    create_info: &DescriptorSetLayoutCreateInfo<'_>,
) -> DescriptorSetLayout {
    let raw = create_info.as_raw();
    // SAFETY: the safe setter stored the bindings with their count.
    let bindings = unsafe { crate::retention::raw_slice(raw.p_bindings, raw.binding_count) };
    // SAFETY: `raw` is a safe struct's.
    let flags: Option<&vk::DescriptorSetLayoutBindingFlagsCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO,
        )
    };
    // SAFETY: the safe setter stored the flags with their count (its checks made that
    // count 0 or the bindings').
    let flags = flags.map_or(&[][..], |f| unsafe {
        crate::retention::raw_slice(f.p_binding_flags, f.binding_count)
    });
    let variable = bindings
        .iter()
        .zip(flags)
        .find(|(_, f)| f.contains(vk::DescriptorBindingFlags::VARIABLE_DESCRIPTOR_COUNT))
        .map(|(b, _)| b.binding);
    let mut ordered: Vec<(BindingRecord, &[vk::Sampler])> = bindings
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let samplers = if b.p_immutable_samplers.is_null() {
                &[][..]
            } else {
                // SAFETY: the safe setter stores the samplers with the binding's
                // count.
                unsafe { crate::retention::raw_slice(b.p_immutable_samplers, b.descriptor_count) }
            };
            let record = BindingRecord {
                binding: b.binding,
                ty: b.descriptor_type,
                count: b.descriptor_count,
                stages: b.stage_flags,
                immutable: !b.p_immutable_samplers.is_null(),
                immutable_bits: samplers
                    .iter()
                    .map(|s| device.live().sampler_bits(*s).unwrap_or(0))
                    .fold(0, |a, b| a | b),
                flags: flags.get(i).copied().unwrap_or_default(),
            };
            (record, samplers)
        })
        .collect();
    ordered.sort_by_key(|(b, _)| b.binding);
    let immutable_samplers = ordered
        .iter()
        .flat_map(|(_, s)| s.iter().copied())
        .collect();
    let bindings: Vec<BindingRecord> = ordered.into_iter().map(|(b, _)| b).collect();
    device.live().set_layout_created(
        layout.raw(),
        SetLayoutRecord {
            bindings,
            update_after_bind: raw
                .flags
                .contains(vk::DescriptorSetLayoutCreateFlags::UPDATE_AFTER_BIND_POOL),
            variable,
            flags: raw.flags,
            immutable_samplers,
        },
    );
    layout
}

/// The device remembers the layout's push-constant ranges and its sets' dynamic
/// descriptors.
pub(crate) fn pipeline_layout_created(
    device: &Device,
    layout: PipelineLayout,
    create_info: &PipelineLayoutCreateInfo<'_>,
) -> PipelineLayout {
    let raw = create_info.as_raw();
    // SAFETY: the safe setters stored both arrays with their counts.
    let (ranges, sets) = unsafe {
        (
            crate::retention::raw_slice(raw.p_push_constant_ranges, raw.push_constant_range_count),
            crate::retention::raw_slice(raw.p_set_layouts, raw.set_layout_count),
        )
    };
    let sets: Vec<Vrc<SetLayoutRecord>> = sets
        .iter()
        .map(|s| device.live().set_layout(*s).unwrap_or_default())
        .collect();
    let set_dynamics = sets.iter().map(|l| l.dynamics()).collect();
    device.live().pipeline_layout_created(
        layout.raw(),
        LayoutRecord {
            push_ranges: ranges.to_vec(),
            set_dynamics,
            sets,
        },
    );
    layout
}

/// The device remembers the pool's type, size and statistics.
pub(crate) fn query_pool_created(
    device: &Device,
    pool: QueryPool,
    create_info: &QueryPoolCreateInfo<'_>,
) -> QueryPool {
    device.live().query_pool_created(
        pool.raw(),
        QueryPoolRecord {
            query_type: create_info.query_type,
            count: create_info.query_count,
            statistics: create_info.pipeline_statistics,
        },
    );
    pool
}

/// The physical device's limits, read once per device.
pub(crate) fn limits(device: &Device) -> &vk::PhysicalDeviceLimits {
    device
        .live()
        .limits(|| device.parent().get_properties().limits)
}

/// The checks of `vkGetQueryPoolResults` that keep the driver inside `data` and the
/// pool: the queries exist, and `data` holds every result at its stride.
pub(crate) fn get_query_pool_results_checks(
    device: &Device,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
    data: &[u8],
    stride: vk::DeviceSize,
    flags: vk::QueryResultFlags,
) -> Result<()> {
    let pool = device
        .live()
        .query_pool(query_pool.raw())
        .ok_or(Error::Misuse(
            "the query pool was not created through the wrappers",
        ))?;
    if first_query >= pool.count {
        refuse("VUID-vkGetQueryPoolResults-firstQuery-00813", format!("firstQuery must be less than the number of queries in queryPool (firstQuery = {first_query}, queries = {})", pool.count))?;
    }
    if u64::from(first_query) + u64::from(query_count) > u64::from(pool.count) {
        refuse("VUID-vkGetQueryPoolResults-firstQuery-00816", format!("firstQuery plus queryCount must be at most the number of queries in queryPool (firstQuery = {first_query}, queryCount = {query_count}, queries = {})", pool.count))?;
    }
    let wide = flags.contains(vk::QueryResultFlags::TYPE_64);
    let unit: u64 = if wide { 8 } else { 4 };
    let address = data.as_ptr() as u64;
    if address % unit != 0 || stride % unit != 0 {
        let vuid = if wide {
            "VUID-vkGetQueryPoolResults-flags-00815"
        } else {
            "VUID-vkGetQueryPoolResults-flags-02827"
        };
        refuse(vuid, format!("pData and stride must be multiples of {unit} (pData = {address:#x}, stride = {stride})"))?;
    }
    if pool.query_type == vk::QueryType::TIMESTAMP && flags.contains(vk::QueryResultFlags::PARTIAL)
    {
        refuse(
            "VUID-vkGetQueryPoolResults-queryType-00818",
            "a timestamp query pool's results cannot be partial".into(),
        )?;
    }
    let values: u64 = match pool.query_type {
        vk::QueryType::OCCLUSION | vk::QueryType::TIMESTAMP => 1,
        vk::QueryType::PIPELINE_STATISTICS => u64::from(pool.statistics.as_raw().count_ones()),
        _ => {
            return Err(Error::Misuse(
                "tuff cannot size the results of this query type; read them with get_query_pool_results_unchecked",
            ))
        }
    };
    let status = flags.intersects(
        vk::QueryResultFlags::WITH_AVAILABILITY | vk::QueryResultFlags::WITH_STATUS_KHR,
    );
    let each = (values + u64::from(status)) * unit;
    let needed = match query_count {
        0 => Some(0),
        n => stride
            .checked_mul(u64::from(n - 1))
            .and_then(|s| s.checked_add(each)),
    };
    match needed {
        Some(needed) if needed <= data.len() as u64 => Ok(()),
        _ => refuse(
            "VUID-vkGetQueryPoolResults-dataSize-00817",
            format!("dataSize must hold every result: {query_count} queries of {each} bytes at a stride of {stride} need more than {} bytes", data.len()),
        ),
    }
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

/// The object types that are not the device nor a child of it.
const INSTANCE_LEVEL: &[vk::ObjectType] = &[
    vk::ObjectType::INSTANCE,
    vk::ObjectType::PHYSICAL_DEVICE,
    vk::ObjectType::SURFACE_KHR,
    vk::ObjectType::DEBUG_UTILS_MESSENGER_EXT,
    vk::ObjectType::DEBUG_REPORT_CALLBACK_EXT,
    vk::ObjectType::DISPLAY_KHR,
    vk::ObjectType::DISPLAY_MODE_KHR,
];

/// Whether `object_handle` is the device or a live object of it of `object_type`.
/// Drivers reach an object's private data and debug name through its handle, as a
/// pointer, so a handle of no live object would be used after free.
fn names_live_object(device: &Device, object_type: vk::ObjectType, object_handle: u64) -> bool {
    let is_device = object_type == vk::ObjectType::DEVICE && object_handle == device.raw().as_raw();
    is_device || device.live().sync_of(object_type, object_handle).is_some()
}

/// Refuses an object that is not the device or a live object of it of the type given.
pub(crate) fn set_private_data_checks(
    device: &Device,
    object_type: vk::ObjectType,
    object_handle: u64,
) -> Result<()> {
    if names_live_object(device, object_type, object_handle) {
        return Ok(());
    }
    if INSTANCE_LEVEL.contains(&object_type) {
        return refuse(
            "VUID-vkSetPrivateData-objectHandle-04016",
            format!("objectHandle must be the device or a child of it, not an object of type {object_type:?}"),
        );
    }
    refuse(
        "VUID-vkSetPrivateData-objectHandle-04017",
        format!("objectHandle ({object_handle:#x}) must be the device or a live object of it of type {object_type:?}"),
    )
}

/// Refuses an object that is not the device or a live object of it of the type given.
pub(crate) fn get_private_data_checks(
    device: &Device,
    object_type: vk::ObjectType,
    object_handle: u64,
) -> Result<()> {
    if names_live_object(device, object_type, object_handle) {
        return Ok(());
    }
    if INSTANCE_LEVEL.contains(&object_type) {
        return refuse(
            "VUID-vkGetPrivateData-objectType-04018",
            format!(
                "`objectType` must be `VK_OBJECT_TYPE_DEVICE`, or an object type whose parent \
                 is VkDevice (`objectType` = {object_type:?})"
            ),
        );
    }
    Err(Error::Misuse(
        "objectHandle must be the device or a live object of it of the type given",
    ))
}

/// Each buffer remembers its level; the device and the pool track its lifecycle.
pub(crate) fn command_buffers_allocated(
    device: &Device,
    cbs: Vec<CommandBuffer>,
    command_pool: &CommandPool,
    allocate_info: &CommandBufferAllocateInfo<'_>,
) -> Vec<CommandBuffer> {
    let cbs: Vec<CommandBuffer> = cbs
        .into_iter()
        .map(|cb| cb.with_level(allocate_info.level))
        .collect();
    for cb in &cbs {
        device.register_command_buffer(cb);
        command_pool.adopt(cb.uses());
    }
    cbs
}

/// The scope of `vkCreateInstance`'s checks: the version and extensions it enables.
pub(crate) fn create_instance_scope(
    create_info: &InstanceCreateInfo<'_>,
) -> crate::validation::Scope<'static> {
    crate::validation::Scope {
        exts: crate::checks::Exts::new(
            vk::api_version_minor(create_info.api_version()),
            &create_info.enabled_extensions(),
        ),
        instance: None,
        device: None,
    }
}

/// Every extension an instance enables is part of the emitted API: an extension
/// tuff does not emit adds rules to the commands tuff does emit (a feature that
/// relaxes or changes what a struct may hold), and no safe method checks those.
pub(crate) fn instance_extensions_emitted(create_info: &InstanceCreateInfo<'_>) -> Result<()> {
    extensions_emitted(&create_info.enabled_extensions())
}

/// What emitted extension `ext` needs beside it: its name and the alternatives of
/// `api_info::EXTENSION_REQUIRES` (none: it can never be enabled); `None` for an
/// extension tuff does not emit.
pub(crate) fn extension_requires(
    ext: &core::ffi::CStr,
) -> Option<(&'static str, Vec<Vec<&'static str>>)> {
    let name = *crate::api_info::EXTENSIONS
        .iter()
        .find(|n| n.as_bytes() == ext.to_bytes())?;
    let alternatives = crate::api_info::EXTENSION_REQUIRES
        .iter()
        .filter(|(n, _)| *n == name)
        .map(|(_, all)| all.split('+').filter(|d| !d.is_empty()).collect())
        .collect();
    Some((name, alternatives))
}

/// [`instance_extensions_emitted`], then [`create_instance_checks`]: the checks
/// `vkCreateInstance` runs before the implicit ones.
pub(crate) fn create_instance_first(create_info: &InstanceCreateInfo<'_>) -> Result<()> {
    instance_extensions_emitted(create_info)?;
    create_instance_checks(create_info)
}

/// An instance names a real API version, enables what its extensions depend on, and
/// chains a debug messenger only with the extension that defines it.
pub(crate) fn create_instance_checks(create_info: &InstanceCreateInfo<'_>) -> Result<()> {
    let version = create_info.api_version();
    if version != 0 && version < vk::API_VERSION_1_0 {
        refuse(
            "VUID-VkApplicationInfo-apiVersion-04010",
            format!(
                "If `apiVersion` is not `0`, then it must be greater than or equal to \
                 VK_API_VERSION_1_0 (`apiVersion` = {version:#x})"
            ),
        )?;
    }
    let enabled = create_info.enabled_extensions();
    let has = |name: &str| enabled.iter().any(|e| e.to_bytes() == name.as_bytes());
    for ext in &enabled {
        let Some((name, alternatives)) = extension_requires(ext) else {
            continue;
        };
        let holds = |dep: &&str| match dep.strip_prefix("VK_VERSION_1_") {
            Some(minor) => minor
                .parse::<u32>()
                .is_ok_and(|m| vk::api_version_minor(version.max(vk::API_VERSION_1_0)) >= m),
            None => has(dep),
        };
        if !alternatives.iter().any(|all| all.iter().all(holds)) {
            refuse(
                "VUID-vkCreateInstance-ppEnabledExtensionNames-01388",
                format!(
                    "All required extensions for each extension in the \
                     VkInstanceCreateInfo::`ppEnabledExtensionNames` list must also be present \
                     in that list (`{name}` needs one of {alternatives:?})"
                ),
            )?;
        }
    }
    let mut next = create_info
        .as_raw()
        .p_next
        .cast::<vk::BaseInStructure<'_>>();
    // SAFETY: the safe struct chains only structs pushed through `push_next`, each a
    // valid Vulkan struct that starts with sType and pNext.
    while let Some(node) = unsafe { next.as_ref() } {
        if node.s_type == vk::StructureType::DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT
            && !has("VK_EXT_debug_utils")
        {
            refuse(
                "VUID-VkInstanceCreateInfo-pNext-04926",
                "If the `pNext` chain of `VkInstanceCreateInfo` includes a \
                 `VkDebugUtilsMessengerCreateInfoEXT` structure, the list of enabled extensions \
                 in `ppEnabledExtensionNames` must contain VK_EXT_debug_utils"
                    .into(),
            )?;
        }
        next = node.p_next;
    }
    Ok(())
}

/// A queue is got as the device was created with it: from a family it has queues
/// of, created without flags (those are got through `get_queue2`), at an
/// index below their count.
pub(crate) fn get_device_queue_checks(device: &Device, family: u32, index: u32) -> Result<()> {
    let infos = device.live().queue_infos();
    if !infos.iter().any(|q| q.0 == family) {
        refuse(
            "VUID-vkGetDeviceQueue-queueFamilyIndex-00384",
            format!("the device was created with no queue of family {family}"),
        )?;
    }
    let Some(&(_, count, _)) = infos.iter().find(|q| q.0 == family && q.2.is_empty()) else {
        return refuse(
            "VUID-vkGetDeviceQueue-flags-01841",
            format!(
                "the queues of family {family} were created with flags; get them with \
                 `get_queue2`"
            ),
        );
    };
    if index >= count {
        refuse(
            "VUID-vkGetDeviceQueue-queueIndex-00385",
            format!(
                "queue index {index} is not below the {count} queues of family {family} the \
                 device was created with"
            ),
        )?;
    }
    Ok(())
}

/// As [`get_device_queue_checks`], for the queues of a family created with the
/// info's flags.
pub(crate) fn get_device_queue2_checks(
    device: &Device,
    queue_info: &crate::structs::DeviceQueueInfo2<'_>,
) -> Result<()> {
    let (family, flags, index) = (
        queue_info.queue_family_index,
        queue_info.flags,
        queue_info.queue_index,
    );
    let infos = device.live().queue_infos();
    if !infos.iter().any(|q| q.0 == family) {
        refuse(
            "VUID-VkDeviceQueueInfo2-queueFamilyIndex-01842",
            format!("the device was created with no queue of family {family}"),
        )?;
    }
    let Some(&(_, count, _)) = infos.iter().find(|q| q.0 == family && q.2 == flags) else {
        return refuse(
            "VUID-VkDeviceQueueInfo2-flags-06225",
            format!(
                "the device was created with no queues of family {family} with flags {flags:?}"
            ),
        );
    };
    if index >= count {
        refuse(
            "VUID-VkDeviceQueueInfo2-queueIndex-01843",
            format!(
                "queue index {index} is not below the {count} queues of family {family} with \
                 flags {flags:?} the device was created with"
            ),
        )?;
    }
    Ok(())
}

/// Every extension a device enables is part of the emitted API (see
/// [`instance_extensions_emitted`]).
pub(crate) fn device_extensions_emitted(create_info: &DeviceCreateInfo<'_>) -> Result<()> {
    extensions_emitted(&create_info.enabled_extensions())
}

fn extensions_emitted(names: &[&core::ffi::CStr]) -> Result<()> {
    for name in names {
        let name = name.to_string_lossy();
        if !crate::api_info::EXTENSIONS.contains(&name.as_ref()) {
            return Err(Error::ExtensionNotEmitted(name.into_owned()));
        }
        // An emitted extension whose rules on other methods are not all checked
        // would leave them to callers of safe methods.
        if !crate::api_info::CHECKED_EXTENSIONS.contains(&name.as_ref()) {
            return Err(Error::ExtensionUnchecked(name.into_owned()));
        }
    }
    Ok(())
}

/// The scope of `vkCreateDevice`'s checks: the instance's, with the device
/// extensions it enables.
pub(crate) fn create_device_scope<'p>(
    physical: &'p PhysicalDevice,
    create_info: &DeviceCreateInfo<'_>,
) -> crate::validation::Scope<'p> {
    let mut s = physical.parent().scope();
    s.exts = s.exts.with(crate::checks::Exts::new(
        0,
        &create_info.enabled_extensions(),
    ));
    s
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
fn check_scissors(
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

/// A shader stage's specialization map entries lie inside its data, which drivers read
/// each constant from.
fn check_specialization(
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    // SAFETY: the safe struct's setter stores a reference that outlives the create info.
    let Some(info) = (unsafe { stage.p_specialization_info.as_ref() }) else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the entries with their count.
    let entries = unsafe { crate::retention::raw_slice(info.p_map_entries, info.map_entry_count) };
    let size = info.data_size as u64;
    for (i, e) in entries.iter().enumerate() {
        let offset = u64::from(e.offset);
        if offset >= size {
            refuse(
                "VUID-VkSpecializationInfo-offset-00773",
                format!("{at}: pMapEntries[{i}].offset must be less than dataSize (offset = {offset}, dataSize = {size})"),
            )?;
        }
        if e.size as u64 > size - offset {
            refuse(
                "VUID-VkSpecializationInfo-pMapEntries-00774",
                format!("{at}: pMapEntries[{i}].size must be at most dataSize minus offset (size = {}, offset = {offset}, dataSize = {size})", e.size),
            )?;
        }
    }
    Ok(())
}

/// A shader stage's subgroup size control: its flags need the features they name
/// (02784, 02785), and a chained `VkPipelineShaderStageRequiredSubgroupSizeCreateInfo`
/// names a power of two within the device's subgroup sizes (02760 to 02762), without
/// a varying size (02754), with `subgroupSizeControl` on and for a stage in
/// `requiredSubgroupSizeStages` (02755).
fn check_stage_subgroups(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    type F = vk::PipelineShaderStageCreateFlags;
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let required: Option<&vk::PipelineShaderStageRequiredSubgroupSizeCreateInfo<'_>> = unsafe {
        chained(
            stage.p_next,
            vk::StructureType::PIPELINE_SHADER_STAGE_REQUIRED_SUBGROUP_SIZE_CREATE_INFO,
        )
    };
    let varying = stage.flags.contains(F::ALLOW_VARYING_SUBGROUP_SIZE);
    let full = stage.flags.contains(F::REQUIRE_FULL_SUBGROUPS);
    if !varying && !full && required.is_none() {
        return Ok(());
    }
    let (control, full_subgroups) = device
        .live()
        .with_features(|f| (f.v13.subgroup_size_control, f.v13.compute_full_subgroups));
    if varying && control != vk::TRUE {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-flags-02784",
            format!("{at}: flags include ALLOW_VARYING_SUBGROUP_SIZE, and the device has not enabled subgroupSizeControl"),
        )?;
    }
    if full && full_subgroups != vk::TRUE {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-flags-02785",
            format!("{at}: flags include REQUIRE_FULL_SUBGROUPS, and the device has not enabled computeFullSubgroups"),
        )?;
    }
    check_workgroup_subgroups(
        device,
        stage,
        required.map(|r| r.required_subgroup_size),
        at,
    )?;
    let Some(required) = required else {
        return Ok(());
    };
    let size = required.required_subgroup_size;
    if !size.is_power_of_two() {
        refuse(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02760",
            format!("{at}: requiredSubgroupSize ({size}) is not a power of two"),
        )?;
    }
    let properties = vulkan13_properties(device);
    let (min, max) = properties.map_or((0, 0), |p| (p.min_subgroup_size, p.max_subgroup_size));
    if size < min {
        refuse(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02761",
            format!("{at}: requiredSubgroupSize ({size}) is below minSubgroupSize ({min})"),
        )?;
    }
    if size > max {
        refuse(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02762",
            format!("{at}: requiredSubgroupSize ({size}) is above maxSubgroupSize ({max}; 0 where the device has no Vulkan 1.3 properties)"),
        )?;
    }
    if varying {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-pNext-02754",
            format!("{at}: a required subgroup size is chained, and flags include ALLOW_VARYING_SUBGROUP_SIZE"),
        )?;
    }
    let stages = properties.map_or(vk::ShaderStageFlags::empty(), |p| {
        p.required_subgroup_size_stages
    });
    if control != vk::TRUE || !stages.contains(stage.stage) {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-pNext-02755",
            format!("{at}: a required subgroup size is chained, and the device has not enabled subgroupSizeControl or {:?} is not among its requiredSubgroupSizeStages ({stages:?})", stage.stage),
        )?;
    }
    Ok(())
}

/// Holds the pipeline cache a pipeline creation uses for the call: a cache created
/// with `VK_PIPELINE_CACHE_CREATE_EXTERNALLY_SYNCHRONIZED_BIT` must not be used by
/// two threads at once (`VUID-vkCreateGraphicsPipelines-pipelineCache-02876`,
/// `VUID-vkCreateComputePipelines-pipelineCache-02873`), and one without it costs
/// the lock only.
pub(crate) fn pipeline_cache_gate(
    _device: &Device,
    cache: Option<&PipelineCache>,
) -> Result<Vec<tuff_runtime::HostSyncGuard>> {
    Ok(tuff_runtime::lock_all(
        cache.map(|c| c.host_sync().clone()).into_iter().collect(),
    ))
}

/// A chained `VkPipelineCreationFeedbackCreateInfo` (in `next`, the chain of a create
/// info of `stages` stages) names where the driver writes the pipeline's feedback
/// (`parameter`: the safe struct has no setter for it, so a safe program's is NULL)
/// and as many stage feedbacks as stages, or none (`count`).
fn check_creation_feedback(
    next: *const core::ffi::c_void,
    stages: u32,
    (parameter, count): (&'static str, &'static str),
    at: &dyn core::fmt::Display,
) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let feedback: Option<&vk::PipelineCreationFeedbackCreateInfo<'_>> = unsafe {
        chained(
            next,
            vk::StructureType::PIPELINE_CREATION_FEEDBACK_CREATE_INFO,
        )
    };
    let Some(feedback) = feedback else {
        return Ok(());
    };
    if feedback.p_pipeline_creation_feedback.is_null() {
        refuse(
            parameter,
            format!("{at}: a chained VkPipelineCreationFeedbackCreateInfo's pPipelineCreationFeedback is NULL, and the driver writes through it"),
        )?;
    }
    let n = feedback.pipeline_stage_creation_feedback_count;
    if n != 0 && n != stages {
        refuse(
            count,
            format!("{at}: pipelineStageCreationFeedbackCount ({n}) is neither 0 nor the pipeline's stage count ({stages})"),
        )?;
    }
    Ok(())
}

/// A stage's workgroup against the subgroups its flags and a chained required size
/// ask for, from the `LocalSize` execution mode of the entry point it names: no more
/// invocations than `maxComputeWorkgroupSubgroups` subgroups of the required size
/// (02756); with full subgroups, a width that is a multiple of the required size
/// (02757), of `maxSubgroupSize` with a varying size (02758), or else of the
/// device's `subgroupSize` (02759). A workgroup size the module gives otherwise
/// (`LocalSizeId`, the `WorkgroupSize` built-in) is not read: where one of these
/// rules applies, the stage is refused.
fn check_workgroup_subgroups(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    required: Option<u32>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    type F = vk::PipelineShaderStageCreateFlags;
    const LOCAL_SIZE: u32 = 17;
    let full = stage.flags.contains(F::REQUIRE_FULL_SUBGROUPS);
    let varying = stage.flags.contains(F::ALLOW_VARYING_SUBGROUP_SIZE);
    let compute_required = required.filter(|_| stage.stage == vk::ShaderStageFlags::COMPUTE);
    if !full && compute_required.is_none() {
        return Ok(());
    }
    let size: Option<[u32; 3]> =
        stage_entry_point(device, stage).and_then(|e| match e.mode(LOCAL_SIZE)? {
            [x, y, z, ..] => Some([*x, *y, *z]),
            _ => None,
        });
    let p13 = vulkan13_properties(device);
    if let Some(required) = compute_required {
        let max = p13.map_or(0, |p| p.max_compute_workgroup_subgroups);
        let invocations = size.map(|[x, y, z]| u64::from(x) * u64::from(y) * u64::from(z));
        if invocations.is_none_or(|n| n > u64::from(max) * u64::from(required)) {
            refuse(
                "VUID-VkPipelineShaderStageCreateInfo-pNext-02756",
                format!("{at}: the workgroup's invocations ({invocations:?}, None where the module does not give them as LocalSize) are more than maxComputeWorkgroupSubgroups ({max}) subgroups of the required size ({required})"),
            )?;
        }
    }
    if !full {
        return Ok(());
    }
    let (multiple, vuid, of) = match (required, varying) {
        (Some(r), _) => (
            r,
            "VUID-VkPipelineShaderStageCreateInfo-pNext-02757",
            "the required subgroup size",
        ),
        (None, true) => (
            p13.map_or(0, |p| p.max_subgroup_size),
            "VUID-VkPipelineShaderStageCreateInfo-flags-02758",
            "maxSubgroupSize",
        ),
        (None, false) => (
            subgroup_size(device),
            "VUID-VkPipelineShaderStageCreateInfo-flags-02759",
            "the device's subgroupSize",
        ),
    };
    let width = size.map(|[x, _, _]| x);
    if !width.is_some_and(|x| multiple != 0 && x % multiple == 0) {
        refuse(
            vuid,
            format!("{at}: with full subgroups, the workgroup's width ({width:?}, None where the module does not give it as LocalSize) must be a multiple of {of} ({multiple})"),
        )?;
    }
    Ok(())
}

/// The device's default `subgroupSize` (Vulkan 1.1), or 0 where it cannot be asked.
fn subgroup_size(device: &Device) -> u32 {
    let version = device.parent().get_properties().api_version;
    let mut subgroup = vk::PhysicalDeviceSubgroupProperties::default();
    if vk::api_version_minor(version) < 1 || !ask_properties2(device, &mut subgroup) {
        return 0;
    }
    subgroup.subgroup_size
}

/// The built-in variables of the entry point a stage names: clip and cull distance
/// arrays within `maxClipDistances` (00708), `maxCullDistances` (00709) and together
/// `maxCombinedClipAndCullDistances` (00710, per storage class), a sample mask within
/// `maxSampleMaskWords` (00711), no cull distance read by a vertex stage (00712) or
/// written by a fragment stage (00718).
fn check_stage_builtins(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    const CLIP: u32 = 3;
    const CULL: u32 = 4;
    const SAMPLE_MASK: u32 = 20;
    const INPUT: u32 = 1;
    const OUTPUT: u32 = 3;
    let Some(entry) = stage_entry_point(device, stage) else {
        return Ok(());
    };
    if entry.builtins.is_empty() {
        return Ok(());
    }
    let limits = limits(device);
    let of = |builtin: u32, storage: Option<u32>| {
        entry
            .builtins
            .iter()
            .filter(move |(b, s, _)| *b == builtin && storage.is_none_or(|w| w == *s))
    };
    let bounds = [
        (
            CLIP,
            limits.max_clip_distances,
            "VUID-VkPipelineShaderStageCreateInfo-maxClipDistances-00708",
            "ClipDistance",
            "maxClipDistances",
        ),
        (
            CULL,
            limits.max_cull_distances,
            "VUID-VkPipelineShaderStageCreateInfo-maxCullDistances-00709",
            "CullDistance",
            "maxCullDistances",
        ),
        (
            SAMPLE_MASK,
            limits.max_sample_mask_words,
            "VUID-VkPipelineShaderStageCreateInfo-maxSampleMaskWords-00711",
            "SampleMask",
            "maxSampleMaskWords",
        ),
    ];
    for (builtin, max, vuid, name, limit) in bounds {
        if let Some((_, _, len)) = of(builtin, None).find(|(_, _, len)| *len > max) {
            refuse(
                vuid,
                format!(
                    "{at}: the entry point's {name} array has {len} elements, past {limit} ({max})"
                ),
            )?;
        }
    }
    let combined = limits.max_combined_clip_and_cull_distances;
    for storage in [INPUT, OUTPUT] {
        let sum: u32 = of(CLIP, Some(storage))
            .chain(of(CULL, Some(storage)))
            .map(|(_, _, len)| *len)
            .sum();
        if sum > combined {
            refuse(
                "VUID-VkPipelineShaderStageCreateInfo-maxCombinedClipAndCullDistances-00710",
                format!("{at}: the entry point's ClipDistance and CullDistance arrays have {sum} elements together, past maxCombinedClipAndCullDistances ({combined})"),
            )?;
        }
    }
    if stage.stage == vk::ShaderStageFlags::VERTEX && of(CULL, Some(INPUT)).next().is_some() {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-stage-00712",
            format!("{at}: a vertex entry point reads a CullDistance input"),
        )?;
    }
    if stage.stage == vk::ShaderStageFlags::FRAGMENT && of(CULL, Some(OUTPUT)).next().is_some() {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-stage-00718",
            format!("{at}: a fragment entry point writes a CullDistance output"),
        )?;
    }
    Ok(())
}

/// Each specialization map entry of a stage that names a constant its module
/// declares gives it as many bytes as the constant's type has, four for a boolean
/// (`VUID-VkSpecializationMapEntry-constantID-00776`).
fn check_constant_sizes(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    // SAFETY: the safe struct's setter stores a reference that outlives the create info.
    let Some(info) = (unsafe { stage.p_specialization_info.as_ref() }) else {
        return Ok(());
    };
    let Some(interface) = device.live().shader_module(stage.module) else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the entries with their count.
    let entries = unsafe { crate::retention::raw_slice(info.p_map_entries, info.map_entry_count) };
    for (k, e) in entries.iter().enumerate() {
        let declared = interface
            .spec_constants
            .iter()
            .find(|(id, _)| *id == e.constant_id);
        if let Some((id, size)) = declared {
            if e.size != *size as usize {
                refuse(
                    "VUID-VkSpecializationMapEntry-constantID-00776",
                    format!("{at}: pMapEntries[{k}] gives specialization constant {id} {} bytes, and its type has {size}", e.size),
                )?;
            }
        }
    }
    Ok(())
}

/// The checks of `vkCreateComputePipelines` that keep the driver inside the
/// specialization data.
pub(crate) fn create_compute_pipelines_checks(
    device: &Device,
    create_infos: &[ComputePipelineCreateInfo<'_>],
) -> Result<()> {
    compute_pipeline_state_checks(device, create_infos)?;
    for (i, info) in create_infos.iter().enumerate() {
        let raw = info.as_raw();
        check_specialization(&raw.stage, &format_args!("pCreateInfos[{i}].stage"))?;
        check_constant_sizes(device, &raw.stage, &format_args!("pCreateInfos[{i}].stage"))?;
        check_stage_subgroups(device, &raw.stage, &format_args!("pCreateInfos[{i}].stage"))?;
        check_creation_feedback(
            raw.p_next,
            1,
            (
                "VUID-VkPipelineCreationFeedbackCreateInfo-pPipelineCreationFeedback-parameter",
                "VUID-VkComputePipelineCreateInfo-pipelineStageCreationFeedbackCount-06566",
            ),
            &format_args!("pCreateInfos[{i}]"),
        )?;
        check_shader_layout(
            device,
            &raw.stage,
            raw.layout,
            "VUID-VkComputePipelineCreateInfo-layout-00703",
            &format_args!("pCreateInfos[{i}].stage"),
        )?;
    }
    Ok(())
}

/// The device remembers what the module's shaders need from a pipeline layout.
pub(crate) fn shader_module_created(
    device: &Device,
    module: ShaderModule,
    create_info: &ShaderModuleCreateInfo<'_>,
) -> ShaderModule {
    let raw = create_info.as_raw();
    // SAFETY: the safe setter stores the code slice with its size in bytes.
    let words = unsafe { crate::retention::raw_slice(raw.p_code, (raw.code_size / 4) as u32) };
    device
        .live()
        .shader_module_created(module.raw(), crate::spirv::interface(words));
    module
}

/// The entry point a stage names in its module, for the stage's execution model
/// (none where the module is not the wrappers' or has no such entry point).
pub(crate) fn stage_entry_point(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
) -> Option<crate::spirv::EntryPoint> {
    let name = stage_name(stage)?;
    let interface = device.live().shader_module(stage.module)?;
    interface.entry_point(name.to_bytes(), stage.stage).cloned()
}

/// The entry point name a stage gives.
fn stage_name<'s>(stage: &'s vk::PipelineShaderStageCreateInfo<'_>) -> Option<&'s core::ffi::CStr> {
    if stage.p_name.is_null() {
        return None;
    }
    // SAFETY: the safe struct's constructor and `name` setter take the name as a
    // `&CStr` the struct borrows, so it is a nul-terminated string that outlives it.
    Some(unsafe { core::ffi::CStr::from_ptr(stage.p_name) })
}

/// A stage's shader against the pipeline layout: every resource variable its module
/// declares has a binding in the layout's set, of a descriptor type that can back
/// it, visible to the stage and with as many descriptors, and its push-constant
/// block lies inside a range for the stage. A shader that reads a descriptor the
/// layout lacks has the driver index past its tables.
fn check_shader_layout(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    layout: vk::PipelineLayout,
    vuid: &'static str,
    at: &dyn std::fmt::Display,
) -> Result<()> {
    if stage.module == vk::ShaderModule::null() {
        // Without the extensions that let a stage name its code another way (not
        // emitted), a stage needs a module: it is how its code got the shader promise.
        return refuse(
            "VUID-VkPipelineShaderStageCreateInfo-module-06716",
            format!("{at}: module is not set"),
        );
    }
    let live = device.live();
    if live.shader_module(stage.module).is_some() && stage_entry_point(device, stage).is_none() {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-pName-00707",
            format!(
                "{at}: the module has no entry point {:?} with the {:?} stage's execution model",
                stage_name(stage),
                stage.stage
            ),
        )?;
    }
    let (Some(interface), Some(layout)) = (
        live.shader_module(stage.module),
        live.pipeline_layout(layout),
    ) else {
        return Ok(());
    };
    let stage_flags = stage.stage;
    for r in &interface.resources {
        let found = layout
            .sets
            .get(r.set as usize)
            .and_then(|set| set.bindings.iter().find(|b| b.binding == r.binding));
        match found {
            None => refuse(
                vuid,
                format!(
                    "{at}: the shader uses set {} binding {}, which the pipeline layout does not have",
                    r.set, r.binding
                ),
            )?,
            Some(b) if !b.stages.contains(stage_flags) => refuse(
                vuid,
                format!(
                    "{at}: set {} binding {} is not visible to the {stage_flags:?} stage (its stages are {:?})",
                    r.set, r.binding, b.stages
                ),
            )?,
            Some(b) if !r.kind.accepts(b.ty) => refuse(
                vuid,
                format!(
                    "{at}: the shader reads set {} binding {} as {:?}, which a {:?} descriptor cannot back",
                    r.set, r.binding, r.kind, b.ty
                ),
            )?,
            Some(b) if r.count > b.count => refuse(
                vuid,
                format!(
                    "{at}: the shader uses {} descriptors at set {} binding {}, which has {}",
                    r.count, r.set, r.binding, b.count
                ),
            )?,
            Some(_) => {}
        }
    }
    if let Some((start, end)) = interface.push_constants {
        let covered = layout.push_ranges.iter().any(|p| {
            p.stage_flags.contains(stage_flags)
                && p.offset <= start
                && u64::from(p.offset) + u64::from(p.size) >= u64::from(end)
        });
        if !covered {
            refuse(
                vuid,
                format!("{at}: the shader's push constants span bytes {start}..{end}, which no push-constant range of the pipeline layout for the {stage_flags:?} stage covers"),
            )?;
        }
    }
    Ok(())
}

/// The checks of `vkCreateGraphicsPipelines` that keep the driver from reading through
/// a NULL array or past the specialization data: the stages are given, and the
/// viewports and scissors are given or dynamic.
pub(crate) fn create_graphics_pipelines_checks(
    device: &Device,
    create_infos: &[GraphicsPipelineCreateInfo<'_>],
) -> Result<()> {
    for (i, info) in create_infos.iter().enumerate() {
        let raw = info.as_raw();
        if raw.stage_count > 0 && raw.p_stages.is_null() {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pStages-06600",
                format!(
                    "pCreateInfos[{i}]: stageCount is {} but pStages is not set",
                    raw.stage_count
                ),
            )?;
        }
        check_creation_feedback(
            raw.p_next,
            raw.stage_count,
            (
                "VUID-VkPipelineCreationFeedbackCreateInfo-pPipelineCreationFeedback-parameter",
                "VUID-VkGraphicsPipelineCreateInfo-pipelineStageCreationFeedbackCount-06594",
            ),
            &format_args!("pCreateInfos[{i}]"),
        )?;
        // SAFETY: the safe setter stores the stages with their count.
        let stages = unsafe { crate::retention::raw_slice(raw.p_stages, raw.stage_count) };
        for (j, stage) in stages.iter().enumerate() {
            // Before the stage's module is read for the stage: a stage no graphics
            // pipeline state has (compute, say) is refused as such.
            let graphics = vk::ShaderStageFlags::VERTEX
                | vk::ShaderStageFlags::TESSELLATION_CONTROL
                | vk::ShaderStageFlags::TESSELLATION_EVALUATION
                | vk::ShaderStageFlags::GEOMETRY
                | vk::ShaderStageFlags::FRAGMENT;
            if !graphics.contains(stage.stage) || stage.stage.is_empty() {
                refuse(
                    "VUID-VkGraphicsPipelineCreateInfo-pStages-06896",
                    format!("pCreateInfos[{i}].pStages[{j}].stage ({:?}) is no stage of pre-rasterization or fragment shader state", stage.stage),
                )?;
            }
            check_specialization(stage, &format_args!("pCreateInfos[{i}].pStages[{j}]"))?;
            check_constant_sizes(
                device,
                stage,
                &format_args!("pCreateInfos[{i}].pStages[{j}]"),
            )?;
            check_stage_builtins(
                device,
                stage,
                &format_args!("pCreateInfos[{i}].pStages[{j}]"),
            )?;
            check_stage_subgroups(
                device,
                stage,
                &format_args!("pCreateInfos[{i}].pStages[{j}]"),
            )?;
            check_shader_layout(
                device,
                stage,
                raw.layout,
                "VUID-VkGraphicsPipelineCreateInfo-layout-00756",
                &format_args!("pCreateInfos[{i}].pStages[{j}]"),
            )?;
        }
        // SAFETY: the safe setters store references that outlive the create info, and
        // each array with its count.
        let (viewport, dynamic, raster) = unsafe {
            (
                raw.p_viewport_state.as_ref(),
                raw.p_dynamic_state.as_ref().map_or(&[][..], |d| {
                    crate::retention::raw_slice(d.p_dynamic_states, d.dynamic_state_count)
                }),
                raw.p_rasterization_state.as_ref(),
            )
        };
        let Some(viewport) = viewport else { continue };
        let has =
            |a: vk::DynamicState, b: vk::DynamicState| dynamic.iter().any(|d| *d == a || *d == b);
        // With rasterization discarded (and not dynamically), the viewport state is
        // not read.
        let discarded = raster.is_some_and(|r| r.rasterizer_discard_enable == vk::TRUE)
            && !has(
                vk::DynamicState::RASTERIZER_DISCARD_ENABLE,
                vk::DynamicState::RASTERIZER_DISCARD_ENABLE,
            );
        if discarded {
            continue;
        }
        let max = limits(device).max_viewports;
        let multi = device.live().features().multi_viewport == vk::TRUE;
        for (count, what, limit_vuid, multi_vuid) in [
            (
                viewport.viewport_count,
                "viewportCount",
                "VUID-VkPipelineViewportStateCreateInfo-viewportCount-01218",
                "VUID-VkPipelineViewportStateCreateInfo-viewportCount-01216",
            ),
            (
                viewport.scissor_count,
                "scissorCount",
                "VUID-VkPipelineViewportStateCreateInfo-scissorCount-01219",
                "VUID-VkPipelineViewportStateCreateInfo-scissorCount-01217",
            ),
        ] {
            if !multi && count > 1 {
                refuse(multi_vuid, format!("pCreateInfos[{i}]: without the multiViewport feature {what} must be at most 1 ({count})"))?;
            }
            if count > max {
                refuse(
                    limit_vuid,
                    format!(
                        "pCreateInfos[{i}]: {what} must be at most maxViewports ({count} > {max})"
                    ),
                )?;
            }
        }
        let dynamic_viewports = has(
            vk::DynamicState::VIEWPORT,
            vk::DynamicState::VIEWPORT_WITH_COUNT,
        );
        if viewport.viewport_count > 0 && viewport.p_viewports.is_null() && !dynamic_viewports {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04130",
                format!("pCreateInfos[{i}]: the viewports are neither given ({} without an array) nor dynamic", viewport.viewport_count),
            )?;
        }
        let dynamic_scissors = has(
            vk::DynamicState::SCISSOR,
            vk::DynamicState::SCISSOR_WITH_COUNT,
        );
        if viewport.scissor_count > 0 && viewport.p_scissors.is_null() && !dynamic_scissors {
            refuse(
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04131",
                format!("pCreateInfos[{i}]: the scissors are neither given ({} without an array) nor dynamic", viewport.scissor_count),
            )?;
        }
    }
    Ok(())
}

/// The struct of type `ty` in a safe struct's `pNext` chain, if it has one.
///
/// # Safety
///
/// `next` is the `pNext` of a safe struct: it chains only structs pushed through
/// `push_next`, each a valid Vulkan struct of the Rust type its `sType` names; `T` is
/// the type `ty` names.
unsafe fn chained<'c, T>(
    mut next: *const core::ffi::c_void,
    ty: vk::StructureType,
) -> Option<&'c T> {
    // SAFETY: the caller's promise: every node starts with sType and pNext.
    while let Some(node) = unsafe { next.cast::<vk::BaseInStructure<'_>>().as_ref() } {
        if node.s_type == ty {
            // SAFETY: the sType says the node is a `T`.
            return Some(unsafe { &*next.cast::<T>() });
        }
        next = node.p_next.cast();
    }
    None
}

/// The checks of `vkQueueSubmit` on a chained `VkDeviceGroupSubmitInfo`: drivers read
/// one device mask and index per command buffer and semaphore of the batch from it.
/// A batch's wait stage masks: no host stage, none without the feature it needs,
/// not 0 without synchronization2, and each stage one the queue's capabilities
/// support.
fn check_wait_stages(queue: &Queue, i: usize, b: &vk::SubmitInfo<'_>) -> Result<()> {
    // SAFETY: the safe setter stores the masks with the wait semaphores' count.
    let masks =
        unsafe { crate::retention::raw_slice(b.p_wait_dst_stage_mask, b.wait_semaphore_count) };
    if masks.is_empty() {
        return Ok(());
    }
    let device = queue.parent();
    let f = device.live().features();
    let sync2 = device.live().with_features(|f| f.v13.synchronization2) != vk::FALSE;
    type S = vk::PipelineStageFlags;
    for (k, m) in masks.iter().enumerate() {
        let at = format!("pSubmits[{i}].pWaitDstStageMask[{k}]");
        if m.contains(S::HOST) {
            refuse(
                "VUID-VkSubmitInfo-pWaitDstStageMask-00078",
                format!("{at} includes VK_PIPELINE_STAGE_HOST_BIT"),
            )?;
        }
        if m.contains(S::GEOMETRY_SHADER) && f.geometry_shader == vk::FALSE {
            refuse(
                "VUID-VkSubmitInfo-pWaitDstStageMask-04090",
                format!(
                    "{at} includes the geometry shader stage, and geometryShader is not enabled"
                ),
            )?;
        }
        if m.intersects(S::TESSELLATION_CONTROL_SHADER | S::TESSELLATION_EVALUATION_SHADER)
            && f.tessellation_shader == vk::FALSE
        {
            refuse(
                "VUID-VkSubmitInfo-pWaitDstStageMask-04091",
                format!(
                    "{at} includes a tessellation stage, and tessellationShader is not enabled"
                ),
            )?;
        }
        if m.is_empty() && !sync2 {
            refuse(
                "VUID-VkSubmitInfo-pWaitDstStageMask-03937",
                format!("{at} is 0, and synchronization2 is not enabled"),
            )?;
        }
        if let Some(s) = stages::unsupported_stage(*m, queue.queue_flags()) {
            refuse(
                "VUID-vkQueueSubmit-pWaitDstStageMask-00066",
                format!(
                    "{at} includes {s:?}, which the queue's capabilities ({:?}) do not support",
                    queue.queue_flags()
                ),
            )?;
        }
    }
    Ok(())
}

/// A chained `VkDeviceGroupSubmitInfo`'s device indices and masks name only the
/// device's physical devices.
fn check_group_indices(device: &Device, i: usize, b: &vk::SubmitInfo<'_>) -> Result<()> {
    // SAFETY: `b` is a safe struct's.
    let group: Option<&vk::DeviceGroupSubmitInfo<'_>> =
        unsafe { chained(b.p_next, vk::StructureType::DEVICE_GROUP_SUBMIT_INFO) };
    let Some(g) = group else { return Ok(()) };
    let count = device.live().physical_count();
    // SAFETY: the safe setters store each array with its count.
    let (waits, signals, masks) = unsafe {
        (
            crate::retention::raw_slice(g.p_wait_semaphore_device_indices, g.wait_semaphore_count),
            crate::retention::raw_slice(
                g.p_signal_semaphore_device_indices,
                g.signal_semaphore_count,
            ),
            crate::retention::raw_slice(g.p_command_buffer_device_masks, g.command_buffer_count),
        )
    };
    if let Some(d) = waits.iter().chain(signals).find(|d| **d >= count) {
        refuse(
            "VUID-VkDeviceGroupSubmitInfo-pWaitSemaphoreDeviceIndices-00085",
            format!("pSubmits[{i}]'s device group info names device index {d}; the device has {count} physical devices"),
        )?;
    }
    if let Some(m) = masks.iter().find(|m| count < 32 && **m >> count != 0) {
        refuse(
            "VUID-VkDeviceGroupSubmitInfo-pCommandBufferDeviceMasks-00086",
            format!("pSubmits[{i}]'s device group info has device mask {m:#x}; the device has {count} physical devices"),
        )?;
    }
    Ok(())
}

fn check_device_group_submit(i: usize, b: &vk::SubmitInfo<'_>) -> Result<()> {
    // SAFETY: `b` is a safe struct's.
    let group: Option<&vk::DeviceGroupSubmitInfo<'_>> =
        unsafe { chained(b.p_next, vk::StructureType::DEVICE_GROUP_SUBMIT_INFO) };
    let Some(g) = group else { return Ok(()) };
    for (vuid, theirs, ours, what) in [
        (
            "VUID-VkDeviceGroupSubmitInfo-waitSemaphoreCount-00082",
            g.wait_semaphore_count,
            b.wait_semaphore_count,
            "waitSemaphoreCount",
        ),
        (
            "VUID-VkDeviceGroupSubmitInfo-commandBufferCount-00083",
            g.command_buffer_count,
            b.command_buffer_count,
            "commandBufferCount",
        ),
        (
            "VUID-VkDeviceGroupSubmitInfo-signalSemaphoreCount-00084",
            g.signal_semaphore_count,
            b.signal_semaphore_count,
            "signalSemaphoreCount",
        ),
    ] {
        if theirs != ours {
            refuse(vuid, format!("pSubmits[{i}]: the chained VkDeviceGroupSubmitInfo's {what} ({theirs}) must equal the batch's ({ours})"))?;
        }
    }
    Ok(())
}

/// The checks of `vkCreateRenderPass` that keep the driver inside the render pass's
/// arrays: attachment indices, dependency subpasses, and the chained multiview and
/// input-attachment-aspect infos.
pub(crate) fn create_render_pass_checks(create_info: &RenderPassCreateInfo<'_>) -> Result<()> {
    let raw = create_info.as_raw();
    let (attachments, subpass_count) = (raw.attachment_count, raw.subpass_count);
    // SAFETY: the safe setters store each array with its count.
    let (subpasses, dependencies) = unsafe {
        (
            crate::retention::raw_slice(raw.p_subpasses, raw.subpass_count),
            crate::retention::raw_slice(raw.p_dependencies, raw.dependency_count),
        )
    };
    let used = |a: u32| a != vk::ATTACHMENT_UNUSED && a >= attachments;
    for (i, s) in subpasses.iter().enumerate() {
        // SAFETY: the safe setters store each array with its count (and the resolve
        // array with the color attachments' count).
        let refs = unsafe {
            let mut refs: Vec<u32> = Vec::new();
            refs.extend(
                crate::retention::raw_slice(s.p_input_attachments, s.input_attachment_count)
                    .iter()
                    .map(|r| r.attachment),
            );
            refs.extend(
                crate::retention::raw_slice(s.p_color_attachments, s.color_attachment_count)
                    .iter()
                    .map(|r| r.attachment),
            );
            if !s.p_resolve_attachments.is_null() {
                refs.extend(
                    crate::retention::raw_slice(s.p_resolve_attachments, s.color_attachment_count)
                        .iter()
                        .map(|r| r.attachment),
                );
            }
            refs.extend(s.p_depth_stencil_attachment.as_ref().map(|r| r.attachment));
            refs.extend(crate::retention::raw_slice(
                s.p_preserve_attachments,
                s.preserve_attachment_count,
            ));
            refs
        };
        if let Some(a) = refs.into_iter().find(|a| used(*a)) {
            refuse(
                "VUID-VkRenderPassCreateInfo-attachment-00834",
                format!(
                    "pSubpasses[{i}] names attachment {a}, but the render pass has {attachments}"
                ),
            )?;
        }
    }
    for (i, d) in dependencies.iter().enumerate() {
        for (vuid, s, what) in [
            (
                "VUID-VkRenderPassCreateInfo-pDependencies-06866",
                d.src_subpass,
                "srcSubpass",
            ),
            (
                "VUID-VkRenderPassCreateInfo-pDependencies-06867",
                d.dst_subpass,
                "dstSubpass",
            ),
        ] {
            if s != vk::SUBPASS_EXTERNAL && s >= subpass_count {
                refuse(vuid, format!("pDependencies[{i}].{what} ({s}) must be less than subpassCount ({subpass_count})"))?;
            }
        }
    }
    // SAFETY: `raw` is a safe struct's.
    let multiview: Option<&vk::RenderPassMultiviewCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_MULTIVIEW_CREATE_INFO,
        )
    };
    if let Some(m) = multiview.filter(|m| m.subpass_count != 0 && m.subpass_count != subpass_count)
    {
        refuse(
            "VUID-VkRenderPassCreateInfo-pNext-01928",
            format!("the chained VkRenderPassMultiviewCreateInfo's subpassCount ({}) must be 0 or the render pass's ({subpass_count})", m.subpass_count),
        )?;
    }
    // SAFETY: as above.
    let aspects: Option<&vk::RenderPassInputAttachmentAspectCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_INPUT_ATTACHMENT_ASPECT_CREATE_INFO,
        )
    };
    if let Some(a) = aspects {
        // SAFETY: the safe setter stores the references with their count.
        let refs =
            unsafe { crate::retention::raw_slice(a.p_aspect_references, a.aspect_reference_count) };
        for (i, r) in refs.iter().enumerate() {
            let Some(s) = subpasses.get(r.subpass as usize) else {
                return refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-01926",
                    format!("pAspectReferences[{i}].subpass ({}) must be less than subpassCount ({subpass_count})", r.subpass),
                );
            };
            if r.input_attachment_index >= s.input_attachment_count {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-01927",
                    format!("pAspectReferences[{i}].inputAttachmentIndex ({}) must be less than subpass {}'s inputAttachmentCount ({})", r.input_attachment_index, r.subpass, s.input_attachment_count),
                )?;
            }
        }
    }
    Ok(())
}

/// The check of `vkAllocateDescriptorSets` on a chained
/// `VkDescriptorSetVariableDescriptorCountAllocateInfo`: drivers read one count per
/// set from it.
/// The descriptor counts of an allocation's variable-count bindings, one per set, or
/// none.
fn variable_counts<'a>(allocate_info: &'a DescriptorSetAllocateInfo<'_>) -> &'a [u32] {
    let raw = allocate_info.as_raw();
    // SAFETY: `raw` is a safe struct's.
    let variable: Option<&vk::DescriptorSetVariableDescriptorCountAllocateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::DESCRIPTOR_SET_VARIABLE_DESCRIPTOR_COUNT_ALLOCATE_INFO,
        )
    };
    // SAFETY: the safe setter stored the counts with their count.
    variable.map_or(&[], |v| unsafe {
        crate::retention::raw_slice(v.p_descriptor_counts, v.descriptor_set_count)
    })
}

/// Sets of update-after-bind layouts come from an update-after-bind pool, and a
/// variable-count binding gets at most the count its layout was created with.
pub(crate) fn allocate_descriptor_sets_layouts(
    device: &Device,
    descriptor_pool: &DescriptorPool,
    allocate_info: &DescriptorSetAllocateInfo<'_>,
) -> Result<()> {
    let raw = allocate_info.as_raw();
    // SAFETY: the safe setter stored the layouts with their count.
    let layouts =
        unsafe { crate::retention::raw_slice(raw.p_set_layouts, raw.descriptor_set_count) };
    let counts = variable_counts(allocate_info);
    let pool_uab = descriptor_pool
        .pool_flags()
        .contains(vk::DescriptorPoolCreateFlags::UPDATE_AFTER_BIND);
    for (i, layout) in layouts.iter().enumerate() {
        let Some(record) = device.live().set_layout(*layout) else {
            continue;
        };
        if record.update_after_bind && !pool_uab {
            refuse(
                "VUID-VkDescriptorSetAllocateInfo-pSetLayouts-03044",
                format!(
                    "`pSetLayouts[{i}]` was created with \
                     `VK_DESCRIPTOR_SET_LAYOUT_CREATE_UPDATE_AFTER_BIND_POOL_BIT`, so \
                     `descriptorPool` must have been created with \
                     `VK_DESCRIPTOR_POOL_CREATE_UPDATE_AFTER_BIND_BIT`"
                ),
            )?;
        }
        let variable = record
            .variable
            .and_then(|v| record.bindings.iter().find(|b| b.binding == v));
        if let (Some(b), Some(&count)) = (variable, counts.get(i)) {
            if count > b.count {
                refuse(
                    "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-pSetLayouts-03046",
                    format!(
                        "`pDescriptorCounts[{i}]` ({count}) must be less than or equal to the \
                         descriptor count of the variable-sized binding {} of its layout ({})",
                        b.binding, b.count
                    ),
                )?;
            }
        }
    }
    Ok(())
}

pub(crate) fn allocate_descriptor_sets_checks(
    allocate_info: &DescriptorSetAllocateInfo<'_>,
) -> Result<()> {
    let raw = allocate_info.as_raw();
    // SAFETY: `raw` is a safe struct's.
    let variable: Option<&vk::DescriptorSetVariableDescriptorCountAllocateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::DESCRIPTOR_SET_VARIABLE_DESCRIPTOR_COUNT_ALLOCATE_INFO,
        )
    };
    match variable {
        Some(v) if v.descriptor_set_count != 0 && v.descriptor_set_count != raw.descriptor_set_count => refuse(
            "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-descriptorSetCount-03045",
            format!("the chained variable-count info's descriptorSetCount ({}) must be 0 or the allocation's ({})", v.descriptor_set_count, raw.descriptor_set_count),
        ),
        _ => Ok(()),
    }
}

/// The device remembers each pipeline's bind point, layout and the vertex bindings
/// its vertex shader reads.
fn pipelines_created(
    device: &Device,
    pipelines: &[Pipeline],
    bind_point: vk::PipelineBindPoint,
    records: impl Iterator<Item = (vk::PipelineLayout, PipelineRecord)>,
) {
    for (p, (layout, record)) in pipelines.iter().zip(records) {
        if let Some(layout) = device.live().pipeline_layout(layout) {
            device.live().pipeline_created(
                p.raw(),
                PipelineRecord {
                    bind_point,
                    layout,
                    ..record
                },
            );
        }
    }
}

/// The resource variables that the modules of a pipeline's stages declare (every
/// one, as which of them the entry points use is not read), by set and binding.
fn stage_resources<'a>(
    device: &Device,
    stages: impl Iterator<Item = &'a vk::PipelineShaderStageCreateInfo<'a>>,
) -> (Vrc<[crate::spirv::Resource]>, Option<(u32, u32)>) {
    let live = device.live();
    let mut resources = Vec::new();
    let mut push: Option<(u32, u32)> = None;
    for stage in stages {
        if let Some(interface) = live.shader_module(stage.module) {
            resources.extend_from_slice(&interface.resources);
            if let Some((start, end)) = interface.push_constants {
                push = Some(push.map_or((start, end), |(s, e)| (s.min(start), e.max(end))));
            }
        }
    }
    resources.sort_unstable_by_key(|r| (r.set, r.binding));
    resources.dedup();
    (resources.into(), push)
}

/// The depth/stencil state of a pipeline that writes neither aspect (a compute
/// pipeline's).
const NO_DEPTH_STENCIL_WRITES: crate::recorder::DepthStencil = crate::recorder::DepthStencil {
    depth_test: false,
    depth_write: false,
    stencil_test: false,
    ops: [[vk::StencilOp::KEEP; 3]; 2],
    masks: [0; 2],
    discard: true,
};

/// A graphics pipeline's static depth/stencil and rasterizer discard state (no
/// depth/stencil state: neither test).
fn static_depth_stencil(raw: &vk::GraphicsPipelineCreateInfo<'_>) -> crate::recorder::DepthStencil {
    // SAFETY: the safe setters store references that outlive the create info.
    let (ds, raster) = unsafe {
        (
            raw.p_depth_stencil_state.as_ref(),
            raw.p_rasterization_state.as_ref(),
        )
    };
    let ops = |s: &vk::StencilOpState| [s.fail_op, s.pass_op, s.depth_fail_op];
    crate::recorder::DepthStencil {
        depth_test: ds.is_some_and(|d| d.depth_test_enable != vk::FALSE),
        depth_write: ds.is_some_and(|d| d.depth_write_enable != vk::FALSE),
        stencil_test: ds.is_some_and(|d| d.stencil_test_enable != vk::FALSE),
        ops: ds.map_or([[vk::StencilOp::KEEP; 3]; 2], |d| {
            [ops(&d.front), ops(&d.back)]
        }),
        masks: ds.map_or([0; 2], |d| [d.front.write_mask, d.back.write_mask]),
        discard: raster.is_some_and(|r| r.rasterizer_discard_enable != vk::FALSE),
    }
}

/// A pipeline's record before its bind point and layout are filled in: what a
/// compute pipeline has, the resources and push constants its stages' modules
/// declare; a graphics pipeline's adds its fixed-function state.
fn pipeline_record(
    flags: vk::PipelineCreateFlags,
    (resources, push): (Vrc<[crate::spirv::Resource]>, Option<(u32, u32)>),
) -> PipelineRecord {
    PipelineRecord {
        bind_point: vk::PipelineBindPoint::COMPUTE,
        flags,
        layout: Vrc::new(LayoutRecord {
            push_ranges: Vec::new(),
            set_dynamics: Vec::new(),
            sets: Vec::new(),
        }),
        vertex_bindings: 0,
        vertex_reads: Vec::new(),
        samples: vk::SampleCountFlags::empty(),
        pass: None,
        dynamic: 0,
        rendering: None,
        resources,
        push,
        viewports: (0, 0),
        depth_stencil: NO_DEPTH_STENCIL_WRITES,
        blend: 0,
    }
}

/// The vertex-buffer bindings (the first 64) that a graphics pipeline's vertex
/// shader reads: those of the attributes at locations its entry point declares as
/// inputs.
fn vertex_bindings(
    device: &Device,
    info: &vk::GraphicsPipelineCreateInfo<'_>,
) -> (u64, Vec<crate::retention::VertexRead>) {
    // SAFETY: the safe struct stores every array with its length, and a stage's
    // module and name from wrappers and C strings that outlive the create info.
    let stages = unsafe { crate::retention::raw_slice(info.p_stages, info.stage_count) };
    let Some(vertex) = stages
        .iter()
        .find(|s| s.stage == vk::ShaderStageFlags::VERTEX)
    else {
        return (0, Vec::new());
    };
    let Some(interface) = device.live().shader_module(vertex.module) else {
        return (0, Vec::new());
    };
    // SAFETY: as above.
    let name = unsafe { std::ffi::CStr::from_ptr(vertex.p_name) }.to_bytes();
    // SAFETY: as above.
    let Some(input) = (unsafe { info.p_vertex_input_state.as_ref() }) else {
        return (0, Vec::new());
    };
    // SAFETY: as above.
    let (attributes, bindings) = unsafe {
        (
            crate::retention::raw_slice(
                input.p_vertex_attribute_descriptions,
                input.vertex_attribute_description_count,
            ),
            crate::retention::raw_slice(
                input.p_vertex_binding_descriptions,
                input.vertex_binding_description_count,
            ),
        )
    };
    let read: Vec<_> = attributes
        .iter()
        .filter(|a| interface.reads_vertex_location(name, a.location))
        .collect();
    let mask = read
        .iter()
        .filter(|a| a.binding < 64)
        .fold(0, |mask, a| mask | 1 << a.binding);
    // What each binding's read attributes reach, past the start of a vertex: an
    // attribute of a format the registry does not describe reaches past any buffer.
    let mut reads: Vec<crate::retention::VertexRead> = Vec::new();
    for a in read {
        let size = crate::formats::block(a.format, vk::ImageAspectFlags::COLOR)
            .map_or(u64::MAX, |(bytes, _)| u64::from(bytes));
        let end = u64::from(a.offset).saturating_add(size);
        if let Some(r) = reads.iter_mut().find(|r| r.binding == a.binding) {
            r.end = r.end.max(end);
        } else if let Some(b) = bindings.iter().find(|b| b.binding == a.binding) {
            reads.push(crate::retention::VertexRead {
                binding: a.binding,
                stride: b.stride,
                instance: b.input_rate == vk::VertexInputRate::INSTANCE,
                end,
            });
        }
    }
    (mask, reads)
}

/// [`pipelines_created`] for `vkCreateComputePipelines`.
pub(crate) fn compute_pipelines_created(
    device: &Device,
    created: Vec<Pipeline>,
    create_infos: &[ComputePipelineCreateInfo<'_>],
) -> Vec<Pipeline> {
    let records = create_infos.iter().map(|i| {
        (
            i.as_raw().layout,
            pipeline_record(
                i.as_raw().flags,
                stage_resources(device, std::iter::once(&i.as_raw().stage)),
            ),
        )
    });
    pipelines_created(device, &created, vk::PipelineBindPoint::COMPUTE, records);
    created
}

/// [`pipelines_created`] for `vkCreateGraphicsPipelines`.
pub(crate) fn graphics_pipelines_created(
    device: &Device,
    created: Vec<Pipeline>,
    create_infos: &[GraphicsPipelineCreateInfo<'_>],
) -> Vec<Pipeline> {
    let records = create_infos.iter().map(|i| {
        let raw = i.as_raw();
        // SAFETY: the safe setter stores a reference that outlives the create info.
        let samples = unsafe { raw.p_multisample_state.as_ref() }
            .map_or(vk::SampleCountFlags::empty(), |m| m.rasterization_samples);
        // SAFETY: as above, and the state's array with its count.
        let dynamic = unsafe { raw.p_dynamic_state.as_ref() }.map_or(0, |d| {
            unsafe { crate::retention::raw_slice(d.p_dynamic_states, d.dynamic_state_count) }
                .iter()
                .fold(0, |bits, s| bits | crate::recorder::dynamic_bit(*s))
        });
        let pass = device
            .live()
            .render_pass(raw.render_pass)
            .map(|r| (r, raw.subpass));
        let rendering = (raw.render_pass == vk::RenderPass::null()).then(|| {
            // SAFETY: the chain of a safe struct, and the type its sType names; the
            // safe setter stores the formats with their count.
            let info: Option<&vk::PipelineRenderingCreateInfo<'_>> = unsafe {
                chained(
                    raw.p_next,
                    vk::StructureType::PIPELINE_RENDERING_CREATE_INFO,
                )
            };
            // SAFETY: the safe setter stores the formats with their count.
            Vrc::new(info.map_or_else(Default::default, |i| unsafe {
                crate::retention::RenderingFormats::from_raw(
                    i.view_mask,
                    i.p_color_attachment_formats,
                    i.color_attachment_count,
                    i.depth_attachment_format,
                    i.stencil_attachment_format,
                )
            }))
        });
        (raw.layout, {
            let (vertex_bindings, vertex_reads) = vertex_bindings(device, raw);
            PipelineRecord {
                vertex_bindings,
                vertex_reads,
                samples,
                pass,
                dynamic,
                rendering,
                // SAFETY: the safe setter stores a reference that outlives the
                // info.
                viewports: unsafe { raw.p_viewport_state.as_ref() }
                    .map_or((0, 0), |v| (v.viewport_count, v.scissor_count)),
                depth_stencil: static_depth_stencil(raw),
                // SAFETY: the safe setter stores a reference that outlives the info,
                // and the attachments with their count.
                blend: unsafe { raw.p_color_blend_state.as_ref() }.map_or(0, |c| {
                    unsafe { crate::retention::raw_slice(c.p_attachments, c.attachment_count) }
                        .iter()
                        .take(32)
                        .enumerate()
                        .filter(|(_, a)| a.blend_enable == vk::TRUE)
                        .fold(0, |bits, (i, _)| bits | (1 << i))
                }),
                // SAFETY: the safe struct stores its stages with their count.
                ..pipeline_record(
                    raw.flags,
                    stage_resources(
                        device,
                        unsafe { crate::retention::raw_slice(raw.p_stages, raw.stage_count) }
                            .iter(),
                    ),
                )
            }
        })
    });
    pipelines_created(device, &created, vk::PipelineBindPoint::GRAPHICS, records);
    created
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
            crate::recorder::dynamic_bit(vk::DynamicState::VERTEX_INPUT_BINDING_STRIDE),
        );
    }
}

/// The vertices and instances a direct draw fetches: (first vertex, vertex count,
/// first instance, instance count, the rule they break past a vertex buffer, the
/// rule of the last instance index in a multiview render pass instance).
pub(crate) type Vertices = Option<(u32, u32, u32, u32, &'static str, &'static str)>;

/// Refuses a draw in a render pass instance with a view mask whose last instance
/// index is past `maxMultiviewInstanceIndex`.
fn multiview_instances<S: Scope>(
    recorder: &Recorder<'_, S>,
    first_instance: u32,
    instance_count: u32,
    vuid: &'static str,
) -> Result<()> {
    let multiview = recorder.instance.as_ref().is_some_and(|i| i.view_mask != 0);
    if !multiview || instance_count == 0 {
        return Ok(());
    }
    let device = recorder.device();
    let max = device.live().max_multiview_instance(|| {
        render_pass::multiview_properties(device).map(|m| m.max_multiview_instance_index)
    });
    let last = u64::from(first_instance) + u64::from(instance_count) - 1;
    match max {
        Some(max) if last > u64::from(max) => refuse(
            vuid,
            format!("the draw's last instance index ({last}) is past maxMultiviewInstanceIndex ({max}) in a multiview render pass instance"),
        ),
        Some(_) => Ok(()),
        None => refuse(
            vuid,
            "a Vulkan 1.0 instance cannot ask maxMultiviewInstanceIndex, so no multiview draw is checked".into(),
        ),
    }
}

/// A draw: a graphics pipeline and its sets and vertex buffers bound
/// ([`bound_pipeline_checks`]), the state it draws with ([`draw_state_checks`]),
/// and for a direct draw, the vertices it fetches inside the bound vertex buffers.
pub(crate) fn draw_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    pipeline_vuid: &'static str,
    sets_vuid: &'static str,
    vertex_vuid: &'static str,
    vertices: Vertices,
    rules: &DrawRules,
) -> Result<()> {
    recorder.verify_state(0, |recorder| {
        // Before the descriptors' layouts: a descriptor that names an attachment is
        // refused for what it does to the attachment's memory first.
        attachment_checks(recorder, &rules.attachments)?;
        bound_pipeline_checks(
            recorder,
            vk::PipelineBindPoint::GRAPHICS,
            pipeline_vuid,
            sets_vuid,
            Some(vertex_vuid),
            &rules.shader,
        )?;
        draw_state_checks(recorder, rules)
    })?;
    let Some((first_vertex, vertex_count, first_instance, instance_count, vuid, multiview)) =
        vertices
    else {
        return Ok(());
    };
    multiview_instances(recorder, first_instance, instance_count, multiview)?;
    vertex_fetch_checks(
        recorder,
        (u64::from(first_vertex), u64::from(vertex_count)),
        (first_instance, instance_count),
        vuid,
    )
}

/// Refuses a draw that fetches vertices `(first, count)` or instances past the end
/// of the vertex buffer bound at a binding the bound pipeline's vertex shader reads.
fn vertex_fetch_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    (first_vertex, vertex_count): (u64, u64),
    (first_instance, instance_count): (u32, u32),
    vuid: &'static str,
) -> Result<()> {
    let Some(pipeline) = &recorder.bound[0].pipeline else {
        return Ok(());
    };
    let bound = &recorder.bound[0];
    let dynamic_stride = pipeline.dynamic
        & crate::recorder::dynamic_bit(vk::DynamicState::VERTEX_INPUT_BINDING_STRIDE)
        != 0;
    if pipeline.vertex_reads.is_empty() {
        return Ok(());
    }
    for read in &pipeline.vertex_reads {
        let (first, count) = if read.instance {
            (u64::from(first_instance), u64::from(instance_count))
        } else {
            (first_vertex, vertex_count)
        };
        if count == 0 {
            continue;
        }
        let Some(Some(range)) = bound.vertex_ranges.get(read.binding as usize) else {
            continue;
        };
        let stride = match (dynamic_stride, range.stride) {
            (true, Some(stride)) => stride,
            _ => u64::from(read.stride),
        };
        let last = first.saturating_add(count - 1);
        let needed = last.saturating_mul(stride).saturating_add(read.end);
        if needed > range.bytes {
            refuse(
                vuid,
                format!("the draw fetches {needed} bytes from the vertex buffer bound at binding {}, which holds {} past its offset", read.binding, range.bytes),
            )?;
        }
    }
    Ok(())
}

/// `vkCmdSetViewportWithCount` (`bits` its state) or `vkCmdSetScissorWithCount`:
/// the state is set, with `count` viewports or scissors.
pub(crate) fn viewport_count_set<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    count: usize,
    bits: u32,
) {
    let count = u32::try_from(count).unwrap_or(u32::MAX);
    if bits == crate::recorder::dynamic_bit(vk::DynamicState::VIEWPORT_WITH_COUNT) {
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

/// The rules of one draw command about the state it draws with.
pub(crate) struct DrawRules {
    /// The bound pipeline's render pass is compatible with the instance's.
    pub render_pass: &'static str,
    /// The bound pipeline's subpass is the instance's current one.
    pub subpass: &'static str,
    /// Every dynamic state of the bound pipeline is set.
    pub dynamic_set: &'static str,
    /// No state static in the bound pipeline was set since it was bound.
    pub static_unset: &'static str,
    /// Rules naming one dynamic state that must be set: (its bit, the rule).
    pub named: [(u32, &'static str); 5],
    /// In dynamic rendering, what the bound pipeline was made for against the
    /// instance: the view mask, the color attachment count, a color format, a
    /// color format for an attachment with no view, the depth format, one for no
    /// depth view, the stencil format, one for no stencil view.
    pub rendering: [&'static str; 8],
    /// Depth and stencil writes against read-only attachment layouts: in any
    /// instance (depth, stencil), then in dynamic rendering by the layout the
    /// attachment info names (depth and stencil in `DEPTH_STENCIL_READ_ONLY_OPTIMAL`,
    /// in `DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL` and
    /// `DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL`, in `DEPTH_READ_ONLY_OPTIMAL` and
    /// `STENCIL_READ_ONLY_OPTIMAL`).
    /// Then the pipeline's rasterization samples against the attachments'.
    pub read_only: [&'static str; 9],
    /// The viewport and scissor counts set with their counts: the viewport count
    /// against the pipeline's scissor count, the scissor count against its viewport
    /// count, and both against each other.
    pub counts: [&'static str; 3],
    /// What its shaders read ([`ShaderRules`]).
    pub shader: ShaderRules,
    /// The instance's attachments as the draw reaches them: an input attachment
    /// variable's index names an input attachment of the subpass, its view is
    /// compatible with the framebuffer's, no descriptor reaches an attachment's
    /// memory (written by the shader, or read), and blending only on attachments
    /// whose format supports it.
    pub attachments: AttachmentRules,
}

/// The rules of [`DrawRules::attachments`]: an input attachment's index (07468),
/// its view (07469), an attachment's memory written (06537) or read (06538) other
/// than as an attachment, and blending (04727).
pub(crate) type AttachmentRules = [&'static str; 5];

/// The rules of a draw or dispatch about what its shaders read: an image view's
/// type for the image type's `Dim` and `Arrayed`, its format's numeric type for the
/// sampled type, every descriptor written, the push constants set, and atomic
/// operations, depth comparison, and storage reads and writes of `Unknown` format
/// only on image views whose format supports them; no protected resource reached
/// from an unprotected command buffer, and no draw or dispatch in a protected one
/// (the command's rule of protected command buffers); then what the samplers that
/// sample a view allow (linear filtering and linear mipmaps by its format, and with
/// unnormalized coordinates its view type, implicit-LOD, depth-comparison and
/// projective instructions, LOD bias and offsets), texels written with as many
/// components as an image view's or a texel buffer view's format has, storage texel
/// buffers of `Unknown` format written and read only where their format allows it,
/// and Y'CbCr conversions only with sampling instructions, without offsets.
pub(crate) type ShaderRules = [&'static str; 21];

/// The dynamic states whose rule a draw command names apart from the general one:
/// primitive topology, vertex input binding stride, rasterizer discard enable,
/// depth bias enable and primitive restart enable.
pub(crate) const NAMED_STATES: [u32; 5] = {
    use crate::recorder::dynamic_bit;
    use vk::DynamicState as D;
    [
        dynamic_bit(D::PRIMITIVE_TOPOLOGY),
        dynamic_bit(D::VERTEX_INPUT_BINDING_STRIDE),
        dynamic_bit(D::RASTERIZER_DISCARD_ENABLE),
        dynamic_bit(D::DEPTH_BIAS_ENABLE),
        dynamic_bit(D::PRIMITIVE_RESTART_ENABLE),
    ]
};

/// Refuses a draw whose bound graphics pipeline was made for another render pass
/// or subpass than the instance's, one of whose dynamic states is not set (or was
/// set before a pipeline bound since had it static), or after a command that set a
/// state the pipeline has static.
#[inline]
fn draw_state_checks<S: Scope>(recorder: &Recorder<'_, S>, rules: &DrawRules) -> Result<()> {
    let Some(pipeline) = &recorder.bound[0].pipeline else {
        return Ok(());
    };
    if let Some(instance) = &recorder.instance {
        match (&pipeline.pass, &instance.record) {
            (Some((made_for, subpass)), Some(current)) => {
                if !Vrc::ptr_eq(made_for, current) && !made_for.compatible(current) {
                    refuse(
                        rules.render_pass,
                        "the bound pipeline was created for a render pass that is not compatible with the render pass instance's".into(),
                    )?;
                }
                if *subpass != instance.subpass {
                    refuse(
                        rules.subpass,
                        format!("the bound pipeline was created for subpass {subpass}, and the render pass instance is in subpass {}", instance.subpass),
                    )?;
                }
            }
            (None, Some(_)) => refuse(
                rules.render_pass,
                "the bound pipeline was created for dynamic rendering, inside a render pass instance".into(),
            )?,
            _ => {}
        }
    }
    if let (Some(made_for), Some(current)) = (
        &pipeline.rendering,
        recorder
            .instance
            .as_ref()
            .and_then(|i| i.rendering.as_ref()),
    ) {
        rendering_checks(made_for, current, &rules.rendering)?;
    }
    let (valid, since_bind) = recorder.dynamic;
    let missing = pipeline.dynamic & !valid;
    if missing != 0 {
        let vuid = rules
            .named
            .iter()
            .find(|(bit, _)| missing & bit != 0)
            .map_or(rules.dynamic_set, |(_, vuid)| vuid);
        refuse(
            vuid,
            format!("dynamic state bit {} of the bound pipeline was not set since a pipeline with it static was bound (or at all)", missing.trailing_zeros()),
        )?;
    }
    let stale = since_bind & !pipeline.dynamic;
    if stale != 0 {
        refuse(
            rules.static_unset,
            format!("dynamic state bit {} was set since the bound pipeline was bound, and the pipeline has it static", stale.trailing_zeros()),
        )?;
    }
    count_checks(recorder.counts, pipeline, &rules.counts)?;
    read_only_checks(recorder, pipeline, &rules.read_only)
}

/// The depth, stencil and rasterizer discard values a draw uses: the bound
/// pipeline's, or the recording's where the pipeline has them dynamic.
fn draw_values<S: Scope>(
    recorder: &Recorder<'_, S>,
    pipeline: &PipelineRecord,
) -> crate::recorder::DepthStencil {
    let mut values = pipeline.depth_stencil;
    values.take(&recorder.depth_stencil, pipeline.dynamic);
    values
}

/// Refuses a draw that rasterizes another sample count than the instance's
/// attachments have, or writes depth or stencil where the instance's depth/stencil
/// attachment has that aspect in a read-only layout (or where its layouts are not
/// known).
fn read_only_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    pipeline: &PipelineRecord,
    rules: &[&'static str; 9],
) -> Result<()> {
    let Some(instance) = &recorder.instance else {
        return Ok(());
    };
    let values = draw_values(recorder, pipeline);
    if !values.discard {
        if let (Some(samples), false) = (instance.attachment_samples(), pipeline.samples.is_empty())
        {
            if samples != pipeline.samples {
                refuse(
                    rules[8],
                    format!("the bound pipeline rasterizes {:?} samples, and the render pass instance's attachments have {samples:?}", pipeline.samples),
                )?;
            }
        }
    }
    let (depth, stencil) = (values.writes_depth(), values.writes_stencil());
    if !depth && !stencil {
        return Ok(());
    }
    let Some((depth_layout, stencil_layout)) = instance.depth_stencil_layouts() else {
        return refuse(
            if depth { rules[0] } else { rules[1] },
            "the draw writes the depth/stencil attachment, whose layouts are not known here (a secondary that continues dynamic rendering: its inheritance info does not give them)".into(),
        );
    };
    type L = vk::ImageLayout;
    // Per aspect: whether the draw writes it, its layout, the layouts that hold it
    // read-only with the dynamic-rendering rule each names, the rule of any
    // instance, and its name with what the draw does to it.
    let aspects = [
        (
            depth,
            depth_layout,
            [
                (L::DEPTH_STENCIL_READ_ONLY_OPTIMAL, rules[2]),
                (L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL, rules[4]),
                (L::DEPTH_READ_ONLY_OPTIMAL, rules[6]),
            ],
            rules[0],
            ("depth", "writes depth (depth test and writes enabled)"),
        ),
        (
            stencil,
            stencil_layout,
            [
                (L::DEPTH_STENCIL_READ_ONLY_OPTIMAL, rules[3]),
                (L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL, rules[5]),
                (L::STENCIL_READ_ONLY_OPTIMAL, rules[7]),
            ],
            rules[1],
            ("stencil", "may write stencil (stencil test enabled, a face with a write mask and an operation other than KEEP)"),
        ),
    ];
    for (writes, layout, read_only, any_instance, (aspect, what)) in aspects {
        let (true, Some(layout)) = (writes, layout) else {
            continue;
        };
        let named = read_only.iter().find(|(l, _)| *l == layout);
        let rule = match named {
            Some((_, rule)) if instance.dynamic => Some(*rule),
            Some(_) => Some(any_instance),
            None if layout == L::READ_ONLY_OPTIMAL => Some(any_instance),
            None => None,
        };
        if let Some(rule) = rule {
            refuse(
                rule,
                format!(
                    "the draw {what}, and the depth/stencil attachment's {aspect} aspect is in {layout:?}"
                ),
            )?;
        }
    }
    Ok(())
}

/// Refuses a draw whose viewport and scissor counts, where the bound pipeline has
/// them dynamic with their counts, differ from each other or from the count the
/// pipeline has static.
fn count_checks(
    (viewports, scissors): (Option<u32>, Option<u32>),
    pipeline: &PipelineRecord,
    rules: &[&'static str; 3],
) -> Result<()> {
    use crate::recorder::dynamic_bit;
    let with = |state| pipeline.dynamic & dynamic_bit(state) != 0;
    let (static_viewports, static_scissors) = pipeline.viewports;
    match (
        with(vk::DynamicState::VIEWPORT_WITH_COUNT),
        with(vk::DynamicState::SCISSOR_WITH_COUNT),
    ) {
        (true, false) if viewports != Some(static_scissors) => refuse(
            rules[0],
            format!("the viewport count set ({viewports:?}) is not the bound pipeline's scissor count ({static_scissors})"),
        ),
        (false, true) if scissors != Some(static_viewports) => refuse(
            rules[1],
            format!("the scissor count set ({scissors:?}) is not the bound pipeline's viewport count ({static_viewports})"),
        ),
        (true, true) if viewports.is_none() || viewports != scissors => refuse(
            rules[2],
            format!("the viewport count set ({viewports:?}) is not the scissor count set ({scissors:?})"),
        ),
        _ => Ok(()),
    }
}

/// Refuses a pipeline made for other dynamic rendering than the instance's: its
/// view mask, color attachment count or formats (`UNDEFINED` where the instance's
/// attachment has no view), or depth or stencil format differ.
fn rendering_checks(
    made_for: &crate::retention::RenderingFormats,
    current: &crate::retention::RenderingFormats,
    rules: &[&'static str; 8],
) -> Result<()> {
    let undefined = vk::Format::UNDEFINED;
    if made_for.view_mask != current.view_mask {
        refuse(
            rules[0],
            format!("the bound pipeline was made for view mask {:#x}, and the render pass instance has {:#x}", made_for.view_mask, current.view_mask),
        )?;
    }
    if made_for.colors.len() != current.colors.len() {
        refuse(
            rules[1],
            format!("the bound pipeline was made for {} color attachments, and the render pass instance has {}", made_for.colors.len(), current.colors.len()),
        )?;
    }
    for (i, (made, now)) in made_for.colors.iter().zip(&current.colors).enumerate() {
        if *now == undefined && *made != undefined {
            refuse(
                rules[3],
                format!("color attachment {i} has no view, and the bound pipeline was made for format {made:?} there"),
            )?;
        }
        if *now != undefined && made != now {
            refuse(
                rules[2],
                format!("color attachment {i} is of format {now:?}, and the bound pipeline was made for {made:?}"),
            )?;
        }
    }
    for (made, now, (defined_rule, undefined_rule), what) in [
        (made_for.depth, current.depth, (rules[4], rules[5]), "depth"),
        (
            made_for.stencil,
            current.stencil,
            (rules[6], rules[7]),
            "stencil",
        ),
    ] {
        if now == undefined && made != undefined {
            refuse(
                undefined_rule,
                format!("the {what} attachment has no view, and the bound pipeline was made for format {made:?}"),
            )?;
        }
        if now != undefined && made != now {
            refuse(
                defined_rule,
                format!("the {what} attachment is of format {now:?}, and the bound pipeline was made for {made:?}"),
            )?;
        }
    }
    Ok(())
}

/// The recording names `event` in an event command: its submission is checked
/// against pending submissions to other queues that name it too.
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
            bound_points.written.resize(n + 1, Default::default());
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

/// The rule of an image descriptor's layout, checked where a draw or dispatch reads
/// it.
const DESCRIPTOR_LAYOUT: &str = "VUID-VkDescriptorImageInfo-imageLayout-00344";

/// The image descriptors a draw or dispatch at `bound` may read: those of the sets
/// bound at every set number of the bound pipeline's layout (which of them the
/// shaders read is not known).
#[inline]
fn used_images(
    bound: &crate::recorder::Bound,
) -> impl Iterator<Item = &crate::retention::ImageDescriptor> {
    let n = bound.pipeline.as_ref().map_or(0, |p| p.layout.sets.len());
    bound
        .images
        .iter()
        .take(n)
        .flatten()
        .flat_map(|images| images.iter().map(|(_, d)| d))
        .filter(|d| d.kind == crate::retention::SlotKind::Image)
}

/// Refuses a draw or dispatch whose pipeline's shaders read push constants that were
/// not all pushed, with a layout compatible for push constants with the pipeline's,
/// unless the device enabled `maintenance4` (which lets them read undefined values).
fn push_constant_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    pipeline: &PipelineRecord,
    vuid: &'static str,
) -> Result<()> {
    let Some((start, end)) = pipeline.push else {
        return Ok(());
    };
    if start >= end
        || recorder
            .device()
            .live()
            .with_features(|f| f.v13.maintenance4)
            == vk::TRUE
    {
        return Ok(());
    }
    let pushed = recorder.pushed.as_ref();
    let compatible = pushed.is_some_and(|p| p.layout.same_push_ranges(&pipeline.layout));
    if !compatible {
        return refuse(
            vuid,
            format!("the bound pipeline's shaders read push constants (bytes {start} to {end}), and none were pushed with a layout of the same push-constant ranges"),
        );
    }
    if let Some(byte) = (start..end).find(|b| !pushed.is_some_and(|p| p.has(*b))) {
        return refuse(
            vuid,
            format!("the bound pipeline's shaders read push constants (bytes {start} to {end}), and byte {byte} was not pushed"),
        );
    }
    Ok(())
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

/// The features of `format` as `VkFormatProperties3` gives them (where the device
/// has Vulkan 1.3): linear tiling, optimal tiling and buffer. On an older device, the
/// bits that `VK_KHR_format_feature_flags2` made per format follow from the first
/// set: depth comparison from sampling a depth format, storage without format from
/// storage (an image's or a texel buffer's) and the device's
/// `shaderStorageImage*WithoutFormat` features.
fn format_features2(device: &Device, format: vk::Format) -> Result<[vk::FormatFeatureFlags2; 3]> {
    let physical = device.parent();
    let instance = physical.parent();
    let version = physical.get_properties().api_version;
    if instance.exts().version(1) && vk::api_version_minor(version) >= 3 {
        let mut p3 = vk::FormatProperties3::default();
        let mut p2 = vk::FormatProperties2::default().push_next(&mut p3);
        // SAFETY: a live physical device of a Vulkan 1.3 device; the chain is local.
        unsafe {
            instance
                .fns()
                .get_physical_device_format_properties2(physical.raw(), format, &mut p2)
        };
        return Ok([
            p3.linear_tiling_features,
            p3.optimal_tiling_features,
            p3.buffer_features,
        ]);
    }
    let live = device.live();
    let props = live.format_properties(physical, format)?;
    let (read, write) = live.with_features(|f| {
        (
            f.v10.shader_storage_image_read_without_format == vk::TRUE,
            f.v10.shader_storage_image_write_without_format == vk::TRUE,
        )
    });
    let depth =
        crate::formats::aspects(format).is_some_and(|a| a.contains(vk::ImageAspectFlags::DEPTH));
    type F = vk::FormatFeatureFlags;
    type F2 = vk::FormatFeatureFlags2;
    let widen = |first: F, storage: F| {
        let mut features = F2::from_raw(u64::from(first.as_raw()));
        if depth && first.contains(F::SAMPLED_IMAGE) {
            features |= F2::SAMPLED_IMAGE_DEPTH_COMPARISON;
        }
        if first.contains(storage) && read {
            features |= F2::STORAGE_READ_WITHOUT_FORMAT;
        }
        if first.contains(storage) && write {
            features |= F2::STORAGE_WRITE_WITHOUT_FORMAT;
        }
        features
    };
    Ok([
        widen(props.linear_tiling_features, F::STORAGE_IMAGE),
        widen(props.optimal_tiling_features, F::STORAGE_IMAGE),
        widen(props.buffer_features, F::STORAGE_TEXEL_BUFFER),
    ])
}

/// The features of the view of `d`'s format for its image's tiling
/// ([`format_features2`]).
fn view_features2(
    device: &Device,
    d: &crate::retention::ImageDescriptor,
) -> Result<vk::FormatFeatureFlags2> {
    let linear = device
        .live()
        .image(d.image)
        .is_some_and(|i| i.tiling == vk::ImageTiling::LINEAR);
    let [linear_features, optimal, _] = format_features2(device, d.format)?;
    Ok(if linear { linear_features } else { optimal })
}

/// Refuses a draw or dispatch in a protected command buffer (`in_protected` names
/// the rule: which resources its pipeline writes, and from which stages, is not
/// followed), and, on a device that enabled protectedMemory without
/// protectedNoFault, one in an unprotected command buffer while a protected buffer
/// or image is alive (which resources its pipeline reaches is not followed).
/// Without protectedMemory no protected object can be made (their creation checks
/// the feature), so nothing is refused.
fn protected_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    vuid: &'static str,
    in_protected: &'static str,
) -> Result<()> {
    let device = recorder.device();
    let live = device.live();
    if live.with_features(|f| f.v11.protected_memory) != vk::TRUE {
        return Ok(());
    }
    let protected = recorder
        .command_buffer()
        .uses()
        .pool()
        .is_some_and(|(_, protected)| protected);
    if protected {
        return refuse(
            in_protected,
            "a draw or dispatch in a protected command buffer: which resources its pipeline writes, and from which stages, is not followed".into(),
        );
    }
    if render_pass::protected_no_fault(device) {
        return Ok(());
    }
    if live.has_protected_resources() {
        return refuse(
            vuid,
            "a draw or dispatch in an unprotected command buffer while protected buffers or images are alive: which resources its pipeline reaches is not followed".into(),
        );
    }
    Ok(())
}

/// Refuses a draw or dispatch whose shaders use atomic operations on the image view
/// of `d`, where the view's format features (for its image's tiling) lack
/// `STORAGE_IMAGE_ATOMIC`.
fn atomic_checks(
    device: &Device,
    d: &crate::retention::ImageDescriptor,
    at: &dyn Fn() -> String,
    vuid: &'static str,
) -> Result<()> {
    if !view_features2(device, d)?.contains(vk::FormatFeatureFlags2::STORAGE_IMAGE_ATOMIC) {
        return refuse(
            vuid,
            format!("{}: the shader uses atomic operations on the image view, and the features of its format {:?} (for its image's tiling) lack STORAGE_IMAGE_ATOMIC", at(), d.format),
        );
    }
    Ok(())
}

/// Refuses a draw or dispatch that reads resource `r` where the set bound at its
/// set number has a descriptor of the binding that was never written.
fn written_checks(
    bound: &crate::recorder::Bound,
    r: &crate::spirv::Resource,
    vuid: &'static str,
) -> Result<()> {
    let (Some(Some(layout)), Some(written)) = (
        bound.sets.get(r.set as usize),
        bound.written.get(r.set as usize),
    ) else {
        return Ok(());
    };
    let Some(b) = layout.bindings.iter().find(|b| b.binding == r.binding) else {
        return Ok(());
    };
    let partly = b
        .flags
        .contains(vk::DescriptorBindingFlags::PARTIALLY_BOUND);
    // A sampler binding with immutable samplers holds its samplers from the start.
    let fixed = b.immutable && b.ty == vk::DescriptorType::SAMPLER;
    if partly || fixed {
        return Ok(());
    }
    // The variable's descriptors (a runtime array's: the binding's), or an inline
    // uniform block's bytes.
    let count = if r.count == 0 || b.ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK {
        b.count
    } else {
        r.count.min(b.count)
    };
    if let Some(element) = (0..count).find(|e| written.binary_search(&(r.binding, *e)).is_err()) {
        let what = if b.ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK {
            "byte"
        } else {
            "element"
        };
        return refuse(
            vuid,
            format!("set {} binding {} {what} {element}, which the pipeline's shaders declare, was never written (when the set was bound)", r.set, r.binding),
        );
    }
    Ok(())
}

/// Refuses a draw or dispatch whose sets hold an image descriptor whose layout is
/// not the one the recording's earlier commands leave its subresources in, or
/// which names an attachment of the render pass instance (whose layout in each
/// subpass the recorder does not follow).
fn descriptor_layout_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    bound: &crate::recorder::Bound,
) -> Result<()> {
    if bound.images.iter().all(Option::is_none) {
        return Ok(());
    }
    // The images of the render pass instance's attachments (a render pass's, not
    // dynamic rendering's, whose layouts the recording follows).
    let in_pass = recorder.instance.as_ref().is_some_and(|i| !i.dynamic);
    for (k, d) in used_images(bound).enumerate() {
        // Two descriptors that state different layouts for one subresource: one of
        // them is wrong whatever the recording did before.
        if let Some(other) = used_images(bound)
            .take(k)
            .find(|e| e.image == d.image && e.layout != d.layout && e.sel.overlaps(&d.sel))
        {
            return refuse(
                DESCRIPTOR_LAYOUT,
                format!("two image descriptors the bound sets hold name one subresource of image 0x{:x} in different layouts ({:?} and {:?})", d.image.as_raw(), other.layout, d.layout),
            );
        }
        if in_pass && recorder.pass_images.contains(&d.image) {
            return refuse(
                DESCRIPTOR_LAYOUT,
                format!("an image descriptor names image 0x{:x}, an attachment of the render pass instance, whose layout in each subpass is not followed", d.image.as_raw()),
            );
        }
        recorder
            .layouts
            .check(d.image, d.sel, d.layout, DESCRIPTOR_LAYOUT)?;
    }
    Ok(())
}

/// A draw or dispatch reads its sets' image descriptors in the layouts they state:
/// subresources the recording has not touched need those layouts at its start,
/// which its submission checks.
pub(crate) fn descriptor_layouts_used<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    bind_point: vk::PipelineBindPoint,
) {
    let Some(i) = crate::recorder::Bound::index(bind_point) else {
        return;
    };
    let bound = &recorder.bound[i];
    let n = bound.pipeline.as_ref().map_or(0, |p| p.layout.sets.len());
    // Most draws read no image descriptor: nothing to collect.
    let image = |l: &crate::retention::SetImages| {
        l.iter()
            .any(|(_, d)| d.kind == crate::retention::SlotKind::Image)
    };
    if !bound.images.iter().take(n).flatten().any(image) {
        return;
    }
    let lists: SmallVec<[crate::retention::SetImages; 4]> =
        bound.images.iter().take(n).flatten().cloned().collect();
    let (live, layouts) = recorder.layouts_mut();
    let images = lists
        .iter()
        .flat_map(|l| l.iter().map(|(_, d)| d))
        .filter(|d| d.kind == crate::retention::SlotKind::Image);
    for d in images {
        layouts.require(live, d.image, d.sel, d.layout, DESCRIPTOR_LAYOUT);
    }
}

/// A dispatch's state checks ([`bound_pipeline_checks`]), once per state, and no
/// dynamic state set since its compute pipeline was bound (`static_unset`: the
/// pipeline has every state static).
pub(crate) fn dispatch_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    pipeline_vuid: &'static str,
    sets_vuid: &'static str,
    static_unset: &'static str,
    shader: &ShaderRules,
) -> Result<()> {
    recorder.verify_state(1, |recorder| {
        bound_pipeline_checks(
            recorder,
            vk::PipelineBindPoint::COMPUTE,
            pipeline_vuid,
            sets_vuid,
            None,
            shader,
        )?;
        let set = recorder.compute_dynamic;
        if set != 0 && recorder.bound[1].pipeline.is_some() {
            refuse(
                static_unset,
                format!("dynamic state bit {} was set since the bound compute pipeline was bound, and a compute pipeline has every state static", set.trailing_zeros()),
            )?;
        }
        Ok(())
    })
}

/// A draw or dispatch has a pipeline bound at its bind point (02700), a set bound
/// at every set number of that pipeline's layout, of the same set layout (02697),
/// the descriptors and push constants its shaders read ([`bound_descriptor_checks`],
/// [`push_constant_checks`]), and its image descriptors in their layouts. Which sets the shaders use is not known here, so every set of the layout
/// must be bound: a program that leaves an unused set unbound is refused too.
fn bound_pipeline_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    bind_point: vk::PipelineBindPoint,
    pipeline_vuid: &'static str,
    sets_vuid: &'static str,
    vertex_vuid: Option<&'static str>,
    shader: &ShaderRules,
) -> Result<()> {
    let Some(bound) = crate::recorder::Bound::index(bind_point).map(|i| &recorder.bound[i]) else {
        return Ok(());
    };
    let Some(pipeline) = &bound.pipeline else {
        return refuse(
            pipeline_vuid,
            format!("no {bind_point:?} pipeline is bound"),
        );
    };
    for (n, wanted) in pipeline.layout.sets.iter().enumerate() {
        let ok = bound
            .sets
            .get(n)
            .and_then(Option::as_ref)
            .is_some_and(|got| SetLayoutRecord::matches(got, wanted));
        if !ok {
            refuse(
                sets_vuid,
                format!("set {n} of the bound pipeline's layout has no descriptor set of its set layout bound"),
            )?;
        }
    }
    // A binding the vertex shader reads through an attribute, with no buffer bound:
    // the device would fetch from no memory.
    let unbound = pipeline.vertex_bindings & !bound.vertex;
    if let (Some(vuid), true) = (vertex_vuid, unbound != 0) {
        refuse(
            vuid,
            format!(
                "the bound pipeline's vertex shader reads binding {}, which has no vertex buffer bound",
                unbound.trailing_zeros()
            ),
        )?;
    }
    bound_descriptor_checks(recorder.device(), bound, pipeline, shader)?;
    protected_checks(recorder, shader[8], shader[9])?;
    push_constant_checks(recorder, pipeline, shader[3])?;
    descriptor_layout_checks(recorder, bound)
}

/// Refuses a draw or dispatch whose sets hold, at a binding a resource variable of
/// its pipeline's shaders reads, a descriptor never written (or whose slot a copy of
/// an unwritten one emptied), or an image view that an image variable cannot read: a
/// view type other than the one the variable's `Dim` and `Arrayed` name, a format
/// whose texels read as another numeric type than the variable's sampled type
/// (float against integer), or a format whose features lack what the shader's
/// operations on it need (atomics, depth comparison, storage reads and writes of an
/// `Unknown` format). Every variable the modules declare counts, as
/// which ones the entry points use is not read; a binding with
/// `PARTIALLY_BOUND` leaves its descriptors to the shader promise (a shader that
/// reads one that was not written reads past what the pipeline gave it).
fn bound_descriptor_checks(
    device: &Device,
    bound: &crate::recorder::Bound,
    pipeline: &PipelineRecord,
    rules: &ShaderRules,
) -> Result<()> {
    // What the separate samplers the modules declare do, together: which of them
    // samples which image is not followed, so each sampled image counts them all.
    let separate = pipeline
        .resources
        .iter()
        .filter(|r| r.kind == crate::spirv::ResourceKind::Sampler)
        .fold(0, |bits, r| {
            bits | slot_sampler_bits(bound, r.set, r.binding, None)
        });
    for r in pipeline.resources.iter() {
        written_checks(bound, r, rules[2])?;
        let Some(shape) = r.image else {
            continue;
        };
        let (set, binding) = (r.set, r.binding);
        let Some(Some(images)) = bound.images.get(set as usize) else {
            continue;
        };
        for ((_, element), d) in images.iter().filter(|((b, _), _)| *b == binding) {
            let at = || format!("set {set} binding {binding} element {element}");
            if d.kind == crate::retention::SlotKind::TexelBuffer {
                texel_buffer_checks(device, r, shape, d, &at, rules)?;
                continue;
            }
            if d.kind != crate::retention::SlotKind::Image {
                continue;
            }
            let samplers = if r.kind == crate::spirv::ResourceKind::CombinedImageSampler {
                slot_sampler_bits(bound, set, binding, Some(d.sampler))
            } else {
                separate
            };
            sampled_view_checks(device, r, d, samplers, &at, rules)?;
            written_components(r, d.format, &at, rules[15])?;
            if let Some(wanted) = shape.view_type() {
                if d.view_type != wanted {
                    refuse(
                        rules[0],
                        format!("{}: the shader's image type (Dim {}, Arrayed {}) reads a view of type {wanted:?}, and the descriptor's view is of type {:?}", at(), shape.dim, u32::from(shape.arrayed), d.view_type),
                    )?;
                }
            }
            let aspect = d.sel.aspect;
            let texels = if aspect == vk::ImageAspectFlags::STENCIL {
                2
            } else if aspect == vk::ImageAspectFlags::DEPTH {
                1
            } else {
                crate::formats::color_numeric(d.format).unwrap_or(0)
            };
            if r.ops & crate::spirv::ops::ATOMIC != 0 {
                atomic_checks(device, d, &at, rules[4])?;
            }
            let unknown_storage =
                shape.format == 0 && r.kind == crate::spirv::ResourceKind::StorageImage;
            let needs = [
                (
                    crate::spirv::ops::DREF,
                    vk::FormatFeatureFlags2::SAMPLED_IMAGE_DEPTH_COMPARISON,
                    rules[5],
                    "samples it with depth comparison",
                ),
                (
                    if unknown_storage {
                        crate::spirv::ops::WRITE
                    } else {
                        0
                    },
                    vk::FormatFeatureFlags2::STORAGE_WRITE_WITHOUT_FORMAT,
                    rules[6],
                    "writes it as a storage image of Unknown format",
                ),
                (
                    if unknown_storage {
                        crate::spirv::ops::READ
                    } else {
                        0
                    },
                    vk::FormatFeatureFlags2::STORAGE_READ_WITHOUT_FORMAT,
                    rules[7],
                    "reads it as a storage image of Unknown format",
                ),
            ];
            for (op, feature, vuid, what) in needs {
                if r.ops & op != 0 && !view_features2(device, d)?.contains(feature) {
                    refuse(
                        vuid,
                        format!("{}: the shader {what}, and the features of the view's format {:?} lack {feature:?}", at(), d.format),
                    )?;
                }
            }
            if shape.numeric != 0 && texels != 0 && shape.numeric != texels {
                let name = |n: u32| if n == 1 { "a float" } else { "an integer" };
                refuse(
                    rules[1],
                    format!("{}: the shader's image type has {} sampled type, and the view's format {:?} reads as {} type", at(), name(shape.numeric), d.format, name(texels)),
                )?;
            }
        }
    }
    Ok(())
}

/// What the samplers at binding `binding` of set `set` do ([`crate::retention::sampler_bits`]):
/// the binding's immutable samplers, and `own` (a combined image sampler's) or,
/// without it, every sampler written there.
fn slot_sampler_bits(
    bound: &crate::recorder::Bound,
    set: u32,
    binding: u32,
    own: Option<u8>,
) -> u8 {
    let immutable = bound
        .sets
        .get(set as usize)
        .and_then(Option::as_ref)
        .and_then(|l| l.bindings.iter().find(|b| b.binding == binding))
        .map_or(0, |b| b.immutable_bits);
    let written = own.unwrap_or_else(|| {
        bound
            .images
            .get(set as usize)
            .and_then(Option::as_ref)
            .map_or(0, |list| {
                list.iter()
                    .filter(|((b, _), _)| *b == binding)
                    .fold(0, |bits, (_, d)| bits | d.sampler)
            })
    });
    immutable | written
}

/// Refuses a draw or dispatch whose shaders sample the image view of `d` with
/// samplers (`samplers`, their [`crate::retention::sampler_bits`]) it does not allow:
/// linear filtering or linear mipmaps where the view's format features lack
/// `SAMPLED_IMAGE_FILTER_LINEAR` (04553, 04770); unnormalized coordinates on a view
/// of a type other than 1D or 2D (02702), with implicit-LOD, depth-comparison or
/// projective instructions (02703) or with a LOD bias or offsets (02704); and a
/// Y'CbCr conversion (of the sampler or the view) with instructions other than
/// sampling (06550) or with offsets (06551).
fn sampled_view_checks(
    device: &Device,
    r: &crate::spirv::Resource,
    d: &crate::retention::ImageDescriptor,
    samplers: u8,
    at: &dyn Fn() -> String,
    rules: &ShaderRules,
) -> Result<()> {
    use crate::retention::{
        SAMPLER_LINEAR, SAMPLER_MIPMAP_LINEAR, SAMPLER_UNNORMALIZED, SAMPLER_YCBCR,
    };
    use crate::spirv::ops;
    let sampled = r.ops & ops::SAMPLE != 0;
    if sampled && samplers & (SAMPLER_LINEAR | SAMPLER_MIPMAP_LINEAR) != 0 {
        let linear = view_features2(device, d)?
            .contains(vk::FormatFeatureFlags2::SAMPLED_IMAGE_FILTER_LINEAR);
        if !linear {
            let (vuid, what) = if samplers & SAMPLER_LINEAR != 0 {
                (rules[10], "a LINEAR magFilter or minFilter")
            } else {
                (rules[11], "a LINEAR mipmapMode")
            };
            refuse(
                vuid,
                format!("{}: a sampler with {what} (and no depth comparison) samples the image view, and the features of its format {:?} (for its image's tiling) lack SAMPLED_IMAGE_FILTER_LINEAR", at(), d.format),
            )?;
        }
    }
    if sampled && samplers & SAMPLER_UNNORMALIZED != 0 {
        use vk::ImageViewType as V;
        if matches!(
            d.view_type,
            V::TYPE_3D | V::CUBE | V::TYPE_1D_ARRAY | V::TYPE_2D_ARRAY | V::CUBE_ARRAY
        ) {
            refuse(
                rules[12],
                format!("{}: a sampler with unnormalized coordinates samples an image view of type {:?}", at(), d.view_type),
            )?;
        }
        if r.ops & ops::IMPLICIT_DREF_PROJ != 0 {
            refuse(
                rules[13],
                format!("{}: a sampler with unnormalized coordinates may sample the image with an OpImageSample instruction with ImplicitLod, Dref or Proj in its name", at()),
            )?;
        }
        if r.ops & ops::SAMPLE_BIAS_OFFSET != 0 {
            refuse(
                rules[14],
                format!("{}: a sampler with unnormalized coordinates may sample the image with a LOD bias or an offset", at()),
            )?;
        }
    }
    if d.ycbcr || (sampled && samplers & SAMPLER_YCBCR != 0) {
        if r.ops & ops::NOT_SAMPLE != 0 {
            refuse(
                rules[19],
                format!("{}: the image view or a sampler of it has a sampler Y'CbCr conversion, and the shader uses it with an instruction other than OpImageSample* and OpImageSparseSample*", at()),
            )?;
        }
        if r.ops & ops::OFFSET != 0 {
            refuse(
                rules[20],
                format!("{}: the image view or a sampler of it has a sampler Y'CbCr conversion, and the shader uses it with ConstOffset or Offset", at()),
            )?;
        }
    }
    Ok(())
}

/// Refuses a draw or dispatch whose shaders write texels with fewer components than
/// the view's `format` has (04115 for an image view, 04469 for a texel buffer view).
fn written_components(
    r: &crate::spirv::Resource,
    format: vk::Format,
    at: &dyn Fn() -> String,
    vuid: &'static str,
) -> Result<()> {
    let Some(has) = crate::formats::color_components(format) else {
        return Ok(());
    };
    if r.write_components != 0 && u32::from(r.write_components) < has {
        return refuse(
            vuid,
            format!("{}: the shader writes texels of {} components with OpImageWrite, and the view's format {format:?} has {has}", at(), r.write_components),
        );
    }
    Ok(())
}

/// Refuses a draw or dispatch whose shaders write the texel buffer view of `d` with
/// texels of fewer components than its format has (04469), or write or read it as a
/// storage texel buffer of `Unknown` format where its format's buffer features lack
/// that (07029, 07030).
fn texel_buffer_checks(
    device: &Device,
    r: &crate::spirv::Resource,
    shape: crate::spirv::ImageShape,
    d: &crate::retention::ImageDescriptor,
    at: &dyn Fn() -> String,
    rules: &ShaderRules,
) -> Result<()> {
    use crate::spirv::ops;
    written_components(r, d.format, at, rules[16])?;
    if shape.format != 0 || r.kind != crate::spirv::ResourceKind::StorageTexelBuffer {
        return Ok(());
    }
    let needs = [
        (
            ops::WRITE,
            vk::FormatFeatureFlags2::STORAGE_WRITE_WITHOUT_FORMAT,
            rules[17],
            "writes",
        ),
        (
            ops::READ,
            vk::FormatFeatureFlags2::STORAGE_READ_WITHOUT_FORMAT,
            rules[18],
            "reads",
        ),
    ];
    for (op, feature, vuid, what) in needs {
        if r.ops & op != 0 && !format_features2(device, d.format)?[2].contains(feature) {
            refuse(
                vuid,
                format!("{}: the shader {what} the storage texel buffer with the Unknown format, and the buffer features of the view's format {:?} lack {feature:?}", at(), d.format),
            )?;
        }
    }
    Ok(())
}

/// The images of the current subpass's attachments (those of the dynamic
/// rendering's views), or `None` where the recorder does not know them (a
/// secondary that continues an instance).
fn attachment_images<S: Scope>(recorder: &Recorder<'_, S>) -> Option<Vec<vk::Image>> {
    let instance = recorder.instance.as_ref()?;
    if instance.dynamic {
        return instance.rendering_images.clone();
    }
    let record = instance.record.as_ref()?;
    let used = record.used.get(instance.subpass as usize)?;
    if used.is_empty() {
        return Some(Vec::new());
    }
    if recorder.pass_images.is_empty() {
        return None;
    }
    Some(
        used.iter()
            .filter_map(|a| recorder.pass_images.get(*a as usize).copied())
            .collect(),
    )
}

/// Whether two bindings of memory overlap.
fn overlaps(a: &crate::retention::Binding, b: &crate::retention::Binding) -> bool {
    let ((memory_a, offset_a, size_a), (memory_b, offset_b, size_b)) = (*a, *b);
    memory_a == memory_b
        && offset_a < offset_b.saturating_add(size_b)
        && offset_b < offset_a.saturating_add(size_a)
}

/// A draw's checks of the render pass instance's attachments as its shaders reach
/// them: each input attachment variable's `InputAttachmentIndex` names a used input
/// attachment of the current subpass (07468), and its descriptor views the image of
/// that attachment in its format (07469); no descriptor the shaders declare reaches
/// the memory of an attachment of the subpass (06537 where the shader may write it,
/// 06538 otherwise: which commands of the subpass write each attachment is not
/// followed); and blending only on color attachments whose format features have
/// `COLOR_ATTACHMENT_BLEND` (04727). Where the attachments are not known (a
/// secondary continuing an instance without its framebuffer), a draw whose shaders
/// declare a descriptor of memory is refused.
fn attachment_checks<S: Scope>(recorder: &Recorder<'_, S>, rules: &AttachmentRules) -> Result<()> {
    use crate::retention::SlotKind;
    use crate::spirv::ResourceKind as K;
    let (Some(instance), Some(pipeline)) = (&recorder.instance, &recorder.bound[0].pipeline) else {
        return Ok(());
    };
    let bound = &recorder.bound[0];
    let live = recorder.device().live();
    let slots = |r: &crate::spirv::Resource| {
        let binding = r.binding;
        bound
            .images
            .get(r.set as usize)
            .and_then(Option::as_ref)
            .into_iter()
            .flat_map(|list| list.iter())
            .filter(move |((b, _), _)| *b == binding)
            .map(|(_, d)| *d)
    };
    let images = attachment_images(recorder);
    for r in pipeline.resources.iter() {
        if r.kind == K::InputAttachment {
            let inputs = instance
                .record
                .as_ref()
                .filter(|_| !instance.dynamic)
                .and_then(|rec| rec.inputs.get(instance.subpass as usize));
            let attachment = match (r.input_index, inputs) {
                (Some(i), Some(inputs)) => inputs
                    .get(i as usize)
                    .map(|(a, _)| *a)
                    .filter(|a| *a != vk::ATTACHMENT_UNUSED),
                _ => None,
            };
            let Some(attachment) = attachment else {
                refuse(
                    rules[0],
                    format!("set {} binding {}: the shader reads an input attachment (InputAttachmentIndex {:?}) that the current subpass does not have", r.set, r.binding, r.input_index),
                )?;
                continue;
            };
            let format = instance
                .record
                .as_ref()
                .and_then(|rec| rec.attachments.get(attachment as usize))
                .map(|a| a.0);
            let image = recorder.pass_images.get(attachment as usize).copied();
            for d in slots(r).filter(|d| d.kind == SlotKind::Image) {
                if Some(d.format) != format || image.is_some_and(|i| i != d.image) {
                    refuse(
                        rules[1],
                        format!("set {} binding {}: the input attachment's view (format {:?}) is not compatible with attachment {attachment} of the framebuffer (format {format:?})", r.set, r.binding, d.format),
                    )?;
                }
            }
            continue;
        }
        for d in slots(r) {
            let object = match d.kind {
                SlotKind::Image => live.binding(d.image),
                SlotKind::TexelBuffer | SlotKind::Buffer => live.binding(d.buffer),
                SlotKind::Sampler => continue,
            };
            let writes = match r.kind {
                K::StorageBuffer => true,
                K::StorageImage | K::StorageTexelBuffer => {
                    r.ops & (crate::spirv::ops::WRITE | crate::spirv::ops::ATOMIC) != 0
                }
                _ => false,
            };
            let vuid = if writes { rules[2] } else { rules[3] };
            let Some(images) = &images else {
                return refuse(
                    vuid,
                    format!("set {} binding {}: the render pass instance's attachments are not known in this secondary command buffer, so a descriptor of memory may alias one", r.set, r.binding),
                );
            };
            for a in images {
                let same = d.kind == SlotKind::Image && d.image == *a;
                let aliased = match (&object, live.binding(*a)) {
                    (Some(o), Some(b)) => overlaps(o, &b),
                    _ => false,
                };
                if same || aliased {
                    refuse(
                        vuid,
                        format!("set {} binding {}: the descriptor reaches the memory of an attachment of the current subpass (image 0x{:x}), which the shader {} other than as an attachment", r.set, r.binding, a.as_raw(), if writes { "may write" } else { "reads" }),
                    )?;
                }
            }
        }
    }
    blend_checks(recorder, instance, pipeline, rules[4])
}

/// Refuses a draw whose bound pipeline blends into a color attachment whose
/// format's features lack `COLOR_ATTACHMENT_BLEND` (unless it discards
/// rasterization). The features are those of optimal tiling, and of linear tiling
/// too where an attachment's image is linear or the attachments are not known.
fn blend_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    instance: &crate::recorder::PassInstance,
    pipeline: &PipelineRecord,
    vuid: &'static str,
) -> Result<()> {
    if pipeline.blend == 0 || draw_values(recorder, pipeline).discard {
        return Ok(());
    }
    let formats: Vec<vk::Format> = if instance.dynamic {
        instance
            .rendering
            .as_ref()
            .map_or_else(Vec::new, |r| r.colors.clone())
    } else {
        instance
            .record
            .as_ref()
            .and_then(|r| r.color_formats.get(instance.subpass as usize).cloned())
            .unwrap_or_default()
    };
    let device = recorder.device();
    let live = device.live();
    let linear = attachment_images(recorder).is_none_or(|images| {
        images.iter().any(|i| {
            live.image(*i)
                .is_some_and(|r| r.tiling == vk::ImageTiling::LINEAR)
        })
    });
    for (i, format) in formats.iter().enumerate() {
        if i >= 32 || pipeline.blend & (1 << i) == 0 || *format == vk::Format::UNDEFINED {
            continue;
        }
        let props = live.format_properties(device.parent(), *format)?;
        let mut features = props.optimal_tiling_features;
        if linear {
            features &= props.linear_tiling_features;
        }
        if !features.contains(vk::FormatFeatureFlags::COLOR_ATTACHMENT_BLEND) {
            refuse(
                vuid,
                format!("the bound pipeline blends into color attachment {i}, and the features of its format {format:?} lack COLOR_ATTACHMENT_BLEND"),
            )?;
        }
    }
    Ok(())
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
    let size = buffer
        .into()
        .and_then(|b| recorder.device().live().buffer(b.raw()))
        .map(|r| r.size);
    recorder.bound[0].index = size.map(|size| (size, offset, index_type));
}

/// A direct indexed draw's index count, first index, first instance, instance
/// count and vertex offset, with the rules of the indices read inside the index
/// buffer (07825), of the last instance in a multiview instance (02688) and of the
/// vertices fetched inside the vertex buffers (02721).
pub(crate) type IndexedRange = (
    u32,
    u32,
    u32,
    u32,
    i32,
    &'static str,
    &'static str,
    &'static str,
);

/// Refuses an indexed draw that could fetch vertices past a bound vertex buffer.
/// The indices are the index buffer's contents, which the device reads and the host
/// does not know, so the vertices are those of every index the index type holds (an
/// index buffer any safe program can fill); a device with `robustBufferAccess`
/// enabled keeps every fetch inside the bound range instead, and nothing is refused.
fn indexed_fetch_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    ty: vk::IndexType,
    vertex_offset: i32,
    instances: (u32, u32),
    vuid: &'static str,
) -> Result<()> {
    let robust = recorder
        .device()
        .live()
        .with_features(|f| f.v10.robust_buffer_access);
    let reads = recorder.bound[0]
        .pipeline
        .as_ref()
        .is_some_and(|p| !p.vertex_reads.is_empty());
    if robust == vk::TRUE || !reads {
        return Ok(());
    }
    let largest: u64 = match ty {
        vk::IndexType::UINT16 => u64::from(u16::MAX),
        vk::IndexType::UINT8_EXT => u64::from(u8::MAX),
        _ => u64::from(u32::MAX),
    };
    let Ok(first) = u64::try_from(vertex_offset) else {
        return refuse(
            vuid,
            format!("the draw's vertex offset ({vertex_offset}) is negative, so an index it reads can name a vertex before the bound vertex buffers; enable robustBufferAccess to draw with it"),
        );
    };
    vertex_fetch_checks(recorder, (first, largest + 1), instances, vuid).map_err(|e| match e {
        Error::Validation { vuid, message } => Error::Validation {
            vuid,
            message: format!("{message}: an indexed draw may fetch any vertex its {ty:?} indices name (the index buffer's contents are not known on the host); enable robustBufferAccess, or bind vertex buffers that hold every such vertex"),
        },
        other => other,
    })
}

/// An indexed draw: a pipeline and its sets bound ([`bound_pipeline_checks`]), an index
/// buffer bound (07312), and, for a direct draw (`range`: index count, first index and
/// the rule), the indices it reads inside that buffer. Whether robustBufferAccess2 is
/// enabled is not known here, so the range is checked whatever it is.
pub(crate) fn indexed_draw_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    pipeline_vuid: &'static str,
    sets_vuid: &'static str,
    bound_vuid: &'static str,
    vertex_vuid: &'static str,
    range: Option<IndexedRange>,
    draw: &DrawRules,
) -> Result<()> {
    draw_checks(recorder, pipeline_vuid, sets_vuid, vertex_vuid, None, draw)?;
    let Some((size, offset, ty)) = recorder.bound[0].index else {
        return refuse(bound_vuid, "no index buffer is bound".into());
    };
    let Some((count, first, first_instance, instance_count, vertex_offset, vuid, multiview, fetch)) =
        range
    else {
        return Ok(());
    };
    multiview_instances(recorder, first_instance, instance_count, multiview)?;
    let index_size: u64 = match ty {
        vk::IndexType::UINT16 => 2,
        vk::IndexType::UINT32 => 4,
        vk::IndexType::UINT8_EXT => 1,
        _ => return Ok(()),
    };
    let end = index_size * (u64::from(first) + u64::from(count)) + offset;
    if end > size {
        refuse(
            vuid,
            format!("the draw reads indices up to byte {end} of an index buffer of {size} bytes (firstIndex = {first}, indexCount = {count}, offset = {offset})"),
        )?;
    }
    indexed_fetch_checks(
        recorder,
        ty,
        vertex_offset,
        (first_instance, instance_count),
        fetch,
    )
}

/// The VUIDs of one bind command's rules, which `vkBindBufferMemory`,
/// `vkBindImageMemory` and their `*2` infos state alike.
struct BindRules {
    /// Not bound before.
    bound: &'static str,
    /// Not created sparse.
    sparse: &'static str,
    /// `memoryOffset` inside the memory.
    offset: &'static str,
    /// The memory's type among the resource's `memoryTypeBits`.
    type_bits: &'static str,
    /// `memoryOffset` a multiple of the resource's `alignment`.
    alignment: &'static str,
    /// The resource's `size` fits in the memory past `memoryOffset`.
    size: &'static str,
}

const BIND_BUFFER: BindRules = BindRules {
    bound: "VUID-vkBindBufferMemory-buffer-07459",
    sparse: "VUID-vkBindBufferMemory-buffer-01030",
    offset: "VUID-vkBindBufferMemory-memoryOffset-01031",
    type_bits: "VUID-vkBindBufferMemory-memory-01035",
    alignment: "VUID-vkBindBufferMemory-memoryOffset-01036",
    size: "VUID-vkBindBufferMemory-size-01037",
};

const BIND_BUFFER2: BindRules = BindRules {
    bound: "VUID-VkBindBufferMemoryInfo-buffer-07459",
    sparse: "VUID-VkBindBufferMemoryInfo-buffer-01030",
    offset: "VUID-VkBindBufferMemoryInfo-memoryOffset-01031",
    type_bits: "VUID-VkBindBufferMemoryInfo-memory-01035",
    alignment: "VUID-VkBindBufferMemoryInfo-memoryOffset-01036",
    size: "VUID-VkBindBufferMemoryInfo-size-01037",
};

const BIND_IMAGE: BindRules = BindRules {
    bound: "VUID-vkBindImageMemory-image-07460",
    sparse: "VUID-vkBindImageMemory-image-01045",
    offset: "VUID-vkBindImageMemory-memoryOffset-01046",
    type_bits: "VUID-vkBindImageMemory-memory-01047",
    alignment: "VUID-vkBindImageMemory-memoryOffset-01048",
    size: "VUID-vkBindImageMemory-size-01049",
};

const BIND_IMAGE2: BindRules = BindRules {
    bound: "VUID-VkBindImageMemoryInfo-image-07460",
    sparse: "VUID-VkBindImageMemoryInfo-image-01045",
    offset: "VUID-VkBindImageMemoryInfo-memoryOffset-01046",
    type_bits: "VUID-VkBindImageMemoryInfo-pNext-01615",
    alignment: "VUID-VkBindImageMemoryInfo-pNext-01616",
    size: "VUID-VkBindImageMemoryInfo-pNext-01617",
};

/// The sparse binding, residency and aliased bits, the same in buffer and image
/// create flags.
const SPARSE_FLAGS: u32 = 0x1 | 0x2 | 0x4;

/// Checks one binding of `memory` at `offset` to a resource: `record` is what the
/// device recorded of it (whether bound, its create flags), `reqs` its memory
/// requirements. A memory the wrappers did not allocate has no record and is not
/// checked against.
fn check_bind(
    device: &Device,
    rules: &BindRules,
    record: Option<(bool, u32)>,
    reqs: vk::MemoryRequirements,
    memory: vk::DeviceMemory,
    offset: vk::DeviceSize,
) -> Result<()> {
    if let Some((bound, flags)) = record {
        if bound {
            refuse(rules.bound, "the object is already bound to memory".into())?;
        }
        if flags & SPARSE_FLAGS != 0 {
            refuse(
                rules.sparse,
                format!("the object was created with sparse flags ({flags:#x})"),
            )?;
        }
    }
    let Some((size, type_index)) = device
        .live()
        .memory(memory, |m| (m.size, m.memory_type_index))
    else {
        return Ok(());
    };
    if offset >= size {
        refuse(
            rules.offset,
            format!("memoryOffset must be less than the size of memory (memoryOffset = {offset}, size = {size})"),
        )?;
    }
    if reqs.memory_type_bits & (1u32.checked_shl(type_index).unwrap_or(0)) == 0 {
        refuse(
            rules.type_bits,
            format!(
                "memory's type {type_index} is not among the object's memoryTypeBits ({:#x})",
                reqs.memory_type_bits
            ),
        )?;
    }
    if reqs.alignment != 0 && offset % reqs.alignment != 0 {
        refuse(
            rules.alignment,
            format!(
                "memoryOffset must be a multiple of the object's alignment (memoryOffset = {offset}, alignment = {})",
                reqs.alignment
            ),
        )?;
    }
    if reqs.size > size.saturating_sub(offset) {
        refuse(
            rules.size,
            format!(
                "the object needs {} bytes, and memory has {} past memoryOffset (size = {size}, memoryOffset = {offset})",
                reqs.size,
                size.saturating_sub(offset)
            ),
        )?;
    }
    Ok(())
}

/// The buffer's memory requirements, from the driver.
fn buffer_requirements(device: &Device, buffer: vk::Buffer) -> vk::MemoryRequirements {
    let mut reqs = vk::MemoryRequirements::default();
    // SAFETY: `buffer` is a live buffer of `device` (a wrapper, or a safe info's
    // member that a wrapper filled), and `reqs` is written storage.
    unsafe {
        (device.fns().fp_v1_0().get_buffer_memory_requirements)(device.raw(), buffer, &mut reqs)
    };
    reqs
}

/// The image's memory requirements, from the driver.
fn image_requirements(device: &Device, image: vk::Image) -> vk::MemoryRequirements {
    let mut reqs = vk::MemoryRequirements::default();
    // SAFETY: as in `buffer_requirements`.
    unsafe {
        (device.fns().fp_v1_0().get_image_memory_requirements)(device.raw(), image, &mut reqs)
    };
    reqs
}

/// The rules of what an allocation asked for that a bind must match, by VUID.
struct KindRules {
    requires_dedicated: &'static str,
    dedicated: &'static str,
    protected: &'static str,
    unprotected: &'static str,
    export: &'static str,
    device_address: Option<&'static str>,
}

/// The object a bind gives memory to, as [`check_memory_kind`] needs it.
struct Bound {
    ty: vk::ObjectType,
    raw: u64,
    protected: bool,
    external: vk::ExternalMemoryHandleTypeFlags,
    device_address: bool,
}

/// Refuses memory of the wrong kind for the object: not dedicated to it where it
/// requires (or the memory is dedicated to another object), protected memory for an
/// unprotected object or the reverse, exportable memory of no handle type the
/// object names, or memory without a device address for a buffer with one.
fn check_memory_kind(
    device: &Device,
    rules: &KindRules,
    object: &Bound,
    memory: vk::DeviceMemory,
    offset: vk::DeviceSize,
) -> Result<()> {
    let Some((asked, type_index)) = device
        .live()
        .memory(memory, |m| (m.asked, m.memory_type_index))
    else {
        return Ok(());
    };
    let mine = asked.dedicated == Some((object.ty, object.raw));
    if dedicated_required(device, object) && !mine {
        refuse(
            rules.requires_dedicated,
            "the object requires a dedicated allocation (VkMemoryDedicatedRequirements), and \
             the memory was not allocated with a VkMemoryDedicatedAllocateInfo naming it"
                .into(),
        )?;
    }
    if asked.dedicated.is_some_and(|(ty, _)| ty == object.ty) && (!mine || offset != 0) {
        refuse(
            rules.dedicated,
            format!(
                "the memory is dedicated to another object, or bound at an offset other than \
                 zero (memoryOffset = {offset})"
            ),
        )?;
    }
    let physical = device.parent();
    let types = physical.get_memory_properties();
    let protected_type = types
        .memory_types_as_slice()
        .get(type_index as usize)
        .is_some_and(|t| {
            t.property_flags
                .contains(vk::MemoryPropertyFlags::PROTECTED)
        });
    if object.protected && !protected_type {
        refuse(
            rules.protected,
            "a protected object must be bound to memory of a protected type".into(),
        )?;
    }
    if !object.protected && protected_type {
        refuse(
            rules.unprotected,
            "an unprotected object must not be bound to memory of a protected type".into(),
        )?;
    }
    if !asked.export.is_empty() && !asked.export.intersects(object.external) {
        refuse(
            rules.export,
            format!(
                "the memory was allocated exportable as {:?}, which must include one of the \
                 handle types the object was created with ({:?})",
                asked.export, object.external
            ),
        )?;
    }
    if let Some(vuid) = rules.device_address {
        let enabled = device.live().with_features(|f| f.v12.buffer_device_address) == vk::TRUE;
        if enabled && object.device_address && !asked.device_address {
            refuse(
                vuid,
                "the buffer was created with VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, so its \
                 memory must have been allocated with VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT"
                    .into(),
            )?;
        }
    }
    Ok(())
}

/// Whether the driver requires the object to have a dedicated allocation (a Vulkan
/// 1.1 query; never below it).
fn dedicated_required(device: &Device, object: &Bound) -> bool {
    if !device.parent().parent().exts().version(1) {
        return false;
    }
    let mut dedicated = vk::MemoryDedicatedRequirements::default();
    let mut reqs = vk::MemoryRequirements2::default().push_next(&mut dedicated);
    // SAFETY: the object is a live buffer or image of `device` (a wrapper's), and
    // the chain is local.
    unsafe {
        if object.ty == vk::ObjectType::BUFFER {
            let info = vk::BufferMemoryRequirementsInfo2::default()
                .buffer(vk::Buffer::from_raw(object.raw));
            device
                .fns()
                .get_buffer_memory_requirements2(&info, &mut reqs);
        } else {
            let info =
                vk::ImageMemoryRequirementsInfo2::default().image(vk::Image::from_raw(object.raw));
            device
                .fns()
                .get_image_memory_requirements2(&info, &mut reqs);
        }
    }
    let _ = reqs;
    dedicated.requires_dedicated_allocation == vk::TRUE
}

const KIND_BUFFER: KindRules = KindRules {
    requires_dedicated: "VUID-vkBindBufferMemory-buffer-01444",
    dedicated: "VUID-vkBindBufferMemory-memory-01508",
    protected: "VUID-vkBindBufferMemory-None-01898",
    unprotected: "VUID-vkBindBufferMemory-None-01899",
    export: "VUID-vkBindBufferMemory-memory-02726",
    device_address: Some("VUID-vkBindBufferMemory-bufferDeviceAddress-03339"),
};

const KIND_IMAGE: KindRules = KindRules {
    requires_dedicated: "VUID-vkBindImageMemory-image-01445",
    dedicated: "VUID-vkBindImageMemory-memory-01509",
    protected: "VUID-vkBindImageMemory-None-01901",
    unprotected: "VUID-vkBindImageMemory-None-01902",
    export: "VUID-vkBindImageMemory-memory-02728",
    device_address: None,
};

/// Refuses a binding that would give the buffer memory it cannot live in: bound
/// before, sparse, or memory of the wrong type, too small past the offset, or at a
/// misaligned offset.
pub(crate) fn bind_buffer_memory_checks(
    device: &Device,
    buffer: &Buffer,
    memory: &DeviceMemory,
    memory_offset: vk::DeviceSize,
) -> Result<()> {
    if let Some(r) = device.live().buffer(buffer.raw()) {
        let object = Bound {
            ty: vk::ObjectType::BUFFER,
            raw: buffer.raw().as_raw(),
            protected: r.flags.contains(vk::BufferCreateFlags::PROTECTED),
            external: r.external,
            device_address: r
                .usage
                .contains(vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS),
        };
        check_memory_kind(device, &KIND_BUFFER, &object, memory.raw(), memory_offset)?;
    }
    let record = device
        .live()
        .buffer(buffer.raw())
        .map(|r| (r.bound, r.flags.as_raw()));
    let reqs = buffer_requirements(device, buffer.raw());
    check_bind(
        device,
        &BIND_BUFFER,
        record,
        reqs,
        memory.raw(),
        memory_offset,
    )
}

/// As [`bind_buffer_memory_checks`], for each info; a buffer named twice is bound
/// twice.
pub(crate) fn bind_buffer_memory2_checks(
    device: &Device,
    bind_infos: &[BindBufferMemoryInfo<'_>],
) -> Result<()> {
    for (i, info) in bind_infos.iter().enumerate() {
        if bind_infos[..i].iter().any(|b| b.buffer == info.buffer) {
            refuse(
                BIND_BUFFER2.bound,
                format!("pBindInfos[{i}] binds a buffer an earlier info binds"),
            )?;
        }
        let record = device
            .live()
            .buffer(info.buffer)
            .map(|r| (r.bound, r.flags.as_raw()));
        let reqs = buffer_requirements(device, info.buffer);
        check_bind(
            device,
            &BIND_BUFFER2,
            record,
            reqs,
            info.memory,
            info.memory_offset,
        )?;
    }
    Ok(())
}

/// As [`bind_buffer_memory_checks`], for an image; a disjoint image binds its
/// planes through `bind_image_memory2` (`VUID-vkBindImageMemory-image-01608`).
pub(crate) fn bind_image_memory_checks(
    device: &Device,
    image: &Image,
    memory: &DeviceMemory,
    memory_offset: vk::DeviceSize,
) -> Result<()> {
    let record = device.live().image(image.raw());
    if record.is_some_and(|r| r.flags.contains(vk::ImageCreateFlags::DISJOINT)) {
        refuse(
            "VUID-vkBindImageMemory-image-01608",
            "the image was created with VK_IMAGE_CREATE_DISJOINT_BIT; bind its planes with bind_image_memory2".into(),
        )?;
    }
    if let Some(r) = record {
        let object = Bound {
            ty: vk::ObjectType::IMAGE,
            raw: image.raw().as_raw(),
            protected: r.flags.contains(vk::ImageCreateFlags::PROTECTED),
            external: r.external,
            device_address: false,
        };
        check_memory_kind(device, &KIND_IMAGE, &object, memory.raw(), memory_offset)?;
    }
    let reqs = image_requirements(device, image.raw());
    check_bind(
        device,
        &BIND_IMAGE,
        record.map(|r| (r.bound, r.flags.as_raw())),
        reqs,
        memory.raw(),
        memory_offset,
    )
}

/// As [`bind_image_memory_checks`], for each info that binds a whole image; an info
/// that binds one plane (a chained `VkBindImagePlaneMemoryInfo`) is checked only
/// for the image being disjoint, and its plane's requirements stay the caller's.
pub(crate) fn bind_image_memory2_checks(
    device: &Device,
    bind_infos: &[BindImageMemoryInfo<'_>],
) -> Result<()> {
    for (i, info) in bind_infos.iter().enumerate() {
        let record = device.live().image(info.image);
        // SAFETY: the safe struct chains only structs pushed through `push_next`,
        // each a valid Vulkan struct that starts with sType and pNext.
        let plane = unsafe { chains(info.p_next, vk::StructureType::BIND_IMAGE_PLANE_MEMORY_INFO) };
        if plane {
            if record.is_some_and(|r| !r.flags.contains(vk::ImageCreateFlags::DISJOINT)) {
                refuse(
                    "VUID-VkBindImageMemoryInfo-pNext-01618",
                    format!("pBindInfos[{i}] binds a plane of an image created without VK_IMAGE_CREATE_DISJOINT_BIT"),
                )?;
            }
            continue;
        }
        if bind_infos[..i].iter().any(|b| b.image == info.image) {
            refuse(
                BIND_IMAGE2.bound,
                format!("pBindInfos[{i}] binds an image an earlier info binds"),
            )?;
        }
        let reqs = image_requirements(device, info.image);
        check_bind(
            device,
            &BIND_IMAGE2,
            record.map(|r| (r.bound, r.flags.as_raw())),
            reqs,
            info.memory,
            info.memory_offset,
        )?;
    }
    Ok(())
}

/// Whether a `pNext` chain holds a struct of type `s_type`.
///
/// # Safety
///
/// Every node of the chain is a live Vulkan struct that starts with sType and
/// pNext.
unsafe fn chains(mut next: *const std::ffi::c_void, s_type: vk::StructureType) -> bool {
    // SAFETY: the caller promises a chain of valid structs.
    while let Some(node) = unsafe { next.cast::<vk::BaseInStructure<'_>>().as_ref() } {
        if node.s_type == s_type {
            return true;
        }
        next = node.p_next.cast();
    }
    false
}

/// The Image Creation Limits of a create info: what
/// `vkGetPhysicalDeviceImageFormatProperties(2)` says of its format, type, tiling,
/// usage and flags, with the chained structs that narrow them (a format list, a
/// stencil usage, each external handle type), intersected; `None` where a query
/// says the combination is not supported.
fn image_creation_limits(
    device: &Device,
    info: &vk::ImageCreateInfo<'_>,
) -> Option<vk::ImageFormatProperties> {
    let physical = device.parent();
    let instance = physical.parent();
    let mut list = None;
    let mut stencil = None;
    let mut handles = vk::ExternalMemoryHandleTypeFlags::empty();
    let mut next = info.p_next.cast::<vk::BaseInStructure<'_>>();
    // SAFETY: the safe struct chains only structs pushed through `push_next`, each a
    // valid Vulkan struct that starts with sType and pNext.
    while let Some(node) = unsafe { next.as_ref() } {
        match node.s_type {
            vk::StructureType::IMAGE_FORMAT_LIST_CREATE_INFO => {
                // SAFETY: the sType says which struct this is.
                list = Some(unsafe { *next.cast::<vk::ImageFormatListCreateInfo<'_>>() });
            }
            vk::StructureType::IMAGE_STENCIL_USAGE_CREATE_INFO => {
                // SAFETY: as above.
                stencil = Some(unsafe { *next.cast::<vk::ImageStencilUsageCreateInfo<'_>>() });
            }
            vk::StructureType::EXTERNAL_MEMORY_IMAGE_CREATE_INFO => {
                // SAFETY: as above.
                handles =
                    unsafe { (*next.cast::<vk::ExternalMemoryImageCreateInfo<'_>>()).handle_types };
            }
            _ => {}
        }
        next = node.p_next;
    }
    let narrowed = list.is_some() || stencil.is_some() || !handles.is_empty();
    if !narrowed || !instance.exts().version(1) {
        // SAFETY: a live physical device of its instance; the values come from a safe
        // create info (the implicit checks passed).
        return unsafe {
            instance.fns().get_physical_device_image_format_properties(
                physical.raw(),
                info.format,
                info.image_type,
                info.tiling,
                info.usage,
                info.flags,
            )
        }
        .ok();
    }
    // Each handle type is its own query; no handle type is one query without one.
    let mut each: Vec<Option<vk::ExternalMemoryHandleTypeFlags>> = (0..32)
        .map(|b| vk::ExternalMemoryHandleTypeFlags::from_raw(1 << b))
        .filter(|h| handles.contains(*h))
        .map(Some)
        .collect();
    if each.is_empty() {
        each.push(None);
    }
    let mut limits: Option<vk::ImageFormatProperties> = None;
    for handle in each {
        let mut format_info = vk::PhysicalDeviceImageFormatInfo2::default()
            .format(info.format)
            .ty(info.image_type)
            .tiling(info.tiling)
            .usage(info.usage)
            .flags(info.flags);
        // The copies join this query's chain instead of the create info's.
        let mut list = list.map(|mut l| {
            l.p_next = std::ptr::null();
            l
        });
        let mut stencil = stencil.map(|mut s| {
            s.p_next = std::ptr::null();
            s
        });
        let mut external =
            handle.map(|h| vk::PhysicalDeviceExternalImageFormatInfo::default().handle_type(h));
        if let Some(l) = list.as_mut() {
            format_info = format_info.push_next(l);
        }
        if let Some(s) = stencil.as_mut() {
            format_info = format_info.push_next(s);
        }
        if let Some(e) = external.as_mut() {
            format_info = format_info.push_next(e);
        }
        let mut out = vk::ImageFormatProperties2::default();
        // SAFETY: a live physical device of a Vulkan 1.1 instance; the chain holds
        // copies of the create info's own structs, each with its pNext reset.
        unsafe {
            instance.fns().get_physical_device_image_format_properties2(
                physical.raw(),
                &format_info,
                &mut out,
            )
        }
        .ok()?;
        let p = out.image_format_properties;
        limits = Some(match limits {
            None => p,
            Some(l) => vk::ImageFormatProperties {
                max_extent: vk::Extent3D {
                    width: l.max_extent.width.min(p.max_extent.width),
                    height: l.max_extent.height.min(p.max_extent.height),
                    depth: l.max_extent.depth.min(p.max_extent.depth),
                },
                max_mip_levels: l.max_mip_levels.min(p.max_mip_levels),
                max_array_layers: l.max_array_layers.min(p.max_array_layers),
                sample_counts: l.sample_counts & p.sample_counts,
                max_resource_size: l.max_resource_size.min(p.max_resource_size),
            },
        });
    }
    limits
}

/// Refuses an image that its format cannot have: a combination of format, type,
/// tiling, usage and flags the device does not support, an extent, level count,
/// layer count or sample count past the Image Creation Limits, or more levels than
/// the extent has.
pub(crate) fn create_image_checks(
    device: &Device,
    create_info: &ImageCreateInfo<'_>,
) -> Result<()> {
    image_create_rules(device, create_info)?;
    let info = create_info.as_raw();
    let e = info.extent;
    let longest = e.width.max(e.height).max(e.depth).max(1);
    let chain = 32 - longest.leading_zeros();
    if info.mip_levels > chain {
        refuse(
            "VUID-VkImageCreateInfo-mipLevels-00958",
            format!(
                "mipLevels must be at most the {chain} levels of a full chain for extent {}x{}x{} (mipLevels = {})",
                e.width, e.height, e.depth, info.mip_levels
            ),
        )?;
    }
    let Some(limits) = image_creation_limits(device, info) else {
        return refuse(
            "VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251",
            format!(
                "the device supports no image of format {:?}, type {:?}, tiling {:?}, usage {:?} and flags {:?}",
                info.format, info.image_type, info.tiling, info.usage, info.flags
            ),
        );
    };
    let m = limits.max_extent;
    for (vuid, dim, value, max) in [
        (
            "VUID-VkImageCreateInfo-extent-02252",
            "width",
            e.width,
            m.width,
        ),
        (
            "VUID-VkImageCreateInfo-extent-02253",
            "height",
            e.height,
            m.height,
        ),
        (
            "VUID-VkImageCreateInfo-extent-02254",
            "depth",
            e.depth,
            m.depth,
        ),
    ] {
        if value > max {
            refuse(
                vuid,
                format!("extent.{dim} must be at most the format's {max} (extent.{dim} = {value})"),
            )?;
        }
    }
    if info.mip_levels > limits.max_mip_levels {
        refuse(
            "VUID-VkImageCreateInfo-mipLevels-02255",
            format!(
                "mipLevels must be at most the format's {} (mipLevels = {})",
                limits.max_mip_levels, info.mip_levels
            ),
        )?;
    }
    if info.array_layers > limits.max_array_layers {
        refuse(
            "VUID-VkImageCreateInfo-arrayLayers-02256",
            format!(
                "arrayLayers must be at most the format's {} (arrayLayers = {})",
                limits.max_array_layers, info.array_layers
            ),
        )?;
    }
    if !limits.sample_counts.contains(info.samples) {
        refuse(
            "VUID-VkImageCreateInfo-samples-02258",
            format!(
                "samples must be one of the format's {:?} (samples = {:?})",
                limits.sample_counts, info.samples
            ),
        )?;
    }
    Ok(())
}

/// The byte just past the last one that a buffer-image copy region reaches in its
/// buffer, by Buffer and Image Addressing: rows of `bufferRowLength` (or the
/// extent's width) texels, `bufferImageHeight` (or its height) rows a slice, one
/// slice per depth and per layer, in texel blocks of the aspect's size. `None` when
/// the format or aspect is not one the registry describes (an aspect mask of more
/// than one aspect), which another rule refuses.
#[allow(clippy::too_many_arguments)]
fn buffer_image_end(
    format: vk::Format,
    aspect: vk::ImageAspectFlags,
    offset: vk::DeviceSize,
    row_length: u32,
    image_height: u32,
    extent: vk::Extent3D,
    layers: u32,
) -> Option<u64> {
    let (bytes, [bw, bh, bd]) = crate::formats::block(format, aspect)?;
    let blocks = |texels: u32, per: u32| u64::from(texels).div_ceil(u64::from(per.max(1)));
    let row = blocks(
        if row_length == 0 {
            extent.width
        } else {
            row_length
        },
        bw,
    );
    let height = blocks(
        if image_height == 0 {
            extent.height
        } else {
            image_height
        },
        bh,
    );
    let (w, h) = (blocks(extent.width, bw), blocks(extent.height, bh));
    let slices = blocks(extent.depth, bd).saturating_mul(u64::from(layers));
    if w == 0 || h == 0 || slices == 0 {
        return Some(offset);
    }
    // A sum past u64 is past any buffer.
    let last_row = (slices - 1)
        .checked_mul(height)
        .and_then(|r| r.checked_add(h - 1))?;
    let texels = last_row.checked_mul(row).and_then(|t| t.checked_add(w));
    Some(
        texels
            .and_then(|t| t.checked_mul(u64::from(bytes)))
            .and_then(|b| b.checked_add(offset))
            .unwrap_or(u64::MAX),
    )
}

/// Refuses a buffer-image copy whose regions reach past the buffer's end (the
/// buffer's size and the image's format as the device recorded them).
#[allow(clippy::too_many_arguments)]
fn check_buffer_image_regions(
    device: &Device,
    buffer: vk::Buffer,
    image: vk::Image,
    regions: impl Iterator<Item = (u64, u32, u32, vk::ImageSubresourceLayers, vk::Extent3D)>,
    vuid: &'static str,
) -> Result<()> {
    let (Some(b), Some(i)) = (device.live().buffer(buffer), device.live().image(image)) else {
        return Ok(());
    };
    for (n, (offset, row_length, image_height, subresource, extent)) in regions.enumerate() {
        let end = buffer_image_end(
            i.format,
            subresource.aspect_mask,
            offset,
            row_length,
            image_height,
            extent,
            subresource.layer_count,
        );
        if let Some(end) = end.filter(|e| *e > b.size) {
            refuse(
                vuid,
                format!(
                    "pRegions[{n}] reaches byte {end} of a buffer of {} bytes (bufferOffset = {offset}, bufferRowLength = {row_length}, bufferImageHeight = {image_height}, imageExtent = {}x{}x{}, layerCount = {})",
                    b.size, extent.width, extent.height, extent.depth, subresource.layer_count
                ),
            )?;
        }
    }
    Ok(())
}

/// The checks of a copy between `buffer` and `image` that memory safety needs:
/// each region against the image (its type, format, texel blocks, subresources,
/// the queue family's granularity), protected memory, the overlap of the two
/// bindings, and the buffer's end (`range_vuid`).
fn check_buffer_image_copy<S: Scope>(
    recorder: &Recorder<'_, S>,
    (buffer, image): (vk::Buffer, vk::Image),
    regions: &[copies::Region],
    (rules, range_vuid, to_image): (&copies::Rules, &'static str, bool),
) -> Result<()> {
    let device = recorder.device();
    let family = pool_family(recorder);
    if let Some(record) = device.live().image(image) {
        copies::check_regions(device, &record, family, regions.iter().copied(), rules)?;
    }
    copies::check_protection(device, family, (buffer, image), to_image, rules)?;
    copies::check_overlap(device, (buffer, image), regions, rules)?;
    check_buffer_image_regions(
        device,
        buffer,
        image,
        regions.iter().map(|r| {
            (
                r.offset,
                r.row_length,
                r.image_height,
                r.subresource,
                r.extent,
            )
        }),
        range_vuid,
    )
}

/// Refuses a copy from a buffer into an image that breaks a rule of its regions.
pub(crate) fn cmd_copy_buffer_to_image_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_buffer: &Buffer,
    dst_image: &Image,
    regions: &[vk::BufferImageCopy],
) -> Result<()> {
    let regions: SmallVec<[copies::Region; 4]> = regions.iter().map(Into::into).collect();
    check_buffer_image_copy(
        recorder,
        (src_buffer.raw(), dst_image.raw()),
        &regions,
        (
            &copies::TO_IMAGE,
            "VUID-vkCmdCopyBufferToImage-pRegions-00171",
            true,
        ),
    )
}

/// Refuses a copy from an image into a buffer that breaks a rule of its regions.
pub(crate) fn cmd_copy_image_to_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_image: &Image,
    dst_buffer: &Buffer,
    regions: &[vk::BufferImageCopy],
) -> Result<()> {
    let regions: SmallVec<[copies::Region; 4]> = regions.iter().map(Into::into).collect();
    check_buffer_image_copy(
        recorder,
        (dst_buffer.raw(), src_image.raw()),
        &regions,
        (
            &copies::TO_BUFFER,
            "VUID-vkCmdCopyImageToBuffer-pRegions-00183",
            false,
        ),
    )
}

/// As [`cmd_copy_buffer_to_image_checks`], for `vkCmdCopyBufferToImage2`.
pub(crate) fn cmd_copy_buffer_to_image2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    info: &CopyBufferToImageInfo2<'_>,
) -> Result<()> {
    let raw = info.as_raw();
    // SAFETY: the safe struct stores the array with its length.
    let regions = unsafe { crate::retention::raw_slice(raw.p_regions, raw.region_count) };
    let regions: SmallVec<[copies::Region; 4]> = regions.iter().map(Into::into).collect();
    check_buffer_image_copy(
        recorder,
        (raw.src_buffer, raw.dst_image),
        &regions,
        (
            &copies::TO_IMAGE2,
            "VUID-VkCopyBufferToImageInfo2-pRegions-00171",
            true,
        ),
    )
}

/// As [`cmd_copy_image_to_buffer_checks`], for `vkCmdCopyImageToBuffer2`.
pub(crate) fn cmd_copy_image_to_buffer2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    info: &CopyImageToBufferInfo2<'_>,
) -> Result<()> {
    let raw = info.as_raw();
    // SAFETY: the safe struct stores the array with its length.
    let regions = unsafe { crate::retention::raw_slice(raw.p_regions, raw.region_count) };
    let regions: SmallVec<[copies::Region; 4]> = regions.iter().map(Into::into).collect();
    check_buffer_image_copy(
        recorder,
        (raw.dst_buffer, raw.src_image),
        &regions,
        (
            &copies::TO_BUFFER2,
            "VUID-VkCopyImageToBufferInfo2-pRegions-00183",
            false,
        ),
    )
}

/// The descriptor types a limit on a pipeline layout's descriptors counts together.
const SAMPLERS: &[vk::DescriptorType] = &[
    vk::DescriptorType::SAMPLER,
    vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
];
const UNIFORM_BUFFERS: &[vk::DescriptorType] = &[
    vk::DescriptorType::UNIFORM_BUFFER,
    vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
];
const STORAGE_BUFFERS: &[vk::DescriptorType] = &[
    vk::DescriptorType::STORAGE_BUFFER,
    vk::DescriptorType::STORAGE_BUFFER_DYNAMIC,
];
const SAMPLED_IMAGES: &[vk::DescriptorType] = &[
    vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
    vk::DescriptorType::SAMPLED_IMAGE,
    vk::DescriptorType::UNIFORM_TEXEL_BUFFER,
];
const STORAGE_IMAGES: &[vk::DescriptorType] = &[
    vk::DescriptorType::STORAGE_IMAGE,
    vk::DescriptorType::STORAGE_TEXEL_BUFFER,
];
const INPUT_ATTACHMENTS: &[vk::DescriptorType] = &[vk::DescriptorType::INPUT_ATTACHMENT];

/// One limit on a pipeline layout's descriptors: the types it counts, whether per
/// stage (or across all stages), whether it counts only layouts created without
/// update-after-bind, its value and its rule.
type DescriptorLimit = (&'static [vk::DescriptorType], bool, bool, u32, &'static str);

/// The descriptor limits of `VkPipelineLayoutCreateInfo`, in the order they are
/// checked: across all stages first (without, then with update-after-bind), then
/// per stage, so that a layout past a set-wide limit is named by it.
fn descriptor_limits(
    l: &vk::PhysicalDeviceLimits,
    uab: Option<&vk::PhysicalDeviceVulkan12Properties<'_>>,
) -> Vec<DescriptorLimit> {
    let mut out: Vec<DescriptorLimit> = vec![
        (
            SAMPLERS,
            false,
            true,
            l.max_descriptor_set_samplers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03028",
        ),
        (
            &[vk::DescriptorType::UNIFORM_BUFFER],
            false,
            true,
            l.max_descriptor_set_uniform_buffers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03029",
        ),
        (
            &[vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC],
            false,
            true,
            l.max_descriptor_set_uniform_buffers_dynamic,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03030",
        ),
        (
            &[vk::DescriptorType::STORAGE_BUFFER],
            false,
            true,
            l.max_descriptor_set_storage_buffers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03031",
        ),
        (
            &[vk::DescriptorType::STORAGE_BUFFER_DYNAMIC],
            false,
            true,
            l.max_descriptor_set_storage_buffers_dynamic,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03032",
        ),
        (
            SAMPLED_IMAGES,
            false,
            true,
            l.max_descriptor_set_sampled_images,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03033",
        ),
        (
            STORAGE_IMAGES,
            false,
            true,
            l.max_descriptor_set_storage_images,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03034",
        ),
        (
            INPUT_ATTACHMENTS,
            false,
            true,
            l.max_descriptor_set_input_attachments,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03035",
        ),
    ];
    if let Some(p) = uab {
        out.extend([
            (
                SAMPLERS,
                false,
                false,
                p.max_descriptor_set_update_after_bind_samplers,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03036",
            ),
            (
                &[vk::DescriptorType::UNIFORM_BUFFER][..],
                false,
                false,
                p.max_descriptor_set_update_after_bind_uniform_buffers,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03037",
            ),
            (
                &[vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC][..],
                false,
                false,
                p.max_descriptor_set_update_after_bind_uniform_buffers_dynamic,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03038",
            ),
            (
                &[vk::DescriptorType::STORAGE_BUFFER][..],
                false,
                false,
                p.max_descriptor_set_update_after_bind_storage_buffers,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03039",
            ),
            (
                &[vk::DescriptorType::STORAGE_BUFFER_DYNAMIC][..],
                false,
                false,
                p.max_descriptor_set_update_after_bind_storage_buffers_dynamic,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03040",
            ),
            (
                SAMPLED_IMAGES,
                false,
                false,
                p.max_descriptor_set_update_after_bind_sampled_images,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03041",
            ),
            (
                STORAGE_IMAGES,
                false,
                false,
                p.max_descriptor_set_update_after_bind_storage_images,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03042",
            ),
            (
                INPUT_ATTACHMENTS,
                false,
                false,
                p.max_descriptor_set_update_after_bind_input_attachments,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03043",
            ),
        ]);
    }
    out.extend([
        (
            SAMPLERS,
            true,
            true,
            l.max_per_stage_descriptor_samplers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03016",
        ),
        (
            UNIFORM_BUFFERS,
            true,
            true,
            l.max_per_stage_descriptor_uniform_buffers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03017",
        ),
        (
            STORAGE_BUFFERS,
            true,
            true,
            l.max_per_stage_descriptor_storage_buffers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03018",
        ),
        (
            SAMPLED_IMAGES,
            true,
            true,
            l.max_per_stage_descriptor_sampled_images,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03019",
        ),
        (
            STORAGE_IMAGES,
            true,
            true,
            l.max_per_stage_descriptor_storage_images,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03020",
        ),
        (
            INPUT_ATTACHMENTS,
            true,
            true,
            l.max_per_stage_descriptor_input_attachments,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03021",
        ),
    ]);
    if let Some(p) = uab {
        out.extend([
            (
                SAMPLERS,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_samplers,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03022",
            ),
            (
                UNIFORM_BUFFERS,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_uniform_buffers,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03023",
            ),
            (
                STORAGE_BUFFERS,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_storage_buffers,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03024",
            ),
            (
                SAMPLED_IMAGES,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_sampled_images,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03025",
            ),
            (
                STORAGE_IMAGES,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_storage_images,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03026",
            ),
            (
                INPUT_ATTACHMENTS,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_input_attachments,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03027",
            ),
        ]);
    }
    out
}

/// The device's Vulkan 1.2 properties (the update-after-bind limits), where the
/// instance can ask for them and the device has Vulkan 1.2.
fn vulkan12_properties(device: &Device) -> Option<vk::PhysicalDeviceVulkan12Properties<'static>> {
    let version = device.parent().get_properties().api_version;
    let mut p12 = vk::PhysicalDeviceVulkan12Properties::default();
    (vk::api_version_minor(version) >= 2 && ask_properties2(device, &mut p12)).then_some(p12)
}

/// Refuses a pipeline layout past the device's limits: more set layouts than
/// `maxBoundDescriptorSets` (00286), two push-constant ranges for one stage (00292),
/// or more descriptors of a kind, in one stage or across all of them, than the
/// limit on that kind (03016 to 03043).
pub(crate) fn create_pipeline_layout_checks(
    device: &Device,
    create_info: &PipelineLayoutCreateInfo<'_>,
) -> Result<()> {
    let raw = create_info.as_raw();
    let limits = *device
        .live()
        .limits(|| device.parent().get_properties().limits);
    if raw.set_layout_count > limits.max_bound_descriptor_sets {
        refuse(
            "VUID-VkPipelineLayoutCreateInfo-setLayoutCount-00286",
            format!(
                "setLayoutCount must be at most maxBoundDescriptorSets ({}) (setLayoutCount = {})",
                limits.max_bound_descriptor_sets, raw.set_layout_count
            ),
        )?;
    }
    // SAFETY: the safe setters stored both arrays with their counts.
    let (ranges, sets) = unsafe {
        (
            crate::retention::raw_slice(raw.p_push_constant_ranges, raw.push_constant_range_count),
            crate::retention::raw_slice(raw.p_set_layouts, raw.set_layout_count),
        )
    };
    for (i, r) in ranges.iter().enumerate() {
        if ranges[..i]
            .iter()
            .any(|o| o.stage_flags.intersects(r.stage_flags))
        {
            refuse(
                "VUID-VkPipelineLayoutCreateInfo-pPushConstantRanges-00292",
                format!(
                    "pPushConstantRanges[{i}] names a stage an earlier range names ({:?})",
                    r.stage_flags
                ),
            )?;
        }
    }
    let records: Vec<Vrc<SetLayoutRecord>> = sets
        .iter()
        .filter_map(|s| device.live().set_layout(*s))
        .collect();
    let uab = vulkan12_properties(device);
    // Every stage bit a binding can name, one at a time.
    let stages = (0..32)
        .map(|b| vk::ShaderStageFlags::from_raw(1 << b))
        .filter(|s| {
            records
                .iter()
                .any(|r| r.bindings.iter().any(|b| b.stages.contains(*s)))
        });
    let stages: Vec<vk::ShaderStageFlags> = stages.collect();
    for (types, per_stage, plain_only, limit, vuid) in descriptor_limits(&limits, uab.as_ref()) {
        let count = |stage: Option<vk::ShaderStageFlags>| -> u64 {
            records
                .iter()
                .filter(|r| !(plain_only && r.update_after_bind))
                .flat_map(|r| r.bindings.iter())
                .filter(|b| types.contains(&b.ty) && stage.is_none_or(|s| b.stages.contains(s)))
                .map(|b| u64::from(b.count))
                .sum()
        };
        let worst = if per_stage {
            stages
                .iter()
                .map(|s| (count(Some(*s)), Some(*s)))
                .max_by_key(|(c, _)| *c)
        } else {
            Some((count(None), None))
        };
        if let Some((total, stage)) = worst.filter(|(c, _)| *c > u64::from(limit)) {
            let where_ = stage.map_or("across all stages".to_owned(), |s| {
                format!("in stage {s:?}")
            });
            refuse(
                vuid,
                format!("the layout has {total} descriptors of types {types:?} {where_}, past the limit of {limit}"),
            )?;
        }
    }
    // Inline uniform blocks count by binding (their descriptor count is in bytes),
    // against the Vulkan 1.3 limits.
    let Some(p13) = vulkan13_properties(device) else {
        return Ok(());
    };
    let blocks = |stage: Option<vk::ShaderStageFlags>, plain_only: bool| -> u64 {
        records
            .iter()
            .filter(|r| !(plain_only && r.update_after_bind))
            .flat_map(|r| r.bindings.iter())
            .filter(|b| {
                b.ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK
                    && stage.is_none_or(|s| b.stages.contains(s))
            })
            .count() as u64
    };
    let block_limits = [
        (
            true,
            true,
            p13.max_per_stage_descriptor_inline_uniform_blocks,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02214",
        ),
        (
            true,
            false,
            p13.max_per_stage_descriptor_update_after_bind_inline_uniform_blocks,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02215",
        ),
        (
            false,
            true,
            p13.max_descriptor_set_inline_uniform_blocks,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02216",
        ),
        (
            false,
            false,
            p13.max_descriptor_set_update_after_bind_inline_uniform_blocks,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02217",
        ),
    ];
    for (per_stage, plain_only, limit, vuid) in block_limits {
        let worst = if per_stage {
            stages.iter().map(|s| blocks(Some(*s), plain_only)).max()
        } else {
            Some(blocks(None, plain_only))
        };
        if let Some(total) = worst.filter(|&c| c > u64::from(limit)) {
            refuse(
                vuid,
                format!("the layout has {total} inline uniform block bindings, past the limit of {limit}"),
            )?;
        }
    }
    Ok(())
}

/// The physical device's Vulkan 1.3 properties, where the instance and device have
/// them.
fn vulkan13_properties(device: &Device) -> Option<vk::PhysicalDeviceVulkan13Properties<'static>> {
    let version = device.parent().get_properties().api_version;
    let mut p13 = vk::PhysicalDeviceVulkan13Properties::default();
    (vk::api_version_minor(version) >= 3 && ask_properties2(device, &mut p13)).then_some(p13)
}

/// The number of queue families of a physical device.
fn family_count(physical: &PhysicalDevice) -> u32 {
    let mut count = 0;
    // SAFETY: a live physical device of its instance; the call writes the count only.
    unsafe {
        (physical
            .parent()
            .fns()
            .fp_v1_0()
            .get_physical_device_queue_family_properties)(
            physical.raw(),
            &mut count,
            core::ptr::null_mut(),
        )
    };
    count
}

/// A queue family index below the physical device's family count.
#[cfg(feature = "khr_surface")]
pub(crate) fn queue_family_exists(
    physical: &PhysicalDevice,
    queue_family_index: u32,
    vuid: &'static str,
) -> Result<()> {
    let count = family_count(physical);
    if queue_family_index >= count {
        refuse(
            vuid,
            format!(
                "`queueFamilyIndex` must be less than `pQueueFamilyPropertyCount` returned by \
                 `vkGetPhysicalDeviceQueueFamilyProperties` for the given `physicalDevice` \
                 (`queueFamilyIndex` = {queue_family_index}, count = {count})"
            ),
        )?;
    }
    Ok(())
}

/// A surface some queue family of the physical device presents to, as
/// `vkGetPhysicalDeviceSurfaceSupportKHR` reports.
///
/// A query without a surface is refused (`missing`): it needs
/// `VK_GOOGLE_surfaceless_query`, which tuff does not emit.
#[cfg(feature = "khr_surface")]
pub(crate) fn surface_supported<'s>(
    physical: &PhysicalDevice,
    surface: impl Into<Option<&'s SurfaceKHR>>,
    vuid: &'static str,
    missing: &'static str,
) -> Result<()> {
    let Some(surface) = surface.into() else {
        return refuse(
            missing,
            "`surface` must be a valid VkSurfaceKHR handle (a query without one needs \
             VK_GOOGLE_surfaceless_query, which tuff does not emit)"
                .into(),
        );
    };
    // Without the extension the call itself fails, with `ExtensionNotEnabled`.
    let Some(fns) = physical.parent().ext().khr_surface.as_ref() else {
        return Ok(());
    };
    for family in 0..family_count(physical) {
        let mut supported = vk::FALSE;
        // SAFETY: a live physical device and a live surface of one instance (the
        // implicit checks ran first), a family below the count, an output it owns.
        let r = unsafe {
            (fns.get_physical_device_surface_support_khr)(
                physical.raw(),
                family,
                surface.raw(),
                &mut supported,
            )
        };
        if r == vk::Result::SUCCESS && supported == vk::TRUE {
            return Ok(());
        }
    }
    refuse(
        vuid,
        "`surface` must be supported by `physicalDevice`, as reported by \
         vkGetPhysicalDeviceSurfaceSupportKHR (no queue family of it presents to the surface)"
            .into(),
    )
}

/// As [`surface_supported`], for the device's physical device: tuff's devices have
/// one. (Only the device-group query of `VK_KHR_swapchain` asks.)
#[cfg(feature = "khr_swapchain")]
pub(crate) fn device_surface_supported(
    device: &Device,
    surface: &SurfaceKHR,
    vuid: &'static str,
) -> Result<()> {
    surface_supported(device.parent(), surface, vuid, vuid)
}

/// An image whose memory is one binding: not created disjoint.
pub(crate) fn whole_image_requirements(device: &Device, image: &Image) -> Result<()> {
    let disjoint = device
        .live()
        .image(image.raw())
        .is_some_and(|r| r.flags.contains(vk::ImageCreateFlags::DISJOINT));
    if disjoint {
        refuse(
            "VUID-vkGetImageMemoryRequirements-image-01588",
            "`image` must not have been created with the `VK_IMAGE_CREATE_DISJOINT_BIT` flag \
             set (its planes have their own requirements: use get_image_memory_requirements2)"
                .into(),
        )?;
    }
    Ok(())
}

/// A merge into a cache that is not also one of its sources.
pub(crate) fn merge_pipeline_caches_checks(
    dst_cache: &PipelineCache,
    src_caches: &[&PipelineCache],
) -> Result<()> {
    if src_caches.iter().any(|c| c.raw() == dst_cache.raw()) {
        refuse(
            "VUID-vkMergePipelineCaches-dstCache-00770",
            "`dstCache` must not appear in the list of source caches".into(),
        )?;
    }
    Ok(())
}

/// A pipeline-statistics pool counts only statistics the API defines.
pub(crate) fn create_query_pool_checks(create_info: &QueryPoolCreateInfo<'_>) -> Result<()> {
    let stats = create_info.pipeline_statistics;
    let known = vk::QueryPipelineStatisticFlags::from_raw(0x7ff);
    if create_info.query_type == vk::QueryType::PIPELINE_STATISTICS && !known.contains(stats) {
        refuse(
            "VUID-VkQueryPoolCreateInfo-queryType-00792",
            format!(
                "If `queryType` is `VK_QUERY_TYPE_PIPELINE_STATISTICS`, `pipelineStatistics` \
                 must be a valid combination of VkQueryPipelineStatisticFlagBits values \
                 (`pipelineStatistics` = {:#x})",
                stats.as_raw()
            ),
        )?;
    }
    Ok(())
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
            "`event` must not have been created with `VK_EVENT_CREATE_DEVICE_ONLY_BIT`".into(),
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

/// Memory whose commitment is asked for is of a lazily allocated type.
pub(crate) fn lazily_allocated(device: &Device, memory: &DeviceMemory) -> Result<()> {
    let Some(index) = device.live().memory(memory.raw(), |r| r.memory_type_index) else {
        return Ok(());
    };
    let physical = device.parent();
    // SAFETY: a live physical device of its instance.
    let properties = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_memory_properties(physical.raw())
    };
    let lazy = properties
        .memory_types_as_slice()
        .get(index as usize)
        .is_some_and(|t| {
            t.property_flags
                .contains(vk::MemoryPropertyFlags::LAZILY_ALLOCATED)
        });
    if !lazy {
        refuse(
            "VUID-vkGetDeviceMemoryCommitment-memory-00690",
            format!(
                "`memory` must have been created with a memory type that reports \
                 `VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT` (its type, {index}, does not)"
            ),
        )?;
    }
    Ok(())
}

/// A sample count a sparse format query asks about is one the format supports for
/// the type, usage and tiling (as `vkGetPhysicalDeviceImageFormatProperties`
/// reports, for an image created with the sparse flags the query is about).
pub(crate) fn sparse_samples(
    physical: &PhysicalDevice,
    (format, ty, samples, usage, tiling): (
        vk::Format,
        vk::ImageType,
        vk::SampleCountFlags,
        vk::ImageUsageFlags,
        vk::ImageTiling,
    ),
    vuid: &'static str,
) -> Result<()> {
    // SAFETY: a live physical device of its instance; the values passed the implicit
    // checks (valid enums and flags).
    let properties = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_image_format_properties(
                physical.raw(),
                format,
                ty,
                tiling,
                usage,
                vk::ImageCreateFlags::empty(),
            )
    };
    let supported = properties.map_or(vk::SampleCountFlags::empty(), |p| p.sample_counts);
    if !supported.contains(samples) {
        refuse(
            vuid,
            format!(
                "`samples` must be a bit value that is set in \
                 `VkImageFormatProperties::sampleCounts` returned by \
                 `vkGetPhysicalDeviceImageFormatProperties` with `format`, `type`, `tiling` \
                 and `usage` (`samples` = {samples:?}, sampleCounts = {supported:?})"
            ),
        )?;
    }
    Ok(())
}

/// As [`sparse_samples`], for the `2` query's info.
pub(crate) fn sparse_samples2(
    physical: &PhysicalDevice,
    format_info: &PhysicalDeviceSparseImageFormatInfo2<'_>,
) -> Result<()> {
    let f = format_info.as_raw();
    sparse_samples(
        physical,
        (f.format, f.ty, f.samples, f.usage, f.tiling),
        "VUID-VkPhysicalDeviceSparseImageFormatInfo2-samples-01095",
    )
}

/// A plane's requirements are asked only of a disjoint multi-planar image, and
/// always of one: a chained `VkImagePlaneMemoryRequirementsInfo` names one of its
/// planes.
pub(crate) fn image_requirements2_planes(
    device: &Device,
    info: &ImageMemoryRequirementsInfo2<'_>,
) -> Result<()> {
    let raw = info.as_raw();
    let Some(record) = device.live().image(raw.image) else {
        return Ok(());
    };
    // SAFETY: `raw` is a safe struct's.
    let plane: Option<&vk::ImagePlaneMemoryRequirementsInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::IMAGE_PLANE_MEMORY_REQUIREMENTS_INFO,
        )
    };
    let aspects = crate::formats::aspects(record.format).unwrap_or_default();
    let planar = aspects.contains(vk::ImageAspectFlags::PLANE_0);
    let disjoint = record.flags.contains(vk::ImageCreateFlags::DISJOINT);
    match plane {
        None if planar && disjoint => refuse(
            "VUID-VkImageMemoryRequirementsInfo2-image-01589",
            "`image` was created with a multi-planar format and the \
             `VK_IMAGE_CREATE_DISJOINT_BIT` flag, so a VkImagePlaneMemoryRequirementsInfo must be \
             chained"
                .into(),
        ),
        Some(_) if !disjoint => refuse(
            "VUID-VkImageMemoryRequirementsInfo2-image-01590",
            "`image` was not created with the `VK_IMAGE_CREATE_DISJOINT_BIT` flag, so no \
             VkImagePlaneMemoryRequirementsInfo may be chained"
                .into(),
        ),
        Some(_) if !planar => refuse(
            "VUID-VkImageMemoryRequirementsInfo2-image-01591",
            "`image` was created with a single-plane format, so no \
             VkImagePlaneMemoryRequirementsInfo may be chained"
                .into(),
        ),
        Some(p)
            if p.plane_aspect.as_raw().count_ones() != 1 || !aspects.contains(p.plane_aspect) =>
        {
            refuse(
                "VUID-VkImagePlaneMemoryRequirementsInfo-planeAspect-02281",
                format!(
                    "`planeAspect` must be a single valid format plane for the image \
                     (`planeAspect` = {:?}, the format's aspects: {aspects:?})",
                    p.plane_aspect
                ),
            )
        }
        _ => Ok(()),
    }
}

/// A reset of queries inside the pool.
pub(crate) fn cmd_reset_query_pool_range<S: Scope>(
    recorder: &Recorder<'_, S>,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
) -> Result<()> {
    let Some(record) = recorder.device().live().query_pool(query_pool.raw()) else {
        return Ok(());
    };
    if first_query >= record.count {
        refuse(
            "VUID-vkCmdResetQueryPool-firstQuery-00796",
            format!(
                "`firstQuery` must be less than the number of queries in `queryPool` \
                 (`firstQuery` = {first_query}, queries = {})",
                record.count
            ),
        )?;
    }
    if u64::from(first_query) + u64::from(query_count) > u64::from(record.count) {
        refuse(
            "VUID-vkCmdResetQueryPool-firstQuery-00797",
            format!(
                "The sum of `firstQuery` and `queryCount` must be less than or equal to the \
                 number of queries in `queryPool` (`firstQuery` = {first_query}, `queryCount` = \
                 {query_count}, queries = {})",
                record.count
            ),
        )?;
    }
    Ok(())
}

/// Whether a subpass description (of either version) uses no attachment: every
/// input, color, resolve and depth/stencil reference it has is unused.
macro_rules! no_attachment {
    ($d:expr) => {{
        let d = $d;
        // SAFETY: the safe setters stored every array with its count; resolve
        // attachments, if any, are one per color attachment, and the depth/stencil
        // reference outlives the create info.
        let (input, color, resolve, depth) = unsafe {
            (
                crate::retention::raw_slice(d.p_input_attachments, d.input_attachment_count),
                crate::retention::raw_slice(d.p_color_attachments, d.color_attachment_count),
                crate::retention::raw_slice(d.p_resolve_attachments, d.color_attachment_count),
                d.p_depth_stencil_attachment.as_ref(),
            )
        };
        input
            .iter()
            .chain(color)
            .chain(resolve)
            .chain(depth)
            .all(|r| r.attachment == vk::ATTACHMENT_UNUSED)
    }};
}

/// The device remembers a render pass's subpasses and their view masks (from a
/// chained `VkRenderPassMultiviewCreateInfo`).
pub(crate) fn render_pass_created(
    device: &Device,
    render_pass: RenderPass,
    create_info: &RenderPassCreateInfo<'_>,
) -> RenderPass {
    let raw = create_info.as_raw();
    // SAFETY: `raw` is a safe struct's.
    let multiview: Option<&vk::RenderPassMultiviewCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_MULTIVIEW_CREATE_INFO,
        )
    };
    // SAFETY: the safe setter stored the masks with their count.
    let masks = multiview.map_or(&[][..], |m| unsafe {
        crate::retention::raw_slice(m.p_view_masks, m.subpass_count)
    });
    let view_masks = (0..raw.subpass_count as usize)
        .map(|i| masks.get(i).copied().unwrap_or(0))
        .collect();
    // SAFETY: the safe setter stored the subpasses with their count.
    let no_attachments = unsafe { crate::retention::raw_slice(raw.p_subpasses, raw.subpass_count) }
        .iter()
        .map(|d| no_attachment!(d))
        .collect();
    let (color_formats, depth_formats) = render_pass::subpass_formats(create_info);
    device.live().render_pass_created(
        render_pass.raw(),
        RenderPassRecord {
            attachments: render_pass::attachment_uses(create_info),
            view_masks,
            no_attachments,
            color_formats,
            depth_formats,
            depth_layouts: render_pass::subpass_depth_layouts(create_info),
            subpass_samples: render_pass::subpass_samples(create_info),
            layouts: render_pass::attachment_layouts(create_info),
            used: render_pass::used_attachments(create_info),
            inputs: render_pass::subpass_inputs(create_info),
            self_dependencies: render_pass::self_dependencies(create_info),
            clear_count: render_pass::clears(create_info),
            taken: render_pass::layouts_taken(create_info),
            stencil_taken: Vec::new(),
            may_alias: render_pass::may_alias(create_info),
            dependency_stages: render_pass::dependency_stages(create_info),
        },
    );
    render_pass
}

/// As [`render_pass_created`], for `vkCreateRenderPass2`, whose subpasses carry
/// their view masks.
pub(crate) fn render_pass2_created(
    device: &Device,
    render_pass: RenderPass,
    create_info: &RenderPassCreateInfo2<'_>,
) -> RenderPass {
    let raw = create_info.as_raw();
    // SAFETY: the safe setter stored the subpasses with their count.
    let subpasses = unsafe { crate::retention::raw_slice(raw.p_subpasses, raw.subpass_count) };
    let view_masks = subpasses.iter().map(|s| s.view_mask).collect();
    let no_attachments = subpasses.iter().map(|d| no_attachment!(d)).collect();
    let (color_formats, depth_formats) = render_pass::subpass_formats2(create_info);
    device.live().render_pass_created(
        render_pass.raw(),
        RenderPassRecord {
            attachments: render_pass::attachment_uses2(create_info),
            view_masks,
            no_attachments,
            color_formats,
            depth_formats,
            depth_layouts: render_pass::subpass_depth_layouts2(create_info),
            subpass_samples: render_pass::subpass_samples2(create_info),
            layouts: render_pass::attachment_layouts2(create_info),
            used: render_pass::used_attachments2(create_info),
            inputs: render_pass::subpass_inputs2(create_info),
            self_dependencies: render_pass::self_dependencies2(create_info),
            clear_count: render_pass::clears2(create_info),
            taken: render_pass::layouts_taken2(create_info),
            stencil_taken: render_pass::stencil_layouts2(create_info),
            may_alias: render_pass::may_alias2(create_info),
            dependency_stages: render_pass::dependency_stages2(create_info),
        },
    );
    render_pass
}

/// The recorder enters subpass 0 of the render pass it begins.
pub(crate) fn render_pass_begun<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    layout_vuid: &'static str,
) {
    layouts::render_pass_layouts(recorder, render_pass_begin, layout_vuid);
    let live = recorder.device().live();
    let images = layouts::pass_views(live, render_pass_begin)
        .iter()
        .map(|v| live.view(*v).map_or(vk::Image::null(), |r| r.image))
        .collect();
    recorder.pass_images = images;
    let record = recorder
        .device()
        .live()
        .render_pass(render_pass_begin.as_raw().render_pass);
    recorder.instance = Some(crate::recorder::PassInstance {
        subpass: 0,
        render_pass: render_pass_begin.as_raw().render_pass,
        subpasses: record.as_ref().map_or(0, |r| r.view_masks.len() as u32),
        view_mask: record
            .as_ref()
            .and_then(|r| r.view_masks.first().copied())
            .unwrap_or(0),
        no_attachments: record
            .as_ref()
            .and_then(|r| r.no_attachments.first().copied())
            .unwrap_or(false),
        samples: None,
        dynamic: false,
        record,
        rendering: None,
        rendering_layouts: None,
        rendering_samples: None,
        rendering_images: None,
    });
}

/// Refuses a render pass instance that suspends or resumes: which commands run
/// between a suspended instance and the one that resumes it, across command buffers
/// and batches, is not followed, so a submission could not check its rules.
pub(crate) fn begin_rendering_checks<S: Scope>(
    _recorder: &Recorder<'_, S>,
    rendering_info: &RenderingInfo<'_>,
) -> Result<()> {
    let flags = vk::RenderingFlags::SUSPENDING | vk::RenderingFlags::RESUMING;
    if rendering_info.flags.intersects(flags) {
        return Err(Error::Misuse(
            "the safe begin_rendering does not suspend or resume render pass instances (their submission rules are not followed); use begin_rendering_unchecked, and keep VUID-VkSubmitInfo-pCommandBuffers-06014 to 06016 and 06193",
        ));
    }
    Ok(())
}

/// The recorder enters dynamic rendering (one subpass, the info's view mask).
pub(crate) fn rendering_begun<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    rendering_info: &RenderingInfo<'_>,
) {
    let raw = rendering_info.as_raw();
    // SAFETY: the safe setters stored the color attachments with their count and the
    // depth and stencil ones as references that outlive the info.
    let (color, depth, stencil) = unsafe {
        (
            crate::retention::raw_slice(raw.p_color_attachments, raw.color_attachment_count),
            raw.p_depth_attachment.as_ref(),
            raw.p_stencil_attachment.as_ref(),
        )
    };
    let no_attachments = color
        .iter()
        .chain(depth)
        .chain(stencil)
        .all(|a| a.image_view == vk::ImageView::null());
    let live = recorder.device().live();
    let format = |a: Option<&vk::RenderingAttachmentInfo<'_>>| {
        a.and_then(|a| live.view(a.image_view))
            .map_or(vk::Format::UNDEFINED, |v| v.format)
    };
    let rendering = crate::retention::RenderingFormats {
        view_mask: raw.view_mask,
        colors: color.iter().map(|a| format(Some(a))).collect(),
        depth: format(depth),
        stencil: format(stencil),
    };
    let layout = |a: Option<&vk::RenderingAttachmentInfo<'_>>| {
        a.filter(|a| a.image_view != vk::ImageView::null())
            .map(|a| a.image_layout)
    };
    // The sample count of the first attachment with a view (they must agree).
    let samples = color
        .iter()
        .chain(depth)
        .chain(stencil)
        .filter_map(|a| live.view(a.image_view))
        .find_map(|v| live.image(v.image))
        .map(|i| i.samples);
    let images = color
        .iter()
        .chain(depth)
        .chain(stencil)
        .flat_map(|a| [a.image_view, a.resolve_image_view])
        .filter_map(|v| live.view(v))
        .map(|v| v.image)
        .collect();
    recorder.instance = Some(crate::recorder::PassInstance {
        view_mask: raw.view_mask,
        no_attachments,
        dynamic: true,
        rendering_images: Some(images),
        rendering: Some(Vrc::new(rendering)),
        rendering_layouts: Some((layout(depth), layout(stencil))),
        rendering_samples: samples,
        ..Default::default()
    });
}

/// A next subpass exists.
pub(crate) fn next_subpass_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    vuid: &'static str,
) -> Result<()> {
    match &recorder.instance {
        Some(i) if i.subpasses != 0 && i.subpass + 1 >= i.subpasses => refuse(
            vuid,
            format!(
                "The current subpass index must be less than the number of subpasses in the \
                 render pass minus one (subpass {} of {})",
                i.subpass, i.subpasses
            ),
        ),
        _ => Ok(()),
    }
}

/// The recorder moves to the next subpass.
pub(crate) fn next_subpass_done<S: Scope>(recorder: &mut Recorder<'_, S>) {
    let Some(i) = recorder.instance.take() else {
        return;
    };
    let record = i.record.clone();
    let next = i.subpass + 1;
    let view_mask = record
        .as_ref()
        .and_then(|r| r.view_masks.get(next as usize).copied())
        .unwrap_or(0);
    let no_attachments = record
        .and_then(|r| r.no_attachments.get(next as usize).copied())
        .unwrap_or(false);
    recorder.instance = Some(crate::recorder::PassInstance {
        subpass: next,
        view_mask,
        no_attachments,
        samples: None,
        ..i
    });
}

/// Ends, before the render pass instance's end is recorded, what a refused end
/// would leave broken: the queries begun inside the instance, and the subpasses not
/// yet visited. The recorder is poisoned by then, so the buffer is not submittable,
/// but the driver only ever sees a valid end.
fn repair_instance_end<S: Scope>(recorder: &mut Recorder<'_, S>, next_subpasses: bool) {
    let raw = recorder.raw();
    let fns = recorder.device().fns().fp_v1_0().clone();
    let inside: Vec<crate::recorder::ActiveQuery> = recorder
        .queries
        .iter()
        .filter(|q| q.subpass.is_some())
        .copied()
        .collect();
    for q in &inside {
        // SAFETY: the query was begun in this recording, inside this instance, and is
        // still active.
        unsafe { (fns.cmd_end_query)(raw, q.pool, q.query) };
    }
    recorder.queries.retain(|q| q.subpass.is_none());
    if let Some(i) = recorder.instance.as_mut().filter(|_| next_subpasses) {
        while i.subpasses != 0 && i.subpass + 1 < i.subpasses {
            // SAFETY: a next subpass exists in the render pass begun in this recording;
            // nothing is recorded in it.
            unsafe { (fns.cmd_next_subpass)(raw, vk::SubpassContents::INLINE) };
            i.subpass += 1;
        }
    }
}

/// A render pass instance ends in its last subpass, with every query begun inside
/// it ended; where not, the recorder is refused and repaired
/// ([`repair_instance_end`]).
pub(crate) fn end_render_pass_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    (last, queries): (&'static str, &'static str),
) -> Result<()> {
    let Some(i) = &recorder.instance else {
        return Ok(());
    };
    let r = if i.subpasses != 0 && i.subpass + 1 != i.subpasses {
        refuse(
            last,
            format!(
                "The current subpass index must be equal to the number of subpasses in the \
                 render pass minus one (subpass {} of {})",
                i.subpass, i.subpasses
            ),
        )
    } else if recorder.queries.iter().any(|q| q.subpass.is_some()) {
        refuse(
            queries,
            "If `vkCmdBeginQuery`* was called within a subpass of the render pass, the \
             corresponding `vkCmdEndQuery`* must have been called subsequently within the same \
             subpass"
                .into(),
        )
    } else {
        Ok(())
    };
    if r.is_err() {
        repair_instance_end(recorder, true);
    }
    r
}

/// Dynamic rendering ends with every query begun inside it ended (repaired as
/// [`end_render_pass_checks`] repairs).
pub(crate) fn end_rendering_checks<S: Scope>(recorder: &mut Recorder<'_, S>) -> Result<()> {
    if recorder.queries.iter().any(|q| q.subpass.is_some()) {
        repair_instance_end(recorder, false);
        return refuse(
            "VUID-vkCmdEndRendering-None-06999",
            "If `vkCmdBeginQuery`* was called within the render pass, the corresponding \
             `vkCmdEndQuery`* must have been called subsequently within the same subpass"
                .into(),
        );
    }
    Ok(())
}

/// The recorder leaves the render pass instance.
pub(crate) fn instance_ended<S: Scope>(recorder: &mut Recorder<'_, S>) {
    recorder.instance = None;
}

/// A query begins inside its pool, on a queue that can run it, while no other
/// query of its type is active, at an index that leaves room for the subpass's
/// views.
pub(crate) fn begin_query_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) -> Result<()> {
    let Some(record) = recorder.device().live().query_pool(query_pool.raw()) else {
        return Ok(());
    };
    if record.query_type == vk::QueryType::TIMESTAMP {
        refuse(
            "VUID-vkCmdBeginQuery-queryType-02804",
            "The `queryType` used to create `queryPool` must not be `VK_QUERY_TYPE_TIMESTAMP`"
                .into(),
        )?;
    }
    if query >= record.count {
        refuse(
            "VUID-vkCmdBeginQuery-query-00802",
            format!(
                "`query` must be less than the number of queries in `queryPool` (`query` = \
                 {query}, queries = {})",
                record.count
            ),
        )?;
    }
    let flags = recorder.pool_queue_flags();
    let graphics_stats = vk::QueryPipelineStatisticFlags::from_raw(0x3ff);
    let compute_stats = vk::QueryPipelineStatisticFlags::COMPUTE_SHADER_INVOCATIONS;
    let needs = |vuid: &'static str, what: vk::QueueFlags| {
        if flags.contains(what) {
            Ok(())
        } else {
            refuse(
                vuid,
                format!("the command buffer's pool is of a queue family without {what:?} operations, which this query needs"),
            )
        }
    };
    match record.query_type {
        vk::QueryType::OCCLUSION => needs(
            "VUID-vkCmdBeginQuery-queryType-00803",
            vk::QueueFlags::GRAPHICS,
        )?,
        vk::QueryType::PIPELINE_STATISTICS => {
            if record.statistics.intersects(graphics_stats) {
                needs(
                    "VUID-vkCmdBeginQuery-queryType-00804",
                    vk::QueueFlags::GRAPHICS,
                )?;
            }
            if record.statistics.intersects(compute_stats) {
                needs(
                    "VUID-vkCmdBeginQuery-queryType-00805",
                    vk::QueueFlags::COMPUTE,
                )?;
            }
        }
        _ => {}
    }
    if let Some(q) = recorder.queries.iter().find(|q| q.ty == record.query_type) {
        refuse(
            "VUID-vkCmdBeginQuery-queryPool-01922",
            format!(
                "`queryPool` must have been created with a `queryType` that differs from that of \
                 any queries that are active within `commandBuffer` (query {} of another pool or \
                 index, of type {:?}, is active)",
                q.query, q.ty
            ),
        )?;
    }
    if let Some(i) = &recorder.instance {
        let views = i.view_mask.count_ones();
        if u64::from(query) + u64::from(views) > u64::from(record.count) {
            refuse(
                "VUID-vkCmdBeginQuery-query-00808",
                format!(
                    "the sum of `query` and the number of bits set in the current subpass's view \
                     mask must be less than or equal to the number of queries in `queryPool` \
                     (`query` = {query}, views = {views}, queries = {})",
                    record.count
                ),
            )?;
        }
    }
    Ok(())
}

/// The recorder remembers the active query.
pub(crate) fn begin_query_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) {
    let ty = recorder
        .device()
        .live()
        .query_pool(query_pool.raw())
        .map_or(vk::QueryType::from_raw(i32::MAX), |r| r.query_type);
    let subpass = recorder.instance.as_ref().map(|i| i.subpass);
    recorder.queries.push(crate::recorder::ActiveQuery {
        pool: query_pool.raw(),
        query,
        ty,
        subpass,
    });
}

/// A query ends where it was begun: active in this recording, in the same subpass,
/// or outside a render pass instance if begun outside.
pub(crate) fn end_query_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) -> Result<()> {
    if let Some(record) = recorder.device().live().query_pool(query_pool.raw()) {
        if query >= record.count {
            refuse(
                "VUID-vkCmdEndQuery-query-00810",
                format!(
                    "`query` must be less than the number of queries in `queryPool` (`query` = \
                     {query}, queries = {})",
                    record.count
                ),
            )?;
        }
        if let Some(i) = &recorder.instance {
            let views = i.view_mask.count_ones();
            if u64::from(query) + u64::from(views) > u64::from(record.count) {
                refuse(
                    "VUID-vkCmdEndQuery-query-00812",
                    format!(
                        "the sum of `query` and the number of bits set in the current subpass's \
                         view mask must be less than or equal to the number of queries in \
                         `queryPool` (`query` = {query}, views = {views}, queries = {})",
                        record.count
                    ),
                )?;
            }
        }
    }
    let Some(active) = recorder
        .queries
        .iter()
        .find(|q| q.pool == query_pool.raw() && q.query == query)
    else {
        return refuse(
            "VUID-vkCmdEndQuery-None-01923",
            format!("All queries used by the command must be active (query {query} is not)"),
        );
    };
    match (
        active.subpass,
        recorder.instance.as_ref().map(|i| i.subpass),
    ) {
        (Some(began), Some(now)) if began != now => refuse(
            "VUID-vkCmdEndQuery-None-07007",
            format!(
                "the query was begun in subpass {began} and is ended in subpass {now}; it must end \
                 in the subpass it began in"
            ),
        ),
        (None, Some(_)) => refuse(
            "VUID-vkCmdEndQuery-None-07008",
            "the query was begun outside a render pass instance, so it must be ended outside one"
                .into(),
        ),
        _ => Ok(()),
    }
}

/// The recorder forgets the ended query.
pub(crate) fn end_query_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) {
    recorder
        .queries
        .retain(|q| !(q.pool == query_pool.raw() && q.query == query));
}

/// Queue family indices of a concurrent resource: each once, each a family of the
/// physical device.
fn concurrent_families(
    physical: &PhysicalDevice,
    families: &[u32],
    vuid: &'static str,
) -> Result<()> {
    let count = family_count(physical);
    for (i, &f) in families.iter().enumerate() {
        if f >= count || families[..i].contains(&f) {
            refuse(
                vuid,
                format!(
                    "each element of `pQueueFamilyIndices` must be unique and must be less than \
                     `pQueueFamilyPropertyCount` (`pQueueFamilyIndices[{i}]` = {f}, families = \
                     {count})"
                ),
            )?;
        }
    }
    Ok(())
}

/// The memory a sparse buffer of this create info requires, from
/// `vkGetDeviceBufferMemoryRequirements` (without creating it), or its size where
/// the device is older than Vulkan 1.3 (rounded up to 64 KiB, the largest sparse
/// block size).
fn sparse_requirement(device: &Device, create_info: &BufferCreateInfo<'_>) -> u64 {
    if vulkan13_properties(device).is_none() {
        return create_info.as_raw().size.div_ceil(1 << 16) << 16;
    }
    let info = vk::DeviceBufferMemoryRequirements::default().create_info(create_info.as_raw());
    let mut out = vk::MemoryRequirements2::default();
    // SAFETY: a live Vulkan 1.3 device; the create info passed the implicit checks.
    unsafe {
        device
            .fns()
            .get_device_buffer_memory_requirements(&info, &mut out)
    };
    out.memory_requirements.size
}

/// Holds other safe sparse creations off while a sparse buffer is checked against
/// `sparseAddressSpaceSize` and made, so that two threads cannot both take the last
/// of it (`VUID-vkCreateBuffer-flags-00911`); a buffer that is not sparse takes no
/// lock.
pub(crate) fn sparse_buffer_gate<'d>(
    device: &'d Device,
    create_info: &BufferCreateInfo<'_>,
) -> Result<Option<tuff_runtime::VutexGuard<'d, ()>>> {
    if !create_info
        .flags
        .contains(vk::BufferCreateFlags::SPARSE_BINDING)
    {
        return Ok(None);
    }
    let gate = device.live().sparse_gate();
    let required = sparse_requirement(device, create_info);
    let total = device.live().sparse_total();
    let limit = limits(device).sparse_address_space_size;
    if total.saturating_add(required) > limit {
        refuse(
            "VUID-vkCreateBuffer-flags-00911",
            format!(
                "creating this sparse buffer, which requires {required} bytes, must not \
                 cause the total required sparse memory ({total} bytes now) to exceed \
                 sparseAddressSpaceSize ({limit})"
            ),
        )?;
    }
    Ok(Some(gate))
}

/// As [`sparse_buffer_gate`], for a sparse image (`VUID-vkCreateImage-flags-00939`).
pub(crate) fn sparse_image_gate<'d>(
    device: &'d Device,
    create_info: &ImageCreateInfo<'_>,
) -> Result<Option<tuff_runtime::VutexGuard<'d, ()>>> {
    if !create_info
        .flags
        .contains(vk::ImageCreateFlags::SPARSE_BINDING)
    {
        return Ok(None);
    }
    let gate = device.live().sparse_gate();
    let required = sparse_image_requirement(device, create_info.as_raw());
    let total = device.live().sparse_total();
    let limit = limits(device).sparse_address_space_size;
    if total.saturating_add(required) > limit {
        refuse(
            "VUID-vkCreateImage-flags-00939",
            format!("this sparse image requires {required} bytes, which with the {total} live sparse resources require is more than sparseAddressSpaceSize ({limit})"),
        )?;
    }
    Ok(Some(gate))
}

/// The memory a sparse image of this create info requires, from
/// `vkGetDeviceImageMemoryRequirements` (without creating it), or, where the device
/// is older than Vulkan 1.3, a bound above it: every texel of every level, layer and
/// sample at the bytes of all its aspects' blocks and at least 16, rounded up to
/// 64 KiB, the largest sparse block size.
fn sparse_image_requirement(device: &Device, info: &vk::ImageCreateInfo<'_>) -> u64 {
    let planes = crate::formats::aspects(info.format)
        .filter(|_| info.flags.contains(vk::ImageCreateFlags::DISJOINT))
        .map_or(0, |a| (a.as_raw() >> 4).count_ones());
    if vulkan13_properties(device).is_some() {
        // A disjoint image's planes are asked for one by one.
        let aspects: Vec<vk::ImageAspectFlags> = if planes == 0 {
            vec![vk::ImageAspectFlags::NONE]
        } else {
            (0..planes)
                .map(|p| vk::ImageAspectFlags::from_raw(0x10 << p))
                .collect()
        };
        return aspects
            .into_iter()
            .map(|plane| {
                let asked = vk::DeviceImageMemoryRequirements::default()
                    .create_info(info)
                    .plane_aspect(plane);
                let mut out = vk::MemoryRequirements2::default();
                // SAFETY: a live Vulkan 1.3 device; the create info passed the
                // implicit checks, and a disjoint one's plane is named.
                unsafe {
                    device
                        .fns()
                        .get_device_image_memory_requirements(&asked, &mut out)
                };
                out.memory_requirements.size
            })
            .fold(0, u64::saturating_add);
    }
    let aspects = crate::formats::aspects(info.format).unwrap_or(vk::ImageAspectFlags::COLOR);
    let bytes = (0..7)
        .map(|b| vk::ImageAspectFlags::from_raw(1 << b))
        .filter(|a| aspects.contains(*a))
        .filter_map(|a| crate::formats::block(info.format, a).map(|b| u64::from(b.0)))
        .sum::<u64>()
        .max(16);
    let e = info.extent;
    let texels: u64 = (0..info.mip_levels.min(32))
        .map(|l| {
            u64::from((e.width >> l).max(1))
                * u64::from((e.height >> l).max(1))
                * u64::from((e.depth >> l).max(1))
        })
        .sum();
    let total = texels
        .saturating_mul(bytes)
        .saturating_mul(u64::from(info.array_layers))
        .saturating_mul(u64::from(info.samples.as_raw().max(1)));
    total.div_ceil(1 << 16).saturating_mul(1 << 16)
}

/// A buffer's creation: its size within `maxBufferSize`, its queue families, the
/// external handle types it is exportable as, a capture address only with the
/// capture-replay flag, and no protected sparse buffer.
pub(crate) fn create_buffer_checks(
    device: &Device,
    create_info: &BufferCreateInfo<'_>,
) -> Result<()> {
    let raw = create_info.as_raw();
    let sparse = vk::BufferCreateFlags::SPARSE_BINDING
        | vk::BufferCreateFlags::SPARSE_RESIDENCY
        | vk::BufferCreateFlags::SPARSE_ALIASED;
    if raw.flags.intersects(sparse) && raw.flags.contains(vk::BufferCreateFlags::PROTECTED) {
        refuse(
            "VUID-VkBufferCreateInfo-None-01888",
            format!(
                "If any of the bits `VK_BUFFER_CREATE_SPARSE_BINDING_BIT`, \
                 `VK_BUFFER_CREATE_SPARSE_RESIDENCY_BIT`, or `VK_BUFFER_CREATE_SPARSE_ALIASED_BIT` \
                 are set, `VK_BUFFER_CREATE_PROTECTED_BIT` must not also be set (`flags` = {:?})",
                raw.flags
            ),
        )?;
    }
    let max = device
        .live()
        .max_buffer_size(|| vulkan13_properties(device).map(|p| p.max_buffer_size));
    if let Some(max) = max.filter(|&m| raw.size > m) {
        refuse(
            "VUID-VkBufferCreateInfo-size-06409",
            format!(
                "`size` must be less than or equal to \
                 VkPhysicalDeviceMaintenance4Properties::`maxBufferSize` (`size` = {}, \
                 maxBufferSize = {max})",
                raw.size
            ),
        )?;
    }
    if raw.sharing_mode == vk::SharingMode::CONCURRENT {
        // SAFETY: the safe setter stored the indices with their count.
        let families = unsafe {
            crate::retention::raw_slice(raw.p_queue_family_indices, raw.queue_family_index_count)
        };
        concurrent_families(
            device.parent(),
            families,
            "VUID-VkBufferCreateInfo-sharingMode-01419",
        )?;
    }
    // SAFETY: `raw` is a safe struct's.
    let (capture, external): (
        Option<&vk::BufferOpaqueCaptureAddressCreateInfo<'_>>,
        Option<&vk::ExternalMemoryBufferCreateInfo<'_>>,
    ) = unsafe {
        (
            chained(
                raw.p_next,
                vk::StructureType::BUFFER_OPAQUE_CAPTURE_ADDRESS_CREATE_INFO,
            ),
            chained(
                raw.p_next,
                vk::StructureType::EXTERNAL_MEMORY_BUFFER_CREATE_INFO,
            ),
        )
    };
    if capture.is_some_and(|c| c.opaque_capture_address != 0)
        && !raw
            .flags
            .contains(vk::BufferCreateFlags::DEVICE_ADDRESS_CAPTURE_REPLAY)
    {
        refuse(
            "VUID-VkBufferCreateInfo-opaqueCaptureAddress-03337",
            "If VkBufferOpaqueCaptureAddressCreateInfo::`opaqueCaptureAddress` is not zero, \
             `flags` must include `VK_BUFFER_CREATE_DEVICE_ADDRESS_CAPTURE_REPLAY_BIT`"
                .into(),
        )?;
    }
    let wanted = external.map_or(vk::ExternalMemoryHandleTypeFlags::empty(), |e| {
        e.handle_types
    });
    let physical = device.parent();
    for bit in (0..32)
        .map(|i| 1u32 << i)
        .filter(|b| wanted.as_raw() & b != 0)
    {
        let info = vk::PhysicalDeviceExternalBufferInfo::default()
            .flags(raw.flags)
            .usage(raw.usage)
            .handle_type(vk::ExternalMemoryHandleTypeFlags::from_raw(bit));
        let mut props = vk::ExternalBufferProperties::default();
        // SAFETY: a live physical device of its instance, a valid info and an output
        // it owns; the external struct is core 1.1, which the implicit checks required.
        unsafe {
            physical
                .parent()
                .fns()
                .get_physical_device_external_buffer_properties(physical.raw(), &info, &mut props)
        };
        let compatible = props.external_memory_properties.compatible_handle_types;
        if !compatible.contains(wanted) {
            refuse(
                "VUID-VkBufferCreateInfo-pNext-00920",
                format!(
                    "the chained VkExternalMemoryBufferCreateInfo's `handleTypes` ({wanted:?}) \
                     must only contain bits that are also in the \
                     `externalMemoryProperties.compatibleHandleTypes` the physical device \
                     reports for {:?} ({compatible:?})",
                    info.handle_type
                ),
            )?;
        }
    }
    Ok(())
}

/// `pData` of a `vkGet*OpaqueCaptureDescriptorDataEXT` holds the capture data the
/// device's descriptor-buffer properties size (`size` reads which), so the driver
/// writes inside the slice.
#[cfg(feature = "ext_descriptor_buffer")]
pub(crate) fn capture_data_fits(
    device: &Device,
    data: &[u8],
    size: fn(&vk::PhysicalDeviceDescriptorBufferPropertiesEXT) -> usize,
    vuid: &'static str,
) -> Result<()> {
    if device.ext().ext_descriptor_buffer.is_none() {
        // The call refuses the missing extension itself.
        return Ok(());
    }
    let mut props = vk::PhysicalDeviceDescriptorBufferPropertiesEXT::default();
    if !ask_properties2(device, &mut props) {
        return Err(Error::Misuse(
            "the capture data size is a Vulkan 1.1 property: make the instance with Vulkan 1.1 or later",
        ));
    }
    let needed = size(&props);
    if data.len() < needed {
        refuse(
            vuid,
            format!(
                "`data` must hold at least {needed} bytes (the device's capture data size), not {}",
                data.len()
            ),
        )?;
    }
    Ok(())
}

/// Each build info's array of per-geometry values (build ranges, maximum primitive
/// counts) holds at least its `geometryCount` elements, which Vulkan reads. `vuid`
/// names the rule where the specification has one.
#[cfg(feature = "khr_acceleration_structure")]
pub(crate) fn per_geometry_fits<T>(
    infos: &[AccelerationStructureBuildGeometryInfoKHR<'_>],
    arrays: &[&[T]],
    vuid: Option<&'static str>,
) -> Result<()> {
    for (i, (info, array)) in infos.iter().zip(arrays).enumerate() {
        let needed = info.geometry_count as usize;
        if array.len() < needed {
            let message = format!(
                "element {i} holds {} values where its build info has {needed} geometries",
                array.len()
            );
            return Err(match vuid {
                Some(vuid) => Error::Validation { vuid, message },
                None => Error::Misuse(
                    "each build info's array of maximum primitive counts must hold a value per geometry",
                ),
            });
        }
    }
    Ok(())
}

/// Fills `props` from the device's physical device through
/// vkGetPhysicalDeviceProperties2: `false`, with `props` as it was, where the
/// instance has no Vulkan 1.1 to ask with.
pub(crate) fn ask_properties2<T: vk::ExtendsPhysicalDeviceProperties2>(
    device: &Device,
    props: &mut T,
) -> bool {
    let physical = device.parent();
    let instance = physical.parent();
    if !instance.exts().version(1) {
        return false;
    }
    let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(props);
    // SAFETY: a live physical device of a Vulkan 1.1 instance; the chain is local
    // and ends at `props`, whose `pNext` push_next left null.
    unsafe {
        instance
            .fns()
            .get_physical_device_properties2(physical.raw(), &mut p2)
    };
    true
}
