//! Descriptor set layouts: their creation checks (binding flags, immutable samplers,
//! limits) and the record the device keeps of each.

use super::{chained, refuse, vulkan13_properties};
use crate::handles::*;
use crate::state::{BindingRecord, SetLayoutRecord};
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;

/// The device remembers the layout's bindings.
pub(crate) fn descriptor_set_layout_created(
    device: &Device,
    layout: DescriptorSetLayout,
    create_info: &DescriptorSetLayoutCreateInfo<'_>,
) -> DescriptorSetLayout {
    let raw = create_info.as_raw();
    // SAFETY: the safe setter stored the bindings with their count.
    let bindings = unsafe { crate::state::raw_slice(raw.p_bindings, raw.binding_count) };
    // SAFETY: `raw` is a safe struct's.
    let flags: Option<&vk::DescriptorSetLayoutBindingFlagsCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO,
        )
    };
    // SAFETY: the safe setter stored the flags with their count (its checks made that
    // count 0 or the bindings').
    let flags = flags.map_or(&[][..], |f| unsafe {
        crate::state::raw_slice(f.p_binding_flags, f.binding_count)
    });
    let variable = bindings
        .iter()
        .zip(flags)
        .find(|(_, f)| f.contains(vk::DescriptorBindingFlags::VARIABLE_DESCRIPTOR_COUNT))
        .map(|(b, _)| b.binding);
    let mut ordered: Vec<(BindingRecord, &[vk::Sampler])> = bindings
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let samplers = if b.p_immutable_samplers.is_null() {
                &[][..]
            } else {
                // SAFETY: the safe setter stores the samplers with the binding's
                // count.
                unsafe { crate::state::raw_slice(b.p_immutable_samplers, b.descriptor_count) }
            };
            let record = BindingRecord {
                binding: b.binding,
                ty: b.descriptor_type,
                count: b.descriptor_count,
                stages: b.stage_flags,
                immutable: !b.p_immutable_samplers.is_null(),
                immutable_bits: samplers
                    .iter()
                    .map(|s| device.live().sampler_bits(*s).unwrap_or(0))
                    .fold(0, |a, b| a | b),
                flags: flags.get(i).copied().unwrap_or_default(),
            };
            (record, samplers)
        })
        .collect();
    ordered.sort_by_key(|(b, _)| b.binding);
    let immutable_samplers = ordered
        .iter()
        .flat_map(|(_, s)| s.iter().copied())
        .collect();
    let bindings: Vec<BindingRecord> = ordered.into_iter().map(|(b, _)| b).collect();
    device.live().set_layout_created(
        layout.raw(),
        SetLayoutRecord {
            bindings,
            update_after_bind: raw
                .flags
                .contains(vk::DescriptorSetLayoutCreateFlags::UPDATE_AFTER_BIND_POOL),
            variable,
            flags: raw.flags,
            immutable_samplers,
        },
    );
    layout
}

/// Which descriptor types the update-after-bind feature of each
/// `descriptorBinding*UpdateAfterBind` covers, with the rule of its absence.
pub(super) const UPDATE_AFTER_BIND: [(&[vk::DescriptorType], &str, &str); 6] = [
    (
        &[vk::DescriptorType::UNIFORM_BUFFER],
        "descriptorBindingUniformBufferUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformBufferUpdateAfterBind-03005",
    ),
    (
        &[
            vk::DescriptorType::SAMPLER,
            vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
            vk::DescriptorType::SAMPLED_IMAGE,
        ],
        "descriptorBindingSampledImageUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingSampledImageUpdateAfterBind-03006",
    ),
    (
        &[vk::DescriptorType::STORAGE_IMAGE],
        "descriptorBindingStorageImageUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageImageUpdateAfterBind-03007",
    ),
    (
        &[vk::DescriptorType::STORAGE_BUFFER],
        "descriptorBindingStorageBufferUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageBufferUpdateAfterBind-03008",
    ),
    (
        &[vk::DescriptorType::UNIFORM_TEXEL_BUFFER],
        "descriptorBindingUniformTexelBufferUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformTexelBufferUpdateAfterBind-03009",
    ),
    (
        &[vk::DescriptorType::STORAGE_TEXEL_BUFFER],
        "descriptorBindingStorageTexelBufferUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageTexelBufferUpdateAfterBind-03010",
    ),
];

/// The checks of `vkCreateDescriptorSetLayout` over its bindings as a set and a
/// chained `VkDescriptorSetLayoutBindingFlagsCreateInfo` against the device's
/// descriptor-indexing features.
pub(crate) fn descriptor_set_layout_checks(
    device: &Device,
    create_info: &DescriptorSetLayoutCreateInfo<'_>,
) -> Result<()> {
    let info = create_info.as_raw();
    // SAFETY: the safe setter stores the bindings with their count.
    let bindings = unsafe { crate::state::raw_slice(info.p_bindings, info.binding_count) };
    // The stages of the emitted API: the graphics stages and compute.
    let stages = vk::ShaderStageFlags::ALL_GRAPHICS | vk::ShaderStageFlags::COMPUTE;
    for (i, b) in bindings.iter().enumerate() {
        if b.descriptor_count != 0
            && b.stage_flags != vk::ShaderStageFlags::ALL
            && !stages.contains(b.stage_flags)
        {
            refuse(
                "VUID-VkDescriptorSetLayoutBinding-descriptorCount-00283",
                format!("pBindings[{i}].stageFlags ({:?}) names stages no emitted version or extension has", b.stage_flags),
            )?;
        }
        if bindings[..i].iter().any(|o| o.binding == b.binding) {
            refuse(
                "VUID-VkDescriptorSetLayoutCreateInfo-binding-00279",
                format!(
                    "pBindings[{i}] is binding {}, as an earlier element is",
                    b.binding
                ),
            )?;
        }
        if b.descriptor_type == vk::DescriptorType::INPUT_ATTACHMENT
            && b.descriptor_count != 0
            && !(vk::ShaderStageFlags::FRAGMENT).contains(b.stage_flags)
        {
            refuse(
                "VUID-VkDescriptorSetLayoutBinding-descriptorType-01510",
                format!("pBindings[{i}] is an input attachment for stages {:?}: only the fragment stage reads one", b.stage_flags),
            )?;
        }
        if b.descriptor_type == vk::DescriptorType::INLINE_UNIFORM_BLOCK {
            let max = vulkan13_properties(device).map(|p| p.max_inline_uniform_block_size);
            if let Some(max) = max.filter(|&max| b.descriptor_count > max) {
                refuse(
                    "VUID-VkDescriptorSetLayoutBinding-descriptorType-02210",
                    format!("pBindings[{i}] is an inline uniform block of {} bytes, more than maxInlineUniformBlockSize ({max})", b.descriptor_count),
                )?;
            }
        }
    }
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let binding_flags: Option<&vk::DescriptorSetLayoutBindingFlagsCreateInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO,
        )
    };
    let Some(binding_flags) = binding_flags else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the flags with their count.
    let all_flags = unsafe {
        crate::state::raw_slice(binding_flags.p_binding_flags, binding_flags.binding_count)
    };
    let dynamic = [
        vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
        vk::DescriptorType::STORAGE_BUFFER_DYNAMIC,
    ];
    let after_bind = all_flags
        .iter()
        .any(|f| f.contains(vk::DescriptorBindingFlags::UPDATE_AFTER_BIND));
    if after_bind
        && !info
            .flags
            .contains(vk::DescriptorSetLayoutCreateFlags::UPDATE_AFTER_BIND_POOL)
    {
        refuse(
            "VUID-VkDescriptorSetLayoutCreateInfo-flags-03000",
            "a binding is updated after bind, so the layout's flags must include UPDATE_AFTER_BIND_POOL",
        )?;
    }
    if after_bind
        && bindings
            .iter()
            .any(|b| dynamic.contains(&b.descriptor_type))
    {
        refuse(
            "VUID-VkDescriptorSetLayoutCreateInfo-descriptorType-03001",
            "a binding is updated after bind, so no binding may be a dynamic buffer",
        )?;
    }
    let highest = bindings.iter().map(|b| b.binding).max();
    for (i, (f, b)) in all_flags.iter().zip(bindings).enumerate() {
        if !f.contains(vk::DescriptorBindingFlags::VARIABLE_DESCRIPTOR_COUNT) {
            continue;
        }
        if bindings.iter().any(|o| o.binding > b.binding) || Some(b.binding) != highest {
            refuse(
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-pBindingFlags-03004",
                format!("pBindingFlags[{i}] makes binding {} variable-sized, which only the highest binding may be", b.binding),
            )?;
        }
        if dynamic.contains(&b.descriptor_type) {
            refuse(
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-pBindingFlags-03015",
                format!("pBindingFlags[{i}] makes a dynamic buffer binding variable-sized"),
            )?;
        }
    }
    if binding_flags.binding_count != 0 && binding_flags.binding_count != info.binding_count {
        return refuse(
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-bindingCount-03002",
            format!(
                "the chained binding flags are for {} bindings; the layout has {}",
                binding_flags.binding_count, info.binding_count
            ),
        );
    }
    // SAFETY: the safe setter stores the flags with their count.
    let flags = unsafe {
        crate::state::raw_slice(binding_flags.p_binding_flags, binding_flags.binding_count)
    };
    let (v12, v13) = device.live().with_features(|f| (f.v12, f.v13));
    let on = |b: vk::Bool32| b == vk::TRUE;
    let update_after_bind_features = [
        on(v12.descriptor_binding_uniform_buffer_update_after_bind),
        on(v12.descriptor_binding_sampled_image_update_after_bind),
        on(v12.descriptor_binding_storage_image_update_after_bind),
        on(v12.descriptor_binding_storage_buffer_update_after_bind),
        on(v12.descriptor_binding_uniform_texel_buffer_update_after_bind),
        on(v12.descriptor_binding_storage_texel_buffer_update_after_bind),
    ];
    for (i, (f, b)) in flags.iter().zip(bindings).enumerate() {
        let at = format!("pBindingFlags[{i}]");
        let ty = b.descriptor_type;
        if f.contains(vk::DescriptorBindingFlags::UPDATE_AFTER_BIND) {
            for ((types, feature, vuid), enabled) in
                UPDATE_AFTER_BIND.iter().zip(update_after_bind_features)
            {
                if types.contains(&ty) && !enabled {
                    refuse(
                        vuid,
                        format!("{at} updates a {ty:?} binding after bind, but the device does not enable {feature}"),
                    )?;
                }
            }
            if ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK
                && !on(v13.descriptor_binding_inline_uniform_block_update_after_bind)
            {
                refuse(
                    "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingInlineUniformBlockUpdateAfterBind-02211",
                    format!("{at} updates an inline uniform block after bind, but the device does not enable descriptorBindingInlineUniformBlockUpdateAfterBind"),
                )?;
            }
            let never = [
                vk::DescriptorType::INPUT_ATTACHMENT,
                vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
                vk::DescriptorType::STORAGE_BUFFER_DYNAMIC,
            ];
            if never.contains(&ty) {
                refuse(
                    "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-None-03011",
                    format!("{at} updates a {ty:?} binding after bind, which no device allows"),
                )?;
            }
        }
        for (flag, enabled, feature, vuid) in [
            (
                vk::DescriptorBindingFlags::UPDATE_UNUSED_WHILE_PENDING,
                v12.descriptor_binding_update_unused_while_pending,
                "descriptorBindingUpdateUnusedWhilePending",
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUpdateUnusedWhilePending-03012",
            ),
            (
                vk::DescriptorBindingFlags::PARTIALLY_BOUND,
                v12.descriptor_binding_partially_bound,
                "descriptorBindingPartiallyBound",
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingPartiallyBound-03013",
            ),
            (
                vk::DescriptorBindingFlags::VARIABLE_DESCRIPTOR_COUNT,
                v12.descriptor_binding_variable_descriptor_count,
                "descriptorBindingVariableDescriptorCount",
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingVariableDescriptorCount-03014",
            ),
        ] {
            if f.contains(flag) && !on(enabled) {
                refuse(vuid, format!("{at} has {flag:?}, but the device does not enable {feature}"))?;
            }
        }
    }
    Ok(())
}
