//! Queue submissions: batches of command buffers, semaphores and fences checked
//! before they reach the queue, and the bookkeeping after (pending state, timelines,
//! queue families).

use super::sync::timeline_difference;
use super::{chained, refuse};
use crate::handles::*;
use crate::special::hazards;
use crate::structs::*;
use crate::submission::{self, Batch, Batches, SubmitRules};
use crate::{Handle, Result};
use ash::vk;
use smallvec::SmallVec;

/// The checks of `vkQueueSubmit` that memory safety needs: the fence, the command
/// buffers' states and the batches' timeline values.
pub(crate) fn queue_submit_checks(
    queue: &Queue,
    submits: &[SubmitInfo<'_>],
    fence: Option<&Fence>,
) -> Result<()> {
    let batches = Batches::of(queue.parent().live(), submits);
    submit_checks(queue, fence, &batches.command_buffers, &submission::SUBMIT)?;
    for (i, b) in submits.iter().enumerate() {
        check_device_group_submit(i, b)?;
        check_group_indices(queue.parent(), i, b)?;
        check_wait_stages(queue, i, b)?;
        check_pools(queue, i, b)?;
    }
    for b in submits {
        submission::check_timeline_batch(queue.parent().live(), b, &submission::SUBMIT_TIMELINE)?;
    }
    // Last: it keeps the state the submission leaves, for `done`.
    let batches: SmallVec<[_; 1]> = submits
        .iter()
        .map(|b| {
            let b = b.as_raw();
            // SAFETY: the safe struct stores each array with its count.
            let (stages, cbs) = unsafe {
                (
                    crate::state::raw_slice(b.p_wait_dst_stage_mask, b.wait_semaphore_count),
                    crate::state::raw_slice(b.p_command_buffers, b.command_buffer_count),
                )
            };
            hazards::Batch {
                waits: stages.iter().map(|s| u64::from(s.as_raw())).collect(),
                command_buffers: cbs.iter().copied().collect(),
            }
        })
        .collect();
    hazards::submit_checks(queue, &batches)
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
    // SAFETY: the safe struct stores the array with its length.
    let cbs =
        unsafe { crate::state::raw_slice(batch.p_command_buffers, batch.command_buffer_count) };
    let at = |j| format!("pSubmits[{i}].pCommandBuffers[{j}]");
    check_batch_pools(queue, protected, cbs.iter().copied(), at, &SUBMIT_POOLS)
}

/// The rules of a batch's command buffers' pools, by field: `VkSubmitInfo`'s and
/// `VkSubmitInfo2`'s differ only in their names.
struct PoolRules {
    /// The pool's queue family is the queue's.
    family: &'static str,
    /// A protected batch's command buffers are protected.
    protected: &'static str,
    /// An unprotected batch's command buffers are not.
    unprotected: &'static str,
}

const SUBMIT_POOLS: PoolRules = PoolRules {
    family: "VUID-vkQueueSubmit-pCommandBuffers-00074",
    protected: "VUID-VkSubmitInfo-pNext-04148",
    unprotected: "VUID-VkSubmitInfo-pNext-04120",
};

const SUBMIT2_POOLS: PoolRules = PoolRules {
    family: "VUID-vkQueueSubmit2-commandBuffer-03878",
    protected: "VUID-VkSubmitInfo2-flags-03886",
    unprotected: "VUID-VkSubmitInfo2-flags-03887",
};

/// Refuses command buffers of a batch (`protected` or not) whose pool, as the device
/// recorded it, is of another queue family than the queue's or of the other
/// protection; `at` names the `j`th.
fn check_batch_pools(
    queue: &Queue,
    protected: bool,
    cbs: impl Iterator<Item = vk::CommandBuffer>,
    at: impl Fn(usize) -> String,
    rules: &PoolRules,
) -> Result<()> {
    let device = queue.parent();
    let family = device.live().queue_family(queue.raw());
    for (j, raw) in cbs.enumerate() {
        let Some((pool_family, pool_protected)) =
            device.command_buffer_uses(raw).and_then(|u| u.pool())
        else {
            continue;
        };
        if family.is_some_and(|f| f != pool_family) {
            refuse(
                rules.family,
                format!(
                    "{} comes from a pool of queue family {pool_family}, not the queue's",
                    at(j)
                ),
            )?;
        }
        if protected != pool_protected {
            let (vuid, is) = match protected {
                true => (
                    rules.protected,
                    "is protected, and the command buffer is not",
                ),
                false => (
                    rules.unprotected,
                    "is not protected, and the command buffer is",
                ),
            };
            refuse(vuid, format!("{}: the batch {is}", at(j)))?;
        }
    }
    Ok(())
}

/// What a submission command checks of its batches under the device's gate, by
/// command.
struct HoldRules {
    /// The rules of its command buffers (an invalid one is not executable).
    submit: &'static SubmitRules,
    /// An event that a pending submission to another queue names; `""` where the
    /// command does not check it.
    events: &'static str,
    /// The rules of its binary semaphore operations.
    binary: &'static submission::BinaryRules,
    /// The rules of its timeline values, where the command checks them.
    values: Option<&'static submission::TimelineValueRules>,
}

/// The rules `vkQueueSubmit` checks under the gate.
const SUBMIT_HOLD: HoldRules = HoldRules {
    submit: &submission::SUBMIT,
    events: "VUID-vkQueueSubmit-pCommandBuffers-00065",
    binary: &submission::SUBMIT_BINARY,
    values: Some(&submission::SUBMIT_TIMELINE_VALUES),
};

/// The rules `vkQueueSubmit2` checks under the gate.
const SUBMIT2_HOLD: HoldRules = HoldRules {
    submit: &submission::SUBMIT2,
    events: "VUID-vkQueueSubmit2-commandBuffer-03867",
    binary: &submission::SUBMIT2_BINARY,
    values: Some(&submission::SUBMIT2_TIMELINE_VALUES),
};

/// The rules `vkQueueBindSparse` checks under the gate.
const BIND_SPARSE_HOLD: HoldRules = HoldRules {
    submit: &submission::BIND_SPARSE,
    events: "",
    binary: &submission::BIND_SPARSE_BINARY,
    values: None,
};

/// Takes the device's descriptor gate for a submission command (held until its
/// bookkeeping is done, so no submission on another queue or update changes what
/// is checked here meanwhile) and refuses command buffers that an update of a set
/// they bind left invalid, queries they use that are not reset, events another
/// queue's pending submission names, and semaphore operations that the states the
/// device records forbid.
fn hold<'q, B: Batch>(
    queue: &'q Queue,
    batches: &[B],
    rules: &HoldRules,
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    let device = queue.parent();
    let b = Batches::of(device.live(), batches);
    // The sets and events the command buffers use, read once for the checks below.
    let (sets, events) = submission::used(device, &b.command_buffers);
    let gate = submission::sets_hold(device, &sets, rules.submit.executable)?;
    // Under the gate: a host reset of queries checks the submissions made, and
    // records its reset, under it too.
    submission::check_queries(device, &b.command_buffers)?;
    if !rules.events.is_empty() {
        submission::check_events(device, queue.raw(), &events, rules.events)?;
        submission::check_event_states(device, &b.command_buffers)?;
    }
    submission::check_binary_ops(device, queue.raw(), &b.ops, rules.binary)?;
    if let Some(values) = rules.values {
        let difference = timeline_difference(device);
        submission::check_timeline_values(device.live(), &b.timeline, difference, values)?;
    }
    Ok(gate)
}

/// Takes the device's gate for `vkQueueSubmit`, and checks under it.
pub(crate) fn queue_submit_hold<'q>(
    queue: &'q Queue,
    submits: &[SubmitInfo<'_>],
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    hold(queue, submits, &SUBMIT_HOLD)
}

/// As [`queue_submit_hold`], for `vkQueueSubmit2`.
pub(crate) fn queue_submit2_hold<'q>(
    queue: &'q Queue,
    submits: &[SubmitInfo2<'_>],
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    hold(queue, submits, &SUBMIT2_HOLD)
}

/// As [`queue_submit_hold`], for `vkQueueBindSparse` (it has no command buffers).
pub(crate) fn queue_bind_sparse_hold<'q>(
    queue: &'q Queue,
    bind_info: &[BindSparseInfo<'_>],
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    hold(queue, bind_info, &BIND_SPARSE_HOLD)
}

/// The checks of `vkQueueSubmit2`: the fence and the command buffers' states.
pub(crate) fn queue_submit2_checks(
    queue: &Queue,
    submits: &[SubmitInfo2<'_>],
    fence: Option<&Fence>,
) -> Result<()> {
    let batches = Batches::of(queue.parent().live(), submits);
    submit_checks(queue, fence, &batches.command_buffers, &submission::SUBMIT2)?;
    for (i, b) in submits.iter().enumerate() {
        check_batch2(queue, i, b)?;
    }
    // Last: it keeps the state the submission leaves, for `done`.
    let batches: SmallVec<[_; 1]> = submits
        .iter()
        .map(|b| {
            let b = b.as_raw();
            // SAFETY: the safe struct stores each array with its count.
            let (waits, cbs) = unsafe {
                (
                    crate::state::raw_slice(b.p_wait_semaphore_infos, b.wait_semaphore_info_count),
                    crate::state::raw_slice(b.p_command_buffer_infos, b.command_buffer_info_count),
                )
            };
            hazards::Batch {
                waits: waits.iter().map(|w| w.stage_mask.as_raw()).collect(),
                command_buffers: cbs.iter().map(|c| c.command_buffer).collect(),
            }
        })
        .collect();
    hazards::submit_checks(queue, &batches)
}

/// The rules of one `VkSubmitInfo2` that the first version's batches keep in other
/// structs: its command buffers' pools (the queue's family, the batch's protection)
/// and device masks, its semaphores' stages and device indices, and a timeline
/// semaphore both waited on and signalled.
fn check_batch2(queue: &Queue, i: usize, batch: &SubmitInfo2<'_>) -> Result<()> {
    let device = queue.parent();
    let live = device.live();
    let b = batch.as_raw();
    let protected = b.flags.contains(vk::SubmitFlags::PROTECTED);
    if protected && !live.is_protected_queue(queue.raw()) {
        refuse(
            "VUID-vkQueueSubmit2-queue-06447",
            format!("pSubmits[{i}].flags has PROTECTED, and the queue was not created protected"),
        )?;
    }
    let count = live.physical_count();
    // SAFETY: the safe struct stores each array with its length.
    let (waits, cbs, signals) = unsafe {
        (
            crate::state::raw_slice(b.p_wait_semaphore_infos, b.wait_semaphore_info_count),
            crate::state::raw_slice(b.p_command_buffer_infos, b.command_buffer_info_count),
            crate::state::raw_slice(b.p_signal_semaphore_infos, b.signal_semaphore_info_count),
        )
    };
    for (j, c) in cbs.iter().enumerate() {
        if c.device_mask != 0 && count < 32 && c.device_mask >> count != 0 {
            refuse(
                "VUID-VkCommandBufferSubmitInfo-deviceMask-03891",
                format!("pSubmits[{i}].pCommandBufferInfos[{j}].deviceMask {:#x} names a physical device the device's {count} do not include", c.device_mask),
            )?;
        }
    }
    let at = |j| format!("pSubmits[{i}].pCommandBufferInfos[{j}]");
    let raws = cbs.iter().map(|c| c.command_buffer);
    check_batch_pools(queue, protected, raws, at, &SUBMIT2_POOLS)?;
    let flags = queue.queue_flags();
    for (infos, name, stage_rule) in [
        (
            waits,
            "pWaitSemaphoreInfos",
            "VUID-vkQueueSubmit2-stageMask-03870",
        ),
        (
            signals,
            "pSignalSemaphoreInfos",
            "VUID-vkQueueSubmit2-stageMask-03869",
        ),
    ] {
        for (j, s) in infos.iter().enumerate() {
            let at = format!("pSubmits[{i}].{name}[{j}]");
            if let Some(stage) = super::stages::unsupported_stage2(s.stage_mask, flags) {
                refuse(
                    stage_rule,
                    format!("{at}.stageMask includes {stage:?}, which the queue's capabilities ({flags:?}) do not support"),
                )?;
            }
            if count == 1 && s.device_index != 0 {
                refuse(
                    "VUID-VkSemaphoreSubmitInfo-device-03888",
                    format!(
                        "{at}.deviceIndex is {}, and the device is not a device group",
                        s.device_index
                    ),
                )?;
            }
            if count > 1 && s.device_index >= count {
                refuse(
                    "VUID-VkSemaphoreSubmitInfo-device-03889",
                    format!(
                        "{at}.deviceIndex is {}, and the device group has {count} physical devices",
                        s.device_index
                    ),
                )?;
            }
        }
    }
    for (j, w) in waits.iter().enumerate() {
        if !live.is_timeline(w.semaphore) {
            continue;
        }
        if let Some(k) = signals
            .iter()
            .position(|s| s.semaphore == w.semaphore && w.value >= s.value)
        {
            refuse(
                "VUID-VkSubmitInfo2-semaphore-03881",
                format!("pSubmits[{i}] waits on a timeline semaphore for {} (pWaitSemaphoreInfos[{j}]) and signals it with {} (pSignalSemaphoreInfos[{k}]); the wait must be below the signal", w.value, signals[k].value),
            )?;
        }
    }
    Ok(())
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
        &Batches::of(queue.parent().live(), bind_info).ops,
        &submission::BIND_SPARSE_BINARY,
    )?;
    for b in bind_info {
        submission::check_timeline_batch(
            queue.parent().live(),
            b,
            &submission::BIND_SPARSE_TIMELINE,
        )?;
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

/// After a submission command: the fence holds everything the submission names (its
/// command buffers, which keep what their recordings use, its semaphores, and whatever
/// else its structs reach) until the submission is known complete; without a fence,
/// the queue does, until a later fence of the queue or an idle wait shows it complete.
fn done<B: Batch>(queue: &Queue, batches: &[B], fence: Option<&Fence>, replayed: bool) {
    let device = queue.parent();
    let live = device.live();
    let mut reached = crate::validation::Reached::keeping(live);
    for b in batches {
        b.walk(&mut reached);
    }
    let kept = reached.kept;
    let b = Batches::of(live, batches);
    let sub = submission::submitted(
        device,
        queue.raw(),
        fence,
        &b.command_buffers,
        kept,
        b.completes,
    );
    submission::record_binary_ops(device, queue.raw(), &b.ops, Some(&sub));
    // A submission whose command buffers the hazard checks replayed: what they
    // did is now the queue's.
    if replayed {
        hazards::submitted(queue, &sub, &b.command_buffers);
    }
    submission::record_timeline_values(live, &b.timeline, &sub);
    if fence.is_none() {
        queue.hold(sub);
    }
}

/// After `vkQueueSubmit`.
pub(crate) fn queue_submit_done(queue: &Queue, submits: &[SubmitInfo<'_>], fence: Option<&Fence>) {
    done(queue, submits, fence, true);
}

/// After `vkQueueSubmit2`.
pub(crate) fn queue_submit2_done(
    queue: &Queue,
    submits: &[SubmitInfo2<'_>],
    fence: Option<&Fence>,
) {
    done(queue, submits, fence, true);
}

/// After `vkQueueBindSparse` (a timeline signal tells nothing of sparse binds yet).
pub(crate) fn queue_bind_sparse_done(
    queue: &Queue,
    bind_info: &[BindSparseInfo<'_>],
    fence: &Fence,
) {
    done(queue, bind_info, Some(fence), false);
}

/// Every queue operation of the queue is complete.
pub(crate) fn queue_wait_idle_done(queue: &Queue) {
    queue.parent().live().ledger().retire_queue(queue.raw());
}

/// Every queue operation of the device is complete.
pub(crate) fn device_wait_idle_done(device: &Device) {
    device.live().ledger().retire_all();
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

/// The checks of `vkQueueSubmit` on a chained `VkDeviceGroupSubmitInfo`: drivers read
/// one device mask and index per command buffer and semaphore of the batch from it.
/// A batch's wait stage masks: no host stage, none without the feature it needs,
/// not 0 without synchronization2, and each stage one the queue's capabilities
/// support.
fn check_wait_stages(queue: &Queue, i: usize, b: &vk::SubmitInfo<'_>) -> Result<()> {
    // SAFETY: the safe setter stores the masks with the wait semaphores' count.
    let masks = unsafe { crate::state::raw_slice(b.p_wait_dst_stage_mask, b.wait_semaphore_count) };
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
        if let Some(s) = super::stages::unsupported_stage(*m, queue.queue_flags()) {
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
            crate::state::raw_slice(g.p_wait_semaphore_device_indices, g.wait_semaphore_count),
            crate::state::raw_slice(
                g.p_signal_semaphore_device_indices,
                g.signal_semaphore_count,
            ),
            crate::state::raw_slice(g.p_command_buffer_device_masks, g.command_buffer_count),
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
