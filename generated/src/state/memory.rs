//! What the device records of device memory: allocations, what is bound where, and
//! sparse resources.

use super::live::Live;
use ash::vk::{self, Handle as _};

/// What the device records of a device memory allocated through the wrappers, which
/// mapping and binds read.
pub(crate) struct MemoryRecord {
    /// `allocationSize`.
    pub(crate) size: u64,
    /// `memoryTypeIndex`.
    pub(crate) memory_type_index: u32,
    /// Whether a [`MappedMemory`] of it lives.
    pub(crate) mapped: bool,
    /// Its type's property flags and the device's `nonCoherentAtomSize`, read at the
    /// first map.
    pub(crate) host: Option<(vk::MemoryPropertyFlags, u64)>,
    /// What its chained infos asked for, which binds are checked against.
    pub(crate) asked: MemoryAsked,
}

/// The records of a device's memories, by raw handle, locked.
pub(crate) type MemoryRecords<'a> = tuff_runtime::VutexGuard<'a, super::HashMap<u64, MemoryRecord>>;

/// Where a buffer or image is bound: the raw memory, the offset there and the
/// bytes it takes.
pub(crate) type Binding = (u64, u64, u64);

/// What an allocation's chained infos asked for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct MemoryAsked {
    /// The buffer (`VK_OBJECT_TYPE_BUFFER`) or image it is dedicated to.
    pub dedicated: Option<(vk::ObjectType, u64)>,
    /// `VkExportMemoryAllocateInfo::handleTypes`.
    pub export: vk::ExternalMemoryHandleTypeFlags,
    /// Allocated with `VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT`.
    pub device_address: bool,
}

impl Live {
    /// Locks out other safe sparse creations.
    pub(crate) fn sparse_gate(&self) -> tuff_runtime::VutexGuard<'_, ()> {
        self.sparse_gate.lock()
    }

    /// The memory all live sparse buffers require.
    pub(crate) fn sparse_total(&self) -> u64 {
        *self.sparse_total.lock()
    }

    /// Records a new sparse buffer's required memory.
    pub(crate) fn sparse_created<H: vk::Handle>(&self, raw: H, size: u64) {
        self.sparse_resources
            .lock()
            .insert((H::TYPE, raw.as_raw()), size);
        *self.sparse_total.lock() += size;
    }

    /// Records that memory is bound to a buffer.
    pub(crate) fn buffer_bound(
        &self,
        raw: vk::Buffer,
        memory: vk::DeviceMemory,
        memory_offset: vk::DeviceSize,
    ) {
        let size = {
            let mut buffers = self.buffers.lock();
            let Some(r) = buffers.get_mut(&raw.as_raw()) else {
                return;
            };
            r.bound = true;
            r.memory_offset = memory_offset;
            r.size
        };
        self.bindings.lock().insert(
            (vk::ObjectType::BUFFER, raw.as_raw()),
            (memory.as_raw(), memory_offset, size),
        );
    }

    /// The memory a buffer or image is bound to, its offset there and the bytes it
    /// takes (`None` before it is bound, or for a sparse one).
    pub(crate) fn binding<H: vk::Handle>(&self, raw: H) -> Option<Binding> {
        self.bindings.lock().get(&(H::TYPE, raw.as_raw())).copied()
    }

    /// Records that memory is bound to an image.
    pub(crate) fn image_bound(
        &self,
        raw: vk::Image,
        memory: vk::DeviceMemory,
        memory_offset: vk::DeviceSize,
        size: vk::DeviceSize,
    ) {
        if let Some(r) = self.images.lock().get_mut(&raw.as_raw()) {
            r.bound = true;
        } else {
            return;
        }
        self.bindings.lock().insert(
            (vk::ObjectType::IMAGE, raw.as_raw()),
            (memory.as_raw(), memory_offset, size),
        );
    }

    /// Keeps the memory bound to a buffer or image as long as the object is listed
    /// (its wrapper lives). Memory that has no wrapper is not kept.
    pub(crate) fn bound2<H: vk::Handle>(&self, raw: H, memory: vk::DeviceMemory) {
        if let Some(memory) = self.get(memory) {
            let old = self
                .bound_memories
                .lock()
                .insert((H::TYPE, raw.as_raw()), memory);
            drop(old);
        }
    }

    /// Records a new device memory's size and type, which mapping checks against.
    pub(crate) fn allocated(
        &self,
        raw: vk::DeviceMemory,
        size: u64,
        memory_type_index: u32,
        asked: MemoryAsked,
    ) {
        self.memories.lock().insert(
            raw.as_raw(),
            MemoryRecord {
                size,
                memory_type_index,
                mapped: false,
                host: None,
                asked,
            },
        );
    }

    /// Locks the records of the device's memories until the guard goes: a check
    /// that a memory is mapped holds them while the driver uses the mapping, as
    /// `DeviceMemory::map` and the unmap hold them while they change one.
    pub(crate) fn memories_locked(&self) -> MemoryRecords<'_> {
        self.memories.lock()
    }

    /// Locks out other safe allocations, and says how many device memories made
    /// through the wrappers are live.
    pub(crate) fn allocation_gate(&self) -> (tuff_runtime::VutexGuard<'_, ()>, usize) {
        let gate = self.allocating.lock();
        let live = self.memories.lock().len();
        (gate, live)
    }

    /// Runs `f` on the record of a device memory, if it was allocated through the
    /// wrappers.
    pub(crate) fn memory<R>(
        &self,
        raw: vk::DeviceMemory,
        f: impl FnOnce(&mut MemoryRecord) -> R,
    ) -> Option<R> {
        self.memories.lock().get_mut(&raw.as_raw()).map(f)
    }
}
