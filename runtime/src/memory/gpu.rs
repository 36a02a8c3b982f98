//! The default allocator: sub-allocation through the `gpu-allocator` crate.

use super::{
    atom_aligned, AllocError, Allocation, AllocationBacking, AllocationParts, AllocationRequest,
    Allocator, DeviceOwner, MemoryLocation,
};
use crate::sync::{Vrc, Vutex};
use ash::vk;
use gpu_allocator::vulkan as ga;

/// Sub-allocates from large blocks through `gpu-allocator`, so thousands of small
/// buffers cost a few `vkAllocateMemory` calls.
///
/// ```no_run
/// # fn demo(owner: tuff_runtime::Vrc<dyn tuff_runtime::DeviceOwner>) -> Result<(), Box<dyn std::error::Error>> {
/// use tuff_runtime::{Allocator, AllocationRequest, GpuAllocator, MemoryLocation};
/// let allocator = GpuAllocator::new(owner)?;
/// let req = ash::vk::MemoryRequirements { size: 64, alignment: 16, memory_type_bits: !0 };
/// let mut uniforms = allocator.allocate(&AllocationRequest::new(req, MemoryLocation::Upload))?;
/// uniforms.write(0, &[1u32; 16])?;
/// # Ok(()) }
/// ```
#[derive(Clone)]
pub struct GpuAllocator {
    shared: Vrc<Shared>,
}

impl core::fmt::Debug for GpuAllocator {
    /// The device's memory types and heaps it allocates from.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("GpuAllocator")
            .field("memory_properties", &self.shared.props)
            .finish_non_exhaustive()
    }
}

// Fields drop in order: the gpu-allocator (which frees its blocks through the
// device) goes before the owner (which destroys the device).
struct Shared {
    allocator: Vutex<ga::Allocator>,
    props: vk::PhysicalDeviceMemoryProperties,
    owner: Vrc<dyn DeviceOwner>,
}

impl GpuAllocator {
    /// An allocator for `owner`'s device.
    ///
    /// ```no_run
    /// # fn demo(owner: tuff_runtime::Vrc<dyn tuff_runtime::DeviceOwner>) -> Result<(), tuff_runtime::AllocError> {
    /// let allocator = tuff_runtime::GpuAllocator::new(owner)?;
    /// # drop(allocator); Ok(()) }
    /// ```
    pub fn new(owner: Vrc<dyn DeviceOwner>) -> Result<Self, AllocError> {
        let allocator = ga::Allocator::new(&ga::AllocatorCreateDesc {
            instance: owner.instance().clone(),
            device: owner.device().clone(),
            physical_device: owner.physical_device(),
            debug_settings: Default::default(),
            buffer_device_address: false,
            allocation_sizes: Default::default(),
        })?;
        // SAFETY: the physical device belongs to the owner's instance, alive here.
        let props = unsafe {
            owner
                .instance()
                .get_physical_device_memory_properties(owner.physical_device())
        };
        Ok(GpuAllocator {
            shared: Vrc::new(Shared {
                allocator: Vutex::new(allocator),
                props,
                owner,
            }),
        })
    }
}

struct GpuBacking {
    shared: Vrc<Shared>,
    allocation: ga::Allocation,
}

impl AllocationBacking for GpuBacking {
    fn free(self: Box<Self>) {
        let GpuBacking { shared, allocation } = *self;
        // Freeing only fails for an allocation of another allocator, which the
        // backing rules out; there is no one to report to from a Drop.
        let _ = shared.allocator.lock().free(allocation);
    }
}

impl Allocator for GpuAllocator {
    fn allocate(&self, request: &AllocationRequest<'_>) -> Result<Allocation, AllocError> {
        let shared = &self.shared;
        if request.requirements.size == 0 {
            return Err(AllocError::InvalidRequirements("size is 0".into()));
        }
        let atom = shared.owner.non_coherent_atom_size();
        let location = match request.location {
            MemoryLocation::DeviceLocal => gpu_allocator::MemoryLocation::GpuOnly,
            MemoryLocation::Upload => gpu_allocator::MemoryLocation::CpuToGpu,
            MemoryLocation::Readback => gpu_allocator::MemoryLocation::GpuToCpu,
        };
        // Every allocation is aligned to whole atoms, device-local ones included:
        // gpu-allocator maps any host-visible block (device-local memory is host-visible
        // on integrated GPUs and lavapipe), and flush ranges rounded to atoms must stay
        // inside this allocation, whose end stands in for the unknown block size.
        let requirements = atom_aligned(request.requirements, atom)?;
        let allocation = shared
            .allocator
            .lock()
            .allocate(&ga::AllocationCreateDesc {
                name: request.name,
                requirements,
                location,
                linear: request.linear,
                allocation_scheme: ga::AllocationScheme::GpuAllocatorManaged,
            })?;
        let properties = allocation.memory_properties();
        // gpu-allocator picks the first allowed type with the flags it reports.
        let memory_type_index = (0..shared.props.memory_type_count)
            .filter(|i| requirements.memory_type_bits & (1 << i) != 0)
            .find(|i| shared.props.memory_types[*i as usize].property_flags == properties)
            .unwrap_or(0);
        let parts = AllocationParts {
            // SAFETY: the memory handle is only used to bind and flush within this
            // allocation, never freed by us.
            memory: unsafe { allocation.memory() },
            offset: allocation.offset(),
            size: allocation.size(),
            // The block's size is not exposed; flush ranges stay within the
            // allocation anyway, because it is aligned to whole atoms.
            memory_size: allocation.offset() + allocation.size(),
            memory_type_index,
            properties,
            mapped: allocation.mapped_ptr().map(|p| p.cast::<u8>()),
            non_coherent_atom_size: atom,
        };
        let backing = Box::new(GpuBacking {
            shared: Vrc::clone(shared),
            allocation,
        });
        // SAFETY: gpu-allocator hands out disjoint ranges of mapped blocks that stay
        // mapped until freed; the backing frees through the allocator and keeps the
        // owner alive.
        Ok(unsafe { Allocation::from_parts(parts, Vrc::clone(&shared.owner), backing) })
    }
}
