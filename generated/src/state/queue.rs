//! What the device records of its queues: families, protection, host synchronization
//! and the ledger of queue operations that may still be executing.

use super::live::Live;
use crate::Handle;
use ash::vk::{self, Handle as _};
use smallvec::SmallVec;
use tuff_runtime::HostSync;
use tuff_runtime::{Retained, Vrc, Vutex, Vweak};

impl Live {
    /// The device's queue operations that may still be executing.
    #[inline]
    pub(crate) fn ledger(&self) -> &Ledger {
        &self.ledger
    }

    /// The host synchronization of a new wrapper of `raw`. A queue can get several
    /// wrappers (`get_queue` twice) and Vulkan synchronizes the queue, not
    /// the wrappers, so every wrapper of one queue shares one for the device's life
    /// (a device has few queues); any other object gets a new one.
    pub(crate) fn sync_for<H: vk::Handle>(&self, raw: H) -> HostSync {
        if H::TYPE == vk::ObjectType::QUEUE {
            self.queues.lock().entry(raw.as_raw()).or_default().clone()
        } else {
            HostSync::new()
        }
    }

    /// The host synchronization of a live object named by its type and raw handle.
    // Used by extension commands only (presentation, debug names).
    #[allow(dead_code)]
    pub(crate) fn sync_of(&self, ty: vk::ObjectType, raw: u64) -> Option<HostSync> {
        self.objects
            .lock()
            .get(&(ty, raw))
            .filter(|(w, _)| w.strong_count() > 0)
            .map(|(_, s)| s.clone())
    }

    /// The host synchronizations of every queue of the device.
    pub(crate) fn queue_syncs(&self) -> Vec<HostSync> {
        self.queues.lock().values().cloned().collect()
    }

    /// Records the queues the device was created with: (family, count, flags) for
    /// each of its queue create infos.
    pub(crate) fn set_queue_infos(&self, queues: Vec<(u32, u32, vk::DeviceQueueCreateFlags)>) {
        let _ = self.queue_infos.set(queues);
    }

    /// The queues the device was created with (none, before they are recorded).
    pub(crate) fn queue_infos(&self) -> &[(u32, u32, vk::DeviceQueueCreateFlags)] {
        self.queue_infos.get().map_or(&[], Vec::as_slice)
    }

    /// Records the queue family a queue of the device belongs to.
    pub(crate) fn queue_family_of(&self, queue: vk::Queue, family: u32) {
        self.queue_families.lock().insert(queue.as_raw(), family);
    }

    /// Records that a queue was got with `VK_DEVICE_QUEUE_CREATE_PROTECTED_BIT`.
    pub(crate) fn queue_protected(&self, queue: vk::Queue) {
        self.protected_queues.lock().insert(queue.as_raw());
    }

    /// Whether a queue was got with `VK_DEVICE_QUEUE_CREATE_PROTECTED_BIT`.
    pub(crate) fn is_protected_queue(&self, queue: vk::Queue) -> bool {
        self.protected_queues.lock().contains(&queue.as_raw())
    }

    /// The queue family of a queue got through the wrappers.
    pub(crate) fn queue_family(&self, queue: vk::Queue) -> Option<u32> {
        self.queue_families.lock().get(&queue.as_raw()).copied()
    }
}

/// The objects a submission or recording keeps alive: a frame's few inline.
pub(crate) type Kept = SmallVec<[Retained; 4]>;

/// For each batch of a submission, the timeline values whose signal shows it
/// finished: a frame's one batch inline.
pub(crate) type Completes = SmallVec<[Vec<(vk::Semaphore, u64)>; 2]>;

/// One queue operation and everything it uses.
pub(crate) struct Submission {
    pub(crate) queue: vk::Queue,
    /// Position in the device's submission order.
    pub(crate) seq: u64,
    /// The fence it signals, or null.
    pub(crate) fence: vk::Fence,
    pub(crate) state: Vutex<SubmissionState>,
}

pub(crate) struct SubmissionState {
    /// What it uses; `None` once it is known complete, or once every batch is known
    /// to have finished executing (its timeline signal was seen).
    pub(crate) kept: Option<Kept>,
    /// Known complete: its fence (or a later one of the queue) was seen signalled or
    /// the queue went idle. A timeline signal alone does not tell this: the fence
    /// may still be waiting to signal.
    pub(crate) complete: bool,
    /// For each batch that has not been seen finished, the timeline values whose
    /// signal shows that it did (a signal that covers all of the batch's commands).
    /// A batch without one keeps the submission's objects until it completes.
    pub(crate) batches: Completes,
}

impl Submission {
    /// Whether the submission is known complete.
    pub(crate) fn is_complete(&self) -> bool {
        self.state.lock().complete
    }

    /// Marks the submission complete and releases what it used.
    pub(crate) fn complete(&self) {
        let kept = {
            let mut state = self.state.lock();
            state.complete = true;
            state.batches.clear();
            state.kept.take()
        };
        // Released outside the lock: the last reference to an object runs its Drop.
        drop(kept);
    }

    /// Timeline semaphore `semaphore` reached `value`: the batches that signal it
    /// with a value no greater have finished, and once every batch has, what the
    /// submission used goes (the submission itself stays incomplete until its fence
    /// is seen).
    pub(crate) fn reached(&self, semaphore: vk::Semaphore, value: u64) {
        let kept = {
            let mut state = self.state.lock();
            if state.kept.is_none() || state.batches.is_empty() {
                return;
            }
            state
                .batches
                .retain(|signals| !signals.iter().any(|(s, v)| *s == semaphore && *v <= value));
            if !state.batches.is_empty() {
                return;
            }
            state.kept.take()
        };
        drop(kept);
    }

    /// Keeps `objects` too, until the submission completes (nothing, once it has).
    pub(crate) fn keep_also(&self, objects: &[Retained]) {
        if let Some(kept) = self.state.lock().kept.as_mut() {
            kept.extend(objects.iter().cloned());
        }
    }

    /// Whether the submission is complete, asking its fence when tuff has not seen
    /// it signalled; a signalled fence retires the submission on `device`.
    pub(crate) fn poll(&self, device: &crate::handles::Device) -> bool {
        let signalled = {
            let state = self.state.lock();
            if state.complete {
                return true;
            }
            if self.fence == vk::Fence::null() {
                return false;
            }
            // SAFETY: the fence lives while this submission is incomplete: its wrapper
            // completes the submission before it destroys the fence, and that takes
            // this lock, which is held here.
            let r = unsafe { (device.fns().fp_v1_0().get_fence_status)(device.raw(), self.fence) };
            r == vk::Result::SUCCESS
        };
        if signalled {
            device.live().ledger().retire(self);
        }
        signalled
    }
}

/// A device's submissions in submission order, held weakly.
pub(crate) struct Ledger {
    pub(crate) state: Vutex<LedgerState>,
}

impl Default for Ledger {
    fn default() -> Self {
        Ledger {
            state: Vutex::new(LedgerState::default()),
        }
    }
}

#[derive(Default)]
pub(crate) struct LedgerState {
    pub(crate) next: u64,
    pub(crate) subs: Vec<Vweak<Submission>>,
}

impl Ledger {
    /// Records a submission to `queue` that signals `fence` (or none) and uses `kept`.
    pub(crate) fn record(
        &self,
        queue: vk::Queue,
        fence: vk::Fence,
        kept: Kept,
        batches: Completes,
    ) -> Vrc<Submission> {
        let mut state = self.state.lock();
        state.next += 1;
        // A batch without a timeline signal can only finish with the fence.
        let batches = if batches.iter().any(Vec::is_empty) {
            Completes::new()
        } else {
            batches
        };
        let sub = Vrc::new(Submission {
            queue,
            seq: state.next,
            fence,
            state: Vutex::new(SubmissionState {
                kept: Some(kept),
                complete: false,
                batches,
            }),
        });
        // A weak entry whose submission is gone or complete is dropped here, so the
        // ledger stays as long as the work in flight.
        state
            .subs
            .retain(|w| w.upgrade().is_some_and(|s| !s.is_complete()));
        state.subs.push(Vrc::downgrade(&sub));
        sub
    }

    /// `done` is complete, and so is every earlier submission to its queue: a fence
    /// signal covers every command submitted before it to that queue.
    pub(crate) fn retire(&self, done: &Submission) {
        let (queue, seq) = (done.queue, done.seq);
        // An acquire's fence (no queue) tells nothing of other acquires.
        if queue != vk::Queue::null() {
            self.retire_where(|s| s.queue == queue && s.seq <= seq);
        }
        done.complete();
    }

    /// Timeline semaphore `semaphore` was seen at `value` (a wait returned, or its
    /// counter was read): the batches that signal it with a value no greater have
    /// finished executing, and submissions whose batches all have release what they
    /// use. A semaphore signal covers only its own batch, so nothing earlier on the
    /// queue is released by it.
    pub(crate) fn reached(&self, semaphore: vk::Semaphore, value: u64) {
        let subs: SmallVec<[Vrc<Submission>; 4]> = {
            let state = self.state.lock();
            state.subs.iter().filter_map(Vweak::upgrade).collect()
        };
        for s in subs {
            s.reached(semaphore, value);
        }
    }

    /// Every submission to `queue` is complete (`vkQueueWaitIdle` returned).
    pub(crate) fn retire_queue(&self, queue: vk::Queue) {
        self.retire_where(|s| s.queue == queue);
    }

    /// Every submission is complete (`vkDeviceWaitIdle` returned), but for acquires,
    /// which the presentation engine, not a queue, completes.
    pub(crate) fn retire_all(&self) {
        self.retire_where(|s| s.queue != vk::Queue::null());
    }

    pub(crate) fn retire_where(&self, done: impl Fn(&Submission) -> bool) {
        let finished: SmallVec<[Vrc<Submission>; 4]> = {
            let state = self.state.lock();
            state
                .subs
                .iter()
                .filter_map(Vweak::upgrade)
                .filter(|s| done(s))
                .collect()
        };
        // Completed outside the ledger's lock, since releasing objects runs their Drop.
        for s in &finished {
            s.complete();
        }
    }
}
