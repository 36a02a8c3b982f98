//! What the device records of buffers.

use super::live::Live;
use ash::vk::{self, Handle as _};

/// A live buffer's creation parameters and binding, which command checks read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct BufferRecord {
    /// `VkBufferCreateInfo::size`.
    pub size: vk::DeviceSize,
    /// `VkBufferCreateInfo::usage`.
    pub usage: vk::BufferUsageFlags,
    /// `VkBufferCreateInfo::flags`.
    pub flags: vk::BufferCreateFlags,
    /// `VkBufferCreateInfo::sharingMode`.
    pub sharing: vk::SharingMode,
    /// Whether memory is bound to it.
    pub bound: bool,
    /// Where in its memory it is bound (0 until it is).
    pub memory_offset: vk::DeviceSize,
    /// `VkExternalMemoryBufferCreateInfo::handleTypes`.
    pub external: vk::ExternalMemoryHandleTypeFlags,
}

impl Live {
    /// Records a new buffer's creation parameters.
    pub(crate) fn buffer_created(&self, raw: vk::Buffer, record: BufferRecord) {
        if record.flags.contains(vk::BufferCreateFlags::PROTECTED) {
            self.protected_one(true);
        }
        self.buffers.lock().insert(raw.as_raw(), record);
    }

    /// The record of a live buffer made through the wrappers.
    pub(crate) fn buffer(&self, raw: vk::Buffer) -> Option<BufferRecord> {
        self.buffers.lock().get(&raw.as_raw()).copied()
    }
}
