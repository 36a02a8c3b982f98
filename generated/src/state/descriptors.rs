//! What the device records of descriptor set layouts and descriptor sets: each
//! layout's bindings, each set's written descriptors, dynamic ranges and uses.

use super::live::Live;
use super::read;
use super::HashMap;
use ash::vk::{self, Handle as _};
use tuff_runtime::{Retained, Vrc, Vweak};

/// Whether a descriptor type takes a dynamic offset at binding.
pub(super) fn is_dynamic(ty: vk::DescriptorType) -> bool {
    matches!(
        ty,
        vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC | vk::DescriptorType::STORAGE_BUFFER_DYNAMIC
    )
}

/// An element of a descriptor set: binding, array element, and which of the
/// descriptor's handles (an image descriptor has a view and a sampler).
pub(super) type Slot = (u32, u32, u8);

/// A dynamic buffer descriptor as written: `offset`, `range` (maybe
/// `VK_WHOLE_SIZE`) and the size of the buffer.
pub(crate) type DynamicRange = (u64, u64, u64);

/// The dynamic buffer descriptors of one set, by binding and array element.
pub(super) type SetRanges = HashMap<(u32, u32), DynamicRange>;

/// What the device knows of the command buffers that bound a descriptor set.
#[derive(Default)]
pub(super) struct SetUse {
    /// Changed by every update that invalidates the command buffers that bound the
    /// set (of a binding without `UPDATE_AFTER_BIND`, of image descriptors, or by a
    /// template): a command buffer remembers the generation it bound, and a
    /// different one refuses its submission.
    pub(super) generation: u64,
    /// The submissions of command buffers that bound the set, weakly; those known
    /// complete are pruned as new ones come.
    pub(super) subs: Vec<Vweak<crate::state::Submission>>,
    /// Whether the set's pool was created with `UPDATE_AFTER_BIND`.
    pub(super) pool_update_after_bind: bool,
    /// The image descriptors the set holds (none: `None`), replaced as a whole by
    /// each update, so a recorder that bound the set keeps the list it saw.
    pub(super) images: Option<SetImages>,
    /// The slots an update wrote (and no copy of an unwritten slot undid since),
    /// replaced as a whole by each update like `images`.
    pub(super) written: SetWritten,
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
    pub sel: crate::state::layouts::Sel,
    /// The descriptor's `imageLayout`.
    pub layout: vk::ImageLayout,
    /// The view's type.
    pub view_type: vk::ImageViewType,
    /// The view's format (an image or texel buffer view's; `UNDEFINED` otherwise).
    pub format: vk::Format,
    /// Whether the slot is an input attachment's.
    pub input: bool,
    /// The bytes `start..end` of `buffer` a buffer descriptor or texel buffer view
    /// reaches, for the hazard tracker (none for a dynamic buffer descriptor, whose
    /// offset binding adds: not tracked).
    pub bytes: Option<(u64, u64)>,
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

impl Live {
    pub(super) fn next_set_generation(&self) -> u64 {
        self.set_generations
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed)
            + 1
    }

    /// The generation of a descriptor set now, what a command buffer that binds it
    /// remembers, the image descriptors it holds and the slots written (`None`: no
    /// record of the set, so none; no empty list is allocated for it).
    pub(crate) fn set_bound(
        &self,
        raw: vk::DescriptorSet,
    ) -> (u64, Option<SetImages>, Option<SetWritten>) {
        self.set_uses.lock().get(&raw.as_raw()).map_or_else(
            || (0, None, None),
            |u| (u.generation, u.images.clone(), Some(u.written.clone())),
        )
    }

    /// Whether slot `slot` of `set` holds a written descriptor.
    pub(super) fn slot_written(&self, set: vk::DescriptorSet, slot: (u32, u32)) -> bool {
        self.set_uses
            .lock()
            .get(&set.as_raw())
            .is_some_and(|u| u.written.binary_search(&slot).is_ok())
    }

    /// A set's slots are now written (`true`) or hold a copy of an unwritten slot.
    /// A slot that loses its descriptor leaves the command buffers that bound the
    /// set invalid whatever the binding's flags, as their draws were checked with
    /// it written.
    pub(super) fn slots_written(&self, set: vk::DescriptorSet, updates: &[((u32, u32), bool)]) {
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
    pub(super) fn slot_descriptor(
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
            sel: crate::state::layouts::Sel {
                aspect: vk::ImageAspectFlags::empty(),
                mips: (0, 0),
                layers: (0, 0),
            },
            layout: vk::ImageLayout::UNDEFINED,
            view_type: vk::ImageViewType::default(),
            format: vk::Format::UNDEFINED,
            input: false,
            bytes: None,
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
                    // The whole buffer: the view's range is not kept.
                    bytes: Some((0, u64::MAX)),
                    ..empty
                })
            }
            T::UNIFORM_BUFFER
            | T::STORAGE_BUFFER
            | T::UNIFORM_BUFFER_DYNAMIC
            | T::STORAGE_BUFFER_DYNAMIC => {
                let info = buffer();
                self.buffer(info.buffer)?;
                let end = match info.range {
                    vk::WHOLE_SIZE => u64::MAX,
                    range => info.offset.saturating_add(range),
                };
                Some(ImageDescriptor {
                    kind: SlotKind::Buffer,
                    buffer: info.buffer,
                    bytes: (!is_dynamic(ty)).then_some((info.offset, end)),
                    ..empty
                })
            }
            ty if names_image_layout(ty) => {
                let info = image();
                let mut d = self.image_descriptor(&info)?;
                if ty == T::COMBINED_IMAGE_SAMPLER {
                    d.sampler = self.sampler_bits(info.sampler).unwrap_or(0);
                }
                d.input = ty == T::INPUT_ATTACHMENT;
                Some(d)
            }
            _ => None,
        }
    }

    /// The image descriptor of `info`: the subresources its view reaches (none for a
    /// view the device has no record of).
    pub(super) fn image_descriptor(
        &self,
        info: &vk::DescriptorImageInfo,
    ) -> Option<ImageDescriptor> {
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
            sel: crate::state::layouts::Sel {
                aspect: view.aspect,
                mips: (view.base_level, view.base_level.saturating_add(view.levels)),
                layers,
            },
            layout: info.image_layout,
            view_type: view.view_type,
            format: view.format,
            input: false,
            bytes: None,
        })
    }

    /// The image descriptors of a set at `slots`.
    pub(super) fn images_at(
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
    pub(super) fn images_written(
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
    pub(crate) fn sets_submitted(&self, sets: &[(u64, u64)], sub: &Vrc<crate::state::Submission>) {
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
    ) -> Vec<Vrc<crate::state::Submission>> {
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

    /// Taken by descriptor updates and submissions (see the field).
    pub(crate) fn descriptor_gate(&self) -> tuff_runtime::VutexGuard<'_, ()> {
        self.descriptor_gate.lock()
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

    pub(super) fn write(&self, set: vk::DescriptorSet, slots: Vec<(Slot, Option<Retained>)>) {
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
    pub(super) fn descriptor(
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
    pub(super) fn landing(
        layout: Option<&SetLayoutRecord>,
        binding: u32,
        element: u32,
    ) -> (u32, u32) {
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
    pub(super) fn dynamic_written(
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
