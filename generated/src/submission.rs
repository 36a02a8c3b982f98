//! Queue submissions: what a submission uses is held until the submission is known
//! to be complete, by any route (its fence seen signalled, a later fence of the same
//! queue seen signalled, `Queue::wait_idle`, `Device::wait_idle`, or a timeline value
//! seen on the host that every one of its batches signals), and never released by a
//! reset. Command buffers carry their lifecycle state here, so that a buffer is
//! neither begun again nor submitted in a state Vulkan forbids.
//!
//! A fence holds its submission strongly; the device's ledger and each submitted
//! command buffer hold it weakly, so no cycle keeps a device alive. A submission
//! without a fence (a presentation) is held by the queue wrapper that made it.

use crate::handles::Device;
use crate::state::{Binary, Standing, Submission, Uses};
use crate::support::refuse;
use crate::{Error, Handle, Result};
use ash::vk;
use ash::vk::Handle as _;
use smallvec::SmallVec;
use tuff_runtime::{Vrc, Vweak};

/// The checks of a command buffer's lifecycle before a begin or a reset, over what
/// the device records of it.
impl Uses {
    /// `vkBeginCommandBuffer` is about to be called; refuses a buffer that is pending
    /// (VUID-vkBeginCommandBuffer-commandBuffer-00049), and one that is not in the
    /// initial state when its pool cannot reset it implicitly (-00050). Returns
    /// whether the buffer is still recording (its recorder was dropped without
    /// `end`), which `begin` must reset first, since begin may not restart a
    /// recording (-00049 again).
    pub(crate) fn check_begin(&self, device: &Device, pool_resets: bool) -> Result<bool> {
        let (begun, recording) = self.lifecycle();
        if !pool_resets && begun {
            return Err(Error::Validation {
                vuid: "VUID-vkBeginCommandBuffer-commandBuffer-00050",
                message: "the command buffer was recorded before and its pool was not created with RESET_COMMAND_BUFFER".into(),
            });
        }
        if self.is_pending(device) {
            return Err(Error::Validation {
                vuid: "VUID-vkBeginCommandBuffer-commandBuffer-00049",
                message: "the command buffer is pending: a submission that uses it may still be executing (wait for its fence first)".into(),
            });
        }
        Ok(recording)
    }

    /// `vkResetCommandBuffer` is about to be called: refuses a pending buffer
    /// (VUID-vkResetCommandBuffer-commandBuffer-00045) and a buffer of a pool
    /// without RESET_COMMAND_BUFFER (-00046).
    pub(crate) fn check_reset(&self, device: &Device, pool_resets: bool) -> Result<()> {
        if !pool_resets {
            return Err(Error::Validation {
                vuid: "VUID-vkResetCommandBuffer-commandBuffer-00046",
                message: "the command buffer's pool was not created with RESET_COMMAND_BUFFER"
                    .into(),
            });
        }
        if self.is_pending(device) {
            return Err(Error::Validation {
                vuid: "VUID-vkResetCommandBuffer-commandBuffer-00045",
                message: "the command buffer is pending: a submission that uses it may still be executing (wait for its fence first)".into(),
            });
        }
        Ok(())
    }
}

/// The rules a submission command checks of its command buffers and its fence, by
/// command.
pub(crate) struct SubmitRules {
    /// The fence must be unsignalled.
    pub fence_signalled: &'static str,
    /// The fence must not be in use by another pending queue operation.
    pub fence_pending: &'static str,
    /// A command buffer must not be secondary.
    pub secondary: &'static str,
    /// A command buffer must be executable or pending.
    pub executable: &'static str,
    /// A pending command buffer must allow simultaneous use.
    pub simultaneous: &'static str,
    /// A secondary executed by a command buffer must be executable or pending.
    pub secondary_executable: &'static str,
    /// A pending secondary must allow simultaneous use.
    pub secondary_simultaneous: &'static str,
}

/// The rules of `vkQueueSubmit`.
pub(crate) const SUBMIT: SubmitRules = SubmitRules {
    fence_signalled: "VUID-vkQueueSubmit-fence-00063",
    fence_pending: "VUID-vkQueueSubmit-fence-00064",
    secondary: "VUID-VkSubmitInfo-pCommandBuffers-00075",
    executable: "VUID-vkQueueSubmit-pCommandBuffers-00070",
    simultaneous: "VUID-vkQueueSubmit-pCommandBuffers-00071",
    secondary_executable: "VUID-vkQueueSubmit-pCommandBuffers-00072",
    secondary_simultaneous: "VUID-vkQueueSubmit-pCommandBuffers-00073",
};

/// The rules of `vkQueueSubmit2`.
pub(crate) const SUBMIT2: SubmitRules = SubmitRules {
    fence_signalled: "VUID-vkQueueSubmit2-fence-04894",
    fence_pending: "VUID-vkQueueSubmit2-fence-04895",
    secondary: "VUID-VkCommandBufferSubmitInfo-commandBuffer-03890",
    executable: "VUID-vkQueueSubmit2-commandBuffer-03874",
    simultaneous: "VUID-vkQueueSubmit2-commandBuffer-03875",
    secondary_executable: "VUID-vkQueueSubmit2-commandBuffer-03876",
    secondary_simultaneous: "VUID-vkQueueSubmit2-commandBuffer-03877",
};

/// The rules of `vkAcquireNextImageKHR` for its fence (it has no command buffers).
#[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
pub(crate) const ACQUIRE: SubmitRules = SubmitRules {
    fence_signalled: "VUID-vkAcquireNextImageKHR-fence-01287",
    fence_pending: "VUID-vkAcquireNextImageKHR-fence-01287",
    secondary: "",
    executable: "",
    simultaneous: "",
    secondary_executable: "",
    secondary_simultaneous: "",
};

/// The rules of `vkQueueBindSparse` (it has no command buffers).
pub(crate) const BIND_SPARSE: SubmitRules = SubmitRules {
    fence_signalled: "VUID-vkQueueBindSparse-fence-01113",
    fence_pending: "VUID-vkQueueBindSparse-fence-01114",
    secondary: "",
    executable: "",
    simultaneous: "",
    secondary_executable: "",
    secondary_simultaneous: "",
};

/// Checks that `fence` may be signalled by a new queue operation: unsignalled, and
/// not in use by one that may still be executing.
pub(crate) fn check_fence(fence: &crate::Fence, rules: &SubmitRules) -> Result<()> {
    // Asked through the fence's own device: the queue's, unless the caller broke
    // `commonparent`, which is not this check's to report.
    let device = fence.parent();
    if let Some(sub) = fence.submission() {
        if !sub.poll(device) {
            return refuse(
                rules.fence_pending,
                "the fence belongs to a queue operation that may still be executing",
            );
        }
    }
    // SAFETY: the fence is a live wrapper of this device.
    let r = unsafe { (device.fns().fp_v1_0().get_fence_status)(device.raw(), fence.raw()) };
    match r {
        vk::Result::NOT_READY => Ok(()),
        vk::Result::SUCCESS => refuse(
            rules.fence_signalled,
            "the fence is signalled; reset it before submitting with it",
        ),
        e => Err(Error::Vk(e)),
    }
}

/// Checks the command buffers of one submission command against `rules`.
pub(crate) fn check_command_buffers(
    device: &Device,
    cbs: &[vk::CommandBuffer],
    rules: &SubmitRules,
) -> Result<()> {
    for (i, raw) in cbs.iter().enumerate() {
        let Some(uses) = device.command_buffer_uses(*raw) else {
            continue;
        };
        let Standing {
            secondary,
            executable,
            simultaneous,
            ..
        } = uses.standing();
        let secondaries = uses.secondaries();
        if secondary {
            return refuse(
                rules.secondary,
                "a secondary command buffer is submitted to a queue",
            );
        }
        if !executable {
            return refuse(
                rules.executable,
                "a command buffer is not executable: it was not ended, a check failed while it was recorded, or it was recorded for one submission and submitted",
            );
        }
        if !simultaneous && (cbs[..i].contains(raw) || uses.is_pending(device)) {
            return refuse(
                rules.simultaneous,
                "a command buffer without SIMULTANEOUS_USE is submitted while a submission that uses it may still be executing",
            );
        }
        for (sec, generation, links) in secondaries {
            let Standing {
                generation: now,
                executable,
                simultaneous,
                links: links_now,
                ..
            } = sec.standing();
            if !simultaneous && links_now != links {
                return refuse(
                    rules.executable,
                    "a secondary command buffer it executes, without SIMULTANEOUS_USE, was recorded into another primary since, which leaves this one invalid",
                );
            }
            if now != generation || !executable {
                return refuse(
                    rules.secondary_executable,
                    "a secondary command buffer it executes was recorded again or reset since",
                );
            }
            if !simultaneous && sec.is_pending(device) {
                return refuse(
                    rules.secondary_simultaneous,
                    "a secondary command buffer it executes without SIMULTANEOUS_USE is pending",
                );
            }
        }
    }
    Ok(())
}

/// Refuses command buffers that need, at their start, image layouts other than
/// those the device's earlier submissions and the command buffers before them in
/// `cbs` leave (the rule of the command that named the layout).
pub(crate) fn check_layouts(device: &Device, cbs: &[vk::CommandBuffer]) -> Result<()> {
    let mut overlay = crate::state::layouts::Overlay::new(device.live());
    for raw in cbs {
        if let Some(layouts) = device.command_buffer_uses(*raw).and_then(|u| u.layouts()) {
            overlay.check(&layouts)?;
            overlay.apply(&layouts);
        }
    }
    Ok(())
}

/// Refuses command buffers that use, before resetting it, a query that the
/// device's earlier submissions, its host resets and the command buffers before
/// them in `cbs` leave other than reset (the rule of the command that uses it).
pub(crate) fn check_queries(device: &Device, cbs: &[vk::CommandBuffer]) -> Result<()> {
    let mut overlay = crate::state::queries::Overlay::new(device.live());
    for raw in cbs {
        if let Some(queries) = device.command_buffer_uses(*raw).and_then(|u| u.queries()) {
            overlay.check(&queries)?;
            overlay.apply(&queries);
        }
    }
    Ok(())
}

/// Records the query states that `cbs`, submitted in this order as `sub`, leave.
fn record_queries(device: &Device, cbs: &[vk::CommandBuffer], sub: &Vrc<Submission>) {
    let mut overlay = crate::state::queries::Overlay::new(device.live());
    for raw in cbs {
        if let Some(queries) = device.command_buffer_uses(*raw).and_then(|u| u.queries()) {
            overlay.apply(&queries);
        }
    }
    overlay.commit(sub);
}

/// Refuses command buffers whose waits on events break on the states the device's
/// earlier submissions, the host and the command buffers before them in `cbs`
/// leave, or whose resets race a wait that may still be executing (the rule of the
/// command that waits or resets).
pub(crate) fn check_event_states(device: &Device, cbs: &[vk::CommandBuffer]) -> Result<()> {
    let mut overlay = crate::state::events::Overlay::new(device.live());
    for raw in cbs {
        if let Some(events) = device
            .command_buffer_uses(*raw)
            .and_then(|u| u.event_states())
        {
            overlay.check(&events, |sub| !sub.poll(device))?;
            overlay.apply(&events);
        }
    }
    Ok(())
}

/// Records the event states that `cbs`, submitted in this order as `sub`, leave.
fn record_event_states(device: &Device, cbs: &[vk::CommandBuffer], sub: &Vrc<Submission>) {
    let mut overlay = crate::state::events::Overlay::new(device.live());
    for raw in cbs {
        if let Some(events) = device
            .command_buffer_uses(*raw)
            .and_then(|u| u.event_states())
        {
            overlay.apply(&events);
        }
    }
    overlay.commit(sub);
}

/// The descriptor sets that `cbs` and the secondaries they execute bound (each with
/// the generation it had then), and the events their event commands name.
pub(crate) fn used(
    device: &Device,
    cbs: &[vk::CommandBuffer],
) -> (crate::state::SetsUsed, crate::state::EventsUsed) {
    let (mut sets, mut events) = (SmallVec::new(), SmallVec::new());
    for raw in cbs {
        if let Some(uses) = device.command_buffer_uses(*raw) {
            uses.used(&mut sets, &mut events);
        }
    }
    sets.sort_unstable();
    sets.dedup();
    events.sort_unstable();
    events.dedup();
    (sets, events)
}

/// Refuses command buffers whose event commands name an event (of `events`, those
/// they name) that a submission to another queue, which may still be executing,
/// names too (`vuid` names the rule).
pub(crate) fn check_events(
    device: &Device,
    queue: vk::Queue,
    events: &crate::state::EventsUsed,
    vuid: &'static str,
) -> Result<()> {
    for &event in events {
        for sub in device.live().event_submissions(event, queue) {
            if !sub.poll(device) {
                return refuse(
                    vuid,
                    format!("event 0x{event:x} is named by a command of a submission to another queue that may still be executing"),
                );
            }
        }
    }
    Ok(())
}

/// Takes the device's descriptor gate for a submission (held until its bookkeeping
/// is done, so no update runs between this check and the submission's record of the
/// sets it uses), and refuses command buffers that bound a descriptor set (of
/// `sets`, those they bound) which an update has changed since: the update left them
/// invalid (`executable` names the rule).
pub(crate) fn sets_hold<'d>(
    device: &'d Device,
    sets: &crate::state::SetsUsed,
    executable: &'static str,
) -> Result<tuff_runtime::VutexGuard<'d, ()>> {
    let gate = device.live().descriptor_gate();
    if let Some(set) = device.live().stale_set(sets) {
        refuse(
            executable,
            format!("a command buffer is invalid: descriptor set 0x{set:x}, which it binds, was updated since it was recorded (update sets before recording, or bindings with UPDATE_AFTER_BIND)"),
        )?;
    }
    Ok(gate)
}

/// Records the image layouts that `cbs`, submitted in this order, leave.
fn record_layouts(device: &Device, cbs: &[vk::CommandBuffer]) {
    let mut overlay = crate::state::layouts::Overlay::new(device.live());
    for raw in cbs {
        if let Some(layouts) = device.command_buffer_uses(*raw).and_then(|u| u.layouts()) {
            overlay.apply(&layouts);
        }
    }
    overlay.commit();
}

/// Records a submission of `cbs` (and the secondaries they execute) and of what
/// `kept` holds, made to `queue` with `fence`; the fence holds it from now on.
pub(crate) fn submitted(
    device: &Device,
    queue: vk::Queue,
    fence: Option<&crate::Fence>,
    cbs: &[vk::CommandBuffer],
    kept: crate::state::Kept,
    batches: crate::state::Completes,
) -> Vrc<Submission> {
    let sub = device.live().ledger().record(
        queue,
        fence.map_or(vk::Fence::null(), |f| f.raw()),
        kept,
        batches,
    );
    for raw in cbs {
        if let Some(uses) = device.command_buffer_uses(*raw) {
            uses.mark(&sub);
        }
    }
    record_layouts(device, cbs);
    record_queries(device, cbs, &sub);
    record_event_states(device, cbs, &sub);
    let (sets, events) = used(device, cbs);
    device.live().sets_submitted(&sets, &sub);
    device.live().events_submitted(&events, queue, &sub);
    if let Some(f) = fence {
        f.track(sub.clone());
    }
    sub
}

/// `vkResetCommandPool` is about to be called on a pool whose buffers have `uses`:
/// refuses a pending buffer (VUID-vkResetCommandPool-commandPool-00040) and a buffer
/// that a live recorder is recording into, whose commands after the reset would be
/// recorded into a buffer that is not recording (VUID-vkEndCommandBuffer-commandBuffer-00059).
pub(crate) fn check_pool_reset(device: &Device, uses: &[Vrc<Uses>]) -> Result<()> {
    for u in uses {
        if u.is_pending(device) {
            return Err(Error::Validation {
                vuid: "VUID-vkResetCommandPool-commandPool-00040",
                message: "a command buffer of the pool is pending: a submission that uses it may still be executing (wait for its fence first)".into(),
            });
        }
        if u.has_recorder() {
            return Err(Error::Validation {
                vuid: "VUID-vkEndCommandBuffer-commandBuffer-00059",
                message: "a recorder of a command buffer of the pool is alive; end or drop it before the pool is reset".into(),
            });
        }
    }
    Ok(())
}

/// The rules of a batch's timeline semaphore values, by the struct that holds it.
pub(crate) struct TimelineRules {
    /// A timeline semaphore without a `VkTimelineSemaphoreSubmitInfo`.
    pub missing: &'static str,
    /// Wait values that are not one per wait semaphore.
    pub waits: &'static str,
    /// Signal values that are not one per signal semaphore.
    pub signals: &'static str,
}

pub(crate) const SUBMIT_TIMELINE: TimelineRules = TimelineRules {
    missing: "VUID-VkSubmitInfo-pWaitSemaphores-03239",
    waits: "VUID-VkSubmitInfo-pNext-03240",
    signals: "VUID-VkSubmitInfo-pNext-03241",
};

pub(crate) const BIND_SPARSE_TIMELINE: TimelineRules = TimelineRules {
    missing: "VUID-VkBindSparseInfo-pWaitSemaphores-03246",
    waits: "VUID-VkBindSparseInfo-pNext-03247",
    signals: "VUID-VkBindSparseInfo-pNext-03248",
};

/// Refuses a batch whose timeline semaphores have no value, or fewer values than
/// semaphores: the driver reads one value per semaphore from the chained
/// `VkTimelineSemaphoreSubmitInfo`.
pub(crate) fn check_timeline_batch(
    live: &crate::state::Live,
    batch: &impl ArrayBatch,
    rules: &TimelineRules,
) -> Result<()> {
    let (waits, signals) = batch.semaphores();
    let wait_timeline = waits.iter().any(|s| live.is_timeline(*s));
    let signal_timeline = signals.iter().any(|s| live.is_timeline(*s));
    if !wait_timeline && !signal_timeline {
        return Ok(());
    }
    let Some(info) = batch.timeline_info() else {
        return Err(Error::Validation {
            vuid: rules.missing,
            message: "a batch names a timeline semaphore but chains no TimelineSemaphoreSubmitInfo"
                .into(),
        });
    };
    // A count set on its own leaves its values unset: the driver would read them.
    if wait_timeline && !waits.is_empty() && info.p_wait_semaphore_values.is_null() {
        return Err(Error::Validation {
            vuid: rules.waits,
            message: "the batch waits on a timeline semaphore but its wait values are not set"
                .into(),
        });
    }
    if signal_timeline && !signals.is_empty() && info.p_signal_semaphore_values.is_null() {
        return Err(Error::Validation {
            vuid: rules.signals,
            message: "the batch signals a timeline semaphore but its signal values are not set"
                .into(),
        });
    }
    if wait_timeline && info.wait_semaphore_value_count as usize != waits.len() {
        return Err(Error::Validation {
            vuid: rules.waits,
            message: format!(
                "{} wait values for {} wait semaphores",
                info.wait_semaphore_value_count,
                waits.len()
            ),
        });
    }
    if signal_timeline && info.signal_semaphore_value_count as usize != signals.len() {
        return Err(Error::Validation {
            vuid: rules.signals,
            message: format!(
                "{} signal values for {} signal semaphores",
                info.signal_semaphore_value_count,
                signals.len()
            ),
        });
    }
    Ok(())
}

/// Whether a semaphore create info asks for a timeline semaphore.
pub(crate) fn timeline_initial(info: &crate::structs::SemaphoreCreateInfo<'_>) -> Option<u64> {
    // SAFETY: the safe create info only chains structs pushed through `push_next`;
    // the sType says what the node is.
    unsafe { crate::support::chain_nodes(info.p_next) }
        .find(|n| n.s_type == vk::StructureType::SEMAPHORE_TYPE_CREATE_INFO)
        .and_then(|n| {
            let t = unsafe {
                &*(n as *const vk::BaseInStructure<'_>).cast::<vk::SemaphoreTypeCreateInfo<'_>>()
            };
            (t.semaphore_type == vk::SemaphoreType::TIMELINE).then_some(t.initial_value)
        })
}

/// One timeline operation of a submission: the semaphore, its value, whether it
/// signals (`true`) or waits, and the index of its batch in the call.
pub(crate) type TimelineOp = (vk::Semaphore, u64, bool, usize);

/// The rules a timeline operation's value breaks, by what they check.
pub(crate) struct TimelineValueRules {
    /// A signal not above the value the semaphore has when it executes.
    pub signal_above: &'static str,
    /// A wait too far from the semaphore's values.
    pub wait_difference: &'static str,
    /// A signal too far from them.
    pub signal_difference: &'static str,
}

/// The rules of `vkQueueSubmit`'s `VkTimelineSemaphoreSubmitInfo` values.
pub(crate) const SUBMIT_TIMELINE_VALUES: TimelineValueRules = TimelineValueRules {
    signal_above: "VUID-VkSubmitInfo-pSignalSemaphores-03242",
    wait_difference: "VUID-VkSubmitInfo-pWaitSemaphores-03243",
    signal_difference: "VUID-VkSubmitInfo-pSignalSemaphores-03244",
};

/// The rules of `vkQueueSubmit2`'s `VkSemaphoreSubmitInfo` values.
pub(crate) const SUBMIT2_TIMELINE_VALUES: TimelineValueRules = TimelineValueRules {
    signal_above: "VUID-VkSubmitInfo2-semaphore-03882",
    wait_difference: "VUID-VkSubmitInfo2-semaphore-03884",
    signal_difference: "VUID-VkSubmitInfo2-semaphore-03883",
};

/// Refuses timeline operations (in submission order) whose values the semaphore
/// may not take: a signal must be above every value the semaphore has or is given
/// before it executes, which is at most the largest value signalled or submitted to
/// be signalled (a stricter bound than the rule's, which speaks of execution order,
/// as the order in which queues execute is not known); every value must lie within
/// `max_difference` of the semaphore's possible current values and of the values of
/// its pending operations, including those earlier in the same call.
pub(crate) fn check_timeline_values(
    live: &crate::state::Live,
    ops: &[TimelineOp],
    max_difference: u64,
    rules: &TimelineValueRules,
) -> Result<()> {
    if ops.is_empty() {
        return Ok(());
    }
    let mut timelines = live.timelines();
    for (i, (semaphore, value, signal, _)) in ops.iter().enumerate() {
        let Some(t) = timelines.get_mut(&semaphore.as_raw()) else {
            continue;
        };
        t.prune();
        let earlier = ops[..i].iter().filter(|(s, ..)| s == semaphore);
        let max_signal = earlier
            .clone()
            .filter(|(_, _, s, _)| *s)
            .map(|(_, v, ..)| *v)
            .fold(t.max_signal.max(t.known), u64::max);
        if *signal && *value <= max_signal {
            return refuse(
                rules.signal_above,
                format!("timeline semaphore 0x{:x} is signalled to {value}, which is not above {max_signal}, a value it has or an earlier signal gives it", semaphore.as_raw()),
            );
        }
        let values = t
            .pending
            .iter()
            .map(|(v, ..)| *v)
            .chain(earlier.map(|(_, v, ..)| *v))
            .chain([t.known, max_signal]);
        let (lo, hi) = values.fold((u64::MAX, 0), |(lo, hi), v| (lo.min(v), hi.max(v)));
        if value.abs_diff(lo) > max_difference || value.abs_diff(hi) > max_difference {
            return refuse(
                if *signal {
                    rules.signal_difference
                } else {
                    rules.wait_difference
                },
                format!("timeline semaphore 0x{:x} is given {value}, more than maxTimelineSemaphoreValueDifference ({max_difference}) from a value it may have or that a pending operation gives it ({lo} to {hi})", semaphore.as_raw()),
            );
        }
    }
    Ok(())
}

/// Records timeline operations that `sub` submitted.
pub(crate) fn record_timeline_values(
    live: &crate::state::Live,
    ops: &[TimelineOp],
    sub: &Vrc<Submission>,
) {
    if ops.is_empty() {
        return;
    }
    let mut timelines = live.timelines();
    for (semaphore, value, signal, batch) in ops {
        if let Some(t) = timelines.get_mut(&semaphore.as_raw()) {
            t.prune();
            t.pending
                .push((*value, *signal, Vrc::downgrade(sub), *batch));
            if *signal {
                t.max_signal = t.max_signal.max(*value);
            }
        }
    }
}

/// Refuses a semaphore of the wrong type for a command that takes only one type.
pub(crate) fn check_semaphore_type(
    live: &crate::state::Live,
    semaphores: &[vk::Semaphore],
    timeline: bool,
    vuid: &'static str,
) -> Result<()> {
    if semaphores.iter().any(|s| live.is_timeline(*s) != timeline) {
        return Err(Error::Validation {
            vuid,
            message: format!(
                "a semaphore is not a {} semaphore",
                if timeline { "timeline" } else { "binary" }
            ),
        });
    }
    Ok(())
}

/// The host synchronization of an object a debug name or tag is given to: that of a
/// live object of the device. The device itself, its physical device and instance
/// have none the device can hold: with `multi_thread`, where another thread could
/// use them meanwhile, naming them is refused. Any other handle the device does not
/// list (a dropped object, a surface or messenger of the instance) is refused with
/// `vuid`, the rule that the handle be a valid one of its type.
#[allow(dead_code)]
pub(crate) fn named_object_sync(
    device: &Device,
    ty: vk::ObjectType,
    raw: u64,
    vuid: &'static str,
) -> Result<tuff_runtime::HostSync> {
    use ash::vk::Handle as _;
    if let Some(sync) = device.live().sync_of(ty, raw) {
        return Ok(sync);
    }
    // A null handle of no type names nothing the driver could reach; the struct's
    // own check refuses it (VUID-VkDebugUtilsObjectNameInfoEXT-objectType-02589).
    if ty == vk::ObjectType::UNKNOWN && raw == 0 {
        return Ok(tuff_runtime::HostSync::new());
    }
    let physical = device.parent();
    let own = match ty {
        vk::ObjectType::DEVICE => raw == device.raw().as_raw(),
        vk::ObjectType::PHYSICAL_DEVICE => raw == physical.raw().as_raw(),
        vk::ObjectType::INSTANCE => raw == physical.parent().raw().as_raw(),
        _ => false,
    };
    match own {
        true if tuff_runtime::MULTI_THREAD => Err(Error::Misuse(
            "with multi_thread, only the device's objects can be named or tagged through it: another thread could use the device or the instance meanwhile",
        )),
        true => Ok(tuff_runtime::HostSync::new()),
        // Drivers reach the name through the handle, as a pointer: a handle of no
        // live object (dropped, of another type, or never made through the wrappers)
        // would be used after free.
        false => Err(Error::Validation {
            vuid,
            message: format!(
                "objectHandle ({raw:#x}) must be a live object of type {ty:?}: the device, its instance or physical device, or an object made through the wrappers"
            ),
        }),
    }
}

/// A binary semaphore's state, as a check reads it.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Seen {
    Unsignaled,
    Signaled,
    /// A wait submitted to this queue may still be pending.
    Waiting(vk::Queue),
}

/// One semaphore operation of a submission command, in the order it defines them
/// (each batch's waits, then its signals).
#[derive(Clone, Copy)]
pub(crate) enum SemOp {
    Wait(vk::Semaphore),
    Signal(vk::Semaphore),
}

/// The rules a command's semaphore operations break: a wait on a semaphore with no
/// signal submitted, and a signal of one that is signaled (or whose wait on another
/// queue, or on no queue for an acquire, may still be pending).
pub(crate) struct BinaryRules {
    pub wait_unsignaled: &'static str,
    pub signal_signaled: &'static str,
    /// Where a pending wait is a rule of its own (an acquire's).
    pub signal_pending: &'static str,
}

/// The rules of `vkQueueSubmit`.
pub(crate) const SUBMIT_BINARY: BinaryRules = BinaryRules {
    wait_unsignaled: "VUID-vkQueueSubmit-pWaitSemaphores-03238",
    signal_signaled: "VUID-vkQueueSubmit-pSignalSemaphores-00067",
    signal_pending: "VUID-vkQueueSubmit-pSignalSemaphores-00067",
};

/// The rules of `vkQueueSubmit2`.
pub(crate) const SUBMIT2_BINARY: BinaryRules = BinaryRules {
    wait_unsignaled: "VUID-vkQueueSubmit2-semaphore-03873",
    signal_signaled: "VUID-vkQueueSubmit2-semaphore-03868",
    signal_pending: "VUID-vkQueueSubmit2-semaphore-03868",
};

/// The rules of `vkQueueBindSparse`.
pub(crate) const BIND_SPARSE_BINARY: BinaryRules = BinaryRules {
    wait_unsignaled: "VUID-vkQueueBindSparse-pWaitSemaphores-03245",
    signal_signaled: "VUID-vkQueueBindSparse-pSignalSemaphores-01115",
    signal_pending: "VUID-vkQueueBindSparse-pSignalSemaphores-01115",
};

/// The rules of `vkQueuePresentKHR` (it only waits).
#[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
pub(crate) const PRESENT_BINARY: BinaryRules = BinaryRules {
    wait_unsignaled: "VUID-vkQueuePresentKHR-pWaitSemaphores-03268",
    signal_signaled: "",
    signal_pending: "",
};

/// The rules of `vkAcquireNextImageKHR` (it only signals, on no queue).
#[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
pub(crate) const ACQUIRE_BINARY: BinaryRules = BinaryRules {
    wait_unsignaled: "",
    signal_signaled: "VUID-vkAcquireNextImageKHR-semaphore-01286",
    signal_pending: "VUID-vkAcquireNextImageKHR-semaphore-01779",
};

/// The rules of `vkAcquireNextImage2KHR`.
#[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
pub(crate) const ACQUIRE2_BINARY: BinaryRules = BinaryRules {
    wait_unsignaled: "",
    signal_signaled: "VUID-VkAcquireNextImageInfoKHR-semaphore-01288",
    signal_pending: "VUID-VkAcquireNextImageInfoKHR-semaphore-01781",
};

fn seen(device: &Device, state: Option<&Binary>) -> Seen {
    match state {
        None => Seen::Unsignaled,
        Some(Binary::Signaled) => Seen::Signaled,
        Some(Binary::Waited { queue, by }) => match by.upgrade() {
            Some(sub) if !sub.poll(device) => Seen::Waiting(*queue),
            _ => Seen::Unsignaled,
        },
    }
}

/// Checks a command's binary semaphore operations, in order, against what was
/// submitted before: a wait needs a signal submitted and not waited on since, and a
/// signal needs the semaphore unsignaled, or waited on earlier on the same queue
/// (`queue` null for an acquire, which no queue orders).
pub(crate) fn check_binary_ops(
    device: &Device,
    queue: vk::Queue,
    ops: &[SemOp],
    rules: &BinaryRules,
) -> Result<()> {
    let live = device.live();
    let ops: Vec<SemOp> = ops
        .iter()
        .copied()
        .filter(|op| match op {
            SemOp::Wait(s) | SemOp::Signal(s) => !live.is_timeline(*s),
        })
        .collect();
    if ops.is_empty() {
        return Ok(());
    }
    // What this command's earlier operations did, over what was submitted before.
    let mut now: Vec<(vk::Semaphore, Seen)> = Vec::new();
    for op in ops {
        let (SemOp::Wait(s) | SemOp::Signal(s)) = op;
        let state = match now.iter().find(|(n, _)| *n == s) {
            Some((_, seen)) => *seen,
            None => {
                // Polled outside the lock: a signalled fence retires submissions.
                let state = live.binaries().get(&s.as_raw()).map(|b| match b {
                    Binary::Signaled => Binary::Signaled,
                    Binary::Waited { queue, by } => Binary::Waited {
                        queue: *queue,
                        by: by.clone(),
                    },
                });
                seen(device, state.as_ref())
            }
        };
        let next = match op {
            SemOp::Wait(_) => {
                if state != Seen::Signaled {
                    return refuse(
                        rules.wait_unsignaled,
                        format!("the binary semaphore {s:?} is waited on, but no signal operation was submitted for it since its last wait"),
                    );
                }
                Seen::Waiting(queue)
            }
            SemOp::Signal(_) => {
                match state {
                    Seen::Signaled => {
                        return refuse(
                            rules.signal_signaled,
                            format!("the binary semaphore {s:?} is signaled, or a signal operation for it was submitted and not waited on"),
                        )
                    }
                    Seen::Waiting(q) if q != queue || queue == vk::Queue::null() => {
                        return refuse(
                            rules.signal_pending,
                            format!("a wait on the binary semaphore {s:?} may still be pending{}", if queue == vk::Queue::null() { "" } else { " on another queue" }),
                        )
                    }
                    _ => {}
                }
                Seen::Signaled
            }
        };
        match now.iter_mut().find(|(n, _)| *n == s) {
            Some(entry) => entry.1 = next,
            None => now.push((s, next)),
        }
    }
    Ok(())
}

/// Records a command's binary semaphore operations, in order: a signal leaves the
/// semaphore signaled, a wait leaves it waited on by `by` on `queue`.
pub(crate) fn record_binary_ops(
    device: &Device,
    queue: vk::Queue,
    ops: &[SemOp],
    by: Option<&Vrc<Submission>>,
) {
    if ops.is_empty() {
        return;
    }
    let live = device.live();
    let mut binaries = live.binaries();
    for op in ops {
        match *op {
            SemOp::Wait(s) if !live.is_timeline(s) => {
                let by = by.map_or_else(Vweak::new, Vrc::downgrade);
                binaries.insert(s.as_raw(), Binary::Waited { queue, by });
            }
            SemOp::Signal(s) if !live.is_timeline(s) => {
                binaries.insert(s.as_raw(), Binary::Signaled);
            }
            _ => {}
        }
    }
}

/// A submission command's batches read into one shape, so that each rule of
/// `vkQueueSubmit`, `vkQueueSubmit2` and `vkQueueBindSparse` is written once.
#[derive(Default)]
pub(crate) struct Batches {
    /// The command buffers of every batch, in order.
    pub command_buffers: SmallVec<[vk::CommandBuffer; 8]>,
    /// The semaphore operations: each batch's waits, then its signals. Its lists
    /// hold a frame's usual few inline: a submission reads its batches three times
    /// (checks, hold, done) and allocates for none of them.
    pub ops: SmallVec<[SemOp; 4]>,
    /// The timeline operations among them that carry a value, in the same order.
    pub timeline: SmallVec<[TimelineOp; 2]>,
    /// For each batch, the timeline values it signals once all its commands are done.
    pub completes: crate::state::Completes,
}

/// One semaphore of a batch as [`Batches`] reads it: the semaphore, its timeline
/// value where the batch gives one, and (for a signal) whether it signals only once
/// all of the batch's commands are done.
type Named = (vk::Semaphore, Option<u64>, bool);

impl Batches {
    /// Reads a submission command's batches.
    pub(crate) fn of<B: Batch>(live: &crate::state::Live, batches: &[B]) -> Batches {
        let mut all = Batches::default();
        for b in batches {
            b.read(live, &mut all);
        }
        all
    }

    /// Appends one batch.
    fn push(
        &mut self,
        live: &crate::state::Live,
        waits: impl Iterator<Item = Named>,
        signals: impl Iterator<Item = Named>,
        command_buffers: impl Iterator<Item = vk::CommandBuffer>,
    ) {
        self.command_buffers.extend(command_buffers);
        let mut completes = Vec::new();
        for (semaphore, value, _) in waits {
            self.ops.push(SemOp::Wait(semaphore));
            if let Some(value) = value.filter(|_| live.is_timeline(semaphore)) {
                self.timeline
                    .push((semaphore, value, false, self.completes.len()));
            }
        }
        for (semaphore, value, whole) in signals {
            self.ops.push(SemOp::Signal(semaphore));
            if let Some(value) = value.filter(|_| live.is_timeline(semaphore)) {
                self.timeline
                    .push((semaphore, value, true, self.completes.len()));
                if whole {
                    completes.push((semaphore, value));
                }
            }
        }
        self.completes.push(completes);
    }

    /// Appends a batch that names its semaphores in arrays and their timeline values
    /// in a chained `VkTimelineSemaphoreSubmitInfo`; `whole` says whether a signal
    /// tells that the whole batch is done.
    fn push_arrays(
        &mut self,
        live: &crate::state::Live,
        batch: &impl ArrayBatch,
        command_buffers: &[vk::CommandBuffer],
        whole: bool,
    ) {
        let (waits, signals) = batch.semaphores();
        // SAFETY: a safe struct's arrays, each stored with its length.
        let (wait_values, signal_values) =
            batch
                .timeline_info()
                .map_or((&[][..], &[][..]), |info| unsafe {
                    (
                        crate::state::raw_slice(
                            info.p_wait_semaphore_values,
                            info.wait_semaphore_value_count,
                        ),
                        crate::state::raw_slice(
                            info.p_signal_semaphore_values,
                            info.signal_semaphore_value_count,
                        ),
                    )
                });
        let named =
            |values: &[u64], j: usize, s: &vk::Semaphore| (*s, values.get(j).copied(), whole);
        self.push(
            live,
            waits
                .iter()
                .enumerate()
                .map(|(j, s)| named(wait_values, j, s)),
            signals
                .iter()
                .enumerate()
                .map(|(j, s)| named(signal_values, j, s)),
            command_buffers.iter().copied(),
        );
    }
}

/// A batch that names its semaphores in arrays and their timeline values in a
/// chained `VkTimelineSemaphoreSubmitInfo`: `VkSubmitInfo` and `VkBindSparseInfo`.
pub(crate) trait ArrayBatch {
    /// Its wait and its signal semaphores.
    fn semaphores(&self) -> (&[vk::Semaphore], &[vk::Semaphore]);
    /// Its chained `VkTimelineSemaphoreSubmitInfo`, if any.
    fn timeline_info(&self) -> Option<&vk::TimelineSemaphoreSubmitInfo<'_>>;
}

/// [`ArrayBatch`] for structs whose fields share the names of `VkSubmitInfo`'s.
macro_rules! array_batch {
    ($($ty:ty),*) => {$(
        impl ArrayBatch for $ty {
            fn semaphores(&self) -> (&[vk::Semaphore], &[vk::Semaphore]) {
                // SAFETY: the safe struct stores each array with its length.
                unsafe {
                    (
                        crate::state::raw_slice(self.p_wait_semaphores, self.wait_semaphore_count),
                        crate::state::raw_slice(self.p_signal_semaphores, self.signal_semaphore_count),
                    )
                }
            }

            fn timeline_info(&self) -> Option<&vk::TimelineSemaphoreSubmitInfo<'_>> {
                // SAFETY: the safe struct chains only structs pushed through
                // `push_next`; the sType says what the node is.
                unsafe { crate::support::chain_nodes(self.p_next) }
                    .find(|n| n.s_type == vk::StructureType::TIMELINE_SEMAPHORE_SUBMIT_INFO)
                    .map(|n| unsafe {
                        &*(n as *const vk::BaseInStructure<'_>)
                            .cast::<vk::TimelineSemaphoreSubmitInfo<'_>>()
                    })
            }
        }
    )*};
}

array_batch!(
    crate::structs::SubmitInfo<'_>,
    crate::structs::BindSparseInfo<'_>
);

/// A batch of a submission command: `VkSubmitInfo`, `VkSubmitInfo2` and
/// `VkBindSparseInfo` each read into [`Batches`], and each say what the submission
/// keeps alive.
pub(crate) trait Batch {
    /// Appends this batch to `all`.
    fn read(&self, live: &crate::state::Live, all: &mut Batches);
    /// Walks what this batch names: to keep it until the submission completes, or
    /// to check it belongs to the queue's device.
    fn walk(&self, out: &mut crate::validation::Reached<'_>);
}

impl Batch for crate::structs::SubmitInfo<'_> {
    fn read(&self, live: &crate::state::Live, all: &mut Batches) {
        // SAFETY: the safe struct stores the array with its length.
        let command_buffers =
            unsafe { crate::state::raw_slice(self.p_command_buffers, self.command_buffer_count) };
        all.push_arrays(live, self, command_buffers, true);
    }

    fn walk(&self, out: &mut crate::validation::Reached<'_>) {
        // SAFETY: the safe struct stores every array with its length.
        unsafe { crate::reach::submit_info(self.as_raw(), out) }
    }
}

impl Batch for crate::structs::BindSparseInfo<'_> {
    fn read(&self, live: &crate::state::Live, all: &mut Batches) {
        // A timeline signal tells nothing of sparse binds yet.
        all.push_arrays(live, self, &[], false);
    }

    fn walk(&self, out: &mut crate::validation::Reached<'_>) {
        // SAFETY: the safe struct stores every array with its length.
        unsafe { crate::reach::bind_sparse_info(self.as_raw(), out) }
    }
}

impl Batch for crate::structs::SubmitInfo2<'_> {
    fn read(&self, live: &crate::state::Live, all: &mut Batches) {
        // SAFETY: the safe struct stores each array with its length.
        let (waits, signals, command_buffers) = unsafe {
            (
                crate::state::raw_slice(
                    self.p_wait_semaphore_infos,
                    self.wait_semaphore_info_count,
                ),
                crate::state::raw_slice(
                    self.p_signal_semaphore_infos,
                    self.signal_semaphore_info_count,
                ),
                crate::state::raw_slice(
                    self.p_command_buffer_infos,
                    self.command_buffer_info_count,
                ),
            )
        };
        // A signal with a narrower stage mask than ALL_COMMANDS says less than that
        // the whole batch is done.
        let whole = |i: &vk::SemaphoreSubmitInfo<'_>| {
            i.stage_mask.contains(vk::PipelineStageFlags2::ALL_COMMANDS)
        };
        all.push(
            live,
            waits.iter().map(|i| (i.semaphore, Some(i.value), false)),
            signals
                .iter()
                .map(|i| (i.semaphore, Some(i.value), whole(i))),
            command_buffers.iter().map(|i| i.command_buffer),
        );
    }

    fn walk(&self, out: &mut crate::validation::Reached<'_>) {
        // SAFETY: the safe struct stores every array with its length.
        unsafe { crate::reach::submit_info2(self.as_raw(), out) }
    }
}
