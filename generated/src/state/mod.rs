//! What the device records of its objects, one file per kind of object (buffer,
//! image, memory, render pass, pipeline, descriptors, query, swapchain, queue, ...),
//! below the checks: `special/` reads these records to check a command, and nothing
//! here reads `special/`.
//!
//! `live.rs` holds [`Live`], one per device, with every side table; each table's
//! methods sit in the file of the object it records. The raw reads of arrays that
//! Vulkan structs point to, which the records and the emitted methods share, are here.

mod buffer;
mod command_buffer;
mod command_pool;
mod descriptors;
pub(crate) mod events;
mod features;
mod framebuffer;
pub(crate) mod hazards;
mod image;
pub(crate) mod layouts;
mod live;
mod memory;
mod pipeline;
pub(crate) mod queries;
mod query;
mod queue;
mod render_pass;
mod sampler;
pub(crate) mod small_map;
mod swapchain;
mod sync;
mod view;

pub(crate) use self::buffer::BufferRecord;
pub(crate) use self::command_buffer::{
    BeginChecked, EventsUsed, Inheritance, InheritedRendering, SetsUsed, Standing, Uses,
};
pub(crate) use self::command_pool::PoolFamily;
pub(crate) use self::descriptors::{
    names_image_layout, sampler_bits, BindingRecord, ImageDescriptor, SetImages, SetLayoutRecord,
    SetWritten, SlotKind, SAMPLER_LINEAR, SAMPLER_MIPMAP_LINEAR, SAMPLER_UNNORMALIZED,
    SAMPLER_YCBCR,
};
pub(crate) use self::features::Features;
pub(crate) use self::framebuffer::{AttachmentImage, AttachmentMemory};
pub(crate) use self::image::ImageRecord;
pub(crate) use self::live::{limits, Live};
pub(crate) use self::memory::{Binding, MemoryAsked, MemoryRecords};
pub(crate) use self::pipeline::{
    dynamic_bit, DepthStencil, DescriptorUse, LayoutRecord, PipelineRecord, RenderingFormats,
    VertexRead,
};
pub(crate) use self::query::QueryPoolRecord;
pub(crate) use self::queue::{Completes, Kept, Ledger, Submission};
pub(crate) use self::render_pass::{
    AttachmentLayouts, Boundary, Compatibility, Edges, RenderPassRecord, SelfDependency,
    SubpassShape, USED_COLOR, USED_DEPTH, USED_DEPTH_RESOLVE, USED_INPUT, USED_RESOLVE,
};
pub(crate) use self::sync::{Binary, Timeline};
pub(crate) use self::view::ViewRecord;

/// The array a raw struct member points to.
///
/// # Safety
///
/// `ptr` points to `count` elements that outlive `'a`, or `count` is 0.
pub(crate) unsafe fn raw_slice<'a, T>(ptr: *const T, count: u32) -> &'a [T] {
    if count == 0 || ptr.is_null() {
        &[]
    } else {
        // SAFETY: the caller vouches for `count` elements at `ptr`.
        unsafe { core::slice::from_raw_parts(ptr, count as usize) }
    }
}

/// Element `i` of a raw array, or a zeroed one (null handles) when the array is null.
///
/// # Safety
///
/// A non-null `ptr` points to more than `i` elements.
pub(super) unsafe fn read<T: Copy + Default>(ptr: *const T, i: usize) -> T {
    if ptr.is_null() {
        T::default()
    } else {
        // SAFETY: the caller vouches for element `i`.
        unsafe { *ptr.add(i) }
    }
}

/// The hash map of the device's records and the recorder's tables: FxHash (their
/// keys are handles and small tuples, looked up on every recorded command), each hash
/// counted by `tuff_runtime::count_hash` (nothing in a build without the runtime's
/// `work_counts`; with it, tests assert the draw path computes none).
pub(crate) type HashMap<K, V> =
    std::collections::HashMap<K, V, core::hash::BuildHasherDefault<CountedFx>>;

/// [`rustc_hash::FxHasher`], counted ([`HashMap`]).
#[derive(Default)]
pub(crate) struct CountedFx(rustc_hash::FxHasher);

impl core::hash::Hasher for CountedFx {
    #[inline]
    fn finish(&self) -> u64 {
        tuff_runtime::count_hash();
        self.0.finish()
    }
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        self.0.write(bytes);
    }
    #[inline]
    fn write_u8(&mut self, n: u8) {
        self.0.write_u8(n);
    }
    #[inline]
    fn write_u16(&mut self, n: u16) {
        self.0.write_u16(n);
    }
    #[inline]
    fn write_u32(&mut self, n: u32) {
        self.0.write_u32(n);
    }
    #[inline]
    fn write_u64(&mut self, n: u64) {
        self.0.write_u64(n);
    }
    #[inline]
    fn write_usize(&mut self, n: usize) {
        self.0.write_usize(n);
    }
}
