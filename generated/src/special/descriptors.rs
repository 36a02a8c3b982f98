//! Descriptor pools and sets: allocation, updates (each write and copy against its
//! set's layout), resets, update templates and descriptor-buffer capture data.

#[cfg(feature = "ext_descriptor_buffer")]
use super::ask_properties2;
use super::{chained, limits, refuse};
use crate::handles::*;
use crate::state::{raw_slice, BindingRecord, Live, SetLayoutRecord};
use crate::structs::*;
use crate::{Error, Handle, Result};
use ash::vk;
use ash::vk::Handle as _;
use tuff_runtime::Vrc;

/// Refuses a pool whose sets are still alive.
pub(crate) fn reset_descriptor_pool_checks(descriptor_pool: &DescriptorPool) -> Result<()> {
    if descriptor_pool.has_sets() {
        return Err(Error::Validation {
            vuid: "VUID-vkResetDescriptorPool-descriptorPool-00313",
            message: "sets allocated from the pool are still alive (held by the program, or by a command buffer or submission that uses them); drop them before the pool is reset".into(),
        });
    }
    Ok(())
}

/// The pool's sets are gone: it forgets those whose free it deferred.
pub(crate) fn reset_descriptor_pool_done(descriptor_pool: &DescriptorPool) {
    descriptor_pool.forget_deferred();
}

/// The set remembers what the template wrote into it.
///
/// # Safety
///
/// `data` is laid out as the template's entries describe (the promise of the
/// `unsafe` method that calls this).
pub(crate) unsafe fn update_descriptor_set_with_template_done(
    device: &Device,
    descriptor_set: &DescriptorSet,
    descriptor_update_template: &DescriptorUpdateTemplate,
    data: *const core::ffi::c_void,
) {
    // Which bindings the template writes is not looked at: the update counts as one
    // that invalidates the command buffers that bound the set.
    device.live().set_invalidated(descriptor_set.raw());
    // SAFETY: the caller's promise, passed on.
    unsafe {
        device.live().write_template(
            descriptor_set.raw(),
            descriptor_update_template.entries(),
            data,
        )
    };
}

/// The pool remembers its flags (whether its sets may be freed one by one).
pub(crate) fn descriptor_pool_created(
    pool: DescriptorPool,
    create_info: &DescriptorPoolCreateInfo<'_>,
) -> DescriptorPool {
    pool.with_flags(create_info.flags)
}

/// Each entry of a descriptor update template names a binding of the set layout the
/// template updates (00354; for push descriptors, the pipeline layout's set `set`),
/// and its elements fit in that binding and the consecutive bindings after it (00355),
/// at multiples of 4 in an inline uniform block (02226, 02227).
pub(crate) fn descriptor_update_template_checks(
    device: &Device,
    create_info: &DescriptorUpdateTemplateCreateInfo<'_>,
) -> Result<()> {
    let raw = create_info.as_raw();
    let live = device.live();
    let layout = if raw.template_type == vk::DescriptorUpdateTemplateType::DESCRIPTOR_SET {
        live.set_layout(raw.descriptor_set_layout)
    } else {
        live.pipeline_layout(raw.pipeline_layout)
            .and_then(|l| l.sets.get(raw.set as usize).cloned())
    };
    let Some(layout) = layout else {
        return Ok(());
    };
    // SAFETY: the safe setter stored the entries with their count.
    let entries = unsafe {
        crate::state::raw_slice(
            raw.p_descriptor_update_entries,
            raw.descriptor_update_entry_count,
        )
    };
    for (n, e) in entries.iter().enumerate() {
        let at = format!("pDescriptorUpdateEntries[{n}]");
        let first = find_binding(&layout, e.dst_binding, &at, TEMPLATE_BINDING)?;
        check_span(
            &layout,
            first,
            e.dst_array_element,
            e.descriptor_count,
            &at,
            TEMPLATE_SPAN,
        )?;
    }
    Ok(())
}

/// The template remembers its entries, which say how to read the data of an update.
pub(crate) fn descriptor_update_template_created(
    template: DescriptorUpdateTemplate,
    create_info: &DescriptorUpdateTemplateCreateInfo<'_>,
) -> DescriptorUpdateTemplate {
    let raw = create_info.as_raw();
    // SAFETY: the safe setter stored the entries with their count.
    template.with_entries(unsafe {
        crate::state::raw_slice(
            raw.p_descriptor_update_entries,
            raw.descriptor_update_entry_count,
        )
    })
}

/// Each set holds a token of its pool, which counts the sets alive, and the device
/// remembers its layout, which writes to it are checked against.
pub(crate) fn descriptor_sets_allocated(
    device: &Device,
    sets: Vec<DescriptorSet>,
    descriptor_pool: &DescriptorPool,
    allocate_info: &DescriptorSetAllocateInfo<'_>,
) -> Vec<DescriptorSet> {
    let raw = allocate_info.as_raw();
    // SAFETY: the safe setter stored the layouts with their count.
    let layouts = unsafe { crate::state::raw_slice(raw.p_set_layouts, raw.descriptor_set_count) };
    let counts = variable_counts(allocate_info);
    for (i, (set, layout)) in sets.iter().zip(layouts).enumerate() {
        let mut record = device.live().set_layout(*layout).unwrap_or_default();
        // A variable-count binding has, in this set, the count the allocation gave
        // it (0 without one), which writes to the set are checked against.
        if let Some(variable) = record.variable {
            let count = counts.get(i).copied().unwrap_or(0);
            let mut own = (*record).clone();
            if let Some(b) = own.bindings.iter_mut().find(|b| b.binding == variable) {
                b.count = count;
            }
            record = Vrc::new(own);
        }
        device.live().set_allocated(set.raw(), record);
        device.live().set_pool_update_after_bind(
            set.raw(),
            descriptor_pool
                .pool_flags()
                .contains(vk::DescriptorPoolCreateFlags::UPDATE_AFTER_BIND),
        );
    }
    sets.into_iter()
        .map(|set| set.with_token(descriptor_pool.set_token()))
        .collect()
}

/// The check of `vkAllocateDescriptorSets` on a chained
/// `VkDescriptorSetVariableDescriptorCountAllocateInfo`: drivers read one count per
/// set from it.
/// The descriptor counts of an allocation's variable-count bindings, one per set, or
/// none.
fn variable_counts<'a>(allocate_info: &'a DescriptorSetAllocateInfo<'_>) -> &'a [u32] {
    let raw = allocate_info.as_raw();
    // SAFETY: `raw` is a safe struct's.
    let variable: Option<&vk::DescriptorSetVariableDescriptorCountAllocateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::DESCRIPTOR_SET_VARIABLE_DESCRIPTOR_COUNT_ALLOCATE_INFO,
        )
    };
    // SAFETY: the safe setter stored the counts with their count.
    variable.map_or(&[], |v| unsafe {
        crate::state::raw_slice(v.p_descriptor_counts, v.descriptor_set_count)
    })
}

/// Sets of update-after-bind layouts come from an update-after-bind pool, and a
/// variable-count binding gets at most the count its layout was created with.
pub(crate) fn allocate_descriptor_sets_layouts(
    device: &Device,
    descriptor_pool: &DescriptorPool,
    allocate_info: &DescriptorSetAllocateInfo<'_>,
) -> Result<()> {
    let raw = allocate_info.as_raw();
    // SAFETY: the safe setter stored the layouts with their count.
    let layouts = unsafe { crate::state::raw_slice(raw.p_set_layouts, raw.descriptor_set_count) };
    let counts = variable_counts(allocate_info);
    let pool_uab = descriptor_pool
        .pool_flags()
        .contains(vk::DescriptorPoolCreateFlags::UPDATE_AFTER_BIND);
    for (i, layout) in layouts.iter().enumerate() {
        let Some(record) = device.live().set_layout(*layout) else {
            continue;
        };
        if record.update_after_bind && !pool_uab {
            refuse(
                "VUID-VkDescriptorSetAllocateInfo-pSetLayouts-03044",
                format!(
                    "`pSetLayouts[{i}]` was created with \
                     `VK_DESCRIPTOR_SET_LAYOUT_CREATE_UPDATE_AFTER_BIND_POOL_BIT`, so \
                     `descriptorPool` must have been created with \
                     `VK_DESCRIPTOR_POOL_CREATE_UPDATE_AFTER_BIND_BIT`"
                ),
            )?;
        }
        let variable = record
            .variable
            .and_then(|v| record.bindings.iter().find(|b| b.binding == v));
        if let (Some(b), Some(&count)) = (variable, counts.get(i)) {
            if count > b.count {
                refuse(
                    "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-pSetLayouts-03046",
                    format!(
                        "`pDescriptorCounts[{i}]` ({count}) must be less than or equal to the \
                         descriptor count of the variable-sized binding {} of its layout ({})",
                        b.binding, b.count
                    ),
                )?;
            }
        }
    }
    Ok(())
}

pub(crate) fn allocate_descriptor_sets_checks(
    allocate_info: &DescriptorSetAllocateInfo<'_>,
) -> Result<()> {
    let raw = allocate_info.as_raw();
    // SAFETY: `raw` is a safe struct's.
    let variable: Option<&vk::DescriptorSetVariableDescriptorCountAllocateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::DESCRIPTOR_SET_VARIABLE_DESCRIPTOR_COUNT_ALLOCATE_INFO,
        )
    };
    match variable {
        Some(v) if v.descriptor_set_count != 0 && v.descriptor_set_count != raw.descriptor_set_count => refuse(
            "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-descriptorSetCount-03045",
            format!("the chained variable-count info's descriptorSetCount ({}) must be 0 or the allocation's ({})", v.descriptor_set_count, raw.descriptor_set_count),
        ),
        _ => Ok(()),
    }
}

/// `pData` of a `vkGet*OpaqueCaptureDescriptorDataEXT` holds the capture data the
/// device's descriptor-buffer properties size (`size` reads which), so the driver
/// writes inside the slice.
#[cfg(feature = "ext_descriptor_buffer")]
pub(crate) fn capture_data_fits(
    device: &Device,
    data: &[u8],
    size: fn(&vk::PhysicalDeviceDescriptorBufferPropertiesEXT) -> usize,
    vuid: &'static str,
) -> Result<()> {
    if device.ext().ext_descriptor_buffer.is_none() {
        // The call refuses the missing extension itself.
        return Ok(());
    }
    let mut props = vk::PhysicalDeviceDescriptorBufferPropertiesEXT::default();
    if !ask_properties2(device, &mut props) {
        return Err(Error::Misuse(
            "the capture data size is a Vulkan 1.1 property: make the instance with Vulkan 1.1 or later",
        ));
    }
    let needed = size(&props);
    if data.len() < needed {
        refuse(
            vuid,
            format!(
                "`data` must hold at least {needed} bytes (the device's capture data size), not {}",
                data.len()
            ),
        )?;
    }
    Ok(())
}

/// The safe structs as ash's, which they are transparent over.
fn raw_writes<'s>(writes: &'s [WriteDescriptorSet<'_>]) -> &'s [vk::WriteDescriptorSet<'s>] {
    // SAFETY: `WriteDescriptorSet` is `repr(transparent)` over ash's struct.
    unsafe { core::slice::from_raw_parts(writes.as_ptr().cast(), writes.len()) }
}

/// The safe copy structs as ash's, which they are transparent over.
fn raw_copies<'s>(copies: &'s [CopyDescriptorSet<'_>]) -> &'s [vk::CopyDescriptorSet<'s>] {
    // SAFETY: `CopyDescriptorSet` is `repr(transparent)` over ash's struct.
    unsafe { core::slice::from_raw_parts(copies.as_ptr().cast(), copies.len()) }
}

/// Refuses a write whose descriptor type selects an array that is not set, a write
/// or copy outside its sets' bindings (drivers index their descriptor arrays with
/// the binding, array element and count), a descriptor whose objects are not of
/// the device or do not fit its type, and a copy whose sets differ in how they may
/// be updated.
pub(crate) fn update_descriptor_sets_checks(
    device: &Device,
    descriptor_writes: &[WriteDescriptorSet<'_>],
    descriptor_copies: &[CopyDescriptorSet<'_>],
) -> Result<()> {
    let writes = raw_writes(descriptor_writes);
    crate::state::Live::check_writes(writes)?;
    let live = device.live();
    let layout_of = |set: vk::DescriptorSet| {
        live.set_layout_of(set).ok_or(Error::Misuse(
            "the descriptor set was not allocated through the wrappers",
        ))
    };
    for (i, w) in writes.iter().enumerate() {
        let layout = layout_of(w.dst_set)?;
        let at = format!("pDescriptorWrites[{i}]");
        let first = find_binding(&layout, w.dst_binding, &at, WRITE_BINDING)?;
        if layout.bindings[first].ty != w.descriptor_type {
            refuse(
                "VUID-VkWriteDescriptorSet-descriptorType-00319",
                format!(
                    "{at}.descriptorType ({:?}) must match the type of binding {} ({:?})",
                    w.descriptor_type, w.dst_binding, layout.bindings[first].ty
                ),
            )?;
        }
        check_span(
            &layout,
            first,
            w.dst_array_element,
            w.descriptor_count,
            &at,
            WRITE_SPAN,
        )?;
        check_descriptors(device, live, &layout.bindings[first], w, &at)?;
    }
    for (i, c) in raw_copies(descriptor_copies).iter().enumerate() {
        let at = format!("pDescriptorCopies[{i}]");
        let src = layout_of(c.src_set)?;
        let dst = layout_of(c.dst_set)?;
        let s = find_binding(&src, c.src_binding, &at, COPY_SRC_BINDING)?;
        let d = find_binding(&dst, c.dst_binding, &at, COPY_DST_BINDING)?;
        if src.bindings[s].ty != dst.bindings[d].ty {
            refuse(
                "VUID-VkCopyDescriptorSet-dstBinding-02632",
                format!(
                    "{at}: the type of dstBinding ({:?}) must equal the type of srcBinding ({:?})",
                    dst.bindings[d].ty, src.bindings[s].ty
                ),
            )?;
        }
        check_span(
            &src,
            s,
            c.src_array_element,
            c.descriptor_count,
            &at,
            COPY_SRC_SPAN,
        )?;
        check_span(
            &dst,
            d,
            c.dst_array_element,
            c.descriptor_count,
            &at,
            COPY_DST_SPAN,
        )?;
        check_copy(live, c, (&src, s), (&dst, d), &at)?;
    }
    Ok(())
}

/// The rules a binding lookup breaks: (no such binding, a binding of no descriptors).
type BindingRules = (&'static str, &'static str);

const WRITE_BINDING: BindingRules = (
    "VUID-VkWriteDescriptorSet-dstBinding-00315",
    "VUID-VkWriteDescriptorSet-dstBinding-00316",
);

const COPY_SRC_BINDING: BindingRules = (
    "VUID-VkCopyDescriptorSet-srcBinding-00345",
    "VUID-VkCopyDescriptorSet-srcBinding-00345",
);

const COPY_DST_BINDING: BindingRules = (
    "VUID-VkCopyDescriptorSet-dstBinding-00347",
    "VUID-VkCopyDescriptorSet-dstBinding-00347",
);

/// The rules a span of array elements breaks: (past the bindings, consecutive
/// bindings that differ in type or stages, an inline uniform block's misaligned
/// offset or size, consecutive bindings that differ in their use of immutable
/// samplers).
type SpanRules = (
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    &'static str,
);

const TEMPLATE_BINDING: BindingRules = (
    "VUID-VkDescriptorUpdateTemplateEntry-dstBinding-00354",
    "VUID-VkDescriptorUpdateTemplateEntry-dstBinding-00354",
);

const TEMPLATE_SPAN: SpanRules = (
    "VUID-VkDescriptorUpdateTemplateEntry-dstArrayElement-00355",
    "VUID-VkDescriptorUpdateTemplateEntry-dstArrayElement-00355",
    "VUID-VkDescriptorUpdateTemplateEntry-descriptor-02226",
    "VUID-VkDescriptorUpdateTemplateEntry-descriptor-02227",
    "VUID-VkDescriptorUpdateTemplateEntry-dstArrayElement-00355",
);

const WRITE_SPAN: SpanRules = (
    "VUID-VkWriteDescriptorSet-dstArrayElement-00321",
    "VUID-VkWriteDescriptorSet-descriptorCount-00317",
    "VUID-VkWriteDescriptorSet-descriptorType-02219",
    "VUID-VkWriteDescriptorSet-descriptorType-02220",
    "VUID-VkWriteDescriptorSet-descriptorCount-00318",
);

const COPY_SRC_SPAN: SpanRules = (
    "VUID-VkCopyDescriptorSet-srcArrayElement-00346",
    "VUID-VkCopyDescriptorSet-srcArrayElement-00346",
    "VUID-VkCopyDescriptorSet-srcBinding-02223",
    "VUID-VkCopyDescriptorSet-srcBinding-02225",
    "VUID-VkCopyDescriptorSet-srcArrayElement-00346",
);

const COPY_DST_SPAN: SpanRules = (
    "VUID-VkCopyDescriptorSet-dstArrayElement-00348",
    "VUID-VkCopyDescriptorSet-dstArrayElement-00348",
    "VUID-VkCopyDescriptorSet-dstBinding-02224",
    "VUID-VkCopyDescriptorSet-srcBinding-02225",
    "VUID-VkCopyDescriptorSet-dstArrayElement-00348",
);

/// The index in `layout` of the binding numbered `binding`, which must exist and hold
/// descriptors.
fn find_binding(
    layout: &SetLayoutRecord,
    binding: u32,
    at: &str,
    rules: BindingRules,
) -> Result<usize> {
    match layout
        .bindings
        .binary_search_by_key(&binding, |b| b.binding)
    {
        Ok(i) if layout.bindings[i].count > 0 => Ok(i),
        Ok(_) => Err(Error::Validation {
            vuid: rules.1,
            message: format!("{at}: binding {binding} of the set's layout has no descriptors"),
        }),
        Err(_) => Err(Error::Validation {
            vuid: rules.0,
            message: format!("{at}: the set's layout has no binding {binding}"),
        }),
    }
}

/// `count` elements from `element` of the binding at `first` fit in it and the
/// consecutive bindings after it, which must be alike (same type, stages and
/// immutable samplers; empty ones are skipped).
fn check_span(
    layout: &SetLayoutRecord,
    first: usize,
    element: u32,
    count: u32,
    at: &str,
    rules: SpanRules,
) -> Result<()> {
    let head = layout.bindings[first];
    if head.ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK {
        if element % 4 != 0 {
            refuse(rules.2, format!("{at}: the offset into an inline uniform block must be a multiple of 4 ({element})"))?;
        }
        if count % 4 != 0 {
            refuse(rules.3, format!("{at}: the size of an inline uniform block update must be a multiple of 4 ({count})"))?;
        }
    }
    let mut remaining = u64::from(element) + u64::from(count);
    for b in layout.bindings[first..].iter().filter(|b| b.count > 0) {
        if (b.ty, b.stages) != (head.ty, head.stages) {
            return refuse(
                rules.1,
                format!("{at}: the update runs on from binding {} into binding {}, which differs in type or stages", head.binding, b.binding),
            );
        }
        if b.immutable != head.immutable {
            return refuse(
                rules.4,
                format!("{at}: the update runs on from binding {} into binding {}, which differs in its use of immutable samplers", head.binding, b.binding),
            );
        }
        if remaining <= u64::from(b.count) {
            return Ok(());
        }
        remaining -= u64::from(b.count);
    }
    refuse(
        rules.0,
        format!("{at}: array element {element} plus descriptorCount {count} runs past binding {} and the consecutive bindings after it", head.binding),
    )
}

/// The sets remember what they now hold.
pub(crate) fn update_descriptor_sets_done(
    device: &Device,
    descriptor_writes: &[WriteDescriptorSet<'_>],
    descriptor_copies: &[CopyDescriptorSet<'_>],
) {
    let copies = raw_copies(descriptor_copies);
    let writes = raw_writes(descriptor_writes);
    let live = device.live();
    let written = written_sets(live, writes, copies);
    // SAFETY: the setters of the safe structs keep every array that is set as long as
    // its count, and `update_descriptor_sets_checks` refused a write whose type
    // selects an array that is not set.
    unsafe { live.write_sets(writes, copies) };
    // After the contents: a recorder that binds the set and reads the new
    // generation also reads the new image descriptors.
    for (set, _, invalidates) in written {
        if invalidates {
            live.set_invalidated(set);
        }
    }
}

/// The layouts a sampled image or combined image sampler descriptor may name (the
/// specification's list for both types).
const SAMPLED_LAYOUTS: &[vk::ImageLayout] = &[
    vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
    vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
    vk::ImageLayout::GENERAL,
    vk::ImageLayout::SHARED_PRESENT_KHR,
    vk::ImageLayout::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
    vk::ImageLayout::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
    vk::ImageLayout::DEPTH_READ_ONLY_OPTIMAL,
    vk::ImageLayout::STENCIL_READ_ONLY_OPTIMAL,
    vk::ImageLayout::READ_ONLY_OPTIMAL,
    vk::ImageLayout::ATTACHMENT_FEEDBACK_LOOP_OPTIMAL_EXT,
];

/// The layouts a storage image descriptor may name.
const STORAGE_LAYOUTS: &[vk::ImageLayout] = &[
    vk::ImageLayout::SHARED_PRESENT_KHR,
    vk::ImageLayout::GENERAL,
];

/// What one image descriptor type needs of its view: (usage bit and its rule, the
/// allowed layouts and their rule).
type ImageNeeds = (
    (vk::ImageUsageFlags, &'static str),
    (&'static [vk::ImageLayout], &'static str),
);

/// What an image descriptor of type `ty` needs of its view, if it has a view.
fn image_needs(ty: vk::DescriptorType) -> Option<ImageNeeds> {
    use vk::DescriptorType as T;
    Some(match ty {
        T::SAMPLED_IMAGE => (
            (
                vk::ImageUsageFlags::SAMPLED,
                "VUID-VkWriteDescriptorSet-descriptorType-00337",
            ),
            (
                SAMPLED_LAYOUTS,
                "VUID-VkWriteDescriptorSet-descriptorType-04149",
            ),
        ),
        T::COMBINED_IMAGE_SAMPLER => (
            (
                vk::ImageUsageFlags::SAMPLED,
                "VUID-VkWriteDescriptorSet-descriptorType-00337",
            ),
            (
                SAMPLED_LAYOUTS,
                "VUID-VkWriteDescriptorSet-descriptorType-04150",
            ),
        ),
        T::INPUT_ATTACHMENT => (
            (
                vk::ImageUsageFlags::INPUT_ATTACHMENT,
                "VUID-VkWriteDescriptorSet-descriptorType-00338",
            ),
            (
                SAMPLED_LAYOUTS,
                "VUID-VkWriteDescriptorSet-descriptorType-04151",
            ),
        ),
        T::STORAGE_IMAGE => (
            (
                vk::ImageUsageFlags::STORAGE,
                "VUID-VkWriteDescriptorSet-descriptorType-00339",
            ),
            (
                STORAGE_LAYOUTS,
                "VUID-VkWriteDescriptorSet-descriptorType-04152",
            ),
        ),
        _ => return None,
    })
}

/// Checks each descriptor of write `w` (the binding it starts at is `head`, whose
/// type and immutable samplers the bindings it runs on into share): its objects are
/// of this device, and fit the descriptor's type.
fn check_descriptors(
    device: &Device,
    live: &Live,
    head: &BindingRecord,
    w: &vk::WriteDescriptorSet<'_>,
    at: &str,
) -> Result<()> {
    use vk::DescriptorType as T;
    let count = w.descriptor_count;
    match w.descriptor_type {
        T::SAMPLER
        | T::COMBINED_IMAGE_SAMPLER
        | T::SAMPLED_IMAGE
        | T::STORAGE_IMAGE
        | T::INPUT_ATTACHMENT => {
            if w.descriptor_type == T::SAMPLER && head.immutable {
                refuse(
                    "VUID-VkWriteDescriptorSet-descriptorType-02752",
                    format!(
                        "{at}: a sampler is written into binding {}, whose samplers are immutable",
                        head.binding
                    ),
                )?;
            }
            let samples = matches!(w.descriptor_type, T::SAMPLER | T::COMBINED_IMAGE_SAMPLER)
                && !head.immutable;
            // SAFETY: `Live::check_writes` refused a write of this type whose
            // `pImageInfo` is not set, and the safe setter stores it with the count.
            let infos = unsafe { raw_slice(w.p_image_info, count) };
            for (j, info) in infos.iter().enumerate() {
                // A descriptor image info may leave out what a type does not read;
                // where it is read, a null one is refused before the lookups below.
                if samples && info.sampler == vk::Sampler::null() {
                    refuse(
                        "VUID-VkWriteDescriptorSet-descriptorType-00325",
                        format!("{at}.pImageInfo[{j}] has no sampler, and binding {} has no immutable samplers", head.binding),
                    )?;
                }
                if w.descriptor_type != T::SAMPLER && info.image_view == vk::ImageView::null() {
                    let vuid = if w.descriptor_type == T::INPUT_ATTACHMENT {
                        "VUID-VkWriteDescriptorSet-descriptorType-07683"
                    } else {
                        "VUID-VkWriteDescriptorSet-descriptorType-02997"
                    };
                    refuse(vuid, format!("{at}.pImageInfo[{j}] has no image view"))?;
                }
                if samples && live.get(info.sampler).is_none() {
                    refuse(
                        "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06238",
                        format!("{at}.pImageInfo[{j}].sampler was not created on this device"),
                    )?;
                }
                if w.descriptor_type != T::SAMPLER {
                    check_image_descriptor(
                        live,
                        w.descriptor_type,
                        info,
                        samples,
                        &format!("{at}.pImageInfo[{j}]"),
                    )?;
                }
            }
        }
        T::UNIFORM_BUFFER
        | T::UNIFORM_BUFFER_DYNAMIC
        | T::STORAGE_BUFFER
        | T::STORAGE_BUFFER_DYNAMIC => {
            // SAFETY: as for images, with `pBufferInfo`.
            let infos = unsafe { raw_slice(w.p_buffer_info, count) };
            for (j, info) in infos.iter().enumerate() {
                check_buffer_descriptor(
                    device,
                    live,
                    w.descriptor_type,
                    info,
                    &format!("{at}.pBufferInfo[{j}]"),
                )?;
            }
        }
        T::UNIFORM_TEXEL_BUFFER | T::STORAGE_TEXEL_BUFFER => {
            // SAFETY: as for images, with `pTexelBufferView`.
            let views = unsafe { raw_slice(w.p_texel_buffer_view, count) };
            let (usage, vuid) = if w.descriptor_type == T::UNIFORM_TEXEL_BUFFER {
                (
                    vk::BufferUsageFlags::UNIFORM_TEXEL_BUFFER,
                    "VUID-VkWriteDescriptorSet-descriptorType-00334",
                )
            } else {
                (
                    vk::BufferUsageFlags::STORAGE_TEXEL_BUFFER,
                    "VUID-VkWriteDescriptorSet-descriptorType-00335",
                )
            };
            for (j, view) in views.iter().enumerate() {
                if *view == vk::BufferView::null() {
                    refuse(
                        "VUID-VkWriteDescriptorSet-descriptorType-02995",
                        format!("{at}.pTexelBufferView[{j}] is null, and the nullDescriptor feature is not enabled"),
                    )?;
                }
                let Some(buffer) = live.buffer_view(*view) else {
                    return refuse(
                        "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06236",
                        format!("{at}.pTexelBufferView[{j}] was not created on this device"),
                    );
                };
                if !live.buffer(buffer).is_some_and(|b| b.usage.contains(usage)) {
                    refuse(
                        vuid,
                        format!(
                            "{at}.pTexelBufferView[{j}]'s buffer was not created with {usage:?}"
                        ),
                    )?;
                }
            }
        }
        T::INLINE_UNIFORM_BLOCK if count > 0 => {
            // SAFETY: the chain of a safe struct, and the type its sType names.
            let block: Option<&vk::WriteDescriptorSetInlineUniformBlock<'_>> = unsafe {
                chained(
                    w.p_next,
                    vk::StructureType::WRITE_DESCRIPTOR_SET_INLINE_UNIFORM_BLOCK,
                )
            };
            if block.map(|b| b.data_size) != Some(count) {
                refuse(
                    "VUID-VkWriteDescriptorSet-descriptorType-02221",
                    format!("{at}: an inline uniform block write chains no VkWriteDescriptorSetInlineUniformBlock whose dataSize is its descriptorCount ({count})"),
                )?;
            }
        }
        _ => {}
    }
    Ok(())
}

/// Checks an image descriptor's view: of this device, of a shape and aspects the
/// descriptor can use, with the usage and a layout its type allows.
fn check_image_descriptor(
    live: &Live,
    ty: vk::DescriptorType,
    info: &vk::DescriptorImageInfo,
    samples: bool,
    at: &str,
) -> Result<()> {
    use vk::DescriptorType as T;
    let Some(view) = live.view(info.image_view) else {
        return refuse(
            "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06239",
            format!("{at}.imageView was not created on this device"),
        );
    };
    let image = live.image(view.image);
    if image.is_some_and(|i| i.image_type == vk::ImageType::TYPE_3D) {
        match view.view_type {
            vk::ImageViewType::TYPE_2D => refuse(
                "VUID-VkDescriptorImageInfo-imageView-06711",
                format!("{at}.imageView is a 2D view of a 3D image"),
            )?,
            vk::ImageViewType::TYPE_2D_ARRAY => refuse(
                "VUID-VkDescriptorImageInfo-imageView-06712",
                format!("{at}.imageView is a 2D array view of a 3D image"),
            )?,
            _ => {}
        }
    }
    if ty == T::INPUT_ATTACHMENT && view.aspect.as_raw().count_ones() != 1 {
        refuse(
            "VUID-VkWriteDescriptorSet-descriptorType-07729",
            format!(
                "{at}.imageView of an input attachment must have exactly one aspect ({:?})",
                view.aspect
            ),
        )?;
    }
    let depth_stencil = vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL;
    let format = image.map_or(view.format, |i| i.format);
    let aspects = crate::formats::aspects(format).unwrap_or_default();
    if aspects.intersects(depth_stencil) && (view.aspect & depth_stencil).as_raw().count_ones() != 1
    {
        refuse(
            "VUID-VkDescriptorImageInfo-imageView-01976",
            format!("{at}.imageView of a depth/stencil image must have the depth or the stencil aspect, not both ({:?})", view.aspect),
        )?;
    }
    if ty == T::COMBINED_IMAGE_SAMPLER && samples && aspects.contains(vk::ImageAspectFlags::PLANE_0)
    {
        let planes = vk::ImageAspectFlags::PLANE_0
            | vk::ImageAspectFlags::PLANE_1
            | vk::ImageAspectFlags::PLANE_2;
        let mutable = image.is_some_and(|i| i.flags.contains(vk::ImageCreateFlags::MUTABLE_FORMAT));
        if !mutable
            || !(aspects & planes).contains(view.aspect)
            || view.aspect.as_raw().count_ones() != 1
        {
            refuse(
                "VUID-VkDescriptorImageInfo-sampler-01564",
                format!("{at}: a sampler reads a multi-planar image through a view of one plane of a MUTABLE_FORMAT image, not through {:?}", view.aspect),
            )?;
        }
    }
    if matches!(ty, T::STORAGE_IMAGE | T::INPUT_ATTACHMENT) && !view.identity {
        refuse(
            "VUID-VkWriteDescriptorSet-descriptorType-00336",
            format!("{at}.imageView of a {ty:?} descriptor must have the identity swizzle"),
        )?;
    }
    if let Some(((usage, usage_vuid), (layouts, layout_vuid))) = image_needs(ty) {
        if !view.usage.contains(usage) {
            refuse(
                usage_vuid,
                format!("{at}.imageView was not created with {usage:?} usage"),
            )?;
        }
        if !layouts.contains(&info.image_layout) {
            refuse(
                layout_vuid,
                format!(
                    "{at}.imageLayout {:?} is not a layout a {ty:?} descriptor can name",
                    info.image_layout
                ),
            )?;
        }
    }
    Ok(())
}

/// Checks a buffer descriptor: a bound buffer of this device with the usage its
/// type needs, an offset aligned to the limit, and a range within it.
fn check_buffer_descriptor(
    device: &Device,
    live: &Live,
    ty: vk::DescriptorType,
    info: &vk::DescriptorBufferInfo,
    at: &str,
) -> Result<()> {
    use vk::DescriptorType as T;
    if info.buffer == vk::Buffer::null() {
        return refuse(
            "VUID-VkDescriptorBufferInfo-buffer-02998",
            format!("{at}.buffer is null, and the nullDescriptor feature is not enabled"),
        );
    }
    let Some(buffer) = live.buffer(info.buffer) else {
        return refuse(
            "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06237",
            format!("{at}.buffer was not created on this device"),
        );
    };
    let limits = limits(device);
    let uniform = matches!(ty, T::UNIFORM_BUFFER | T::UNIFORM_BUFFER_DYNAMIC);
    let (usage, usage_vuid, align, align_vuid, max, max_vuid) = if uniform {
        (
            vk::BufferUsageFlags::UNIFORM_BUFFER,
            "VUID-VkWriteDescriptorSet-descriptorType-00330",
            limits.min_uniform_buffer_offset_alignment,
            "VUID-VkWriteDescriptorSet-descriptorType-00327",
            limits.max_uniform_buffer_range,
            "VUID-VkWriteDescriptorSet-descriptorType-00332",
        )
    } else {
        (
            vk::BufferUsageFlags::STORAGE_BUFFER,
            "VUID-VkWriteDescriptorSet-descriptorType-00331",
            limits.min_storage_buffer_offset_alignment,
            "VUID-VkWriteDescriptorSet-descriptorType-00328",
            limits.max_storage_buffer_range,
            "VUID-VkWriteDescriptorSet-descriptorType-00333",
        )
    };
    if info.offset % align.max(1) != 0 {
        refuse(
            align_vuid,
            format!("{at}.offset ({}) must be a multiple of the device's alignment for {ty:?} descriptors ({align})", info.offset),
        )?;
    }
    let sparse = buffer.flags.contains(vk::BufferCreateFlags::SPARSE_BINDING);
    if !sparse && !buffer.bound {
        refuse(
            "VUID-VkWriteDescriptorSet-descriptorType-00329",
            format!("{at}.buffer has no memory bound"),
        )?;
    }
    if !buffer.usage.contains(usage) {
        refuse(
            usage_vuid,
            format!("{at}.buffer was not created with {usage:?}"),
        )?;
    }
    let range = if info.range == vk::WHOLE_SIZE {
        buffer.size.saturating_sub(info.offset)
    } else {
        info.range
    };
    if range > u64::from(max) {
        refuse(
            max_vuid,
            format!("{at}: the range ({range} bytes) is above the device's limit for {ty:?} descriptors ({max})"),
        )?;
    }
    Ok(())
}

/// The checks of a copy beyond its spans: the two sets' update-after-bind
/// creation agrees, a sampler binding with immutable samplers is not copied into,
/// and a copy inside one set does not overlap itself.
fn check_copy(
    live: &Live,
    c: &vk::CopyDescriptorSet<'_>,
    (src, s): (&SetLayoutRecord, usize),
    (dst, d): (&SetLayoutRecord, usize),
    at: &str,
) -> Result<()> {
    if src.update_after_bind != dst.update_after_bind {
        let vuid = if src.update_after_bind {
            "VUID-VkCopyDescriptorSet-srcSet-01918"
        } else {
            "VUID-VkCopyDescriptorSet-srcSet-04886"
        };
        refuse(vuid, format!("{at}: one set's layout was created with UPDATE_AFTER_BIND_POOL and the other's without"))?;
    }
    let (src_pool, dst_pool) = (
        live.set_pool_is_update_after_bind(c.src_set),
        live.set_pool_is_update_after_bind(c.dst_set),
    );
    if src_pool != dst_pool {
        let vuid = if src_pool {
            "VUID-VkCopyDescriptorSet-srcSet-01920"
        } else {
            "VUID-VkCopyDescriptorSet-srcSet-04888"
        };
        refuse(
            vuid,
            format!(
                "{at}: one set's pool was created with UPDATE_AFTER_BIND and the other's without"
            ),
        )?;
    }
    let target = dst.bindings[d];
    if target.ty == vk::DescriptorType::SAMPLER && target.immutable {
        refuse(
            "VUID-VkCopyDescriptorSet-dstBinding-02753",
            format!(
                "{at}: binding {} of the destination holds immutable samplers",
                target.binding
            ),
        )?;
    }
    if c.src_set == c.dst_set {
        let from = flat(src, s, c.src_array_element);
        let to = flat(dst, d, c.dst_array_element);
        let n = u64::from(c.descriptor_count);
        if from < to + n && to < from + n {
            refuse(
                "VUID-VkCopyDescriptorSet-srcSet-00349",
                format!("{at}: the source and destination ranges of a copy inside one set overlap"),
            )?;
        }
    }
    Ok(())
}

/// The position of element `element` of the binding at `index` among every element
/// of the set, in binding order: where consecutive binding updates run.
pub(super) fn flat(layout: &SetLayoutRecord, index: usize, element: u32) -> u64 {
    layout.bindings[..index]
        .iter()
        .map(|b| u64::from(b.count))
        .sum::<u64>()
        + u64::from(element)
}

/// The bindings that `count` elements from `element` of the binding at `first`
/// reach, running on into the consecutive bindings (empty ones skipped).
fn touched(
    layout: &SetLayoutRecord,
    first: usize,
    element: u32,
    count: u32,
) -> impl Iterator<Item = &BindingRecord> {
    let mut remaining = u64::from(element) + u64::from(count).max(1);
    layout.bindings[first..]
        .iter()
        .filter(|b| b.count > 0)
        .take_while(move |b| {
            let reached = remaining > 0;
            remaining = remaining.saturating_sub(u64::from(b.count));
            reached
        })
}

/// Each set an update writes into, with whether it rewrites a binding that a
/// pending submission must not see rewritten (one created with neither
/// `UPDATE_AFTER_BIND` nor `UPDATE_UNUSED_WHILE_PENDING`) and whether it
/// invalidates the command buffers that bound the set (a binding without
/// `UPDATE_AFTER_BIND`, or of image descriptors). A set or binding tuff has no
/// record of counts as both.
fn written_sets(
    live: &Live,
    writes: &[vk::WriteDescriptorSet<'_>],
    copies: &[vk::CopyDescriptorSet<'_>],
) -> Vec<(vk::DescriptorSet, bool, bool)> {
    let targets = writes
        .iter()
        .map(|w| {
            (
                w.dst_set,
                w.dst_binding,
                w.dst_array_element,
                w.descriptor_count,
            )
        })
        .chain(copies.iter().map(|c| {
            (
                c.dst_set,
                c.dst_binding,
                c.dst_array_element,
                c.descriptor_count,
            )
        }));
    let after_bind = vk::DescriptorBindingFlags::UPDATE_AFTER_BIND;
    let while_pending = after_bind | vk::DescriptorBindingFlags::UPDATE_UNUSED_WHILE_PENDING;
    targets
        .map(|(set, binding, element, count)| {
            let Some(layout) = live.set_layout_of(set) else {
                return (set, true, true);
            };
            let Ok(first) = layout
                .bindings
                .binary_search_by_key(&binding, |b| b.binding)
            else {
                return (set, true, true);
            };
            let (mut guarded, mut invalidates) = (false, false);
            for b in touched(&layout, first, element, count) {
                // An image descriptor's layout is checked where a recording reads
                // it, which a pending submission did before the rewrite: rewriting
                // one under it is refused even where the binding allows updates
                // while pending.
                guarded |=
                    !b.flags.intersects(while_pending) || crate::state::names_image_layout(b.ty);
                // A recording follows the layouts of the image descriptors its sets
                // held when it bound them: rewriting one leaves it invalid even in a
                // binding updatable after bind.
                invalidates |=
                    !b.flags.contains(after_bind) || crate::state::names_image_layout(b.ty);
            }
            (set, guarded, invalidates)
        })
        .collect()
}

/// Takes the device's descriptor gate for an update (the host access to the sets
/// it writes is externally synchronized), and refuses to rewrite a binding of a set
/// that a submission which may still be executing bound, unless the binding allows
/// it: the descriptor may be read by that submission as it is rewritten.
pub(crate) fn update_descriptor_sets_hold<'d>(
    device: &'d Device,
    descriptor_writes: &[WriteDescriptorSet<'_>],
    descriptor_copies: &[CopyDescriptorSet<'_>],
) -> Result<tuff_runtime::VutexGuard<'d, ()>> {
    let live = device.live();
    let gate = live.descriptor_gate();
    let written = written_sets(
        live,
        raw_writes(descriptor_writes),
        raw_copies(descriptor_copies),
    );
    for (set, guarded, _) in written {
        if guarded && live.set_submissions(set).iter().any(|s| !s.poll(device)) {
            return Err(Error::Validation {
                vuid: "VUID-vkUpdateDescriptorSets-None-03047",
                message: format!("descriptor set 0x{:x} is bound by a command buffer of a submission that may still be executing, and the update rewrites a binding created without UPDATE_AFTER_BIND or UPDATE_UNUSED_WHILE_PENDING: wait for the submission's fence first", set.as_raw()),
            });
        }
    }
    Ok(gate)
}
