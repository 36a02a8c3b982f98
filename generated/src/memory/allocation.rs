//! Buffers and images with memory from one of the runtime's allocators.
//!
//! [`Device::create_buffer_in`] and [`Device::create_image_in`] create the resource,
//! ask the allocator for memory that fits its requirements where the caller wants it
//! to live ([`MemoryLocation`]), and bind it. The resource keeps its memory: the
//! memory is freed after the resource is destroyed, and the resource is destroyed only
//! once every submission that used it has completed, so the memory is never freed
//! under the GPU (`VUID-vkFreeMemory-memory-00677`).
//!
//! The binding rules hold by construction or are checked before the bind: the
//! resource is new, so it was never bound; the allocation must come from this device,
//! of a memory type the resource allows, aligned and large enough; and resources that
//! need memory the allocators cannot give (sparse, disjoint, protected, device-address,
//! external or dedicated memory) are refused with the rule they would break.
//!
//! ```no_run
//! # fn f(device: &tuff::Device) -> tuff::Result<()> {
//! use tuff::{vk, MemoryLocation};
//! let allocator = device.gpu_allocator()?;
//! let info = tuff::BufferCreateInfo::new()
//!     .size(12)
//!     .usage(vk::BufferUsageFlags::VERTEX_BUFFER);
//! let vertices = device.create_buffer_in(&info, &allocator, MemoryLocation::Upload)?;
//! vertices.memory().write(0, &[0.0f32, -0.5, 0.5])?;
//! # Ok(()) }
//! ```

use crate::support::refuse;
use crate::{Buffer, BufferCreateInfo, Device, Error, Handle, Image, ImageCreateInfo, Result};
use ash::vk;
use tuff_runtime::{Allocation, AllocationRequest, Allocator, DeviceOwner, Vrc, Vutex};

pub use tuff_runtime::{GpuAllocator, MemoryLocation, NaiveAllocator};

/// The device as the runtime's allocators see it. It holds a clone of the device,
/// so the device outlives every allocator and allocation made through it.
struct Owner {
    device: Device,
    atom: u64,
}

// SAFETY: the wrapper's device, its physical device and instance stay alive while the
// owner holds the device (each wrapper keeps its parent), and `atom` is read from
// that physical device's limits.
unsafe impl DeviceOwner for Owner {
    fn instance(&self) -> &ash::Instance {
        self.device.parent().parent().fns()
    }
    fn physical_device(&self) -> vk::PhysicalDevice {
        self.device.parent().raw()
    }
    fn device(&self) -> &ash::Device {
        self.device.fns()
    }
    fn non_coherent_atom_size(&self) -> u64 {
        self.atom
    }
}

impl Device {
    /// This device as the runtime's allocators take it: for an allocator of your own
    /// (any [`Allocator`]) built the way [`GpuAllocator::new`] is.
    ///
    /// ```no_run
    /// # fn f(device: &tuff::Device) {
    /// let allocator = tuff::NaiveAllocator::new(device.memory_owner());
    /// # drop(allocator); }
    /// ```
    pub fn memory_owner(&self) -> Vrc<dyn DeviceOwner> {
        let atom = self.parent().get_properties().limits.non_coherent_atom_size;
        Vrc::new(Owner {
            device: self.clone(),
            atom,
        })
    }

    /// The sub-allocating allocator (through `gpu-allocator`): few `vkAllocateMemory`
    /// calls however many resources there are.
    ///
    /// ```no_run
    /// # fn f(device: &tuff::Device) -> tuff::Result<()> {
    /// let allocator = device.gpu_allocator()?;
    /// # drop(allocator); Ok(()) }
    /// ```
    pub fn gpu_allocator(&self) -> Result<GpuAllocator> {
        GpuAllocator::new(self.memory_owner()).map_err(alloc_error)
    }

    /// The allocator that gives every resource a `VkDeviceMemory` of its own: slow, and
    /// simple to reason about when debugging.
    ///
    /// ```no_run
    /// # fn f(device: &tuff::Device) {
    /// let allocator = device.naive_allocator();
    /// # drop(allocator); }
    /// ```
    pub fn naive_allocator(&self) -> NaiveAllocator {
        NaiveAllocator::new(self.memory_owner())
    }

    crate::helpers::as_safe_as! { vkCreateBuffer,
        /// A buffer of `usage` holding `data`: made with [`Device::create_buffer_in`] in
        /// host-visible memory ([`MemoryLocation::Upload`]) from `allocator`, then
        /// written. Empty `data` gives a one-byte buffer, as a buffer cannot be empty
        /// (`VUID-VkBufferCreateInfo-size-00912`).
        ///
        /// # Safety
        ///
        /// As [`Device::create_buffer_in`] (safe with this crate's emitted API), for a
        /// create info of `usage` and the data's size.
        ///
        /// ```no_run
        /// # fn f(device: &tuff::Device) -> tuff::Result<()> {
        /// let allocator = device.gpu_allocator()?;
        /// let usage = tuff::vk::BufferUsageFlags::INDEX_BUFFER;
        /// let indices = device.create_buffer_with(usage, &[0u32, 1, 2], &allocator)?;
        /// assert_eq!(indices.memory().read::<u32>(0, 3)?, [0, 1, 2]);
        /// # Ok(()) }
        /// ```
        pub fn create_buffer_with<A: Allocator + ?Sized, T: bytemuck::NoUninit>(
            &self,
            usage: vk::BufferUsageFlags,
            data: &[T],
            allocator: &A,
        ) -> Result<Bound<Buffer>> {
            let size = (core::mem::size_of_val(data) as u64).max(1);
            let info = BufferCreateInfo::new().size(size).usage(usage);
            #[allow(unused_unsafe)]
            // SAFETY: where `create_buffer_in` is `unsafe`, so is this method, and its
            // caller upholds what it asks of the info.
            let buffer = unsafe { self.create_buffer_in(&info, allocator, MemoryLocation::Upload) }?;
            buffer.memory().write(0, data)?;
            Ok(buffer)
        }
    }

    crate::helpers::as_safe_as! { vkCreateBuffer,
            /// Creates a buffer and binds memory from `allocator` at `location` to it.
            ///
            /// Fails with the rule's VUID when the buffer needs memory no allocator of the
            /// runtime gives (sparse, protected, device-address or external memory) or when the
            /// allocation does not fit the buffer, and with [`Error::Alloc`] when the allocator
            /// fails.
            ///
            /// # Safety
            ///
            /// This method is `unsafe` exactly when [`Device::create_buffer`] is: with the
            /// emitted API of this crate (core 1.0-1.3, WSI, debug utils) it is safe; a
            /// crate generated from more of the registry, or a newer one, may leave it
            /// rules, and the caller then upholds those its `# Safety` section lists for
            /// `info`, except those this method refuses above.
            ///
            /// ```no_run
            /// # fn f(device: &tuff::Device) -> tuff::Result<()> {
            /// use tuff::{vk, MemoryLocation};
            /// let info = tuff::BufferCreateInfo::new()
            ///     .size(64)
            ///     .usage(vk::BufferUsageFlags::UNIFORM_BUFFER);
            /// let uniforms = device.create_buffer_in(&info, &device.naive_allocator(), MemoryLocation::Upload)?;
            /// uniforms.memory().write(0, &[1.0f32; 16])?;
            /// # Ok(()) }
            /// ```
            pub fn create_buffer_in<A: Allocator + ?Sized>(
                &self,
                info: &BufferCreateInfo<'_>,
                allocator: &A,
                location: MemoryLocation,
            ) -> Result<Bound<Buffer>> {
                let raw = info.as_raw();
                let sparse = vk::BufferCreateFlags::SPARSE_BINDING
                    | vk::BufferCreateFlags::SPARSE_RESIDENCY
                    | vk::BufferCreateFlags::SPARSE_ALIASED;
                if raw.flags.intersects(sparse) {
     refuse("VUID-vkBindBufferMemory-buffer-01030", "a sparse buffer is bound with vkQueueBindSparse, not to one allocation")?;
    }
                if raw.flags.contains(vk::BufferCreateFlags::PROTECTED) {
     refuse("VUID-vkBindBufferMemory-None-01898", "a protected buffer needs protected memory, which the allocators do not give")?;
    }
                if raw.usage
                        .contains(vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS) {
     refuse("VUID-vkBindBufferMemory-bufferDeviceAddress-03339", "a buffer with a device address needs memory allocated with \
                     VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT, which the allocators do not ask for")?;
    }
                refuse_chain(raw.p_next, "VUID-vkBindBufferMemory-buffer-01444")?;
                // `create_buffer` is safe in the pinned configuration and `unsafe` in wider
                // ones.
                #[allow(unused_unsafe)]
                // SAFETY: where `create_buffer` is `unsafe`, so is this method, and its caller
                // upholds the rules it lists.
                let buffer = unsafe { self.create_buffer(info) }?;
                let requirements = self.get_buffer_memory_requirements(&buffer)?;
                let allocation = allocator
                    .allocate(&AllocationRequest::new(requirements, location))
                    .map_err(alloc_error)?;
                fits(self, &allocation, &requirements, BUFFER_RULES)?;
                // SAFETY: the buffer is new and unbound, not sparse; the allocation is memory
                // of this device of an allowed type, aligned, large enough, and not protected.
                unsafe {
                    self.fns()
                        .bind_buffer_memory(buffer.raw(), allocation.memory(), allocation.offset())
                }?;
                self.live()
                    .buffer_bound(buffer.raw(), allocation.memory(), allocation.offset());
                let memory = BoundMemory::new(allocation);
                buffer.retain_memory(memory.cell.clone());
                Ok(Bound {
                    resource: buffer,
                    memory,
                })
            }
        }

    crate::helpers::as_safe_as! { vkCreateImage,
            /// Creates an image and binds memory from `allocator` at `location` to it.
            ///
            /// Fails with the rule's VUID when the image needs memory no allocator of the
            /// runtime gives (sparse, disjoint, protected or external memory) or when the
            /// allocation does not fit the image, and with [`Error::Alloc`] when the allocator
            /// fails.
            ///
            /// # Safety
            ///
            /// This method is `unsafe` exactly when [`Device::create_image`] is (it is safe
            /// with this crate's emitted API); the caller then upholds the rules its
            /// `# Safety` section lists for `info`, except those this method refuses above.
            ///
            /// ```no_run
            /// # fn f(device: &tuff::Device) -> tuff::Result<()> {
            /// use tuff::{vk, MemoryLocation};
            /// let info = tuff::ImageCreateInfo::new()
            ///     .image_type(vk::ImageType::TYPE_2D)
            ///     .format(vk::Format::D32_SFLOAT)
            ///     .extent(vk::Extent3D { width: 64, height: 64, depth: 1 })
            ///     .mip_levels(1)
            ///     .array_layers(1)
            ///     .samples(vk::SampleCountFlags::TYPE_1)
            ///     .usage(vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT);
            /// let depth = device.create_image_in(&info, &device.gpu_allocator()?, MemoryLocation::DeviceLocal)?;
            /// # drop(depth); Ok(()) }
            /// ```
            pub fn create_image_in<A: Allocator + ?Sized>(
                &self,
                info: &ImageCreateInfo<'_>,
                allocator: &A,
                location: MemoryLocation,
            ) -> Result<Bound<Image>> {
                let raw = info.as_raw();
                let sparse = vk::ImageCreateFlags::SPARSE_BINDING
                    | vk::ImageCreateFlags::SPARSE_RESIDENCY
                    | vk::ImageCreateFlags::SPARSE_ALIASED;
                if raw.flags.intersects(sparse) {
     refuse("VUID-vkBindImageMemory-image-01045", "a sparse image is bound with vkQueueBindSparse, not to one allocation")?;
    }
                if raw.flags.contains(vk::ImageCreateFlags::DISJOINT) {
     refuse("VUID-vkBindImageMemory-image-01608", "a disjoint image binds each plane with vkBindImageMemory2")?;
    }
                if raw.flags.contains(vk::ImageCreateFlags::PROTECTED) {
     refuse("VUID-vkBindImageMemory-None-01901", "a protected image needs protected memory, which the allocators do not give")?;
    }
                refuse_chain(raw.p_next, "VUID-vkBindImageMemory-image-01445")?;
                // `create_image` is safe in the pinned configuration and `unsafe` in wider
                // ones.
                #[allow(unused_unsafe)]
                // SAFETY: where `create_image` is `unsafe`, so is this method, and its caller
                // upholds the rules it lists.
                let image = unsafe { self.create_image(info) }?;
                let requirements = self.get_image_memory_requirements(&image)?;
                let mut request = AllocationRequest::new(requirements, location);
                request.linear = raw.tiling == vk::ImageTiling::LINEAR;
                let allocation = allocator.allocate(&request).map_err(alloc_error)?;
                fits(self, &allocation, &requirements, IMAGE_RULES)?;
                // SAFETY: as for buffers: a new, unbound, non-sparse, non-disjoint image and
                // fitting, unprotected memory of this device.
                unsafe {
                    self.fns()
                        .bind_image_memory(image.raw(), allocation.memory(), allocation.offset())
                }?;
                self.live().image_bound(
                    image.raw(),
                    allocation.memory(),
                    allocation.offset(),
                    requirements.size,
                );
                let memory = BoundMemory::new(allocation);
                image.retain_memory(memory.cell.clone());
                Ok(Bound {
                    resource: image,
                    memory,
                })
            }
        }
}

/// A buffer or image with the memory bound to it. It dereferences to the resource,
/// so it goes wherever the resource does.
///
/// ```no_run
/// # fn f(vertices: &tuff::Bound<tuff::Buffer>) -> tuff::Result<()> {
/// let buffer: &tuff::Buffer = vertices;
/// vertices.memory().write(0, &[1u16, 2, 3])?;
/// # let _ = buffer; Ok(()) }
/// ```
// `repr(C)` with the resource first: a reference to a `Bound` is one to its resource,
// which is how it stands for an array of one handle (`Handles`).
#[repr(C)]
pub struct Bound<T> {
    resource: T,
    memory: BoundMemory,
}

impl<T: core::fmt::Debug> core::fmt::Debug for Bound<T> {
    /// The resource and its memory.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Bound")
            .field("resource", &self.resource)
            .field("memory", &self.memory)
            .finish()
    }
}

impl<T> Bound<T> {
    /// The memory bound to the resource.
    ///
    /// ```no_run
    /// # fn f(b: &tuff::Bound<tuff::Buffer>) -> tuff::Result<()> {
    /// let first: Vec<u32> = b.memory().read(0, 1)?;
    /// # let _ = first; Ok(()) }
    /// ```
    pub fn memory(&self) -> &BoundMemory {
        &self.memory
    }

    /// The resource and its memory apart. The resource still keeps the memory.
    ///
    /// ```no_run
    /// # fn f(b: tuff::Bound<tuff::Image>) {
    /// let (image, memory) = b.into_parts();
    /// # drop((image, memory)); }
    /// ```
    pub fn into_parts(self) -> (T, BoundMemory) {
        (self.resource, self.memory)
    }
}

impl<T: Handle> crate::support::sealed::Sealed for &Bound<T> {}

/// A bound resource stands for its one handle, as the resource itself does.
impl<'a, T: Handle> crate::Handles<'a, T> for &'a Bound<T> {
    #[inline]
    fn raws(self) -> &'a [T::Raw] {
        core::slice::from_ref(self.resource.raw_ref())
    }
    #[inline]
    fn wrappers(&self) -> &[&'a T] {
        let this: &&'a Bound<T> = self;
        // SAFETY: `Bound` is `repr(C)` with `resource` first, at offset 0, so the
        // address `this` points to is that of a `&'a T` to the resource, borrowed as long.
        let resource: &&'a T = unsafe { &*(this as *const &'a Bound<T>).cast::<&'a T>() };
        core::slice::from_ref(resource)
    }
}

impl<T> core::ops::Deref for Bound<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.resource
    }
}

/// Memory an allocator gave to a buffer or image. Clones share it; it goes back to
/// its allocator once the resource and every clone are gone.
///
/// The runtime's allocators keep host-visible memory mapped for its whole life, so a
/// write is a bounds-checked copy (and a flush where the memory is not coherent). What
/// stays with the caller, as with any mapped memory: host access must not race with
/// GPU access to the same bytes.
///
/// ```no_run
/// # fn f(m: &tuff::BoundMemory) -> tuff::Result<()> {
/// m.write(0, &[0.25f32; 4])?;
/// let back: Vec<f32> = m.read(0, 4)?;
/// assert_eq!(back, [0.25; 4]);
/// # Ok(()) }
/// ```
#[derive(Clone)]
pub struct BoundMemory {
    cell: Vrc<Vutex<Allocation>>,
}

/// A [`BoundMemory`] held for a run of writes and reads ([`BoundMemory::lock`]).
pub struct LockedMemory<'a>(tuff_runtime::VutexGuard<'a, Allocation>);

impl core::fmt::Debug for LockedMemory<'_> {
    /// The allocation's size; its contents are the device's.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("LockedMemory")
            .field("size", &self.0.size())
            .finish()
    }
}

impl LockedMemory<'_> {
    /// [`BoundMemory::write`], under the lock held.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) -> tuff::Result<()> {
    /// m.lock().write(16, &[7u32])?;
    /// # Ok(()) }
    /// ```
    pub fn write<T: bytemuck::NoUninit>(&mut self, offset: u64, data: &[T]) -> Result<()> {
        self.0.write_slice(offset, data).map_err(Error::Map)
    }

    /// [`BoundMemory::write_value`], under the lock held.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) -> tuff::Result<()> {
    /// m.lock().write_value(0, &[[1.0f32; 4]; 4])?;
    /// # Ok(()) }
    /// ```
    #[inline]
    pub fn write_value<T: bytemuck::NoUninit>(&mut self, offset: u64, value: &T) -> Result<()> {
        self.0.write(offset, value).map_err(Error::Map)
    }

    /// [`BoundMemory::read`], under the lock held.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) -> tuff::Result<()> {
    /// let back: Vec<u32> = m.lock().read(16, 1)?;
    /// # let _ = back; Ok(()) }
    /// ```
    pub fn read<T: bytemuck::AnyBitPattern + bytemuck::NoUninit>(
        &self,
        offset: u64,
        count: usize,
    ) -> Result<Vec<T>> {
        let mut out = vec![T::zeroed(); count];
        self.0.read_slice(offset, &mut out).map_err(Error::Map)?;
        Ok(out)
    }
}

impl core::fmt::Debug for BoundMemory {
    /// Its shared allocation's address; the allocation itself is behind a lock.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_tuple("BoundMemory")
            .field(&Vrc::as_ptr(&self.cell))
            .finish()
    }
}

impl BoundMemory {
    fn new(allocation: Allocation) -> Self {
        BoundMemory {
            cell: Vrc::new(Vutex::new(allocation)),
        }
    }

    /// Copies `data` to `offset` bytes into the memory. Fails with [`Error::Map`] when
    /// the memory is not host-visible or the copy does not fit.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) -> tuff::Result<()> {
    /// m.write(16, &[7u32])?;
    /// # Ok(()) }
    /// ```
    pub fn write<T: bytemuck::NoUninit>(&self, offset: u64, data: &[T]) -> Result<()> {
        self.lock().write(offset, data)
    }

    /// Copies one value to `offset` bytes into the memory: the fast path for a uniform
    /// block written each frame.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) -> tuff::Result<()> {
    /// m.write_value(0, &[[1.0f32; 4]; 4])?;
    /// # Ok(()) }
    /// ```
    pub fn write_value<T: bytemuck::NoUninit>(&self, offset: u64, value: &T) -> Result<()> {
        self.lock().write_value(offset, value)
    }

    /// Holds the memory for a run of writes and reads: one lock for all of them,
    /// where [`BoundMemory::write_value`] takes one per call. With `multi_thread` a
    /// lock is an atomic read-modify-write, which on x86 also drains the processor's
    /// write-combining buffers: on memory the GPU exposes write-combined (a discrete
    /// GPU's host-visible VRAM) each call's lock then sends its writes out one by one.
    /// Other clones of the memory wait while the guard lives.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) -> tuff::Result<()> {
    /// let mut held = m.lock();
    /// for i in 0..1000u64 {
    ///     held.write_value(i * 64, &[[1.0f32; 4]; 4])?;
    /// }
    /// # Ok(()) }
    /// ```
    pub fn lock(&self) -> LockedMemory<'_> {
        LockedMemory(self.cell.lock())
    }

    /// Reads `count` values from `offset` bytes into the memory. Fails with
    /// [`Error::Map`] when the memory is not host-visible or the read does not fit.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) -> tuff::Result<()> {
    /// let pixels: Vec<u8> = m.read(0, 4 * 64 * 64)?;
    /// # let _ = pixels; Ok(()) }
    /// ```
    pub fn read<T: bytemuck::AnyBitPattern + bytemuck::NoUninit>(
        &self,
        offset: u64,
        count: usize,
    ) -> Result<Vec<T>> {
        self.lock().read(offset, count)
    }

    /// The size in bytes, at least what the resource required.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) {
    /// assert!(m.size() > 0);
    /// # }
    /// ```
    pub fn size(&self) -> u64 {
        self.cell.lock().size()
    }

    /// The property flags of the memory's type.
    ///
    /// ```no_run
    /// # fn f(m: &tuff::BoundMemory) {
    /// let mapped = m.properties().contains(tuff::vk::MemoryPropertyFlags::HOST_VISIBLE);
    /// # let _ = mapped; }
    /// ```
    pub fn properties(&self) -> vk::MemoryPropertyFlags {
        self.cell.lock().properties()
    }
}

/// The rules an allocation must meet to be bound, by resource kind: parent, memory
/// type, alignment, size, and no protected memory for an unprotected resource.
type Rules = [&'static str; 5];

const BUFFER_RULES: Rules = [
    "VUID-vkBindBufferMemory-memory-parent",
    "VUID-vkBindBufferMemory-memory-01035",
    "VUID-vkBindBufferMemory-memoryOffset-01036",
    "VUID-vkBindBufferMemory-size-01037",
    "VUID-vkBindBufferMemory-None-01899",
];

const IMAGE_RULES: Rules = [
    "VUID-vkBindImageMemory-memory-parent",
    "VUID-vkBindImageMemory-memory-01047",
    "VUID-vkBindImageMemory-memoryOffset-01048",
    "VUID-vkBindImageMemory-size-01049",
    "VUID-vkBindImageMemory-None-01902",
];

/// An allocator's error as the wrappers report it.
fn alloc_error(e: tuff_runtime::AllocError) -> Error {
    Error::Alloc(e.to_string())
}

/// Refuses create infos whose chain asks for external, imported or dedicated memory:
/// such resources may require a dedicated allocation, which the allocators do not make.
fn refuse_chain(next: *const core::ffi::c_void, vuid: &'static str) -> Result<()> {
    let refused = [
        vk::StructureType::EXTERNAL_MEMORY_BUFFER_CREATE_INFO,
        vk::StructureType::EXTERNAL_MEMORY_IMAGE_CREATE_INFO,
        vk::StructureType::EXTERNAL_MEMORY_IMAGE_CREATE_INFO_NV,
        vk::StructureType::DEDICATED_ALLOCATION_BUFFER_CREATE_INFO_NV,
        vk::StructureType::DEDICATED_ALLOCATION_IMAGE_CREATE_INFO_NV,
    ];
    // SAFETY: the safe create infos only chain structs pushed through `push_next`.
    for node in unsafe { crate::support::chain_nodes(next) } {
        if refused.contains(&node.s_type) {
            refuse(
                vuid,
                format!(
                    "a resource made with {:?} in its chain may need a dedicated allocation",
                    node.s_type
                ),
            )?;
        }
    }
    Ok(())
}

/// Checks that `allocation` can be bound where `requirements` say.
fn fits(
    device: &Device,
    allocation: &Allocation,
    requirements: &vk::MemoryRequirements,
    [parent, kind, alignment, size, protected]: Rules,
) -> Result<()> {
    if allocation.device() != device.raw() {
        refuse(parent, "the allocator belongs to another device")?;
    }
    let index = allocation.memory_type_index();
    if index >= 32 || requirements.memory_type_bits & (1 << index) == 0 {
        refuse(
            kind,
            format!(
                "memory type {index} is not in the allowed bits {:#x}",
                requirements.memory_type_bits
            ),
        )?;
    }
    if requirements.alignment != 0 && allocation.offset() % requirements.alignment != 0 {
        refuse(
            alignment,
            format!(
                "offset {} is not a multiple of the alignment {}",
                allocation.offset(),
                requirements.alignment
            ),
        )?;
    }
    if allocation.size() < requirements.size {
        refuse(
            size,
            format!(
                "{} bytes allocated, {} required",
                allocation.size(),
                requirements.size
            ),
        )?;
    }
    if allocation
        .properties()
        .contains(vk::MemoryPropertyFlags::PROTECTED)
    {
        return refuse(
            protected,
            "an unprotected resource cannot use protected memory",
        );
    }
    Ok(())
}
