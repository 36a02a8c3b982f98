//! What the device records of timeline and binary semaphores and of events.

use super::live::Live;
use ash::vk::{self, Handle as _};
use rustc_hash::FxHashMap as HashMap;
use tuff_runtime::{Vrc, Vweak};

/// The submissions whose command buffers name one event, with their queues.
pub(super) type EventSubmissions = Vec<(vk::Queue, Vweak<crate::submission::Submission>)>;

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
            .insert(raw.as_raw(), crate::submission::Timeline::new(initial));
    }

    /// What the device knows of its timeline semaphores' values, for a command that
    /// signals or waits on them to read and update.
    pub(crate) fn timelines(
        &self,
    ) -> tuff_runtime::VutexGuard<'_, HashMap<u64, crate::submission::Timeline>> {
        self.timelines.lock()
    }

    /// The physical device's `maxTimelineSemaphoreValueDifference`, read from `read`
    /// the first time.
    pub(crate) fn timeline_difference(&self, read: impl FnOnce() -> u64) -> u64 {
        *self.timeline_difference.get_or_init(read)
    }

    /// The state of binary semaphores, for a submission command to read and update.
    pub(crate) fn binaries(
        &self,
    ) -> tuff_runtime::VutexGuard<'_, HashMap<u64, crate::submission::Binary>> {
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
        sub: &Vrc<crate::submission::Submission>,
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
    ) -> Vec<Vrc<crate::submission::Submission>> {
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
