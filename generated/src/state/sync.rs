//! What the device records of timeline and binary semaphores and of events.

use super::live::Live;
use super::queue::Submission;
use super::HashMap;
use ash::vk::{self, Handle as _};
use tuff_runtime::{Vrc, Vweak};

/// What the device knows of a timeline semaphore's value: a value it has reached,
/// and the operations submitted on it that may not have executed yet. Its value when
/// an operation executes lies between the two.
#[derive(Debug)]
pub(crate) struct Timeline {
    /// A value it is known to have reached (its initial value, one the host read,
    /// waited for or signalled, or one a completed submission signalled).
    pub(crate) known: u64,
    /// The largest value any signal operation submitted, or the host, gives it.
    pub(crate) max_signal: u64,
    /// The wait (`false`) and signal (`true`) operations submitted and not known
    /// complete, with their values, submissions and batch indices.
    pub(crate) pending: Vec<(u64, bool, Vweak<Submission>, usize)>,
}

impl Timeline {
    /// A new timeline semaphore's state.
    pub(crate) fn new(initial: u64) -> Self {
        Timeline {
            known: initial,
            max_signal: initial,
            pending: Vec::new(),
        }
    }

    /// Drops the operations of submissions known complete; their signals were
    /// reached.
    pub(crate) fn prune(&mut self) {
        let mut known = self.known;
        self.pending.retain(|(value, signal, sub, _)| {
            let done = sub.upgrade().is_none_or(|s| s.is_complete());
            if done && *signal {
                known = known.max(*value);
            }
            !done
        });
        self.known = known;
    }

    /// The host saw the semaphore at `value` (or signalled it to `value`).
    pub(crate) fn seen(&mut self, value: u64, host_signal: bool) {
        self.known = self.known.max(value);
        if host_signal {
            self.max_signal = self.max_signal.max(value);
        }
    }
}

/// What a binary semaphore has had submitted that still matters. A semaphore the
/// device does not list is unsignaled, with no signal or wait pending.
pub(crate) enum Binary {
    /// A signal operation was submitted (by a queue batch or an acquire), and no
    /// wait since: the semaphore is signaled, or will be.
    Signaled,
    /// A wait was submitted to `queue` by `by`; once that operation completes the
    /// semaphore is unsignaled (a submission no longer held is complete: an
    /// incomplete one is held by its fence or its queue).
    Waited {
        queue: vk::Queue,
        by: Vweak<Submission>,
    },
}

/// The submissions whose command buffers name one event, with their queues.
pub(super) type EventSubmissions = Vec<(vk::Queue, Vweak<super::queue::Submission>)>;

impl Live {
    /// Records that a new event was created device-only.
    pub(crate) fn set_device_only(&self, raw: vk::Event) {
        self.device_only_events.lock().insert(raw.as_raw());
    }

    /// Whether a live event was created device-only.
    pub(crate) fn is_device_only(&self, raw: vk::Event) -> bool {
        self.device_only_events.lock().contains(&raw.as_raw())
    }

    /// Records that a new semaphore is a timeline semaphore, with its initial value.
    pub(crate) fn set_timeline(&self, raw: vk::Semaphore, initial: u64) {
        self.timelines
            .lock()
            .insert(raw.as_raw(), Timeline::new(initial));
    }

    /// What the device knows of its timeline semaphores' values, for a command that
    /// signals or waits on them to read and update.
    pub(crate) fn timelines(&self) -> tuff_runtime::VutexGuard<'_, HashMap<u64, Timeline>> {
        self.timelines.lock()
    }

    /// The physical device's `maxTimelineSemaphoreValueDifference`, read from `read`
    /// the first time.
    pub(crate) fn timeline_difference(&self, read: impl FnOnce() -> u64) -> u64 {
        *self.timeline_difference.get_or_init(read)
    }

    /// The state of binary semaphores, for a submission command to read and update.
    pub(crate) fn binaries(&self) -> tuff_runtime::VutexGuard<'_, HashMap<u64, Binary>> {
        self.binaries.lock()
    }

    /// Whether a live semaphore is a timeline semaphore.
    pub(crate) fn is_timeline(&self, raw: vk::Semaphore) -> bool {
        self.timelines.lock().contains_key(&raw.as_raw())
    }

    /// `sub`, a submission to `queue`, has command buffers that name `events`.
    pub(crate) fn events_submitted(
        &self,
        events: &[u64],
        queue: vk::Queue,
        sub: &Vrc<super::queue::Submission>,
    ) {
        if events.is_empty() {
            return;
        }
        let mut uses = self.event_uses.lock();
        for event in events {
            let subs = uses.entry(*event).or_default();
            subs.retain(|(_, w)| w.upgrade().is_some_and(|s| !s.is_complete()));
            subs.push((queue, Vrc::downgrade(sub)));
        }
    }

    /// The submissions to queues other than `queue` whose command buffers name an
    /// event and that tuff has not seen complete.
    pub(crate) fn event_submissions(
        &self,
        event: u64,
        queue: vk::Queue,
    ) -> Vec<Vrc<super::queue::Submission>> {
        self.event_uses
            .lock()
            .get(&event)
            .map_or(Vec::new(), |subs| {
                subs.iter()
                    .filter(|(q, _)| *q != queue)
                    .filter_map(|(_, w)| w.upgrade())
                    .filter(|s| !s.is_complete())
                    .collect()
            })
    }
}
