//! Indirect arguments the host writes, so that tuff can check them: an
//! [`IndirectBuffer`] holds draws, indexed draws, dispatches or draw counts in
//! host-visible memory that only its own methods write, and keeps a copy on the host.
//!
//! An indirect command reads its arguments from GPU memory when it executes, so the
//! generated `draw_indirect` and its siblings, which take any buffer, leave the
//! arguments' rules to their caller. The safe forms (`Recorder::draw_indirect_from`
//! and its siblings, `special/indirect.rs`) take an `IndirectBuffer` instead and
//! check its copy as the direct command's arguments are checked. What the device
//! reads is what was checked because nothing else writes the buffer: it is created
//! with `INDIRECT_BUFFER` usage alone (so no transfer, storage or texel write can
//! name it), its memory is never handed out, and [`IndirectBuffer::write`] is
//! refused while a command buffer that recorded it could still run (every recording
//! that names it keeps a token of it, dropped when the command buffer is recorded
//! again or freed). Host writes made before a submission are visible to it
//! (`vkQueueSubmit`'s host-write ordering), so no barrier is needed.
//!
//! ```no_run
//! # fn f(device: &tuff::Device) -> tuff::Result<()> {
//! use tuff::vk;
//! let allocator = device.gpu_allocator()?;
//! let draw = vk::DrawIndirectCommand {
//!     vertex_count: 3,
//!     instance_count: 1,
//!     first_vertex: 0,
//!     first_instance: 0,
//! };
//! let mut draws = device.create_indirect_buffer(&[draw; 4], &allocator)?;
//! draws.write(2, &[vk::DrawIndirectCommand { instance_count: 0, ..draw }])?;
//! assert_eq!(draws.arguments()[2].instance_count, 0);
//! # Ok(()) }
//! ```

use crate::memory::allocation::{Bound, MemoryLocation};
use crate::support::refuse;
use crate::{Buffer, BufferCreateInfo, Device, Error, Result};
use ash::vk;
use tuff_runtime::{Allocator, Retained, Vrc};

mod sealed {
    /// What tuff knows of one kind of indirect argument: its words as the device
    /// reads them, and the rules of its struct that hold whatever draws it.
    pub trait Arguments: Copy + core::fmt::Debug + 'static {
        /// Appends the 32-bit words of one element, in the struct's layout.
        fn words(&self, out: &mut Vec<u32>);
        /// Refuses an element that breaks a rule of its struct on `device`.
        fn check(&self, device: &crate::Device) -> crate::Result<()>;
    }
}

/// An indirect argument an [`IndirectBuffer`] can hold: `vk::DrawIndirectCommand`,
/// `vk::DrawIndexedIndirectCommand`, `vk::DispatchIndirectCommand`, or `u32` (the
/// draw count of `draw_indirect_count_from`). Sealed: these are the layouts the
/// device reads.
pub trait IndirectArguments: sealed::Arguments {}

impl sealed::Arguments for vk::DrawIndirectCommand {
    fn words(&self, out: &mut Vec<u32>) {
        out.extend([
            self.vertex_count,
            self.instance_count,
            self.first_vertex,
            self.first_instance,
        ]);
    }
    fn check(&self, device: &Device) -> Result<()> {
        first_instance(
            device,
            self.first_instance,
            "VUID-VkDrawIndirectCommand-firstInstance-00501",
        )
    }
}
impl IndirectArguments for vk::DrawIndirectCommand {}

impl sealed::Arguments for vk::DrawIndexedIndirectCommand {
    fn words(&self, out: &mut Vec<u32>) {
        out.extend([
            self.index_count,
            self.instance_count,
            self.first_index,
            self.vertex_offset as u32,
            self.first_instance,
        ]);
    }
    fn check(&self, device: &Device) -> Result<()> {
        first_instance(
            device,
            self.first_instance,
            "VUID-VkDrawIndexedIndirectCommand-firstInstance-00554",
        )
    }
}
impl IndirectArguments for vk::DrawIndexedIndirectCommand {}

impl sealed::Arguments for vk::DispatchIndirectCommand {
    fn words(&self, out: &mut Vec<u32>) {
        out.extend([self.x, self.y, self.z]);
    }
    fn check(&self, device: &Device) -> Result<()> {
        let max = crate::state::limits(device).max_compute_work_group_count;
        let rules = [
            "VUID-VkDispatchIndirectCommand-x-00417",
            "VUID-VkDispatchIndirectCommand-y-00418",
            "VUID-VkDispatchIndirectCommand-z-00419",
        ];
        for (i, (count, rule)) in [self.x, self.y, self.z].into_iter().zip(rules).enumerate() {
            if count > max[i] {
                refuse(
                    rule,
                    format!("the dispatch's group count {i} is {count}, past maxComputeWorkGroupCount[{i}] ({})", max[i]),
                )?;
            }
        }
        Ok(())
    }
}
impl IndirectArguments for vk::DispatchIndirectCommand {}

/// Refuses a draw whose first instance is not 0 on a device without
/// `drawIndirectFirstInstance`.
fn first_instance(device: &Device, first: u32, rule: &'static str) -> Result<()> {
    let feature = device
        .live()
        .with_features(|f| f.v10.draw_indirect_first_instance);
    if first != 0 && feature == vk::FALSE {
        refuse(
            rule,
            format!("the draw's firstInstance is {first}, and the device did not enable the drawIndirectFirstInstance feature"),
        )?;
    }
    Ok(())
}

/// A draw count: every value is one the buffer may hold (the count a draw reads is
/// checked against `maxDrawIndirectCount` where it is recorded).
impl sealed::Arguments for u32 {
    fn words(&self, out: &mut Vec<u32>) {
        out.push(*self);
    }
    fn check(&self, _device: &Device) -> Result<()> {
        Ok(())
    }
}
impl IndirectArguments for u32 {}

/// Indirect arguments in host-visible memory that only the host writes, through
/// [`IndirectBuffer::write`], with a copy tuff reads to check the safe indirect
/// commands (module docs).
pub struct IndirectBuffer<T: IndirectArguments> {
    buffer: Bound<Buffer>,
    arguments: Vec<T>,
    /// Kept by every recording that names the buffer: while anyone else holds it, a
    /// command buffer that could run may read the arguments.
    token: Vrc<()>,
}

impl<T: IndirectArguments> core::fmt::Debug for IndirectBuffer<T> {
    /// The buffer and the arguments it holds.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("IndirectBuffer")
            .field("buffer", &*self.buffer)
            .field("arguments", &self.arguments)
            .finish()
    }
}

impl Device {
    crate::helpers::as_safe_as! { vkCreateBuffer,
        /// An [`IndirectBuffer`] holding `arguments`, in host-visible memory from
        /// `allocator`: a buffer of `INDIRECT_BUFFER` usage alone, as long as the
        /// arguments (one element at least: a buffer cannot be empty). Each element is
        /// checked first, as [`IndirectBuffer::write`] checks it.
        ///
        /// # Safety
        ///
        /// As [`Device::create_buffer_in`] (safe with this crate's emitted API).
        ///
        /// ```no_run
        /// # fn f(device: &tuff::Device) -> tuff::Result<()> {
        /// let groups = tuff::vk::DispatchIndirectCommand { x: 8, y: 8, z: 1 };
        /// let dispatches = device.create_indirect_buffer(&[groups], &device.gpu_allocator()?)?;
        /// assert_eq!(dispatches.len(), 1);
        /// # Ok(()) }
        /// ```
        pub fn create_indirect_buffer<T: IndirectArguments, A: Allocator + ?Sized>(
            &self,
            arguments: &[T],
            allocator: &A,
        ) -> Result<IndirectBuffer<T>> {
            if arguments.is_empty() {
                return Err(Error::Misuse(
                    "an indirect buffer holds one argument at least: a buffer cannot be empty",
                ));
            }
            for a in arguments {
                a.check(self)?;
            }
            let words = words(arguments);
            let info = BufferCreateInfo::new()
                .size(core::mem::size_of_val(words.as_slice()) as u64)
                .usage(vk::BufferUsageFlags::INDIRECT_BUFFER);
            #[allow(unused_unsafe)]
            // SAFETY: where `create_buffer_in` is `unsafe`, so is this method, and its
            // caller upholds what it asks of the info.
            let buffer = unsafe { self.create_buffer_in(&info, allocator, MemoryLocation::Upload) }?;
            buffer.memory().write(0, &words)?;
            Ok(IndirectBuffer {
                buffer,
                arguments: arguments.to_vec(),
                token: Vrc::new(()),
            })
        }
    }
}

/// The words of `arguments`, as the device reads them.
fn words<T: IndirectArguments>(arguments: &[T]) -> Vec<u32> {
    let mut out = Vec::with_capacity(arguments.len() * 5);
    for a in arguments {
        a.words(&mut out);
    }
    out
}

impl<T: IndirectArguments> IndirectBuffer<T> {
    /// Writes `arguments` from element `first` on, each checked first (a draw's
    /// `firstInstance` against the `drawIndirectFirstInstance` feature, a dispatch's
    /// group counts against `maxComputeWorkGroupCount`). Refused with
    /// [`Error::Misuse`] while a command buffer that recorded this buffer has not been
    /// recorded again or freed (it could still run and read the old arguments), or
    /// when the elements do not fit; nothing is written then.
    ///
    /// ```no_run
    /// # fn f(draws: &mut tuff::IndirectBuffer<tuff::vk::DrawIndexedIndirectCommand>) -> tuff::Result<()> {
    /// let draw = tuff::vk::DrawIndexedIndirectCommand { index_count: 36, instance_count: 1, ..Default::default() };
    /// draws.write(0, &[draw])?;
    /// # Ok(()) }
    /// ```
    pub fn write(&mut self, first: usize, arguments: &[T]) -> Result<()> {
        if Vrc::strong_count(&self.token) > 1 {
            return Err(Error::Misuse(
                "the indirect buffer is named by a command buffer that could still run: record that command buffer again (or free it) before writing the arguments",
            ));
        }
        let end = first.checked_add(arguments.len());
        if end.is_none_or(|end| end > self.arguments.len()) {
            return Err(Error::Misuse(
                "the arguments written reach past the end of the indirect buffer",
            ));
        }
        let device = self.buffer.parent();
        for a in arguments {
            a.check(device)?;
        }
        let offset = (first * core::mem::size_of::<T>()) as u64;
        self.buffer.memory().write(offset, &words(arguments))?;
        self.arguments[first..first + arguments.len()].copy_from_slice(arguments);
        Ok(())
    }

    /// The arguments the buffer holds, as the device reads them.
    ///
    /// ```no_run
    /// # fn f(counts: &tuff::IndirectBuffer<u32>) {
    /// let count = counts.arguments()[0];
    /// # let _ = count; }
    /// ```
    pub fn arguments(&self) -> &[T] {
        &self.arguments
    }

    /// How many elements the buffer holds.
    ///
    /// ```no_run
    /// # fn f(draws: &tuff::IndirectBuffer<tuff::vk::DrawIndirectCommand>) {
    /// assert!(!draws.is_empty());
    /// # let _ = draws.len(); }
    /// ```
    pub fn len(&self) -> usize {
        self.arguments.len()
    }

    /// Never: an indirect buffer holds one element at least.
    ///
    /// ```no_run
    /// # fn f(draws: &tuff::IndirectBuffer<u32>) {
    /// assert!(!draws.is_empty());
    /// # }
    /// ```
    pub fn is_empty(&self) -> bool {
        self.arguments.is_empty()
    }

    /// The buffer, for the recording that reads it.
    pub(crate) fn buffer(&self) -> &Buffer {
        &self.buffer
    }

    /// The token a recording keeps while it may read the arguments.
    pub(crate) fn token(&self) -> Retained {
        self.token.clone()
    }

    /// The size of one element in bytes: the stride the safe forms pass.
    pub(crate) fn stride() -> u32 {
        core::mem::size_of::<T>() as u32
    }
}
