//! Device-memory allocation behind one trait, and typed access to mapped memory.
//!
//! # Who outlives whom
//!
//! The runtime knows `ash`, not the generated crate, so it cannot name the generated
//! `Device` wrapper. Instead it defines [`DeviceOwner`]: whatever owns the `VkDevice`
//! (the generated wrapper does) implements it and destroys the device in its `Drop`.
//! Allocators are built from a `Vrc<dyn DeviceOwner>`, and every [`Allocation`] holds
//! (through its [`AllocationBacking`]) a `Vrc` to the allocator's state, which holds
//! the owner. So the device is destroyed only after the last allocation and the last
//! allocator are gone, whatever order the user drops things in, and the dependency
//! still runs one way: tuff -> tuff-runtime -> ash.
//!
//! ```no_run
//! # fn demo(owner: tuff_runtime::Vrc<dyn tuff_runtime::DeviceOwner>) -> Result<(), Box<dyn std::error::Error>> {
//! use tuff_runtime::{Allocator, AllocationRequest, GpuAllocator, MemoryLocation};
//! use ash::vk;
//! let allocator = GpuAllocator::new(owner)?;
//! let requirements = vk::MemoryRequirements { size: 64, alignment: 16, memory_type_bits: !0 };
//! let mut allocation = allocator.allocate(&AllocationRequest::new(requirements, MemoryLocation::Upload))?;
//! allocation.write(0, &[1.0f32, 2.0, 3.0, 4.0])?;
//! # Ok(()) }
//! ```

mod gpu;
mod naive;

pub use gpu::GpuAllocator;
pub use naive::NaiveAllocator;

use crate::mapped::{check_range, flush_range, MapError, Placement};
use crate::sync::{MaybeSend, MaybeSendSync, Vrc};
use ash::vk;
use std::ptr::NonNull;

/// What allocators need of the device. The generated `Device` wrapper implements it;
/// its `Drop` destroys the device, which therefore outlives every allocator and
/// allocation that holds the owner.
///
/// # Safety
///
/// The allocators call Vulkan with what the owner returns and trust it, so an
/// implementation promises, for as long as any clone of it lives: `instance()` is a
/// live instance, `physical_device()` one of its physical devices, `device()` a live
/// device created from that physical device (not destroyed before the owner is
/// dropped), and `non_coherent_atom_size()` that physical device's
/// `VkPhysicalDeviceLimits::nonCoherentAtomSize`.
///
/// ```
/// use ash::vk;
/// struct MyDevice { instance: ash::Instance, physical: vk::PhysicalDevice, device: ash::Device, atom: u64 }
/// // SAFETY: the fields are a live instance, its physical device, a device created from
/// // it and destroyed only when this owner drops, and that device's atom size.
/// unsafe impl tuff_runtime::DeviceOwner for MyDevice {
///     fn instance(&self) -> &ash::Instance { &self.instance }
///     fn physical_device(&self) -> vk::PhysicalDevice { self.physical }
///     fn device(&self) -> &ash::Device { &self.device }
///     fn non_coherent_atom_size(&self) -> u64 { self.atom }
/// }
/// impl Drop for MyDevice {
///     // SAFETY: runs after every allocator and allocation holding this owner is gone.
///     fn drop(&mut self) { unsafe { self.device.destroy_device(None) } }
/// }
/// ```
pub unsafe trait DeviceOwner: MaybeSendSync + 'static {
    /// The instance the device was created from.
    fn instance(&self) -> &ash::Instance;
    /// The physical device.
    fn physical_device(&self) -> vk::PhysicalDevice;
    /// The logical device.
    fn device(&self) -> &ash::Device;
    /// `VkPhysicalDeviceLimits::nonCoherentAtomSize`.
    fn non_coherent_atom_size(&self) -> u64;
}

/// Where the memory should live, as the resource uses it.
///
/// ```
/// use tuff_runtime::MemoryLocation;
/// let vertex_staging = MemoryLocation::Upload;
/// let screenshot = MemoryLocation::Readback;
/// assert_ne!(vertex_staging, screenshot);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MemoryLocation {
    /// Only the GPU touches it: device-local. It is mapped anyway where device-local
    /// memory is also host-visible (integrated GPUs, lavapipe).
    DeviceLocal,
    /// The CPU writes, the GPU reads: host-visible and mapped.
    Upload,
    /// The GPU writes, the CPU reads back: host-visible (cached if possible) and mapped.
    Readback,
}

/// What a buffer or image needs.
#[derive(Debug, Clone, Copy)]
pub struct AllocationRequest<'a> {
    /// From vkGet*MemoryRequirements.
    pub requirements: vk::MemoryRequirements,
    /// Where it should live.
    pub location: MemoryLocation,
    /// Buffers and linear images are linear; optimally tiled images are not.
    pub linear: bool,
    /// A name for debugging and leak reports.
    pub name: &'a str,
}

impl AllocationRequest<'static> {
    /// A request for a linear resource (a buffer) with no name.
    ///
    /// ```
    /// use tuff_runtime::{AllocationRequest, MemoryLocation};
    /// use ash::vk;
    /// let r = AllocationRequest::new(vk::MemoryRequirements::default(), MemoryLocation::DeviceLocal);
    /// assert!(r.linear);
    /// ```
    pub fn new(requirements: vk::MemoryRequirements, location: MemoryLocation) -> Self {
        AllocationRequest {
            requirements,
            location,
            linear: true,
            name: "",
        }
    }
}

/// Why an allocation failed.
///
/// ```
/// use tuff_runtime::{AllocError, MemoryLocation};
/// let e = AllocError::NoSuitableMemoryType { memory_type_bits: 0, location: MemoryLocation::Upload };
/// assert!(e.to_string().contains("no memory type"));
/// ```
#[derive(Debug)]
pub enum AllocError {
    /// No memory type allowed by the requirements has the needed properties.
    NoSuitableMemoryType {
        /// `memoryTypeBits` of the requirements.
        memory_type_bits: u32,
        /// The wanted location.
        location: MemoryLocation,
    },
    /// A Vulkan call failed.
    Vulkan {
        /// Which call.
        call: &'static str,
        /// What it returned.
        result: vk::Result,
    },
    /// gpu-allocator refused.
    GpuAllocator(gpu_allocator::AllocationError),
    /// The requirements are impossible: size 0, a size larger than the memory heap or
    /// one that overflows when rounded to the atom size.
    InvalidRequirements(String),
}

// Written out rather than derived: thiserror's macro needs a syn of its own, which
// cargo builds before ash and so delays every build of tuff.
impl core::fmt::Display for AllocError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            AllocError::NoSuitableMemoryType {
                memory_type_bits,
                location,
            } => write!(
                f,
                "no memory type in bits {memory_type_bits:#x} suits {location:?} memory"
            ),
            AllocError::Vulkan { call, result } => write!(f, "{call} failed: {result}"),
            AllocError::GpuAllocator(e) => write!(f, "gpu-allocator: {e}"),
            AllocError::InvalidRequirements(what) => {
                write!(f, "invalid memory requirements: {what}")
            }
        }
    }
}

impl std::error::Error for AllocError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            AllocError::GpuAllocator(e) => Some(e),
            _ => None,
        }
    }
}

impl From<gpu_allocator::AllocationError> for AllocError {
    fn from(e: gpu_allocator::AllocationError) -> Self {
        AllocError::GpuAllocator(e)
    }
}

/// Frees an allocation's memory. Each allocator gives its allocations a backing; the
/// backing must keep whatever frees the memory (and the device) alive.
///
/// ```
/// use tuff_runtime::{AllocationBacking, DeviceOwner, Vrc};
/// struct OwnMemory { owner: Vrc<dyn DeviceOwner>, memory: ash::vk::DeviceMemory }
/// impl AllocationBacking for OwnMemory {
///     fn free(self: Box<Self>) {
///         // SAFETY: the memory is this backing's alone; the owner keeps the device alive.
///         unsafe { self.owner.device().free_memory(self.memory, None) }
///     }
/// }
/// ```
pub trait AllocationBacking: MaybeSend {
    /// Return the memory to its allocator. Called once, from the allocation's `Drop`.
    fn free(self: Box<Self>);
}

/// The facts of an allocation, for allocators building one with
/// [`Allocation::from_parts`].
///
/// ```
/// use ash::vk;
/// let parts = tuff_runtime::AllocationParts {
///     memory: vk::DeviceMemory::null(),
///     offset: 256,
///     size: 1024,
///     memory_size: 1 << 20,
///     memory_type_index: 0,
///     properties: vk::MemoryPropertyFlags::DEVICE_LOCAL,
///     mapped: None,
///     non_coherent_atom_size: 64,
/// };
/// assert!(parts.offset + parts.size <= parts.memory_size);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AllocationParts {
    /// The device memory the allocation lies in.
    pub memory: vk::DeviceMemory,
    /// Offset of the allocation inside `memory`.
    pub offset: u64,
    /// Size of the allocation.
    pub size: u64,
    /// Size of the whole `memory` object (flushes never go past it).
    pub memory_size: u64,
    /// Index of the memory type of `memory`.
    pub memory_type_index: u32,
    /// Properties of that memory type.
    pub properties: vk::MemoryPropertyFlags,
    /// Host address of the allocation's first byte, if it is mapped.
    pub mapped: Option<NonNull<u8>>,
    /// `nonCoherentAtomSize` of the device.
    pub non_coherent_atom_size: u64,
}

/// A piece of device memory. It frees itself (through its allocator) when dropped, and
/// keeps its allocator and device alive until then.
///
/// ```no_run
/// # fn demo(device: &ash::Device, buffer: ash::vk::Buffer, allocator: &dyn tuff_runtime::Allocator) -> Result<(), Box<dyn std::error::Error>> {
/// use tuff_runtime::{AllocationRequest, MemoryLocation};
/// // SAFETY: `buffer` is a live, unbound buffer of `device`.
/// let requirements = unsafe { device.get_buffer_memory_requirements(buffer) };
/// let mut allocation = allocator.allocate(&AllocationRequest::new(requirements, MemoryLocation::Upload))?;
/// // SAFETY: the allocation satisfies the buffer's requirements.
/// unsafe { device.bind_buffer_memory(buffer, allocation.memory(), allocation.offset())? };
/// allocation.write_slice(0, &[0u16, 1, 2])?;
/// assert_eq!(allocation.read::<u16>(2)?, 1);
/// # Ok(()) }
/// ```
pub struct Allocation {
    // The hot path of a write reads only these three fields.
    /// The mapping's first byte, or a dangling pointer (never written through) when
    /// the allocation is not mapped.
    base: NonNull<u8>,
    /// Bytes reachable through `base`: `size`, or 0 when not mapped.
    mapped_len: u64,
    /// `mapped_len` where a write needs nothing after the copy (coherent memory),
    /// else 0, so that the fast path of `write` is a single comparison and every
    /// other case (unmapped, out of range, needs a flush) takes the slow path.
    fast_len: u64,
    /// Host writes must be flushed (mapped, non-coherent memory).
    needs_flush: bool,
    parts: AllocationParts,
    owner: Vrc<dyn DeviceOwner>,
    backing: Option<Box<dyn AllocationBacking>>,
}

// SAFETY: the mapped pointer is the only non-Send field. It points into memory that
// this allocation alone may access (allocators hand out disjoint ranges), and every
// access goes through `&self`/`&mut self`, so moving the allocation to another thread
// moves that exclusive access with it. Only compiled where the backing is Send too.
#[cfg(feature = "multi_thread")]
unsafe impl Send for Allocation {}

impl std::fmt::Debug for Allocation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Allocation")
            .field("parts", &self.parts)
            .finish()
    }
}

impl Allocation {
    /// Assemble an allocation. This is how a custom [`crate::Allocator`] returns memory
    /// (`tests/runtime_memory.rs` in the repository has a complete bump allocator).
    ///
    /// ```no_run
    /// # fn demo(owner: tuff_runtime::Vrc<dyn tuff_runtime::DeviceOwner>, parts: tuff_runtime::AllocationParts, backing: Box<dyn tuff_runtime::AllocationBacking>) {
    /// // SAFETY: `parts` describes memory of `owner`'s device that only this allocation
    /// // uses, and `backing` frees it.
    /// let allocation = unsafe { tuff_runtime::Allocation::from_parts(parts, owner, backing) };
    /// # drop(allocation); }
    /// ```
    ///
    /// # Safety
    ///
    /// `parts` must describe memory that `owner`'s device allocated and that nothing
    /// else uses: `offset + size <= memory_size`, and `mapped` (if any) must point to
    /// `size` writable bytes that stay mapped until `backing.free` runs.
    ///
    /// Not a safety condition, but a correctness one: when the memory is mapped and
    /// not coherent, `offset` and `size` should be multiples of
    /// `non_coherent_atom_size` (or end at `memory_size`). Flushes and invalidations
    /// are rounded out to whole atoms, so otherwise they touch the neighbouring
    /// allocations' bytes, and an invalidate can discard a neighbour's unflushed
    /// writes.
    pub unsafe fn from_parts(
        parts: AllocationParts,
        owner: Vrc<dyn DeviceOwner>,
        backing: Box<dyn AllocationBacking>,
    ) -> Allocation {
        let mapped_len = if parts.mapped.is_some() {
            parts.size
        } else {
            0
        };
        let coherent = parts
            .properties
            .contains(vk::MemoryPropertyFlags::HOST_COHERENT);
        Allocation {
            base: parts.mapped.unwrap_or(NonNull::dangling()),
            mapped_len,
            fast_len: if coherent { mapped_len } else { 0 },
            needs_flush: parts.mapped.is_some() && !coherent,
            parts,
            owner,
            backing: Some(backing),
        }
    }

    /// The device memory, to bind a buffer or image to (at [`Allocation::offset`]).
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// let (memory, offset) = (a.memory(), a.offset());
    /// # let _ = (memory, offset);
    /// # Ok(()) }
    /// ```
    pub fn memory(&self) -> vk::DeviceMemory {
        self.parts.memory
    }

    /// Offset of the allocation inside [`Allocation::memory`].
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// assert_eq!(a.offset() % 16, 0, "suballocations honour the requested alignment");
    /// # Ok(()) }
    /// ```
    pub fn offset(&self) -> u64 {
        self.parts.offset
    }

    /// Size in bytes (at least the requested size).
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// let bytes = vec![0u8; a.size() as usize];
    /// a.write_slice(0, &bytes)?;
    /// # Ok(()) }
    /// ```
    pub fn size(&self) -> u64 {
        self.parts.size
    }

    /// The device whose memory this is, so that a binder can refuse memory of
    /// another device (`VUID-vkBindBufferMemory-memory-parent`).
    ///
    /// ```no_run
    /// # fn demo(a: &tuff_runtime::Allocation, device: &ash::Device) {
    /// assert_eq!(a.device(), device.handle());
    /// # }
    /// ```
    pub fn device(&self) -> vk::Device {
        self.owner.device().handle()
    }

    /// Index of the memory type.
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// println!("memory type {}", a.memory_type_index());
    /// # Ok(()) }
    /// ```
    pub fn memory_type_index(&self) -> u32 {
        self.parts.memory_type_index
    }

    /// Properties of the memory type.
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// let host = a.properties().contains(ash::vk::MemoryPropertyFlags::HOST_VISIBLE);
    /// assert_eq!(host, a.mapped_ptr().is_some());
    /// # Ok(()) }
    /// ```
    pub fn properties(&self) -> vk::MemoryPropertyFlags {
        self.parts.properties
    }

    /// Host address of the first byte, if mapped. Prefer the checked accessors; the
    /// pointer is for handing the mapping to code that needs one.
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// if let Some(ptr) = a.mapped_ptr() {
    ///     println!("mapped at {ptr:p}");
    /// }
    /// # Ok(()) }
    /// ```
    pub fn mapped_ptr(&self) -> Option<NonNull<u8>> {
        self.parts.mapped
    }

    /// Whether the memory is host-coherent. When it is not, host writes need a flush
    /// and device writes an invalidate; the accessors of this type do both.
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// if !a.is_coherent() {
    ///     a.flush(0, a.size())?;
    /// }
    /// # Ok(()) }
    /// ```
    #[inline]
    pub fn is_coherent(&self) -> bool {
        self.parts
            .properties
            .contains(vk::MemoryPropertyFlags::HOST_COHERENT)
    }

    fn placement(&self) -> Placement {
        Placement {
            offset: self.parts.offset,
            size: self.parts.size,
            memory_size: self.parts.memory_size,
        }
    }

    /// Checked pointer to `len` bytes at `offset`.
    #[inline]
    fn span(&self, offset: u64, len: u64) -> Result<*mut u8, MapError> {
        // One subtraction and one comparison. An unmapped allocation has
        // mapped_len 0, so only an empty access (which touches no byte) passes.
        match self.mapped_len.checked_sub(len) {
            Some(max) if offset <= max => {
                // SAFETY: offset + len <= mapped_len. When mapped, the mapping covers
                // `size` bytes from `base` (from_parts' contract), so `offset` fits in
                // the address space (usize) and the pointer stays inside the mapping;
                // when not, offset and len are 0 and the dangling pointer is only
                // used for an access of no bytes.
                Ok(unsafe { self.base.as_ptr().add(offset as usize) })
            }
            _ => Err(self.span_error(offset, len)),
        }
    }

    #[cold]
    #[inline(never)]
    fn span_error(&self, offset: u64, len: u64) -> MapError {
        if self.parts.mapped.is_none() {
            return MapError::NotMapped;
        }
        match check_range(self.parts.size, offset, len) {
            Err(e) => e,
            // Unreachable: the fast check in `span` and check_range agree. Kept as an
            // error rather than a panic.
            Ok(_) => MapError::OutOfRange {
                offset,
                size: len,
                allocation_size: self.parts.size,
            },
        }
    }

    /// Write `value` at `offset` (flushed when the memory is not coherent).
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// a.write(0, &[0.5f32; 16])?; // a 4x4 matrix
    /// # Ok(()) }
    /// ```
    #[inline]
    pub fn write<T: bytemuck::NoUninit>(&mut self, offset: u64, value: &T) -> Result<(), MapError> {
        let len = std::mem::size_of::<T>() as u64;
        // One comparison: offset + len <= fast_len, written so that it cannot
        // overflow (saturating_sub is branch-free). Zero-sized values, and every case
        // that needs more than a copy, take the slow path with its full checks.
        if len != 0 && offset < self.fast_len.saturating_sub(len - 1) {
            // SAFETY: offset + len <= fast_len <= size, inside the mapping (as in
            // `span`); both store kinds write without making a reference.
            unsafe {
                let dst = self.base.as_ptr().add(offset as usize).cast::<T>();
                if dst.is_aligned() {
                    dst.write(*value);
                } else {
                    dst.write_unaligned(*value);
                }
            }
            Ok(())
        } else {
            self.write_bytes_slow(offset, bytemuck::bytes_of(value))
        }
    }

    /// Every write that is not an in-range write to coherent memory: checks fully,
    /// copies, flushes.
    #[inline(never)]
    fn write_bytes_slow(&mut self, offset: u64, bytes: &[u8]) -> Result<(), MapError> {
        let len = bytes.len() as u64;
        let dst = self.span(offset, len)?;
        // SAFETY: `dst` is valid for `len` bytes (span); a byte copy needs no
        // alignment, and the mapping cannot overlap a Rust slice we hold.
        unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), dst, bytes.len()) };
        self.flush_if_needed(offset, len)
    }

    /// Write `values` starting at `offset` (flushed when the memory is not coherent).
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// let vertices: [[f32; 3]; 3] = [[0.0, -0.5, 0.0], [0.5, 0.5, 0.0], [-0.5, 0.5, 0.0]];
    /// a.write_slice(0, &vertices)?;
    /// # Ok(()) }
    /// ```
    #[inline]
    pub fn write_slice<T: bytemuck::NoUninit>(
        &mut self,
        offset: u64,
        values: &[T],
    ) -> Result<(), MapError> {
        let bytes: &[u8] = bytemuck::cast_slice(values);
        let len = bytes.len() as u64;
        let dst = self.span(offset, len)?;
        // SAFETY: `dst` is valid for `len` bytes (span); a byte copy needs no
        // alignment, and the mapping cannot overlap a Rust slice we hold.
        unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), dst, bytes.len()) };
        self.flush_if_needed(offset, len)
    }

    /// Read `out.len()` values starting at `offset` (invalidated first when the memory
    /// is not coherent).
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// let mut pixels = vec![0u32; 64 * 64];
    /// a.read_slice(0, &mut pixels)?;
    /// # Ok(()) }
    /// ```
    pub fn read_slice<T: bytemuck::AnyBitPattern + bytemuck::NoUninit>(
        &self,
        offset: u64,
        out: &mut [T],
    ) -> Result<(), MapError> {
        let len = std::mem::size_of_val(out) as u64;
        let src = self.span(offset, len)?;
        if self.needs_flush {
            self.invalidate(offset, len)?;
        }
        let dst: &mut [u8] = bytemuck::cast_slice_mut(out);
        // SAFETY: `src` is valid for `len` bytes (span), `dst` is exactly `len` bytes,
        // and any bit pattern is a valid T.
        unsafe { std::ptr::copy_nonoverlapping(src, dst.as_mut_ptr(), dst.len()) };
        Ok(())
    }

    /// Read one value at `offset`.
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// let counter: u32 = a.read(0)?;
    /// # let _ = counter;
    /// # Ok(()) }
    /// ```
    pub fn read<T: bytemuck::AnyBitPattern + bytemuck::NoUninit>(
        &self,
        offset: u64,
    ) -> Result<T, MapError> {
        let mut out = [T::zeroed()];
        self.read_slice(offset, &mut out)?;
        Ok(out[0])
    }

    #[inline]
    fn flush_if_needed(&self, offset: u64, len: u64) -> Result<(), MapError> {
        if self.needs_flush {
            self.flush_written(offset, len)
        } else {
            Ok(())
        }
    }

    // Kept out of line so the coherent path of every write stays a few instructions.
    #[inline(never)]
    fn flush_written(&self, offset: u64, len: u64) -> Result<(), MapError> {
        self.flush(offset, len)
    }

    fn mapped_range(
        &self,
        offset: u64,
        len: u64,
    ) -> Result<Option<vk::MappedMemoryRange<'static>>, MapError> {
        if self.parts.mapped.is_none() {
            return Err(MapError::NotMapped);
        }
        Ok(flush_range(
            self.placement(),
            self.parts.non_coherent_atom_size,
            offset,
            len,
        )?
        .map(|(start, size)| {
            vk::MappedMemoryRange::default()
                .memory(self.parts.memory)
                .offset(start)
                .size(size)
        }))
    }

    /// Make host writes to `len` bytes at `offset` visible to the device. Needed only for
    /// non-coherent memory (the writes above do it themselves); harmless otherwise.
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// a.flush(0, 256)?;
    /// # Ok(()) }
    /// ```
    pub fn flush(&self, offset: u64, len: u64) -> Result<(), MapError> {
        if let Some(range) = self.mapped_range(offset, len)? {
            // SAFETY: the range lies inside mapped memory of this device (flush_range
            // keeps it inside the device memory, rounded to the atom size).
            unsafe { self.owner.device().flush_mapped_memory_ranges(&[range]) }
                .map_err(MapError::Vulkan)?;
        }
        Ok(())
    }

    /// Make device writes to `len` bytes at `offset` visible to the host. Needed only for
    /// non-coherent memory (the reads above do it themselves); harmless otherwise.
    ///
    /// ```no_run
    /// # fn demo(a: &mut tuff_runtime::Allocation) -> Result<(), tuff_runtime::MapError> {
    /// a.invalidate(0, 256)?;
    /// # Ok(()) }
    /// ```
    pub fn invalidate(&self, offset: u64, len: u64) -> Result<(), MapError> {
        if let Some(range) = self.mapped_range(offset, len)? {
            // SAFETY: as in `flush`.
            unsafe {
                self.owner
                    .device()
                    .invalidate_mapped_memory_ranges(&[range])
            }
            .map_err(MapError::Vulkan)?;
        }
        Ok(())
    }
}

impl Drop for Allocation {
    fn drop(&mut self) {
        if let Some(backing) = self.backing.take() {
            backing.free();
        }
        // `owner` is dropped after this, so the device outlives the free.
    }
}

/// Allocates device memory for buffers and images. The wrappers call it when a
/// resource needs memory; a user's allocator plugs in by implementing it.
///
/// ```
/// use std::sync::atomic::{AtomicUsize, Ordering};
/// use tuff_runtime::{AllocError, Allocation, AllocationRequest, Allocator};
/// /// Counts requests and hands them to another allocator.
/// struct Counting<A> { inner: A, count: AtomicUsize }
/// impl<A: Allocator> Allocator for Counting<A> {
///     fn allocate(&self, request: &AllocationRequest<'_>) -> Result<Allocation, AllocError> {
///         self.count.fetch_add(1, Ordering::Relaxed);
///         self.inner.allocate(request)
///     }
/// }
/// ```
pub trait Allocator: MaybeSendSync {
    /// Allocate memory that satisfies `request`.
    fn allocate(&self, request: &AllocationRequest<'_>) -> Result<Allocation, AllocError>;
}

/// The index of the first memory type allowed by `type_bits` that has all of
/// `required` and, among those, prefers one with all of `preferred`.
///
/// ```
/// use ash::vk;
/// let mut props = vk::PhysicalDeviceMemoryProperties::default();
/// props.memory_type_count = 2;
/// props.memory_types[0].property_flags = vk::MemoryPropertyFlags::DEVICE_LOCAL;
/// props.memory_types[1].property_flags = vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
/// let host = vk::MemoryPropertyFlags::HOST_VISIBLE;
/// assert_eq!(tuff_runtime::memory::find_memory_type(&props, 0b11, host, host), Some(1));
/// assert_eq!(tuff_runtime::memory::find_memory_type(&props, 0b01, host, host), None);
/// ```
pub fn find_memory_type(
    props: &vk::PhysicalDeviceMemoryProperties,
    type_bits: u32,
    required: vk::MemoryPropertyFlags,
    preferred: vk::MemoryPropertyFlags,
) -> Option<u32> {
    let count = (props.memory_type_count as usize).min(props.memory_types.len());
    let candidates = || {
        (0..count)
            .filter(move |i| type_bits & (1u32 << i) != 0)
            .filter(move |i| props.memory_types[*i].property_flags.contains(required))
    };
    candidates()
        .find(|i| props.memory_types[*i].property_flags.contains(preferred))
        .or_else(|| candidates().next())
        .map(|i| i as u32)
}

/// The (required, preferred) property flags of a location.
pub(crate) fn location_flags(
    location: MemoryLocation,
) -> (vk::MemoryPropertyFlags, vk::MemoryPropertyFlags) {
    use vk::MemoryPropertyFlags as F;
    match location {
        MemoryLocation::DeviceLocal => (F::DEVICE_LOCAL, F::DEVICE_LOCAL),
        MemoryLocation::Upload => (F::HOST_VISIBLE, F::HOST_VISIBLE | F::HOST_COHERENT),
        MemoryLocation::Readback => (F::HOST_VISIBLE, F::HOST_VISIBLE | F::HOST_CACHED),
    }
}

/// Requirements made safe to flush: for non-coherent memory the size and alignment
/// are rounded up to the atom size, so that rounded flush ranges never reach into a
/// neighbouring allocation.
pub(crate) fn atom_aligned(
    requirements: vk::MemoryRequirements,
    atom: u64,
) -> Result<vk::MemoryRequirements, AllocError> {
    if atom == 0 || !atom.is_power_of_two() {
        return Err(AllocError::InvalidRequirements(format!(
            "nonCoherentAtomSize {atom} is not a power of two"
        )));
    }
    let size = requirements
        .size
        .checked_next_multiple_of(atom)
        .ok_or_else(|| {
            AllocError::InvalidRequirements(format!(
                "size {} overflows when rounded",
                requirements.size
            ))
        })?;
    Ok(vk::MemoryRequirements {
        size,
        alignment: requirements.alignment.max(atom),
        memory_type_bits: requirements.memory_type_bits,
    })
}
