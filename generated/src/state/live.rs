//! The device's live objects and its side tables, one `Live` per device; the methods
//! about each kind of object are in that object's file beside this one.
//!
//! What keeps objects alive when Vulkan reaches them through raw handles stored in
//! structs rather than through wrapper arguments: a view's image, a framebuffer's
//! attachments, a pipeline's layout, a render pass instance's framebuffer, and the
//! buffers, views and samplers written into a descriptor set.
//!
//! Every object of a device is listed in `Live` (weakly) under its raw handle while its
//! wrapper lives. A wrapper that Vulkan lets refer to others looks them up and keeps
//! them (strongly); a descriptor set keeps what was last written into each of its
//! elements until it is rewritten or the set goes.

use super::buffer::BufferRecord;
use super::descriptors::{SetLayoutRecord, SetRanges, SetUse, Slot};
use super::framebuffer::{AttachmentImage, FramebufferRecord};
use super::image::ImageRecord;
use super::memory::Binding;
use super::pipeline::{LayoutRecord, PipelineRecord};
use super::queries::PoolQueries;
use super::query::QueryPoolRecord;
use super::render_pass::RenderPassRecord;
use super::swapchain::SwapchainState;
use super::sync::EventSubmissions;
use super::view::ViewRecord;
use super::HashMap;
use ash::vk;
use tuff_runtime::{HostSync, Retained, Vrc, Vutex, Vweak};

/// A live object, weakly, and its host synchronization.
pub(super) type LiveEntry = (Vweak<dyn tuff_runtime::Retain>, HostSync);

/// The live objects of one device, and what each descriptor set refers to.
pub(crate) struct Live {
    /// Each live object, weakly, with the host synchronization that every wrapper of
    /// its handle shares.
    pub(super) objects: Vutex<HashMap<(vk::ObjectType, u64), LiveEntry>>,
    pub(super) sets: Vutex<HashMap<u64, HashMap<Slot, Retained>>>,
    /// For each dynamic buffer descriptor written (set, then binding and array
    /// element): the offset and range written, and the buffer's size, which a
    /// binding's dynamic offset is checked against.
    pub(super) dynamic_ranges: Vutex<HashMap<u64, SetRanges>>,
    /// Each device memory's size, type and whether it is mapped now.
    pub(super) memories: Vutex<HashMap<u64, super::memory::MemoryRecord>>,
    /// Each live image view's parameters.
    pub(super) views: Vutex<HashMap<u64, ViewRecord>>,
    /// Each live framebuffer's attachments (none for an imageless one) and its
    /// width, height and layer count.
    pub(super) framebuffers: Vutex<HashMap<u64, FramebufferRecord>>,
    /// Each live imageless framebuffer's attachment image infos.
    pub(super) imageless: Vutex<HashMap<u64, Vec<AttachmentImage>>>,
    /// The record of the render pass each live framebuffer was created with.
    pub(super) framebuffer_passes: Vutex<HashMap<u64, Vrc<RenderPassRecord>>>,
    /// The view formats each live image's create info listed, where it listed any.
    pub(super) view_formats: Vutex<HashMap<u64, Vec<vk::Format>>>,
    /// Each live sampler Y'CbCr conversion's format and chroma filter.
    pub(super) conversions: Vutex<HashMap<u64, (vk::Format, vk::Filter)>>,
    /// Held by a safe sampler creation from its count check until its sampler is
    /// listed, so two threads cannot both take the last sampler
    /// `maxSamplerAllocationCount` allows.
    pub(super) sampling: Vutex<()>,
    /// Held by a safe allocation from its count check until its memory is listed,
    /// so two threads cannot both take the last allocation `maxMemoryAllocationCount`
    /// allows.
    pub(super) allocating: Vutex<()>,
    /// The device's queue operations that may still be executing.
    pub(super) ledger: crate::state::Ledger,
    /// The host synchronization of each queue of the device.
    pub(super) queues: Vutex<HashMap<u64, HostSync>>,
    /// The queue family of each queue got through the wrappers.
    pub(super) queue_families: Vutex<HashMap<u64, u32>>,
    /// Each live command pool's queue family: its flags and image transfer
    /// granularity, and whether the pool is protected.
    pub(super) pools: Vutex<HashMap<u64, super::command_pool::PoolFamily>>,
    /// Each bound buffer's and image's memory, offset and size there.
    pub(super) bindings: Vutex<HashMap<(vk::ObjectType, u64), Binding>>,
    /// The format properties asked of the physical device, by format.
    pub(super) formats: Vutex<HashMap<i32, vk::FormatProperties>>,
    /// `VkDeviceGroupPresentCapabilitiesKHR::presentMask`, read once.
    #[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
    pub(super) present_masks: Vutex<Option<[u32; vk::MAX_DEVICE_GROUP_SIZE]>>,
    /// The device's timeline semaphores (the others are binary).
    pub(super) timelines: Vutex<HashMap<u64, crate::state::Timeline>>,
    /// The binary semaphores with a signal or wait submitted that may matter still
    /// (an unlisted one is unsignaled with nothing pending).
    pub(super) binaries: Vutex<HashMap<u64, crate::state::Binary>>,
    /// The live events created with `VK_EVENT_CREATE_DEVICE_ONLY_BIT`, which the
    /// host may not set, reset or read.
    pub(super) device_only_events: Vutex<std::collections::HashSet<u64>>,
    /// The memory each live sparse buffer or image requires, and their sum, which
    /// `sparseAddressSpaceSize` bounds.
    pub(super) sparse_resources: Vutex<HashMap<(vk::ObjectType, u64), u64>>,
    pub(super) sparse_total: Vutex<u64>,
    /// Held by a safe sparse creation from its check against
    /// `sparseAddressSpaceSize` until its resource is listed.
    pub(super) sparse_gate: Vutex<()>,
    /// What the recorder needs of each live render pass.
    pub(super) render_passes: Vutex<HashMap<u64, Vrc<RenderPassRecord>>>,
    /// What the checks of commands that use a buffer need to know of it.
    pub(super) buffers: Vutex<HashMap<u64, BufferRecord>>,
    /// Each shader module's interface, which pipeline creation checks layouts against.
    pub(super) shader_modules: Vutex<HashMap<u64, Vrc<crate::spirv::Interface>>>,
    /// What the checks of commands and structs that name an image need to know of it.
    pub(super) images: Vutex<HashMap<u64, ImageRecord>>,
    /// The layout of each subresource of an image (numbered as
    /// [`crate::state::layouts::Shape`] does) as the submissions so far leave it; an
    /// unlisted image is wholly `UNDEFINED`.
    pub(super) layouts: Vutex<HashMap<u64, super::image::ImageLayouts>>,
    /// Each swapchain's images, as one record: what `get_swapchain_images_khr`
    /// records for every image it returns.
    pub(super) swapchains: Vutex<HashMap<u64, ImageRecord>>,
    /// Each live swapchain's surface, whether a later creation retired it, and the
    /// indices of the images acquired and not presented since.
    pub(super) swapchain_states: Vutex<HashMap<u64, SwapchainState>>,
    /// Each query pool's type, query count and statistics.
    pub(super) query_pools: Vutex<HashMap<u64, QueryPoolRecord>>,
    /// Each query pool's query states as the submissions and host resets so far
    /// leave them, and the submissions that touch its queries.
    pub(super) query_states: Vutex<HashMap<u64, PoolQueries>>,
    /// Held by the host's reads and resets of queries, which may not run at once.
    pub(super) query_host: Vutex<()>,
    /// Each pipeline layout's push-constant ranges and sets.
    pub(super) pipeline_layouts: Vutex<HashMap<u64, Vrc<LayoutRecord>>>,
    /// Each pipeline's bind point and layout.
    pub(super) pipelines: Vutex<HashMap<u64, Vrc<PipelineRecord>>>,
    /// Each descriptor set layout's bindings.
    pub(super) set_layouts: Vutex<HashMap<u64, Vrc<SetLayoutRecord>>>,
    /// Each descriptor set's layout record.
    pub(super) sets_layouts: Vutex<HashMap<u64, Vrc<SetLayoutRecord>>>,
    /// The physical device's limits, read once.
    pub(super) limits: std::sync::OnceLock<vk::PhysicalDeviceLimits>,
    /// `maxMultiviewInstanceIndex`, read the first time a draw in a multiview
    /// render pass instance needs it.
    pub(super) max_multiview_instance: std::sync::OnceLock<Option<u32>>,
    /// How many live buffers and images were created protected.
    pub(super) protected_resources: std::sync::atomic::AtomicUsize,
    /// The physical device's `maxBufferSize`, read once (none below Vulkan 1.3).
    pub(super) max_buffer_size: std::sync::OnceLock<Option<u64>>,
    /// The core features the device was created with.
    pub(super) features: std::sync::OnceLock<super::features::Features>,
    /// The queue families the device was created with, each with its queue count
    /// and create flags, one per `VkDeviceQueueCreateInfo`.
    pub(super) queue_infos: std::sync::OnceLock<Vec<(u32, u32, vk::DeviceQueueCreateFlags)>>,
    /// How many physical devices make up the device (a chained
    /// `VkDeviceGroupDeviceCreateInfo`'s count, or 1), which bounds device masks.
    pub(super) physical_count: std::sync::OnceLock<u32>,
    /// The memory bound to each buffer or image by `vkBind*Memory2`, kept as long
    /// as the object is listed (`vkBind*Memory` keep it in the wrapper instead).
    pub(super) bound_memories: Vutex<HashMap<(vk::ObjectType, u64), Retained>>,
    /// Each live descriptor set's generation and the submissions of the command
    /// buffers that bound it.
    pub(super) set_uses: Vutex<HashMap<u64, SetUse>>,
    /// The last generation given to a descriptor set: a device-wide count, so a set
    /// handle that a pool reuses never meets a generation of the set it was before.
    pub(super) set_generations: std::sync::atomic::AtomicU64,
    /// Held by every descriptor update, and by every queue submission from its
    /// checks of what other submissions use and leave (descriptor sets, events,
    /// semaphores) to its record of its own: the host access to a set is externally
    /// synchronized, and no update or submission on another queue runs between a
    /// submission's checks and its bookkeeping.
    pub(super) descriptor_gate: Vutex<()>,
    /// The buffer of each live buffer view.
    pub(super) buffer_views: Vutex<HashMap<u64, (vk::Buffer, vk::Format)>>,
    /// What each live sampler does, as [`sampler_bits`] gives it.
    pub(super) samplers: Vutex<HashMap<u64, u8>>,
    /// The queues got with `VK_DEVICE_QUEUE_CREATE_PROTECTED_BIT`.
    pub(super) protected_queues: Vutex<std::collections::HashSet<u64>>,
    /// The physical device's `maxTimelineSemaphoreValueDifference`, read once.
    pub(super) timeline_difference: std::sync::OnceLock<u64>,
    /// The submissions whose command buffers name each event, with their queues,
    /// weakly; those known complete are pruned as new ones come.
    pub(super) event_uses: Vutex<HashMap<u64, EventSubmissions>>,
    /// Each event's state as the submissions and the host so far leave it, with
    /// the last submissions that set, reset or wait on it.
    pub(super) event_records: Vutex<HashMap<u64, super::events::EventRecord>>,
    /// What each queue's submissions not known complete did to memory, by queue.
    pub(crate) hazard_queues: Vutex<HashMap<u64, super::hazards::QueueHazards>>,
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
            sampling: Vutex::new(()),
            ledger: Default::default(),
            queues: Vutex::new(HashMap::default()),
            timelines: Vutex::new(HashMap::default()),
            timeline_difference: std::sync::OnceLock::new(),
            event_uses: Vutex::new(HashMap::default()),
            event_records: Vutex::new(HashMap::default()),
            hazard_queues: Vutex::new(HashMap::default()),
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
            query_states: Vutex::new(HashMap::default()),
            query_host: Vutex::new(()),
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
    pub(super) fn add_raw(&self, ty: vk::ObjectType, raw: u64, object: &Retained, sync: &HostSync) {
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

    pub(super) fn remove_raw(&self, ty: vk::ObjectType, raw: u64) {
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
            self.forget_event(key.1);
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
                self.forget_query_states(key.1);
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

    /// Records the core features the device was created with.
    pub(crate) fn set_physical_count(&self, count: u32) {
        let _ = self.physical_count.set(count);
    }

    /// How many physical devices make up the device; a valid device mask sets no bit
    /// at or above it.
    pub(crate) fn physical_count(&self) -> u32 {
        self.physical_count.get().copied().unwrap_or(1)
    }

    pub(crate) fn set_features(&self, features: super::features::Features) {
        let _ = self.features.set(features);
    }

    /// The Vulkan 1.0 features the device was created with.
    pub(crate) fn features(&self) -> vk::PhysicalDeviceFeatures {
        self.with_features(|f| f.v10)
    }

    /// Runs `read` on the core features the device was created with (none, before
    /// they are recorded).
    pub(crate) fn with_features<R>(&self, read: impl FnOnce(&super::features::Features) -> R) -> R {
        read(self.features_or_none())
    }

    // Out of the generic `with_features`, which every feature check instantiates: the
    // features, or a set with none on, made once.
    pub(super) fn features_or_none(&self) -> &super::features::Features {
        static NONE: std::sync::OnceLock<super::features::Features> = std::sync::OnceLock::new();
        match self.features.get() {
            Some(f) => f,
            None => NONE.get_or_init(super::features::Features::default),
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
    pub(super) fn protected_one(&self, created: bool) {
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

    /// A strong reference to the live object with this raw handle, if it has a wrapper.
    pub(crate) fn get<H: vk::Handle>(&self, raw: H) -> Option<Retained> {
        self.get_raw(H::TYPE, raw.as_raw())
    }

    /// [`Live::get`] by object type and raw handle.
    pub(crate) fn get_raw(&self, ty: vk::ObjectType, raw: u64) -> Option<Retained> {
        if raw == 0 {
            return None;
        }
        self.objects
            .lock()
            .get(&(ty, raw))
            .and_then(|(w, _)| w.upgrade())
    }
}

/// The physical device's limits, read once per device.
pub(crate) fn limits(device: &crate::handles::Device) -> &vk::PhysicalDeviceLimits {
    device
        .live()
        .limits(|| device.parent().get_properties().limits)
}
