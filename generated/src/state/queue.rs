//! What the device records of its queues: families, protection, host synchronization
//! and the ledger of queue operations that may still be executing.

use super::live::Live;
use ash::vk::{self, Handle as _};
use tuff_runtime::HostSync;

impl Live {
    /// The device's queue operations that may still be executing.
    #[inline]
    pub(crate) fn ledger(&self) -> &crate::submission::Ledger {
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
