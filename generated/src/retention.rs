//! What keeps objects alive when Vulkan reaches them through raw handles stored in
//! structs rather than through wrapper arguments: a view's image, a framebuffer's
//! attachments, a pipeline's layout, a render pass instance's framebuffer, and the
//! buffers, views and samplers written into a descriptor set.
//!
//! Every object of a device is listed here (weakly) under its raw handle while its
//! wrapper lives. A wrapper that Vulkan lets refer to others looks them up and keeps
//! them (strongly); a descriptor set keeps what was last written into each of its
//! elements until it is rewritten or the set goes.

use ash::vk::{self, Handle as _};
// Looked up on every call that keeps or checks an object: a fast hash for handles.
use rustc_hash::FxHashMap as HashMap;
use tuff_runtime::{HostSync, Retained, Vrc, Vutex, Vweak};

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
unsafe fn read<T: Copy + Default>(ptr: *const T, i: usize) -> T {
    if ptr.is_null() {
        T::default()
    } else {
        // SAFETY: the caller vouches for element `i`.
        unsafe { *ptr.add(i) }
    }
}

/// Whether a descriptor type takes a dynamic offset at binding.
fn is_dynamic(ty: vk::DescriptorType) -> bool {
    matches!(
        ty,
        vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC | vk::DescriptorType::STORAGE_BUFFER_DYNAMIC
    )
}

/// An element of a descriptor set: binding, array element, and which of the
/// descriptor's handles (an image descriptor has a view and a sampler).
type Slot = (u32, u32, u8);

/// A dynamic buffer descriptor as written: `offset`, `range` (maybe
/// `VK_WHOLE_SIZE`) and the size of the buffer.
pub(crate) type DynamicRange = (u64, u64, u64);

/// The dynamic buffer descriptors of one set, by binding and array element.
type SetRanges = HashMap<(u32, u32), DynamicRange>;

/// A framebuffer's attachments (none for an imageless one) and its width, height
/// and layer count.
pub(crate) type FramebufferRecord = (Vec<vk::ImageView>, [u32; 3]);

/// What an imageless framebuffer's `VkFramebufferAttachmentImageInfo` says of the
/// view that a render pass instance on it gives for one attachment.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct AttachmentImage {
    /// `flags`.
    pub flags: vk::ImageCreateFlags,
    /// `usage`.
    pub usage: vk::ImageUsageFlags,
    /// `width`, `height` and `layerCount`.
    pub size: [u32; 3],
    /// `pViewFormats`, sorted.
    pub formats: Vec<vk::Format>,
}

/// Where a buffer or image is bound: the raw memory, the offset there and the
/// bytes it takes.
pub(crate) type Binding = (u64, u64, u64);

/// A live object, weakly, and its host synchronization.
type LiveEntry = (Vweak<dyn tuff_runtime::Retain>, HostSync);

/// The live objects of one device, and what each descriptor set refers to.
pub(crate) struct Live {
    /// Each live object, weakly, with the host synchronization that every wrapper of
    /// its handle shares.
    objects: Vutex<HashMap<(vk::ObjectType, u64), LiveEntry>>,
    sets: Vutex<HashMap<u64, HashMap<Slot, Retained>>>,
    /// For each dynamic buffer descriptor written (set, then binding and array
    /// element): the offset and range written, and the buffer's size, which a
    /// binding's dynamic offset is checked against.
    dynamic_ranges: Vutex<HashMap<u64, SetRanges>>,
    /// Each device memory's size, type and whether it is mapped now.
    memories: Vutex<HashMap<u64, crate::mapping::MemoryRecord>>,
    /// Each live image view's parameters.
    views: Vutex<HashMap<u64, ViewRecord>>,
    /// Each live framebuffer's attachments (none for an imageless one) and its
    /// width, height and layer count.
    framebuffers: Vutex<HashMap<u64, FramebufferRecord>>,
    /// Each live imageless framebuffer's attachment image infos.
    imageless: Vutex<HashMap<u64, Vec<AttachmentImage>>>,
    /// The record of the render pass each live framebuffer was created with.
    framebuffer_passes: Vutex<HashMap<u64, Vrc<RenderPassRecord>>>,
    /// The view formats each live image's create info listed, where it listed any.
    view_formats: Vutex<HashMap<u64, Vec<vk::Format>>>,
    /// Each live sampler Y'CbCr conversion's format.
    conversions: Vutex<HashMap<u64, vk::Format>>,
    /// Held by a safe allocation from its count check until its memory is listed,
    /// so two threads cannot both take the last allocation `maxMemoryAllocationCount`
    /// allows.
    allocating: Vutex<()>,
    /// The device's queue operations that may still be executing.
    ledger: crate::submission::Ledger,
    /// The host synchronization of each queue of the device.
    queues: Vutex<HashMap<u64, HostSync>>,
    /// The queue family of each queue got through the wrappers.
    queue_families: Vutex<HashMap<u64, u32>>,
    /// Each live command pool's queue family: its flags and image transfer
    /// granularity, and whether the pool is protected.
    pools: Vutex<HashMap<u64, crate::special::PoolFamily>>,
    /// Each bound buffer's and image's memory, offset and size there.
    bindings: Vutex<HashMap<(vk::ObjectType, u64), Binding>>,
    /// The format properties asked of the physical device, by format.
    formats: Vutex<HashMap<i32, vk::FormatProperties>>,
    /// `VkDeviceGroupPresentCapabilitiesKHR::presentMask`, read once.
    #[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
    present_masks: Vutex<Option<[u32; vk::MAX_DEVICE_GROUP_SIZE]>>,
    /// The device's timeline semaphores (the others are binary).
    timelines: Vutex<HashMap<u64, crate::submission::Timeline>>,
    /// The binary semaphores with a signal or wait submitted that may matter still
    /// (an unlisted one is unsignaled with nothing pending).
    binaries: Vutex<HashMap<u64, crate::submission::Binary>>,
    /// The live events created with `VK_EVENT_CREATE_DEVICE_ONLY_BIT`, which the
    /// host may not set, reset or read.
    device_only_events: Vutex<std::collections::HashSet<u64>>,
    /// The memory each live sparse buffer or image requires, and their sum, which
    /// `sparseAddressSpaceSize` bounds.
    sparse_resources: Vutex<HashMap<(vk::ObjectType, u64), u64>>,
    sparse_total: Vutex<u64>,
    /// Held by a safe sparse creation from its check against
    /// `sparseAddressSpaceSize` until its resource is listed.
    sparse_gate: Vutex<()>,
    /// What the recorder needs of each live render pass.
    render_passes: Vutex<HashMap<u64, Vrc<RenderPassRecord>>>,
    /// What the checks of commands that use a buffer need to know of it.
    buffers: Vutex<HashMap<u64, BufferRecord>>,
    /// Each shader module's interface, which pipeline creation checks layouts against.
    shader_modules: Vutex<HashMap<u64, Vrc<crate::spirv::Interface>>>,
    /// What the checks of commands and structs that name an image need to know of it.
    images: Vutex<HashMap<u64, ImageRecord>>,
    /// The layout of each subresource of an image (numbered as
    /// [`crate::layouts::Shape`] does) as the submissions so far leave it; an
    /// unlisted image is wholly `UNDEFINED`.
    layouts: Vutex<HashMap<u64, Vec<vk::ImageLayout>>>,
    /// Each swapchain's images, as one record: what `get_swapchain_images_khr`
    /// records for every image it returns.
    swapchains: Vutex<HashMap<u64, ImageRecord>>,
    /// Each live swapchain's surface, whether a later creation retired it, and the
    /// indices of the images acquired and not presented since.
    swapchain_states: Vutex<HashMap<u64, SwapchainState>>,
    /// Each query pool's type, query count and statistics.
    query_pools: Vutex<HashMap<u64, QueryPoolRecord>>,
    /// Each pipeline layout's push-constant ranges and sets.
    pipeline_layouts: Vutex<HashMap<u64, Vrc<LayoutRecord>>>,
    /// Each pipeline's bind point and layout.
    pipelines: Vutex<HashMap<u64, PipelineRecord>>,
    /// Each descriptor set layout's bindings.
    set_layouts: Vutex<HashMap<u64, Vrc<SetLayoutRecord>>>,
    /// Each descriptor set's layout record.
    sets_layouts: Vutex<HashMap<u64, Vrc<SetLayoutRecord>>>,
    /// The physical device's limits, read once.
    limits: std::sync::OnceLock<vk::PhysicalDeviceLimits>,
    /// `maxMultiviewInstanceIndex`, read the first time a draw in a multiview
    /// render pass instance needs it.
    max_multiview_instance: std::sync::OnceLock<Option<u32>>,
    /// How many live buffers and images were created protected.
    protected_resources: std::sync::atomic::AtomicUsize,
    /// The physical device's `maxBufferSize`, read once (none below Vulkan 1.3).
    max_buffer_size: std::sync::OnceLock<Option<u64>>,
    /// The core features the device was created with.
    features: std::sync::OnceLock<crate::validation::Features>,
    /// The queue families the device was created with, each with its queue count
    /// and create flags, one per `VkDeviceQueueCreateInfo`.
    queue_infos: std::sync::OnceLock<Vec<(u32, u32, vk::DeviceQueueCreateFlags)>>,
    /// How many physical devices make up the device (a chained
    /// `VkDeviceGroupDeviceCreateInfo`'s count, or 1), which bounds device masks.
    physical_count: std::sync::OnceLock<u32>,
    /// The memory bound to each buffer or image by `vkBind*Memory2`, kept as long
    /// as the object is listed (`vkBind*Memory` keep it in the wrapper instead).
    bound_memories: Vutex<HashMap<(vk::ObjectType, u64), Retained>>,
    /// Each live descriptor set's generation and the submissions of the command
    /// buffers that bound it.
    set_uses: Vutex<HashMap<u64, SetUse>>,
    /// The last generation given to a descriptor set: a device-wide count, so a set
    /// handle that a pool reuses never meets a generation of the set it was before.
    set_generations: std::sync::atomic::AtomicU64,
    /// Held by every descriptor update, and by every queue submission from its
    /// checks of what other submissions use and leave (descriptor sets, events,
    /// semaphores) to its record of its own: the host access to a set is externally
    /// synchronized, and no update or submission on another queue runs between a
    /// submission's checks and its bookkeeping.
    descriptor_gate: Vutex<()>,
    /// The buffer of each live buffer view.
    buffer_views: Vutex<HashMap<u64, (vk::Buffer, vk::Format)>>,
    /// What each live sampler does, as [`sampler_bits`] gives it.
    samplers: Vutex<HashMap<u64, u8>>,
    /// The queues got with `VK_DEVICE_QUEUE_CREATE_PROTECTED_BIT`.
    protected_queues: Vutex<std::collections::HashSet<u64>>,
    /// The physical device's `maxTimelineSemaphoreValueDifference`, read once.
    timeline_difference: std::sync::OnceLock<u64>,
    /// The submissions whose command buffers name each event, with their queues,
    /// weakly; those known complete are pruned as new ones come.
    event_uses: Vutex<HashMap<u64, EventSubmissions>>,
}

/// The submissions whose command buffers name one event, with their queues.
type EventSubmissions = Vec<(vk::Queue, Vweak<crate::submission::Submission>)>;

/// What the device knows of the command buffers that bound a descriptor set.
#[derive(Default)]
struct SetUse {
    /// Changed by every update that invalidates the command buffers that bound the
    /// set (of a binding without `UPDATE_AFTER_BIND`, of image descriptors, or by a
    /// template): a command buffer remembers the generation it bound, and a
    /// different one refuses its submission.
    generation: u64,
    /// The submissions of command buffers that bound the set, weakly; those known
    /// complete are pruned as new ones come.
    subs: Vec<Vweak<crate::submission::Submission>>,
    /// Whether the set's pool was created with `UPDATE_AFTER_BIND`.
    pool_update_after_bind: bool,
    /// The image descriptors the set holds (none: `None`), replaced as a whole by
    /// each update, so a recorder that bound the set keeps the list it saw.
    images: Option<SetImages>,
    /// The slots an update wrote (and no copy of an unwritten slot undid since),
    /// replaced as a whole by each update like `images`.
    written: SetWritten,
}

/// The slots (binding, array element) of a set that hold a written descriptor
/// (an inline uniform block's: each byte written), sorted.
pub(crate) type SetWritten = Vrc<Vec<(u32, u32)>>;

/// What a descriptor slot of a set holds, as the checks of draws and dispatches
/// read it: an image view (with the subresources it reaches, the layout the
/// descriptor says they are in, and a combined image sampler's sampler), a sampler,
/// a texel buffer view, or a buffer.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ImageDescriptor {
    /// Which of them the slot holds.
    pub kind: SlotKind,
    /// The view's image (null for a slot that holds no image view).
    pub image: vk::Image,
    /// The buffer of a texel buffer view or a buffer descriptor (null otherwise).
    pub buffer: vk::Buffer,
    /// What the slot's sampler does ([`sampler_bits`]; 0 without a sampler, or for
    /// one the wrappers did not create).
    pub sampler: u8,
    /// The image view was created with a sampler Y'CbCr conversion.
    pub ycbcr: bool,
    /// The view's subresources.
    pub sel: crate::layouts::Sel,
    /// The descriptor's `imageLayout`.
    pub layout: vk::ImageLayout,
    /// The view's type.
    pub view_type: vk::ImageViewType,
    /// The view's format (an image or texel buffer view's; `UNDEFINED` otherwise).
    pub format: vk::Format,
}

/// What a descriptor slot holds, in [`ImageDescriptor::kind`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SlotKind {
    /// An image view, alone or with a sampler.
    Image,
    /// A sampler alone.
    Sampler,
    /// A texel buffer view.
    TexelBuffer,
    /// A uniform or storage buffer.
    Buffer,
}

/// Sampler [`ImageDescriptor::sampler`] bits: `magFilter` or `minFilter` is
/// `LINEAR` with `compareEnable` off.
pub(crate) const SAMPLER_LINEAR: u8 = 1;
/// `mipmapMode` is `LINEAR` with `compareEnable` off.
pub(crate) const SAMPLER_MIPMAP_LINEAR: u8 = 2;
/// `unnormalizedCoordinates` is on.
pub(crate) const SAMPLER_UNNORMALIZED: u8 = 4;
/// A sampler Y'CbCr conversion is chained.
pub(crate) const SAMPLER_YCBCR: u8 = 8;

/// The [`SAMPLER_LINEAR`] and other bits of a sampler created with `info`, the
/// chained conversion given by `ycbcr`.
pub(crate) fn sampler_bits(info: &vk::SamplerCreateInfo<'_>, ycbcr: bool) -> u8 {
    let compare = info.compare_enable == vk::TRUE;
    let mut bits = 0;
    if !compare && (info.mag_filter == vk::Filter::LINEAR || info.min_filter == vk::Filter::LINEAR)
    {
        bits |= SAMPLER_LINEAR;
    }
    if !compare && info.mipmap_mode == vk::SamplerMipmapMode::LINEAR {
        bits |= SAMPLER_MIPMAP_LINEAR;
    }
    if info.unnormalized_coordinates == vk::TRUE {
        bits |= SAMPLER_UNNORMALIZED;
    }
    if ycbcr {
        bits |= SAMPLER_YCBCR;
    }
    bits
}

/// The image descriptors of a set, by (binding, array element) as written.
pub(crate) type SetImages = Vrc<Vec<((u32, u32), ImageDescriptor)>>;

/// Whether a descriptor of type `ty` names an image view whose layout it states.
pub(crate) fn names_image_layout(ty: vk::DescriptorType) -> bool {
    matches!(
        ty,
        vk::DescriptorType::SAMPLED_IMAGE
            | vk::DescriptorType::STORAGE_IMAGE
            | vk::DescriptorType::COMBINED_IMAGE_SAMPLER
            | vk::DescriptorType::INPUT_ATTACHMENT
    )
}

/// A live query pool's creation parameters, which `get_query_pool_results` checks
/// against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct QueryPoolRecord {
    /// `VkQueryPoolCreateInfo::queryType`.
    pub query_type: vk::QueryType,
    /// `VkQueryPoolCreateInfo::queryCount`.
    pub count: u32,
    /// `VkQueryPoolCreateInfo::pipelineStatistics`.
    pub statistics: vk::QueryPipelineStatisticFlags,
}

/// A live render pass's subpasses, which the recorder follows an instance of it
/// through.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct RenderPassRecord {
    /// Each attachment's format, sample count and the roles the subpasses give it
    /// (`USED_*` bits).
    pub attachments: Vec<(vk::Format, vk::SampleCountFlags, u8)>,
    /// Each subpass's view mask (0 without multiview), in order.
    pub view_masks: Vec<u32>,
    /// Whether each subpass uses no attachment (every reference unused, or none).
    pub no_attachments: Vec<bool>,
    /// Each subpass's color attachments' formats (`UNDEFINED` for an unused one).
    pub color_formats: Vec<Vec<vk::Format>>,
    /// Each subpass's depth/stencil attachment's format, if it uses one.
    pub depth_formats: Vec<Option<vk::Format>>,
    /// Each subpass's color and depth/stencil attachments' sample count, if it uses
    /// any (its creation checks they agree).
    pub subpass_samples: Vec<Option<vk::SampleCountFlags>>,
    /// Each subpass's depth/stencil reference's layouts (depth aspect, stencil
    /// aspect), if it uses one.
    pub depth_layouts: Vec<Option<(vk::ImageLayout, vk::ImageLayout)>>,
    /// Each attachment's initial and final layouts, and those of its stencil
    /// aspect (the same unless a `VkAttachmentDescriptionStencilLayout` says
    /// otherwise).
    pub layouts: Vec<AttachmentLayouts>,
    /// The attachments each subpass references.
    pub used: Vec<Vec<u32>>,
    /// Each subpass's input attachment references: the attachment each names
    /// (`VK_ATTACHMENT_UNUSED` for an unused one), and the aspects the fragment
    /// shader may read through it (empty: every aspect of its format).
    pub inputs: Vec<Vec<(u32, vk::ImageAspectFlags)>>,
    /// Its dependencies from a subpass to itself.
    pub self_dependencies: Vec<SelfDependency>,
    /// One more than the largest attachment index that a render pass instance
    /// clears (0: none), the `clearValueCount` it needs at least.
    pub clear_count: u32,
    /// Every layout each attachment takes: initial, final, and in each reference.
    pub taken: Vec<Vec<vk::ImageLayout>>,
    /// The layouts each attachment's stencil aspect takes through
    /// `VkAttachmentDescriptionStencilLayout` and `VkAttachmentReferenceStencilLayout`.
    pub stencil_taken: Vec<Vec<vk::ImageLayout>>,
    /// Each attachment's `VK_ATTACHMENT_DESCRIPTION_MAY_ALIAS_BIT`.
    pub may_alias: Vec<bool>,
    /// The union of the source and of the destination stage masks of its
    /// dependencies.
    pub dependency_stages: (vk::PipelineStageFlags, vk::PipelineStageFlags),
}

impl RenderPassRecord {
    /// Whether two render passes are compatible: their attachments agree in format
    /// and sample count, and their subpasses in the attachments they use, their
    /// formats and view masks.
    pub(crate) fn compatible(&self, other: &RenderPassRecord) -> bool {
        self.attachments.len() == other.attachments.len()
            && self
                .attachments
                .iter()
                .zip(&other.attachments)
                .all(|(a, b)| a.0 == b.0 && a.1 == b.1)
            && self.view_masks == other.view_masks
            && self.color_formats == other.color_formats
            && self.depth_formats == other.depth_formats
            && self.used == other.used
    }
}

/// A render pass's dependency from a subpass to itself, which a pipeline barrier
/// inside the subpass must fit in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct SelfDependency {
    /// The subpass.
    pub subpass: u32,
    /// Its source and destination stage masks.
    pub stages: (vk::PipelineStageFlags, vk::PipelineStageFlags),
    /// Its source and destination access masks.
    pub access: (vk::AccessFlags, vk::AccessFlags),
}

/// The layouts a render pass instance needs an attachment in and leaves it in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct AttachmentLayouts {
    /// `initialLayout`.
    pub initial: vk::ImageLayout,
    /// `finalLayout`.
    pub last: vk::ImageLayout,
    /// The stencil aspect's `initialLayout`.
    pub stencil_initial: vk::ImageLayout,
    /// The stencil aspect's `finalLayout`.
    pub stencil_last: vk::ImageLayout,
}

/// An attachment's role in some subpass: color, resolve, depth/stencil, input, or
/// depth/stencil resolve.
pub(crate) const USED_COLOR: u8 = 1;
/// See [`USED_COLOR`].
pub(crate) const USED_RESOLVE: u8 = 2;
/// See [`USED_COLOR`].
pub(crate) const USED_DEPTH: u8 = 4;
/// See [`USED_COLOR`].
pub(crate) const USED_INPUT: u8 = 8;
/// See [`USED_COLOR`].
pub(crate) const USED_DEPTH_RESOLVE: u8 = 16;

/// A live image view's parameters, as a framebuffer's checks read them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ViewRecord {
    /// The image it views.
    pub image: vk::Image,
    /// `VkImageViewCreateInfo::format`.
    pub format: vk::Format,
    /// `VkImageViewCreateInfo::viewType`.
    pub view_type: vk::ImageViewType,
    /// Its level count, `VK_REMAINING_MIP_LEVELS` resolved.
    pub levels: u32,
    /// Its layer count, `VK_REMAINING_ARRAY_LAYERS` resolved.
    pub layers: u32,
    /// Every component has the identity swizzle.
    pub identity: bool,
    /// Its usage, as the specification derives it.
    pub usage: vk::ImageUsageFlags,
    /// Its subresource range's aspects.
    pub aspect: vk::ImageAspectFlags,
    /// Its subresource range's first mip level.
    pub base_level: u32,
    /// Its subresource range's first array layer.
    pub base_layer: u32,
    /// Created with a chained `VkSamplerYcbcrConversionInfo`.
    pub ycbcr: bool,
}

/// A live pipeline layout's push-constant ranges and the dynamic descriptors of its
/// sets, which the recorder checks push constants and bound sets against.
#[derive(Clone, Debug)]
pub(crate) struct LayoutRecord {
    /// `VkPipelineLayoutCreateInfo::pPushConstantRanges`.
    pub push_ranges: Vec<vk::PushConstantRange>,
    /// For each set layout: its count of dynamic buffer descriptors.
    pub set_dynamics: Vec<u32>,
    /// The set layouts, by set number.
    pub sets: Vec<Vrc<SetLayoutRecord>>,
}

impl LayoutRecord {
    /// Whether two layouts are compatible for push constants: created with
    /// identical push-constant ranges.
    pub(crate) fn same_push_ranges(&self, other: &LayoutRecord) -> bool {
        let key = |r: &vk::PushConstantRange| (r.stage_flags, r.offset, r.size);
        self.push_ranges.len() == other.push_ranges.len()
            && self
                .push_ranges
                .iter()
                .zip(&other.push_ranges)
                .all(|(a, b)| key(a) == key(b))
    }
}

/// A live pipeline's bind point and layout, which the recorder checks draws and
/// dispatches against.
#[derive(Clone, Debug)]
pub(crate) struct PipelineRecord {
    /// Graphics or compute.
    pub bind_point: vk::PipelineBindPoint,
    /// Its create info's flags.
    pub flags: vk::PipelineCreateFlags,
    /// The layout it was created with.
    pub layout: Vrc<LayoutRecord>,
    /// The vertex-buffer bindings (the first 64) its vertex shader reads, one bit
    /// each.
    pub vertex_bindings: u64,
    /// For each vertex binding its vertex shader reads: the stride, rate and how far
    /// past a vertex's start the read attributes reach.
    pub vertex_reads: Vec<VertexRead>,
    /// Its rasterization sample count (empty for a compute pipeline).
    pub samples: vk::SampleCountFlags,
    /// The render pass it was created for, with the subpass (none for a compute
    /// pipeline, or one made for dynamic rendering).
    pub pass: Option<(Vrc<RenderPassRecord>, u32)>,
    /// Its dynamic states, as [`crate::recorder::dynamic_bit`] bits.
    pub dynamic: u32,
    /// For a graphics pipeline made for dynamic rendering, the view mask and
    /// attachment formats its chained `VkPipelineRenderingCreateInfo` gives.
    pub rendering: Option<Vrc<RenderingFormats>>,
    /// The resource variables its stages' modules declare, by set and binding.
    pub resources: Vrc<[crate::spirv::Resource]>,
    /// The bytes `start..end` of the push-constant blocks its stages' modules
    /// declare, if any does.
    pub push: Option<(u32, u32)>,
    /// Its viewport state's viewport and scissor counts (0 without one).
    pub viewports: (u32, u32),
    /// Its depth/stencil and rasterizer discard state, where static.
    pub depth_stencil: crate::recorder::DepthStencil,
    /// The color attachments (the first 32) its color blend state enables blending
    /// for, one bit each.
    pub blend: u32,
}

impl RenderingFormats {
    /// The formats a `VkPipelineRenderingCreateInfo` or a
    /// `VkCommandBufferInheritanceRenderingInfo` gives.
    ///
    /// # Safety
    ///
    /// `colors` points to `count` formats (a safe struct's array and its count).
    pub(crate) unsafe fn from_raw(
        view_mask: u32,
        colors: *const vk::Format,
        count: u32,
        depth: vk::Format,
        stencil: vk::Format,
    ) -> Self {
        RenderingFormats {
            view_mask,
            // SAFETY: the caller's promise.
            colors: unsafe { raw_slice(colors, count) }.to_vec(),
            depth,
            stencil,
        }
    }
}

/// A vertex binding a pipeline's vertex shader reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct VertexRead {
    /// The binding.
    pub binding: u32,
    /// Its stride (unless the pipeline has it dynamic).
    pub stride: u32,
    /// Whether it advances per instance rather than per vertex.
    pub instance: bool,
    /// How many bytes past a vertex's start its read attributes reach.
    pub end: u64,
}

/// The view mask and attachment formats of dynamic rendering: those a pipeline was
/// made for, or those of a render pass instance (`UNDEFINED` for an attachment with
/// no image view).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct RenderingFormats {
    /// The view mask.
    pub view_mask: u32,
    /// Each color attachment's format.
    pub colors: Vec<vk::Format>,
    /// The depth attachment's format.
    pub depth: vk::Format,
    /// The stencil attachment's format.
    pub stencil: vk::Format,
}

/// One binding of a descriptor set layout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct BindingRecord {
    /// `binding`.
    pub binding: u32,
    /// `descriptorType`.
    pub ty: vk::DescriptorType,
    /// `descriptorCount` (bytes, for an inline uniform block).
    pub count: u32,
    /// `stageFlags`.
    pub stages: vk::ShaderStageFlags,
    /// Whether it has immutable samplers.
    pub immutable: bool,
    /// What its immutable samplers do, together ([`sampler_bits`]).
    pub immutable_bits: u8,
    /// Its `VkDescriptorBindingFlags`.
    pub flags: vk::DescriptorBindingFlags,
}

/// A live descriptor set layout's bindings, in binding order, which descriptor
/// writes, copies and set bindings are checked against.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct SetLayoutRecord {
    /// The bindings, sorted by binding number.
    pub bindings: Vec<BindingRecord>,
    /// Created with `VK_DESCRIPTOR_SET_LAYOUT_CREATE_UPDATE_AFTER_BIND_POOL_BIT`.
    pub update_after_bind: bool,
    /// The binding created with `VK_DESCRIPTOR_BINDING_VARIABLE_DESCRIPTOR_COUNT_BIT`,
    /// whose count each set picks at its allocation (its record here is the
    /// largest a set may pick).
    pub variable: Option<u32>,
    /// `VkDescriptorSetLayoutCreateInfo::flags`.
    pub flags: vk::DescriptorSetLayoutCreateFlags,
    /// The immutable samplers of every binding, in binding order: with the rest,
    /// what makes two layouts identically defined (samplers compared by handle, so
    /// two identically defined samplers make the layouts differ here).
    pub immutable_samplers: Vec<vk::Sampler>,
}

impl SetLayoutRecord {
    /// Whether two set layouts are the same object or identically defined: what a
    /// set bound for a pipeline layout's set number must have been allocated with.
    pub fn matches(a: &Vrc<SetLayoutRecord>, b: &Vrc<SetLayoutRecord>) -> bool {
        Vrc::ptr_eq(a, b) || **a == **b
    }
}

impl SetLayoutRecord {
    /// The count of dynamic uniform and storage buffer descriptors.
    pub fn dynamics(&self) -> u32 {
        self.bindings
            .iter()
            .filter(|b| {
                matches!(
                    b.ty,
                    vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC
                        | vk::DescriptorType::STORAGE_BUFFER_DYNAMIC
                )
            })
            .map(|b| b.count)
            .fold(0, u32::saturating_add)
    }
}

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

/// What the device knows of a live swapchain beyond its images' parameters.
#[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
pub(crate) struct SwapchainState {
    /// The surface it presents to.
    surface: u64,
    /// A later creation named it as `oldSwapchain`.
    retired: bool,
    /// The indices of its images acquired and not presented since, with the device
    /// mask each was acquired with.
    acquired: Vec<(u32, u32)>,
    /// Its images, by index, once `get_swapchain_images_khr` returned them.
    images: Vec<vk::Image>,
    /// The device-group present modes it may use (`VkDeviceGroupSwapchainCreateInfoKHR`).
    modes: vk::DeviceGroupPresentModeFlagsKHR,
    /// The queue families (as bits; the first 64) seen to support presentation to
    /// its surface.
    present_families: u64,
}

/// An image's creation parameters, as its checks read them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ImageRecord {
    /// `VkImageCreateInfo::flags`.
    pub flags: vk::ImageCreateFlags,
    /// `VkImageCreateInfo::imageType`.
    pub image_type: vk::ImageType,
    /// `VkImageCreateInfo::format`.
    pub format: vk::Format,
    /// `VkImageCreateInfo::extent`: the size of mip level 0.
    pub extent: vk::Extent3D,
    /// `VkImageCreateInfo::mipLevels`.
    pub mip_levels: u32,
    /// `VkImageCreateInfo::arrayLayers`.
    pub array_layers: u32,
    /// `VkImageCreateInfo::usage`.
    pub usage: vk::ImageUsageFlags,
    /// `VkImageCreateInfo::tiling`.
    pub tiling: vk::ImageTiling,
    /// `VkImageCreateInfo::samples`.
    pub samples: vk::SampleCountFlags,
    /// A chained `VkImageStencilUsageCreateInfo::stencilUsage`, if one was.
    pub stencil_usage: Option<vk::ImageUsageFlags>,
    /// `VkImageCreateInfo::sharingMode`.
    pub sharing: vk::SharingMode,
    /// The queue families of a concurrent image, as bits (`u64::MAX` when one is 64
    /// or more, which matches no other set).
    #[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
    pub families: u64,
    /// Whether memory is bound to it.
    pub bound: bool,
    /// `VkExternalMemoryImageCreateInfo::handleTypes`.
    pub external: vk::ExternalMemoryHandleTypeFlags,
}

impl Default for Live {
    fn default() -> Self {
        Self {
            objects: Vutex::new(HashMap::default()),
            dynamic_ranges: Vutex::new(HashMap::default()),
            sets: Vutex::new(HashMap::default()),
            memories: Vutex::new(HashMap::default()),
            allocating: Vutex::new(()),
            view_formats: Vutex::new(HashMap::default()),
            views: Vutex::new(HashMap::default()),
            conversions: Vutex::new(HashMap::default()),
            ledger: Default::default(),
            queues: Vutex::new(HashMap::default()),
            timelines: Vutex::new(HashMap::default()),
            timeline_difference: std::sync::OnceLock::new(),
            event_uses: Vutex::new(HashMap::default()),
            binaries: Vutex::new(HashMap::default()),
            device_only_events: Vutex::new(std::collections::HashSet::new()),
            render_passes: Vutex::new(HashMap::default()),
            sparse_resources: Vutex::new(HashMap::default()),
            sparse_total: Vutex::new(0),
            sparse_gate: Vutex::new(()),
            buffers: Vutex::new(HashMap::default()),
            images: Vutex::new(HashMap::default()),
            layouts: Vutex::new(HashMap::default()),
            queue_families: Vutex::new(HashMap::default()),
            pools: Vutex::new(HashMap::default()),
            bindings: Vutex::new(HashMap::default()),
            formats: Vutex::new(HashMap::default()),
            present_masks: Vutex::new(None),
            framebuffers: Vutex::new(HashMap::default()),
            imageless: Vutex::new(HashMap::default()),
            framebuffer_passes: Vutex::new(HashMap::default()),
            swapchains: Vutex::new(HashMap::default()),
            swapchain_states: Vutex::new(HashMap::default()),
            shader_modules: Vutex::new(HashMap::default()),
            query_pools: Vutex::new(HashMap::default()),
            pipeline_layouts: Vutex::new(HashMap::default()),
            pipelines: Vutex::new(HashMap::default()),
            set_layouts: Vutex::new(HashMap::default()),
            sets_layouts: Vutex::new(HashMap::default()),
            limits: std::sync::OnceLock::new(),
            max_multiview_instance: std::sync::OnceLock::new(),
            protected_resources: std::sync::atomic::AtomicUsize::new(0),
            max_buffer_size: std::sync::OnceLock::new(),
            features: std::sync::OnceLock::new(),
            queue_infos: std::sync::OnceLock::new(),
            physical_count: std::sync::OnceLock::new(),
            bound_memories: Vutex::new(HashMap::default()),
            set_uses: Vutex::new(HashMap::default()),
            set_generations: std::sync::atomic::AtomicU64::new(0),
            descriptor_gate: Vutex::new(()),
            buffer_views: Vutex::new(HashMap::default()),
            samplers: Vutex::new(HashMap::default()),
            protected_queues: Vutex::new(std::collections::HashSet::new()),
        }
    }
}

impl Live {
    /// The device's queue operations that may still be executing.
    #[inline]
    pub(crate) fn ledger(&self) -> &crate::submission::Ledger {
        &self.ledger
    }

    /// The host synchronization of a new wrapper of `raw`. A queue can get several
    /// wrappers (`get_queue` twice) and Vulkan synchronizes the queue, not
    /// the wrappers, so every wrapper of one queue shares one for the device's life
    /// (a device has few queues); any other object gets a new one.
    pub(crate) fn sync_for<H: vk::Handle>(&self, raw: H) -> HostSync {
        if H::TYPE == vk::ObjectType::QUEUE {
            self.queues.lock().entry(raw.as_raw()).or_default().clone()
        } else {
            HostSync::new()
        }
    }

    /// The host synchronization of a live object named by its type and raw handle.
    // Used by extension commands only (presentation, debug names).
    #[allow(dead_code)]
    pub(crate) fn sync_of(&self, ty: vk::ObjectType, raw: u64) -> Option<HostSync> {
        self.objects
            .lock()
            .get(&(ty, raw))
            .filter(|(w, _)| w.strong_count() > 0)
            .map(|(_, s)| s.clone())
    }

    /// The host synchronizations of every queue of the device.
    pub(crate) fn queue_syncs(&self) -> Vec<HostSync> {
        self.queues.lock().values().cloned().collect()
    }

    /// Records that a new event was created device-only.
    pub(crate) fn set_device_only(&self, raw: vk::Event) {
        self.device_only_events.lock().insert(raw.as_raw());
    }

    /// Whether a live event was created device-only.
    pub(crate) fn is_device_only(&self, raw: vk::Event) -> bool {
        self.device_only_events.lock().contains(&raw.as_raw())
    }

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

    /// Records a new render pass's subpasses.
    pub(crate) fn render_pass_created(&self, raw: vk::RenderPass, record: RenderPassRecord) {
        self.render_passes
            .lock()
            .insert(raw.as_raw(), Vrc::new(record));
    }

    /// The record of a live render pass made through the wrappers.
    pub(crate) fn render_pass(&self, raw: vk::RenderPass) -> Option<Vrc<RenderPassRecord>> {
        self.render_passes.lock().get(&raw.as_raw()).cloned()
    }

    /// Records that a new semaphore is a timeline semaphore, with its initial value.
    pub(crate) fn set_timeline(&self, raw: vk::Semaphore, initial: u64) {
        self.timelines
            .lock()
            .insert(raw.as_raw(), crate::submission::Timeline::new(initial));
    }

    /// What the device knows of its timeline semaphores' values, for a command that
    /// signals or waits on them to read and update.
    pub(crate) fn timelines(
        &self,
    ) -> tuff_runtime::VutexGuard<'_, HashMap<u64, crate::submission::Timeline>> {
        self.timelines.lock()
    }

    /// The physical device's `maxTimelineSemaphoreValueDifference`, read from `read`
    /// the first time.
    pub(crate) fn timeline_difference(&self, read: impl FnOnce() -> u64) -> u64 {
        *self.timeline_difference.get_or_init(read)
    }

    /// The state of binary semaphores, for a submission command to read and update.
    pub(crate) fn binaries(
        &self,
    ) -> tuff_runtime::VutexGuard<'_, HashMap<u64, crate::submission::Binary>> {
        self.binaries.lock()
    }

    /// Whether a live semaphore is a timeline semaphore.
    pub(crate) fn is_timeline(&self, raw: vk::Semaphore) -> bool {
        self.timelines.lock().contains_key(&raw.as_raw())
    }

    /// How many listed objects are alive.
    pub(crate) fn count(&self) -> usize {
        self.objects
            .lock()
            .values()
            .filter(|(w, _)| w.strong_count() > 0)
            .count()
    }

    /// Lists a new object under its raw handle.
    pub(crate) fn add<H: vk::Handle>(&self, raw: H, object: &Retained, sync: &HostSync) {
        self.add_raw(H::TYPE, raw.as_raw(), object, sync);
    }

    // One body for every handle type: the generic `add` and `remove` would otherwise
    // copy it once per type (a twentieth of the crate's machine code).
    fn add_raw(&self, ty: vk::ObjectType, raw: u64, object: &Retained, sync: &HostSync) {
        self.objects
            .lock()
            .insert((ty, raw), (Vrc::downgrade(object), sync.clone()));
        if ty == vk::ObjectType::DESCRIPTOR_SET {
            // A new set starts empty, even if its handle was a set's that a pool reset
            // freed while that set's wrapper lived on; released outside the lock.
            let stale = self.sets.lock().remove(&raw);
            drop(stale);
            self.dynamic_ranges.lock().remove(&raw);
            let generation = self.next_set_generation();
            self.set_uses.lock().insert(
                raw,
                SetUse {
                    generation,
                    ..SetUse::default()
                },
            );
        }
    }

    /// Unlists an object whose wrapper is going. An entry that another live wrapper of
    /// the same handle took over (swapchain images are wrapped anew by every
    /// `get_swapchain_images_khr`) stays.
    pub(crate) fn remove<H: vk::Handle>(&self, raw: H) {
        self.remove_raw(H::TYPE, raw.as_raw());
    }

    fn remove_raw(&self, ty: vk::ObjectType, raw: u64) {
        let key = (ty, raw);
        let unlisted = {
            let mut objects = self.objects.lock();
            let gone = objects
                .get(&key)
                .is_some_and(|(w, _)| w.strong_count() == 0);
            if gone {
                objects.remove(&key);
            }
            gone
        };
        if unlisted && ty == vk::ObjectType::DEVICE_MEMORY {
            self.memories.lock().remove(&key.1);
        }
        if unlisted && ty == vk::ObjectType::SEMAPHORE {
            self.timelines.lock().remove(&key.1);
            let state = self.binaries.lock().remove(&key.1);
            drop(state);
        }
        if unlisted && ty == vk::ObjectType::EVENT {
            self.device_only_events.lock().remove(&key.1);
            self.event_uses.lock().remove(&key.1);
        }
        if unlisted && ty == vk::ObjectType::RENDER_PASS {
            let gone = self.render_passes.lock().remove(&key.1);
            drop(gone);
        }
        match ty {
            _ if !unlisted => {}
            vk::ObjectType::BUFFER => {
                let gone = self.buffers.lock().remove(&key.1);
                if gone.is_some_and(|b| b.flags.contains(vk::BufferCreateFlags::PROTECTED)) {
                    self.protected_one(false);
                }
                self.bindings.lock().remove(&key);
                if let Some(size) = self.sparse_resources.lock().remove(&key) {
                    *self.sparse_total.lock() -= size;
                }
            }
            vk::ObjectType::IMAGE_VIEW => {
                self.views.lock().remove(&key.1);
            }
            vk::ObjectType::BUFFER_VIEW => {
                self.buffer_views.lock().remove(&key.1);
            }
            vk::ObjectType::SAMPLER => {
                self.samplers.lock().remove(&key.1);
            }
            vk::ObjectType::FRAMEBUFFER => {
                self.framebuffers.lock().remove(&key.1);
                self.imageless.lock().remove(&key.1);
                let pass = self.framebuffer_passes.lock().remove(&key.1);
                drop(pass);
            }
            vk::ObjectType::COMMAND_POOL => {
                self.pools.lock().remove(&key.1);
            }
            vk::ObjectType::SAMPLER_YCBCR_CONVERSION => {
                self.conversions.lock().remove(&key.1);
            }
            vk::ObjectType::IMAGE => {
                let gone = self.images.lock().remove(&key.1);
                if gone.is_some_and(|i| i.flags.contains(vk::ImageCreateFlags::PROTECTED)) {
                    self.protected_one(false);
                }
                self.layouts.lock().remove(&key.1);
                self.bindings.lock().remove(&key);
                self.view_formats.lock().remove(&key.1);
                if let Some(size) = self.sparse_resources.lock().remove(&key) {
                    *self.sparse_total.lock() -= size;
                }
            }
            vk::ObjectType::SHADER_MODULE => {
                let record = self.shader_modules.lock().remove(&key.1);
                drop(record);
            }
            vk::ObjectType::QUERY_POOL => {
                self.query_pools.lock().remove(&key.1);
            }
            vk::ObjectType::SWAPCHAIN_KHR => {
                self.swapchains.lock().remove(&key.1);
                self.swapchain_states.lock().remove(&key.1);
            }
            vk::ObjectType::PIPELINE => {
                let record = self.pipelines.lock().remove(&key.1);
                drop(record);
            }
            vk::ObjectType::PIPELINE_LAYOUT => {
                let record = self.pipeline_layouts.lock().remove(&key.1);
                drop(record);
            }
            vk::ObjectType::DESCRIPTOR_SET_LAYOUT => {
                let record = self.set_layouts.lock().remove(&key.1);
                drop(record);
            }
            vk::ObjectType::DESCRIPTOR_SET => {
                let record = self.sets_layouts.lock().remove(&key.1);
                drop(record);
            }
            _ => {}
        }
        if unlisted && matches!(ty, vk::ObjectType::BUFFER | vk::ObjectType::IMAGE) {
            // Released outside the lock: it may be the last reference to the memory.
            let memory = self.bound_memories.lock().remove(&key);
            drop(memory);
        }
        // A set whose handle a newer wrapper took over keeps that wrapper's contents.
        if unlisted && ty == vk::ObjectType::DESCRIPTOR_SET {
            // Dropped outside the lock: releasing the last reference to a view or
            // buffer runs its Drop, which unlists it.
            let written = self.sets.lock().remove(&key.1);
            drop(written);
            self.dynamic_ranges.lock().remove(&key.1);
            self.set_uses.lock().remove(&key.1);
        }
    }

    fn next_set_generation(&self) -> u64 {
        self.set_generations
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed)
            + 1
    }

    /// The generation of a descriptor set now, what a command buffer that binds it
    /// remembers, the image descriptors it holds and the slots written.
    pub(crate) fn set_bound(&self, raw: vk::DescriptorSet) -> (u64, Option<SetImages>, SetWritten) {
        self.set_uses.lock().get(&raw.as_raw()).map_or_else(
            || (0, None, SetWritten::default()),
            |u| (u.generation, u.images.clone(), u.written.clone()),
        )
    }

    /// Whether slot `slot` of `set` holds a written descriptor.
    fn slot_written(&self, set: vk::DescriptorSet, slot: (u32, u32)) -> bool {
        self.set_uses
            .lock()
            .get(&set.as_raw())
            .is_some_and(|u| u.written.binary_search(&slot).is_ok())
    }

    /// A set's slots are now written (`true`) or hold a copy of an unwritten slot.
    /// A slot that loses its descriptor leaves the command buffers that bound the
    /// set invalid whatever the binding's flags, as their draws were checked with
    /// it written.
    fn slots_written(&self, set: vk::DescriptorSet, updates: &[((u32, u32), bool)]) {
        let undone = {
            let mut uses = self.set_uses.lock();
            let Some(u) = uses.get_mut(&set.as_raw()) else {
                return;
            };
            // Copied only where a recorder still holds the list it bound, and only
            // when the update changes it.
            let written = &mut u.written;
            let mut undone = false;
            for &(slot, now) in updates {
                match (written.binary_search(&slot), now) {
                    (Err(at), true) => Vrc::make_mut(written).insert(at, slot),
                    (Ok(at), false) => {
                        Vrc::make_mut(written).remove(at);
                        undone = true;
                    }
                    _ => {}
                }
            }
            undone
        };
        if undone {
            self.set_invalidated(set);
        }
    }

    /// What a descriptor of type `ty` holds, read from the array its type selects
    /// (none for an object the device has no record of, or a type the checks of
    /// draws and dispatches do not read).
    fn slot_descriptor(
        &self,
        ty: vk::DescriptorType,
        image: impl Fn() -> vk::DescriptorImageInfo,
        buffer: impl Fn() -> vk::DescriptorBufferInfo,
        texel: impl Fn() -> vk::BufferView,
    ) -> Option<ImageDescriptor> {
        use vk::DescriptorType as T;
        let empty = ImageDescriptor {
            kind: SlotKind::Sampler,
            image: vk::Image::null(),
            buffer: vk::Buffer::null(),
            sampler: 0,
            ycbcr: false,
            sel: crate::layouts::Sel {
                aspect: vk::ImageAspectFlags::empty(),
                mips: (0, 0),
                layers: (0, 0),
            },
            layout: vk::ImageLayout::UNDEFINED,
            view_type: vk::ImageViewType::default(),
            format: vk::Format::UNDEFINED,
        };
        match ty {
            T::SAMPLER => {
                let sampler = self.sampler_bits(image().sampler)?;
                Some(ImageDescriptor { sampler, ..empty })
            }
            T::UNIFORM_TEXEL_BUFFER | T::STORAGE_TEXEL_BUFFER => {
                let (buffer, format) = self.buffer_view_record(texel())?;
                Some(ImageDescriptor {
                    kind: SlotKind::TexelBuffer,
                    buffer,
                    format,
                    ..empty
                })
            }
            T::UNIFORM_BUFFER
            | T::STORAGE_BUFFER
            | T::UNIFORM_BUFFER_DYNAMIC
            | T::STORAGE_BUFFER_DYNAMIC => {
                let b = buffer().buffer;
                self.buffer(b)?;
                Some(ImageDescriptor {
                    kind: SlotKind::Buffer,
                    buffer: b,
                    ..empty
                })
            }
            ty if names_image_layout(ty) => {
                let info = image();
                let mut d = self.image_descriptor(&info)?;
                if ty == T::COMBINED_IMAGE_SAMPLER {
                    d.sampler = self.sampler_bits(info.sampler).unwrap_or(0);
                }
                Some(d)
            }
            _ => None,
        }
    }

    /// The image descriptor of `info`: the subresources its view reaches (none for a
    /// view the device has no record of).
    fn image_descriptor(&self, info: &vk::DescriptorImageInfo) -> Option<ImageDescriptor> {
        let view = self.view(info.image_view)?;
        // A 2D view of a 3D image reaches depth slices of its one layer.
        let flat = self
            .image(view.image)
            .is_some_and(|i| i.image_type == vk::ImageType::TYPE_3D);
        let layers = if flat {
            (0, 1)
        } else {
            (view.base_layer, view.base_layer.saturating_add(view.layers))
        };
        Some(ImageDescriptor {
            kind: SlotKind::Image,
            image: view.image,
            buffer: vk::Buffer::null(),
            sampler: 0,
            ycbcr: view.ycbcr,
            sel: crate::layouts::Sel {
                aspect: view.aspect,
                mips: (view.base_level, view.base_level.saturating_add(view.levels)),
                layers,
            },
            layout: info.image_layout,
            view_type: view.view_type,
            format: view.format,
        })
    }

    /// The image descriptors of a set at `slots`.
    fn images_at(
        &self,
        set: vk::DescriptorSet,
        slots: &[(u32, u32)],
    ) -> Vec<Option<ImageDescriptor>> {
        let uses = self.set_uses.lock();
        let images = uses.get(&set.as_raw()).and_then(|u| u.images.clone());
        slots
            .iter()
            .map(|slot| {
                images
                    .as_ref()
                    .and_then(|i| i.iter().find(|(s, _)| s == slot).map(|(_, d)| *d))
            })
            .collect()
    }

    /// A set's descriptors at these slots now name these images (or none).
    fn images_written(
        &self,
        set: vk::DescriptorSet,
        updates: Vec<((u32, u32), Option<ImageDescriptor>)>,
    ) {
        let mut uses = self.set_uses.lock();
        let Some(u) = uses.get_mut(&set.as_raw()) else {
            return;
        };
        if u.images.is_none() && updates.iter().all(|(_, d)| d.is_none()) {
            return;
        }
        let mut images: Vec<_> = u.images.as_deref().cloned().unwrap_or_default();
        for (slot, d) in updates {
            images.retain(|(s, _)| *s != slot);
            if let Some(d) = d {
                images.push((slot, d));
            }
        }
        u.images = (!images.is_empty()).then(|| Vrc::new(images));
    }

    /// A descriptor set was updated in a way that invalidates the command buffers
    /// that bound it.
    pub(crate) fn set_invalidated(&self, raw: vk::DescriptorSet) {
        let generation = self.next_set_generation();
        if let Some(u) = self.set_uses.lock().get_mut(&raw.as_raw()) {
            u.generation = generation;
        }
    }

    /// The first of `sets` (raw set, generation bound) whose generation changed
    /// since: an update invalidated the command buffer that bound it.
    pub(crate) fn stale_set(&self, sets: &[(u64, u64)]) -> Option<u64> {
        let uses = self.set_uses.lock();
        sets.iter()
            .find(|(set, generation)| uses.get(set).is_some_and(|u| u.generation != *generation))
            .map(|(set, _)| *set)
    }

    /// `sub` submits command buffers that bound `sets`.
    pub(crate) fn sets_submitted(
        &self,
        sets: &[(u64, u64)],
        sub: &Vrc<crate::submission::Submission>,
    ) {
        let mut uses = self.set_uses.lock();
        for (set, _) in sets {
            if let Some(u) = uses.get_mut(set) {
                u.subs
                    .retain(|w| w.upgrade().is_some_and(|s| !s.is_complete()));
                u.subs.push(Vrc::downgrade(sub));
            }
        }
    }

    /// The submissions of command buffers that bound a set and that tuff has not seen
    /// complete (they may be: ask each with `poll`).
    pub(crate) fn set_submissions(
        &self,
        raw: vk::DescriptorSet,
    ) -> Vec<Vrc<crate::submission::Submission>> {
        self.set_uses
            .lock()
            .get(&raw.as_raw())
            .map_or(Vec::new(), |u| {
                u.subs
                    .iter()
                    .filter_map(Vweak::upgrade)
                    .filter(|s| !s.is_complete())
                    .collect()
            })
    }

    /// Records that a set's pool was created with `UPDATE_AFTER_BIND` or not.
    pub(crate) fn set_pool_update_after_bind(&self, raw: vk::DescriptorSet, on: bool) {
        if let Some(u) = self.set_uses.lock().get_mut(&raw.as_raw()) {
            u.pool_update_after_bind = on;
        }
    }

    /// Whether a set's pool was created with `UPDATE_AFTER_BIND`.
    pub(crate) fn set_pool_is_update_after_bind(&self, raw: vk::DescriptorSet) -> bool {
        self.set_uses
            .lock()
            .get(&raw.as_raw())
            .is_some_and(|u| u.pool_update_after_bind)
    }

    /// `sub`, a submission to `queue`, has command buffers that name `events`.
    pub(crate) fn events_submitted(
        &self,
        events: &[u64],
        queue: vk::Queue,
        sub: &Vrc<crate::submission::Submission>,
    ) {
        if events.is_empty() {
            return;
        }
        let mut uses = self.event_uses.lock();
        for event in events {
            let subs = uses.entry(*event).or_default();
            subs.retain(|(_, w)| w.upgrade().is_some_and(|s| !s.is_complete()));
            subs.push((queue, Vrc::downgrade(sub)));
        }
    }

    /// The submissions to queues other than `queue` whose command buffers name an
    /// event and that tuff has not seen complete.
    pub(crate) fn event_submissions(
        &self,
        event: u64,
        queue: vk::Queue,
    ) -> Vec<Vrc<crate::submission::Submission>> {
        self.event_uses
            .lock()
            .get(&event)
            .map_or(Vec::new(), |subs| {
                subs.iter()
                    .filter(|(q, _)| *q != queue)
                    .filter_map(|(_, w)| w.upgrade())
                    .filter(|s| !s.is_complete())
                    .collect()
            })
    }

    /// Taken by descriptor updates and submissions (see the field).
    pub(crate) fn descriptor_gate(&self) -> tuff_runtime::VutexGuard<'_, ()> {
        self.descriptor_gate.lock()
    }

    /// Records a new buffer view's buffer and format.
    pub(crate) fn buffer_view_created(
        &self,
        raw: vk::BufferView,
        buffer: vk::Buffer,
        format: vk::Format,
    ) {
        self.buffer_views
            .lock()
            .insert(raw.as_raw(), (buffer, format));
    }

    /// The buffer of a live buffer view made through the wrappers.
    pub(crate) fn buffer_view(&self, raw: vk::BufferView) -> Option<vk::Buffer> {
        self.buffer_view_record(raw).map(|(b, _)| b)
    }

    /// The buffer and format of a live buffer view made through the wrappers.
    pub(crate) fn buffer_view_record(
        &self,
        raw: vk::BufferView,
    ) -> Option<(vk::Buffer, vk::Format)> {
        self.buffer_views.lock().get(&raw.as_raw()).copied()
    }

    /// Records what a new sampler does ([`sampler_bits`]).
    pub(crate) fn sampler_created(&self, raw: vk::Sampler, bits: u8) {
        self.samplers.lock().insert(raw.as_raw(), bits);
    }

    /// What a live sampler made through the wrappers does ([`sampler_bits`]).
    pub(crate) fn sampler_bits(&self, raw: vk::Sampler) -> Option<u8> {
        self.samplers.lock().get(&raw.as_raw()).copied()
    }

    /// Records a new query pool's creation parameters.
    pub(crate) fn query_pool_created(&self, raw: vk::QueryPool, record: QueryPoolRecord) {
        self.query_pools.lock().insert(raw.as_raw(), record);
    }

    /// The record of a live query pool made through the wrappers.
    pub(crate) fn query_pool(&self, raw: vk::QueryPool) -> Option<QueryPoolRecord> {
        self.query_pools.lock().get(&raw.as_raw()).copied()
    }

    /// Records a new descriptor set layout's bindings.
    pub(crate) fn set_layout_created(&self, raw: vk::DescriptorSetLayout, record: SetLayoutRecord) {
        self.set_layouts
            .lock()
            .insert(raw.as_raw(), Vrc::new(record));
    }

    /// The record of a live set layout made through the wrappers.
    pub(crate) fn set_layout(&self, raw: vk::DescriptorSetLayout) -> Option<Vrc<SetLayoutRecord>> {
        self.set_layouts.lock().get(&raw.as_raw()).cloned()
    }

    /// Records the layout a new descriptor set was allocated with.
    pub(crate) fn set_allocated(&self, raw: vk::DescriptorSet, layout: Vrc<SetLayoutRecord>) {
        let old = self.sets_layouts.lock().insert(raw.as_raw(), layout);
        drop(old);
    }

    /// The layout record of a live set.
    pub(crate) fn set_layout_of(&self, raw: vk::DescriptorSet) -> Option<Vrc<SetLayoutRecord>> {
        self.sets_layouts.lock().get(&raw.as_raw()).cloned()
    }

    /// Records a new pipeline's bind point and layout.
    pub(crate) fn pipeline_created(&self, raw: vk::Pipeline, record: PipelineRecord) {
        let old = self.pipelines.lock().insert(raw.as_raw(), record);
        drop(old);
    }

    /// The record of a live pipeline made through the wrappers.
    pub(crate) fn pipeline(&self, raw: vk::Pipeline) -> Option<PipelineRecord> {
        self.pipelines.lock().get(&raw.as_raw()).cloned()
    }

    /// Records a new pipeline layout's push-constant ranges and sets.
    pub(crate) fn pipeline_layout_created(&self, raw: vk::PipelineLayout, record: LayoutRecord) {
        self.pipeline_layouts
            .lock()
            .insert(raw.as_raw(), Vrc::new(record));
    }

    /// The record of a live pipeline layout made through the wrappers.
    pub(crate) fn pipeline_layout(&self, raw: vk::PipelineLayout) -> Option<Vrc<LayoutRecord>> {
        self.pipeline_layouts.lock().get(&raw.as_raw()).cloned()
    }

    /// Records the queues the device was created with: (family, count, flags) for
    /// each of its queue create infos.
    pub(crate) fn set_queue_infos(&self, queues: Vec<(u32, u32, vk::DeviceQueueCreateFlags)>) {
        let _ = self.queue_infos.set(queues);
    }

    /// The queues the device was created with (none, before they are recorded).
    pub(crate) fn queue_infos(&self) -> &[(u32, u32, vk::DeviceQueueCreateFlags)] {
        self.queue_infos.get().map_or(&[], Vec::as_slice)
    }

    /// Records the core features the device was created with.
    pub(crate) fn set_physical_count(&self, count: u32) {
        let _ = self.physical_count.set(count);
    }

    /// How many physical devices make up the device; a valid device mask sets no bit
    /// at or above it.
    pub(crate) fn physical_count(&self) -> u32 {
        self.physical_count.get().copied().unwrap_or(1)
    }

    pub(crate) fn set_features(&self, features: crate::validation::Features) {
        let _ = self.features.set(features);
    }

    /// The Vulkan 1.0 features the device was created with.
    pub(crate) fn features(&self) -> vk::PhysicalDeviceFeatures {
        self.with_features(|f| f.v10)
    }

    /// Runs `read` on the core features the device was created with (none, before
    /// they are recorded).
    pub(crate) fn with_features<R>(
        &self,
        read: impl FnOnce(&crate::validation::Features) -> R,
    ) -> R {
        read(self.features_or_none())
    }

    // Out of the generic `with_features`, which every feature check instantiates: the
    // features, or a set with none on, made once.
    fn features_or_none(&self) -> &crate::validation::Features {
        static NONE: std::sync::OnceLock<crate::validation::Features> = std::sync::OnceLock::new();
        match self.features.get() {
            Some(f) => f,
            None => NONE.get_or_init(crate::validation::Features::default),
        }
    }

    /// The physical device's limits, read from `read` the first time.
    pub(crate) fn limits(
        &self,
        read: impl FnOnce() -> vk::PhysicalDeviceLimits,
    ) -> &vk::PhysicalDeviceLimits {
        self.limits.get_or_init(read)
    }

    /// A protected buffer or image was created (`true`) or is gone.
    fn protected_one(&self, created: bool) {
        use std::sync::atomic::Ordering::Relaxed;
        if created {
            self.protected_resources.fetch_add(1, Relaxed);
        } else {
            self.protected_resources.fetch_sub(1, Relaxed);
        }
    }

    /// Whether a protected buffer or image is alive.
    pub(crate) fn has_protected_resources(&self) -> bool {
        self.protected_resources
            .load(std::sync::atomic::Ordering::Relaxed)
            != 0
    }

    /// The physical device's `maxMultiviewInstanceIndex`, read from `read` the
    /// first time.
    pub(crate) fn max_multiview_instance(&self, read: impl FnOnce() -> Option<u32>) -> Option<u32> {
        *self.max_multiview_instance.get_or_init(read)
    }

    /// The physical device's `maxBufferSize`, read from `read` the first time.
    pub(crate) fn max_buffer_size(&self, read: impl FnOnce() -> Option<u64>) -> Option<u64> {
        *self.max_buffer_size.get_or_init(read)
    }

    /// Records a new buffer's creation parameters.
    pub(crate) fn buffer_created(&self, raw: vk::Buffer, record: BufferRecord) {
        if record.flags.contains(vk::BufferCreateFlags::PROTECTED) {
            self.protected_one(true);
        }
        self.buffers.lock().insert(raw.as_raw(), record);
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

    /// Records a new shader module's interface.
    pub(crate) fn shader_module_created(
        &self,
        raw: vk::ShaderModule,
        interface: crate::spirv::Interface,
    ) {
        self.shader_modules
            .lock()
            .insert(raw.as_raw(), Vrc::new(interface));
    }

    /// The interface of a live shader module made through the wrappers.
    pub(crate) fn shader_module(
        &self,
        raw: vk::ShaderModule,
    ) -> Option<Vrc<crate::spirv::Interface>> {
        self.shader_modules.lock().get(&raw.as_raw()).cloned()
    }

    /// Records a new image's creation parameters, and the view formats it listed.
    pub(crate) fn image_created(&self, raw: vk::Image, record: ImageRecord, views: &[vk::Format]) {
        if record.flags.contains(vk::ImageCreateFlags::PROTECTED) {
            self.protected_one(true);
        }
        self.images.lock().insert(raw.as_raw(), record);
        if !views.is_empty() {
            self.view_formats
                .lock()
                .insert(raw.as_raw(), views.to_vec());
        }
    }

    /// The view formats a live image's create info listed (empty: none listed).
    pub(crate) fn view_formats(&self, raw: vk::Image) -> Vec<vk::Format> {
        self.view_formats
            .lock()
            .get(&raw.as_raw())
            .cloned()
            .unwrap_or_default()
    }

    /// Records a new image view's parameters.
    pub(crate) fn view_created(&self, raw: vk::ImageView, record: ViewRecord) {
        self.views.lock().insert(raw.as_raw(), record);
    }

    /// The parameters of a live image view of this device.
    pub(crate) fn view(&self, raw: vk::ImageView) -> Option<ViewRecord> {
        self.views.lock().get(&raw.as_raw()).copied()
    }

    /// Records a new framebuffer's attachments.
    pub(crate) fn framebuffer_created(
        &self,
        raw: vk::Framebuffer,
        views: &[vk::ImageView],
        size: [u32; 3],
    ) {
        self.framebuffers
            .lock()
            .insert(raw.as_raw(), (views.to_vec(), size));
    }

    /// Records an imageless framebuffer's attachment image infos.
    pub(crate) fn imageless_created(&self, raw: vk::Framebuffer, infos: Vec<AttachmentImage>) {
        self.imageless.lock().insert(raw.as_raw(), infos);
    }

    /// A live imageless framebuffer's attachment image infos (`None` for a
    /// framebuffer with image views).
    pub(crate) fn imageless(&self, raw: vk::Framebuffer) -> Option<Vec<AttachmentImage>> {
        self.imageless.lock().get(&raw.as_raw()).cloned()
    }

    /// Records the render pass a new framebuffer was created with.
    pub(crate) fn framebuffer_pass(&self, raw: vk::Framebuffer, pass: vk::RenderPass) {
        if let Some(record) = self.render_pass(pass) {
            self.framebuffer_passes.lock().insert(raw.as_raw(), record);
        }
    }

    /// The record of the render pass a live framebuffer was created with.
    pub(crate) fn framebuffer_pass_record(
        &self,
        raw: vk::Framebuffer,
    ) -> Option<Vrc<RenderPassRecord>> {
        self.framebuffer_passes.lock().get(&raw.as_raw()).cloned()
    }

    /// A live framebuffer's width, height and layer count.
    pub(crate) fn framebuffer_size(&self, raw: vk::Framebuffer) -> Option<[u32; 3]> {
        self.framebuffers.lock().get(&raw.as_raw()).map(|f| f.1)
    }

    /// The attachments of a live framebuffer (empty for an imageless one).
    pub(crate) fn framebuffer_views(&self, raw: vk::Framebuffer) -> Vec<vk::ImageView> {
        self.framebuffers
            .lock()
            .get(&raw.as_raw())
            .map(|f| f.0.clone())
            .unwrap_or_default()
    }

    /// Records a new sampler Y'CbCr conversion's format.
    pub(crate) fn conversion_created(&self, raw: vk::SamplerYcbcrConversion, format: vk::Format) {
        self.conversions.lock().insert(raw.as_raw(), format);
    }

    /// The format a live sampler Y'CbCr conversion was created with.
    pub(crate) fn conversion_format(&self, raw: vk::SamplerYcbcrConversion) -> Option<vk::Format> {
        self.conversions.lock().get(&raw.as_raw()).copied()
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

    /// Records what a swapchain's images are.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain_created(
        &self,
        raw: vk::SwapchainKHR,
        surface: vk::SurfaceKHR,
        images: ImageRecord,
        modes: vk::DeviceGroupPresentModeFlagsKHR,
    ) {
        self.swapchains.lock().insert(raw.as_raw(), images);
        self.swapchain_states.lock().insert(
            raw.as_raw(),
            SwapchainState {
                surface: surface.as_raw(),
                retired: false,
                acquired: Vec::new(),
                images: Vec::new(),
                modes,
                present_families: 0,
            },
        );
    }

    /// The device-group present modes a live swapchain may use.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain_modes(
        &self,
        raw: vk::SwapchainKHR,
    ) -> vk::DeviceGroupPresentModeFlagsKHR {
        self.swapchain_states
            .lock()
            .get(&raw.as_raw())
            .map_or(vk::DeviceGroupPresentModeFlagsKHR::LOCAL, |s| s.modes)
    }

    /// Whether queue family `family` was seen to support presentation to the
    /// swapchain's surface.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn presents_from(&self, raw: vk::SwapchainKHR, family: u32) -> bool {
        family < 64
            && self
                .swapchain_states
                .lock()
                .get(&raw.as_raw())
                .is_some_and(|s| s.present_families & (1 << family) != 0)
    }

    /// Queue family `family` supports presentation to the swapchain's surface.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn set_presents_from(&self, raw: vk::SwapchainKHR, family: u32) {
        if let (true, Some(s)) = (
            family < 64,
            self.swapchain_states.lock().get_mut(&raw.as_raw()),
        ) {
            s.present_families |= 1 << family;
        }
    }

    /// Records a new command pool's queue family.
    pub(crate) fn pool_created(&self, raw: vk::CommandPool, family: crate::special::PoolFamily) {
        self.pools.lock().insert(raw.as_raw(), family);
    }

    /// The queue family of a live command pool made through the wrappers.
    pub(crate) fn pool_family(&self, raw: vk::CommandPool) -> Option<crate::special::PoolFamily> {
        self.pools.lock().get(&raw.as_raw()).copied()
    }

    /// A format's properties, asked of the physical device once.
    pub(crate) fn format_properties(
        &self,
        physical: &crate::PhysicalDevice,
        format: vk::Format,
    ) -> crate::Result<vk::FormatProperties> {
        if let Some(p) = self.formats.lock().get(&format.as_raw()) {
            return Ok(*p);
        }
        let p = physical.get_format_properties(format)?;
        self.formats.lock().insert(format.as_raw(), p);
        Ok(p)
    }

    /// Records the queue family a queue of the device belongs to.
    pub(crate) fn queue_family_of(&self, queue: vk::Queue, family: u32) {
        self.queue_families.lock().insert(queue.as_raw(), family);
    }

    /// Records that a queue was got with `VK_DEVICE_QUEUE_CREATE_PROTECTED_BIT`.
    pub(crate) fn queue_protected(&self, queue: vk::Queue) {
        self.protected_queues.lock().insert(queue.as_raw());
    }

    /// Whether a queue was got with `VK_DEVICE_QUEUE_CREATE_PROTECTED_BIT`.
    pub(crate) fn is_protected_queue(&self, queue: vk::Queue) -> bool {
        self.protected_queues.lock().contains(&queue.as_raw())
    }

    /// The queue family of a queue got through the wrappers.
    pub(crate) fn queue_family(&self, queue: vk::Queue) -> Option<u32> {
        self.queue_families.lock().get(&queue.as_raw()).copied()
    }

    /// `VkDeviceGroupPresentCapabilitiesKHR::presentMask`, once read.
    #[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
    pub(crate) fn present_masks(&self) -> Option<[u32; vk::MAX_DEVICE_GROUP_SIZE]> {
        *self.present_masks.lock()
    }

    /// Records `VkDeviceGroupPresentCapabilitiesKHR::presentMask`.
    #[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
    pub(crate) fn set_present_masks(&self, masks: [u32; vk::MAX_DEVICE_GROUP_SIZE]) {
        *self.present_masks.lock() = Some(masks);
    }

    /// The surface a live swapchain presents to.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain_surface(&self, raw: vk::SwapchainKHR) -> Option<vk::SurfaceKHR> {
        self.swapchain_states
            .lock()
            .get(&raw.as_raw())
            .map(|s| vk::SurfaceKHR::from_raw(s.surface))
    }

    /// Marks a swapchain retired: a creation named it as `oldSwapchain`.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn retire(&self, raw: vk::SwapchainKHR) {
        if let Some(s) = self.swapchain_states.lock().get_mut(&raw.as_raw()) {
            s.retired = true;
        }
    }

    /// Whether a creation retired the swapchain.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn is_retired(&self, raw: vk::SwapchainKHR) -> bool {
        self.swapchain_states
            .lock()
            .get(&raw.as_raw())
            .is_some_and(|s| s.retired)
    }

    /// How many images of the swapchain are acquired and not presented.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn acquired_count(&self, raw: vk::SwapchainKHR) -> usize {
        self.swapchain_states
            .lock()
            .get(&raw.as_raw())
            .map_or(0, |s| s.acquired.len())
    }

    /// Image `index` of the swapchain was acquired.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn image_acquired(&self, raw: vk::SwapchainKHR, index: u32, device_mask: u32) {
        if let Some(s) = self.swapchain_states.lock().get_mut(&raw.as_raw()) {
            s.acquired.retain(|(i, _)| *i != index);
            s.acquired.push((index, device_mask));
        }
    }

    /// Image `index` of the swapchain was handed to a presentation.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn image_presented(&self, raw: vk::SwapchainKHR, index: u32) {
        if let Some(s) = self.swapchain_states.lock().get_mut(&raw.as_raw()) {
            s.acquired.retain(|(i, _)| *i != index);
        }
    }

    /// The image record a swapchain's images get.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain(&self, raw: vk::SwapchainKHR) -> Option<ImageRecord> {
        self.swapchains.lock().get(&raw.as_raw()).copied()
    }

    /// Records a swapchain's images, as it was created, once they are wrapped.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain_images(&self, raw: vk::SwapchainKHR, images: &[vk::Image]) {
        let Some(record) = self.swapchains.lock().get(&raw.as_raw()).copied() else {
            return;
        };
        {
            let mut recorded = self.images.lock();
            for image in images {
                recorded.insert(image.as_raw(), record);
            }
        }
        if let Some(s) = self.swapchain_states.lock().get_mut(&raw.as_raw()) {
            s.images = images.to_vec();
        }
    }

    /// Image `index` of a swapchain, if it is acquired and not presented since
    /// (`Err(false)`: not acquired; `Err(true)`: acquired, but its image was never
    /// returned by `get_swapchain_images_khr`).
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn acquired_image(
        &self,
        raw: vk::SwapchainKHR,
        index: u32,
    ) -> core::result::Result<(vk::Image, u32), bool> {
        let states = self.swapchain_states.lock();
        let Some(s) = states.get(&raw.as_raw()) else {
            return Err(false);
        };
        let Some((_, mask)) = s.acquired.iter().find(|(i, _)| *i == index) else {
            return Err(false);
        };
        let image = s.images.get(index as usize).copied().ok_or(true)?;
        Ok((image, *mask))
    }

    /// The record of a live image made through the wrappers, or of a swapchain's
    /// image that `get_swapchain_images_khr` returned.
    pub(crate) fn image(&self, raw: vk::Image) -> Option<ImageRecord> {
        self.images.lock().get(&raw.as_raw()).copied()
    }

    /// The layouts of an image's `len` subresources as the submissions so far
    /// leave them.
    pub(crate) fn image_layouts(&self, image: u64, len: usize) -> Vec<vk::ImageLayout> {
        match self.layouts.lock().get(&image) {
            Some(l) if l.len() == len => l.clone(),
            _ => vec![vk::ImageLayout::UNDEFINED; len],
        }
    }

    /// Records that a new image's subresources start `PREINITIALIZED`.
    pub(crate) fn image_preinitialized(&self, image: vk::Image) {
        if let Some(record) = self.image(image) {
            let len = crate::layouts::Shape::of(&record).len();
            self.layouts
                .lock()
                .insert(image.as_raw(), vec![vk::ImageLayout::PREINITIALIZED; len]);
        }
    }

    /// Records the layouts a submission leaves an image's subresources in.
    pub(crate) fn set_image_layouts(&self, image: u64, layouts: Vec<vk::ImageLayout>) {
        // Only a listed image: one destroyed since the check keeps no entry.
        if self.images.lock().contains_key(&image) {
            self.layouts.lock().insert(image, layouts);
        }
    }

    /// The record of a live buffer made through the wrappers.
    pub(crate) fn buffer(&self, raw: vk::Buffer) -> Option<BufferRecord> {
        self.buffers.lock().get(&raw.as_raw()).copied()
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
            crate::mapping::MemoryRecord {
                size,
                memory_type_index,
                mapped: false,
                host: None,
                asked,
            },
        );
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
        f: impl FnOnce(&mut crate::mapping::MemoryRecord) -> R,
    ) -> Option<R> {
        self.memories.lock().get_mut(&raw.as_raw()).map(f)
    }

    /// A strong reference to the live object with this raw handle, if it has a wrapper.
    pub(crate) fn get<H: vk::Handle>(&self, raw: H) -> Option<Retained> {
        let raw = raw.as_raw();
        if raw == 0 {
            return None;
        }
        self.objects
            .lock()
            .get(&(H::TYPE, raw))
            .and_then(|(w, _)| w.upgrade())
    }

    /// The live objects among `raws`, for a wrapper to keep.
    pub(crate) fn keep<H: vk::Handle + Copy>(&self, raws: &[H]) -> Vec<Retained> {
        raws.iter().filter_map(|r| self.get(*r)).collect()
    }

    fn write(&self, set: vk::DescriptorSet, slots: Vec<(Slot, Option<Retained>)>) {
        let mut old = Vec::new();
        {
            let mut sets = self.sets.lock();
            let kept = sets.entry(set.as_raw()).or_default();
            for (slot, object) in slots {
                let previous = match object {
                    Some(o) => kept.insert(slot, o),
                    None => kept.remove(&slot),
                };
                old.extend(previous);
            }
        }
        // A submission that bound the set may still read what the update replaced
        // (bindings updated after bind or unused while pending may be rewritten under
        // it): it keeps the replaced objects until it completes.
        if !old.is_empty() {
            for sub in self.set_submissions(set) {
                sub.keep_also(&old);
            }
        }
        // Released outside the lock, for the same reason as in `remove`.
        drop(old);
    }

    /// The objects one descriptor of type `ty` names; only the reader `ty` selects
    /// is called.
    fn descriptor(
        &self,
        ty: vk::DescriptorType,
        image: impl FnOnce() -> vk::DescriptorImageInfo,
        buffer: impl FnOnce() -> vk::DescriptorBufferInfo,
        view: impl FnOnce() -> vk::BufferView,
    ) -> [Option<Retained>; 2] {
        use vk::DescriptorType as T;
        match ty {
            T::SAMPLER => [self.get(image().sampler), None],
            T::COMBINED_IMAGE_SAMPLER => {
                let i = image();
                [self.get(i.image_view), self.get(i.sampler)]
            }
            T::SAMPLED_IMAGE | T::STORAGE_IMAGE | T::INPUT_ATTACHMENT => {
                [self.get(image().image_view), None]
            }
            T::UNIFORM_BUFFER
            | T::STORAGE_BUFFER
            | T::UNIFORM_BUFFER_DYNAMIC
            | T::STORAGE_BUFFER_DYNAMIC => [self.get(buffer().buffer), None],
            T::UNIFORM_TEXEL_BUFFER | T::STORAGE_TEXEL_BUFFER => [self.get(view()), None],
            _ => [None, None],
        }
    }

    /// Refuses a write whose type selects an array that was not set: the driver
    /// reads `descriptorCount` elements of that array.
    pub(crate) fn check_writes(writes: &[vk::WriteDescriptorSet<'_>]) -> crate::Result<()> {
        use vk::DescriptorType as T;
        for (i, w) in writes.iter().enumerate() {
            if w.descriptor_count == 0 {
                continue;
            }
            let (missing, vuid, array) = match w.descriptor_type {
                T::SAMPLER
                | T::COMBINED_IMAGE_SAMPLER
                | T::SAMPLED_IMAGE
                | T::STORAGE_IMAGE
                | T::INPUT_ATTACHMENT => (
                    w.p_image_info.is_null(),
                    "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06493",
                    "pImageInfo",
                ),
                T::UNIFORM_BUFFER
                | T::STORAGE_BUFFER
                | T::UNIFORM_BUFFER_DYNAMIC
                | T::STORAGE_BUFFER_DYNAMIC => (
                    w.p_buffer_info.is_null(),
                    "VUID-VkWriteDescriptorSet-descriptorType-00324",
                    "pBufferInfo",
                ),
                T::UNIFORM_TEXEL_BUFFER | T::STORAGE_TEXEL_BUFFER => (
                    w.p_texel_buffer_view.is_null(),
                    "VUID-VkWriteDescriptorSet-descriptorType-02994",
                    "pTexelBufferView",
                ),
                _ => (false, "", ""),
            };
            if missing {
                return Err(crate::Error::Validation {
                    vuid,
                    message: format!(
                        "write {i} is of type {:?} but its `{array}` is not set",
                        w.descriptor_type
                    ),
                });
            }
        }
        Ok(())
    }

    /// Where element `element` of binding `binding` of a set of `layout` lands: an
    /// update runs on into the consecutive bindings (empty ones skipped), so the
    /// slot it names is the binding and element it reaches. Without a record of the
    /// layout, or past its bindings, the slot stays as named.
    fn landing(layout: Option<&SetLayoutRecord>, binding: u32, element: u32) -> (u32, u32) {
        let Some(layout) = layout else {
            return (binding, element);
        };
        let Ok(first) = layout
            .bindings
            .binary_search_by_key(&binding, |b| b.binding)
        else {
            return (binding, element);
        };
        let mut e = u64::from(element);
        for b in layout.bindings[first..].iter().filter(|b| b.count > 0) {
            if e < u64::from(b.count) {
                return (b.binding, e as u32);
            }
            e -= u64::from(b.count);
        }
        (binding, element)
    }

    /// Keeps what `writes` put into their sets, and copies what `copies` copy.
    ///
    /// # Safety
    ///
    /// The array each write's type selects holds `descriptorCount` elements or is
    /// null: the safe setters keep every array that is set as long as the count, and
    /// [`Live::check_writes`] refuses a write whose array is not set.
    pub(crate) unsafe fn write_sets(
        &self,
        writes: &[vk::WriteDescriptorSet<'_>],
        copies: &[vk::CopyDescriptorSet<'_>],
    ) {
        for w in writes {
            let layout = self.set_layout_of(w.dst_set);
            let land = |i: usize| {
                Self::landing(
                    layout.as_deref(),
                    w.dst_binding,
                    w.dst_array_element.saturating_add(i as u32),
                )
            };
            let mut slots = Vec::with_capacity(w.descriptor_count as usize);
            let images = (0..w.descriptor_count as usize)
                .map(|i| {
                    let slot = land(i);
                    // SAFETY: as for the readers below.
                    let named = self.slot_descriptor(
                        w.descriptor_type,
                        || unsafe { read(w.p_image_info, i) },
                        || unsafe { read(w.p_buffer_info, i) },
                        || unsafe { read(w.p_texel_buffer_view, i) },
                    );
                    (slot, named)
                })
                .collect();
            self.images_written(w.dst_set, images);
            let written: Vec<_> = (0..w.descriptor_count as usize)
                .map(|i| (land(i), true))
                .collect();
            self.slots_written(w.dst_set, &written);
            for i in 0..w.descriptor_count as usize {
                // SAFETY (each reader): the caller vouches for `descriptor_count`
                // elements of the array the type selects, and only that one is read.
                let objects = self.descriptor(
                    w.descriptor_type,
                    || unsafe { read(w.p_image_info, i) },
                    || unsafe { read(w.p_buffer_info, i) },
                    || unsafe { read(w.p_texel_buffer_view, i) },
                );
                for (k, o) in objects.into_iter().enumerate() {
                    let (binding, element) = land(i);
                    slots.push(((binding, element, k as u8), o));
                }
                if is_dynamic(w.descriptor_type) {
                    // SAFETY: as for the reader above.
                    let b = unsafe { read(w.p_buffer_info, i) };
                    self.dynamic_written(w.dst_set, land(i), b);
                }
            }
            self.write(w.dst_set, slots);
        }
        for c in copies {
            let (src_layout, dst_layout) =
                (self.set_layout_of(c.src_set), self.set_layout_of(c.dst_set));
            let from_slot = |i: u32| {
                Self::landing(
                    src_layout.as_deref(),
                    c.src_binding,
                    c.src_array_element.saturating_add(i),
                )
            };
            let to_slot = |i: u32| {
                Self::landing(
                    dst_layout.as_deref(),
                    c.dst_binding,
                    c.dst_array_element.saturating_add(i),
                )
            };
            let mut slots = Vec::with_capacity(2 * c.descriptor_count as usize);
            {
                let mut ranges = self.dynamic_ranges.lock();
                let copied: Vec<((u32, u32), DynamicRange)> = (0..c.descriptor_count)
                    .filter_map(|i| {
                        let from = from_slot(i);
                        let r = ranges.get(&c.src_set.as_raw())?.get(&from)?;
                        Some((to_slot(i), *r))
                    })
                    .collect();
                if !copied.is_empty() {
                    ranges.entry(c.dst_set.as_raw()).or_default().extend(copied);
                }
            }
            let from: Vec<(u32, u32)> = (0..c.descriptor_count).map(from_slot).collect();
            let written: Vec<_> = (0..c.descriptor_count)
                .map(|i| (to_slot(i), self.slot_written(c.src_set, from_slot(i))))
                .collect();
            self.slots_written(c.dst_set, &written);
            let images = (0..c.descriptor_count)
                .map(to_slot)
                .zip(self.images_at(c.src_set, &from))
                .collect();
            self.images_written(c.dst_set, images);
            {
                let sets = self.sets.lock();
                let src = sets.get(&c.src_set.as_raw());
                for i in 0..c.descriptor_count {
                    for k in 0..2u8 {
                        let (b, e) = from_slot(i);
                        let from = (b, e, k);
                        let object = src.and_then(|s| s.get(&from)).cloned();
                        let (b, e) = to_slot(i);
                        slots.push(((b, e, k), object));
                    }
                }
            }
            self.write(c.dst_set, slots);
        }
    }

    /// Keeps what a descriptor update template writes into `set` from `data`.
    ///
    /// # Safety
    ///
    /// `data` is laid out as `entries` describe, as `vkUpdateDescriptorSetWithTemplate`
    /// requires of its caller.
    pub(crate) unsafe fn write_template(
        &self,
        set: vk::DescriptorSet,
        entries: &[vk::DescriptorUpdateTemplateEntry],
        data: *const core::ffi::c_void,
    ) {
        let mut slots = Vec::new();
        let mut images = Vec::new();
        let mut written = Vec::new();
        let layout = self.set_layout_of(set);
        for e in entries {
            if e.descriptor_type == vk::DescriptorType::INLINE_UNIFORM_BLOCK {
                // The entry's bytes are the block's, from its offset on.
                written.extend((0..e.descriptor_count).map(|i| {
                    let slot = Self::landing(
                        layout.as_deref(),
                        e.dst_binding,
                        e.dst_array_element.saturating_add(i),
                    );
                    (slot, true)
                }));
                continue;
            }
            for i in 0..e.descriptor_count as usize {
                let at = data.cast::<u8>().wrapping_add(e.offset + i * e.stride);
                // SAFETY: as for the readers below.
                let named = self.slot_descriptor(
                    e.descriptor_type,
                    || unsafe { at.cast::<vk::DescriptorImageInfo>().read_unaligned() },
                    || unsafe { at.cast::<vk::DescriptorBufferInfo>().read_unaligned() },
                    || unsafe { at.cast::<vk::BufferView>().read_unaligned() },
                );
                let slot = Self::landing(
                    layout.as_deref(),
                    e.dst_binding,
                    e.dst_array_element.saturating_add(i as u32),
                );
                images.push((slot, named));
                written.push((slot, true));
                // SAFETY (each reader): the caller vouches that the entry's descriptors
                // lie at its offset and stride, and only the kind the type selects is
                // read. Template data need not be aligned, so it is read unaligned.
                let objects = self.descriptor(
                    e.descriptor_type,
                    || unsafe { at.cast::<vk::DescriptorImageInfo>().read_unaligned() },
                    || unsafe { at.cast::<vk::DescriptorBufferInfo>().read_unaligned() },
                    || unsafe { at.cast::<vk::BufferView>().read_unaligned() },
                );
                for (k, o) in objects.into_iter().enumerate() {
                    slots.push(((slot.0, slot.1, k as u8), o));
                }
                if is_dynamic(e.descriptor_type) {
                    // SAFETY: as for the readers above.
                    let b = unsafe { at.cast::<vk::DescriptorBufferInfo>().read_unaligned() };
                    self.dynamic_written(set, slot, b);
                }
            }
        }
        self.images_written(set, images);
        self.slots_written(set, &written);
        self.write(set, slots);
    }

    /// Records a dynamic buffer descriptor's offset and range, with its buffer's size
    /// (a buffer without a wrapper's record is not recorded, and its binding not
    /// checked).
    fn dynamic_written(
        &self,
        set: vk::DescriptorSet,
        slot: (u32, u32),
        b: vk::DescriptorBufferInfo,
    ) {
        let size = self.buffer(b.buffer).map(|r| r.size);
        let mut ranges = self.dynamic_ranges.lock();
        let of_set = ranges.entry(set.as_raw()).or_default();
        match size {
            Some(size) => {
                of_set.insert(slot, (b.offset, b.range, size));
            }
            None => {
                of_set.remove(&slot);
            }
        }
    }

    /// What the dynamic buffer descriptor at `slot` of `set` was written with.
    pub(crate) fn dynamic_range(
        &self,
        set: vk::DescriptorSet,
        slot: (u32, u32),
    ) -> Option<DynamicRange> {
        self.dynamic_ranges
            .lock()
            .get(&set.as_raw())
            .and_then(|s| s.get(&slot))
            .copied()
    }
}
