//! One `vkAllocateMemory` per resource: simple to reason about, for tests and
//! debugging, and slow.

use super::{
    atom_aligned, find_memory_type, location_flags, AllocError, Allocation, AllocationBacking,
    AllocationParts, AllocationRequest, Allocator, DeviceOwner,
};
use crate::sync::Vrc;
use ash::vk;
use std::ptr::NonNull;

/// Allocates every resource its own `VkDeviceMemory`, mapped whole when host-visible.
///
/// ```no_run
/// # fn demo(owner: tuff_runtime::Vrc<dyn tuff_runtime::DeviceOwner>) -> Result<(), tuff_runtime::AllocError> {
/// use tuff_runtime::{Allocator, AllocationRequest, MemoryLocation, NaiveAllocator};
/// let allocator = NaiveAllocator::new(owner);
/// let req = ash::vk::MemoryRequirements { size: 256, alignment: 64, memory_type_bits: !0 };
/// let allocation = allocator.allocate(&AllocationRequest::new(req, MemoryLocation::Readback))?;
/// assert!(allocation.mapped_ptr().is_some());
/// # Ok(()) }
/// ```
#[derive(Clone)]
pub struct NaiveAllocator {
    shared: Vrc<Shared>,
}

impl core::fmt::Debug for NaiveAllocator {
    /// The device's memory types and heaps it allocates from.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("NaiveAllocator")
            .field("memory_properties", &self.shared.props)
            .finish_non_exhaustive()
    }
}

struct Shared {
    owner: Vrc<dyn DeviceOwner>,
    props: vk::PhysicalDeviceMemoryProperties,
}

impl NaiveAllocator {
    /// An allocator for `owner`'s device.
    ///
    /// ```no_run
    /// # fn demo(owner: tuff_runtime::Vrc<dyn tuff_runtime::DeviceOwner>) {
    /// let debug_allocator = tuff_runtime::NaiveAllocator::new(owner);
    /// # drop(debug_allocator); }
    /// ```
    pub fn new(owner: Vrc<dyn DeviceOwner>) -> Self {
        // SAFETY: the physical device belongs to the owner's instance, alive here.
        let props = unsafe {
            owner
                .instance()
                .get_physical_device_memory_properties(owner.physical_device())
        };
        NaiveAllocator {
            shared: Vrc::new(Shared { owner, props }),
        }
    }
}

struct NaiveBacking {
    shared: Vrc<Shared>,
    memory: vk::DeviceMemory,
}

impl AllocationBacking for NaiveBacking {
    fn free(self: Box<Self>) {
        // SAFETY: the memory came from this device and is freed once; freeing also
        // unmaps it. The device is alive: `shared` holds its owner.
        unsafe { self.shared.owner.device().free_memory(self.memory, None) };
    }
}

impl Allocator for NaiveAllocator {
    fn allocate(&self, request: &AllocationRequest<'_>) -> Result<Allocation, AllocError> {
        let shared = &self.shared;
        let reqs = request.requirements;
        if reqs.size == 0 {
            return Err(AllocError::InvalidRequirements("size is 0".into()));
        }
        let (required, preferred) = location_flags(request.location);
        let index = find_memory_type(&shared.props, reqs.memory_type_bits, required, preferred)
            .ok_or(AllocError::NoSuitableMemoryType {
                memory_type_bits: reqs.memory_type_bits,
                location: request.location,
            })?;
        let properties = shared.props.memory_types[index as usize].property_flags;
        let host_visible = properties.contains(vk::MemoryPropertyFlags::HOST_VISIBLE);
        let atom = shared.owner.non_coherent_atom_size();
        let size = if host_visible {
            atom_aligned(reqs, atom)?.size
        } else {
            reqs.size
        };
        let heap = shared.props.memory_types[index as usize].heap_index as usize;
        let heap_size = shared.props.memory_heaps.get(heap).map_or(0, |h| h.size);
        if size > heap_size {
            return Err(AllocError::InvalidRequirements(format!(
                "{size} bytes do not fit in memory heap {heap} of {heap_size} bytes"
            )));
        }
        let device = shared.owner.device();
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(size)
            .memory_type_index(index);
        // SAFETY: a valid allocate info for this device.
        let memory = unsafe { device.allocate_memory(&info, None) }.map_err(|result| {
            AllocError::Vulkan {
                call: "vkAllocateMemory",
                result,
            }
        })?;
        let mapped = if host_visible {
            // SAFETY: the memory is host-visible, freshly allocated and not mapped.
            match unsafe {
                device.map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
            } {
                Ok(ptr) => NonNull::new(ptr.cast::<u8>()),
                Err(result) => {
                    // SAFETY: allocated above, not used by anything.
                    unsafe { device.free_memory(memory, None) };
                    return Err(AllocError::Vulkan {
                        call: "vkMapMemory",
                        result,
                    });
                }
            }
        } else {
            None
        };
        let parts = AllocationParts {
            memory,
            offset: 0,
            size,
            memory_size: size,
            memory_type_index: index,
            properties,
            mapped,
            non_coherent_atom_size: atom,
        };
        let backing = Box::new(NaiveBacking {
            shared: Vrc::clone(shared),
            memory,
        });
        // SAFETY: the whole memory object is this allocation's and stays mapped until
        // the backing frees it; the backing keeps the owner alive.
        Ok(unsafe { Allocation::from_parts(parts, Vrc::clone(&shared.owner), backing) })
    }
}
