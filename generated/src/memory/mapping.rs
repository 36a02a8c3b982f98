//! Host access to device memory: [`DeviceMemory::map`] maps the whole allocation and
//! returns a guard with checked, typed copies in and out; the guard unmaps on drop.
//!
//! The rules of `vkMapMemory` hold by construction or are checked: the memory is
//! mapped whole (offset 0, `VK_WHOLE_SIZE`), so the range rules hold; a second map of
//! the same memory while a guard lives is refused (`VUID-vkMapMemory-memory-00678`),
//! and so is memory whose type is not host-visible (`VUID-vkMapMemory-memory-00682`).
//! Copies are bounds-checked, and memory that is not host-coherent is flushed after a
//! write and invalidated before a read, over ranges rounded to `nonCoherentAtomSize`.
//!
//! What stays with the caller: host access must not race with GPU access to the same
//! bytes (wait on the fence of a submission that reads or writes them first), and
//! memory from a multi-instance heap is not mapped (`VUID-vkMapMemory-memory-00683`).
//! A [`MappedMemory`] holds a raw pointer, so it stays on the thread that mapped it.

use crate::{DeviceMemory, Error, Handle, Result};
use ash::vk;
use core::ptr::NonNull;
use tuff_runtime::mapped::{check_range, flush_range, Placement};

/// A device memory mapped for host access; unmapped when dropped.
///
/// ```no_run
/// # fn f(memory: &tuff::DeviceMemory) -> tuff::Result<()> {
/// let mut mapped = memory.map()?;
/// mapped.write(0, &[1.0f32, 2.0, 3.0])?;
/// let back: Vec<f32> = mapped.read(0, 3)?;
/// assert_eq!(back, [1.0, 2.0, 3.0]);
/// # Ok(()) }
/// ```
pub struct MappedMemory<'a> {
    memory: &'a DeviceMemory,
    ptr: NonNull<u8>,
    size: u64,
    coherent: bool,
    atom: u64,
}

impl core::fmt::Debug for MappedMemory<'_> {
    /// The memory, where it is mapped and its size.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("MappedMemory")
            .field("memory", self.memory)
            .field("ptr", &self.ptr)
            .field("size", &self.size)
            .field("coherent", &self.coherent)
            .finish_non_exhaustive()
    }
}

impl DeviceMemory {
    /// Maps the whole memory for host access.
    ///
    /// Fails with the rule's VUID when the memory is already mapped
    /// (`VUID-vkMapMemory-memory-00678`) or its type is not host-visible
    /// (`VUID-vkMapMemory-memory-00682`), and with [`Error::Vk`] when
    /// `vkMapMemory` fails.
    ///
    /// ```no_run
    /// # fn f(memory: &tuff::DeviceMemory) -> tuff::Result<()> {
    /// let pixels: Vec<u8> = memory.map()?.read(0, 16)?;
    /// # Ok(()) }
    /// ```
    pub fn map(&self) -> Result<MappedMemory<'_>> {
        let device = self.parent();
        // Every wrapper comes from `allocate_memory`, which records it.
        let (size, type_index, host) = device
            .live()
            .memory(self.raw(), |r| (r.size, r.memory_type_index, r.host))
            .ok_or(Error::Vk(vk::Result::ERROR_MEMORY_MAP_FAILED))?;
        let (flags, atom) = match host {
            Some(host) => host,
            None => {
                let physical = device.parent();
                let flags = physical
                    .get_memory_properties()
                    .memory_types
                    .get(type_index as usize)
                    .map(|t| t.property_flags)
                    .unwrap_or_default();
                let atom = physical.get_properties().limits.non_coherent_atom_size;
                device
                    .live()
                    .memory(self.raw(), |r| r.host = Some((flags, atom)));
                (flags, atom)
            }
        };
        if !flags.contains(vk::MemoryPropertyFlags::HOST_VISIBLE) {
            return Err(Error::Validation {
                vuid: "VUID-vkMapMemory-memory-00682",
                message: format!("memory type {type_index} is not HOST_VISIBLE"),
            });
        }
        // Mapped and marked under the records' lock, which the safe flushes and
        // invalidates hold while they check a mapping and use it: none of them sees
        // the mark before the mapping exists.
        let mapped = device.live().memory(self.raw(), |r| {
            if r.mapped {
                return Err(Error::Validation {
                    vuid: "VUID-vkMapMemory-memory-00678",
                    message: "the memory is already mapped".into(),
                });
            }
            let mut ptr = core::ptr::null_mut();
            // SAFETY: the memory is a live allocation of this device, host-visible,
            // not mapped now (the record says so, under its lock), and mapped whole,
            // so offset and size are in range.
            let r_map = unsafe {
                (device.fns().fp_v1_0().map_memory)(
                    device.raw(),
                    self.raw(),
                    0,
                    vk::WHOLE_SIZE,
                    vk::MemoryMapFlags::empty(),
                    &mut ptr,
                )
            };
            if r_map != vk::Result::SUCCESS {
                return Err(Error::Vk(r_map));
            }
            let Some(ptr) = NonNull::new(ptr.cast::<u8>()) else {
                // SAFETY: the call above mapped the memory; a null pointer is useless,
                // so it is unmapped again.
                unsafe { (device.fns().fp_v1_0().unmap_memory)(device.raw(), self.raw()) };
                return Err(Error::Vk(vk::Result::ERROR_MEMORY_MAP_FAILED));
            };
            r.mapped = true;
            Ok(ptr)
        });
        let ptr = mapped.ok_or(Error::Vk(vk::Result::ERROR_MEMORY_MAP_FAILED))??;
        // From here the guard's Drop unmaps and clears the mark.
        Ok(MappedMemory {
            memory: self,
            ptr,
            size,
            coherent: flags.contains(vk::MemoryPropertyFlags::HOST_COHERENT),
            atom,
        })
    }
}

impl MappedMemory<'_> {
    /// The size of the mapping in bytes (the whole allocation).
    #[inline]
    pub fn size(&self) -> u64 {
        self.size
    }

    /// The device-memory range to flush or invalidate for `len` bytes at `offset`.
    fn range(&self, offset: u64, len: u64) -> Result<Option<vk::MappedMemoryRange<'static>>> {
        if self.coherent {
            return Ok(None);
        }
        let placement = Placement {
            offset: 0,
            size: self.size,
            memory_size: self.size,
        };
        Ok(flush_range(placement, self.atom, offset, len)
            .map_err(Error::Map)?
            .map(|(offset, size)| {
                vk::MappedMemoryRange::default()
                    .memory(self.memory.raw())
                    .offset(offset)
                    .size(size)
            }))
    }

    /// Copies `data` to `offset` bytes into the memory, and flushes it when the memory
    /// is not host-coherent. Fails with [`Error::Map`] when it does not fit.
    ///
    /// ```no_run
    /// # fn f(memory: &tuff::DeviceMemory) -> tuff::Result<()> {
    /// memory.map()?.write(16, &[0u32; 4])?;
    /// # Ok(()) }
    /// ```
    pub fn write<T: bytemuck::NoUninit>(&mut self, offset: u64, data: &[T]) -> Result<()> {
        let bytes: &[u8] = bytemuck::cast_slice(data);
        let len = bytes.len() as u64;
        check_range(self.size, offset, len).map_err(Error::Map)?;
        // SAFETY: `offset + len` lies inside the mapping (checked above), `bytes` is
        // host memory that cannot overlap the mapping, and `&mut self` makes this the
        // only host access through the guard.
        unsafe {
            core::ptr::copy_nonoverlapping(
                bytes.as_ptr(),
                self.ptr.as_ptr().add(offset as usize),
                bytes.len(),
            )
        };
        if let Some(range) = self.range(offset, len)? {
            let device = self.memory.parent();
            // SAFETY: the range lies in this mapped memory and is rounded to
            // nonCoherentAtomSize (VUID-VkMappedMemoryRange-size-01390).
            let r = unsafe {
                (device.fns().fp_v1_0().flush_mapped_memory_ranges)(device.raw(), 1, &range)
            };
            if r != vk::Result::SUCCESS {
                return Err(Error::Vk(r));
            }
        }
        Ok(())
    }

    /// Copies `count` values of `T` out of the memory, starting `offset` bytes in,
    /// after invalidating them when the memory is not host-coherent. Fails with
    /// [`Error::Map`] when they do not fit.
    ///
    /// ```no_run
    /// # fn f(memory: &tuff::DeviceMemory) -> tuff::Result<()> {
    /// let words: Vec<u32> = memory.map()?.read(0, 4)?;
    /// # Ok(()) }
    /// ```
    pub fn read<T: bytemuck::AnyBitPattern>(&self, offset: u64, count: usize) -> Result<Vec<T>> {
        let len = (count as u64)
            .checked_mul(core::mem::size_of::<T>() as u64)
            .ok_or(Error::Map(tuff_runtime::MapError::Overflow {
                offset,
                size: count as u64,
            }))?;
        check_range(self.size, offset, len).map_err(Error::Map)?;
        if let Some(range) = self.range(offset, len)? {
            let device = self.memory.parent();
            // SAFETY: as for the flush in `write`.
            let r = unsafe {
                (device.fns().fp_v1_0().invalidate_mapped_memory_ranges)(device.raw(), 1, &range)
            };
            if r != vk::Result::SUCCESS {
                return Err(Error::Vk(r));
            }
        }
        let mut out = vec![T::zeroed(); count];
        // SAFETY: `offset + len` lies inside the mapping (checked above) and `out` holds
        // exactly `len` bytes; any bit pattern is a valid `T`.
        unsafe {
            core::ptr::copy_nonoverlapping(
                self.ptr.as_ptr().add(offset as usize),
                out.as_mut_ptr().cast::<u8>(),
                len as usize,
            )
        };
        Ok(out)
    }
}

impl Drop for MappedMemory<'_> {
    fn drop(&mut self) {
        let device = self.memory.parent();
        // SAFETY: this guard mapped the memory, which its borrow keeps alive, and no
        // pointer into the mapping outlives the guard.
        let unmap =
            || unsafe { (device.fns().fp_v1_0().unmap_memory)(device.raw(), self.memory.raw()) };
        // Unmapped under the records' lock, beside no safe flush or invalidate (see
        // `map`); the record lives as long as the memory.
        let found = device.live().memory(self.memory.raw(), |r| {
            unmap();
            r.mapped = false;
        });
        if found.is_none() {
            unmap();
        }
    }
}
