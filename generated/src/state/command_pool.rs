//! What the device records of command pools: the queue family each was made for.

use super::live::Live;
use ash::vk::{self, Handle as _};

/// What the device records of a command pool's queue family, which the checks of
/// commands recorded from it read.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PoolFamily {
    /// The family's index.
    pub index: u32,
    /// Its queue flags.
    pub flags: vk::QueueFlags,
    /// Its `minImageTransferGranularity`.
    pub granularity: vk::Extent3D,
    /// Its `timestampValidBits`: 0 where its queues write no timestamps.
    pub timestamp_bits: u32,
    /// Whether the pool was created with `VK_COMMAND_POOL_CREATE_PROTECTED_BIT`.
    pub protected: bool,
}

impl Live {
    /// Records a new command pool's queue family.
    pub(crate) fn pool_created(&self, raw: vk::CommandPool, family: PoolFamily) {
        self.pools.lock().insert(raw.as_raw(), family);
    }

    /// The queue family of a live command pool made through the wrappers.
    pub(crate) fn pool_family(&self, raw: vk::CommandPool) -> Option<PoolFamily> {
        self.pools.lock().get(&raw.as_raw()).copied()
    }
}
