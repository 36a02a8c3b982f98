//! Pipeline layouts: their creation, against the device's per-stage and total
//! descriptor limits and push constant ranges.

use super::{refuse, vulkan12_properties, vulkan13_properties};
use crate::handles::*;
use crate::state::{LayoutRecord, SetLayoutRecord};
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;
use tuff_runtime::Vrc;

/// The device remembers the layout's push-constant ranges and its sets' dynamic
/// descriptors.
pub(crate) fn pipeline_layout_created(
    device: &Device,
    layout: PipelineLayout,
    create_info: &PipelineLayoutCreateInfo<'_>,
) -> PipelineLayout {
    let raw = create_info.as_raw();
    // SAFETY: the safe setters stored both arrays with their counts.
    let (ranges, sets) = unsafe {
        (
            crate::state::raw_slice(raw.p_push_constant_ranges, raw.push_constant_range_count),
            crate::state::raw_slice(raw.p_set_layouts, raw.set_layout_count),
        )
    };
    let sets: Vec<Vrc<SetLayoutRecord>> = sets
        .iter()
        .map(|s| device.live().set_layout(*s).unwrap_or_default())
        .collect();
    let set_dynamics = sets.iter().map(|l| l.dynamics()).collect();
    device.live().pipeline_layout_created(
        layout.raw(),
        LayoutRecord {
            push_ranges: ranges.to_vec(),
            set_dynamics,
            sets,
        },
    );
    layout
}

/// The descriptor types a limit on a pipeline layout's descriptors counts together.
const SAMPLERS: &[vk::DescriptorType] = &[
    vk::DescriptorType::SAMPLER,
    vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
];

const UNIFORM_BUFFERS: &[vk::DescriptorType] = &[
    vk::DescriptorType::UNIFORM_BUFFER,
    vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
];

const STORAGE_BUFFERS: &[vk::DescriptorType] = &[
    vk::DescriptorType::STORAGE_BUFFER,
    vk::DescriptorType::STORAGE_BUFFER_DYNAMIC,
];

const SAMPLED_IMAGES: &[vk::DescriptorType] = &[
    vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
    vk::DescriptorType::SAMPLED_IMAGE,
    vk::DescriptorType::UNIFORM_TEXEL_BUFFER,
];

const STORAGE_IMAGES: &[vk::DescriptorType] = &[
    vk::DescriptorType::STORAGE_IMAGE,
    vk::DescriptorType::STORAGE_TEXEL_BUFFER,
];

const INPUT_ATTACHMENTS: &[vk::DescriptorType] = &[vk::DescriptorType::INPUT_ATTACHMENT];

/// One limit on a pipeline layout's descriptors: the types it counts, whether per
/// stage (or across all stages), whether it counts only layouts created without
/// update-after-bind, its value and its rule.
type DescriptorLimit = (&'static [vk::DescriptorType], bool, bool, u32, &'static str);

/// The descriptor limits of `VkPipelineLayoutCreateInfo`, in the order they are
/// checked: across all stages first (without, then with update-after-bind), then
/// per stage, so that a layout past a set-wide limit is named by it.
fn descriptor_limits(
    l: &vk::PhysicalDeviceLimits,
    uab: Option<&vk::PhysicalDeviceVulkan12Properties<'_>>,
) -> Vec<DescriptorLimit> {
    let mut out: Vec<DescriptorLimit> = vec![
        (
            SAMPLERS,
            false,
            true,
            l.max_descriptor_set_samplers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03028",
        ),
        (
            &[vk::DescriptorType::UNIFORM_BUFFER],
            false,
            true,
            l.max_descriptor_set_uniform_buffers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03029",
        ),
        (
            &[vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC],
            false,
            true,
            l.max_descriptor_set_uniform_buffers_dynamic,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03030",
        ),
        (
            &[vk::DescriptorType::STORAGE_BUFFER],
            false,
            true,
            l.max_descriptor_set_storage_buffers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03031",
        ),
        (
            &[vk::DescriptorType::STORAGE_BUFFER_DYNAMIC],
            false,
            true,
            l.max_descriptor_set_storage_buffers_dynamic,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03032",
        ),
        (
            SAMPLED_IMAGES,
            false,
            true,
            l.max_descriptor_set_sampled_images,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03033",
        ),
        (
            STORAGE_IMAGES,
            false,
            true,
            l.max_descriptor_set_storage_images,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03034",
        ),
        (
            INPUT_ATTACHMENTS,
            false,
            true,
            l.max_descriptor_set_input_attachments,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03035",
        ),
    ];
    if let Some(p) = uab {
        out.extend([
            (
                SAMPLERS,
                false,
                false,
                p.max_descriptor_set_update_after_bind_samplers,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03036",
            ),
            (
                &[vk::DescriptorType::UNIFORM_BUFFER][..],
                false,
                false,
                p.max_descriptor_set_update_after_bind_uniform_buffers,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03037",
            ),
            (
                &[vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC][..],
                false,
                false,
                p.max_descriptor_set_update_after_bind_uniform_buffers_dynamic,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03038",
            ),
            (
                &[vk::DescriptorType::STORAGE_BUFFER][..],
                false,
                false,
                p.max_descriptor_set_update_after_bind_storage_buffers,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03039",
            ),
            (
                &[vk::DescriptorType::STORAGE_BUFFER_DYNAMIC][..],
                false,
                false,
                p.max_descriptor_set_update_after_bind_storage_buffers_dynamic,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03040",
            ),
            (
                SAMPLED_IMAGES,
                false,
                false,
                p.max_descriptor_set_update_after_bind_sampled_images,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03041",
            ),
            (
                STORAGE_IMAGES,
                false,
                false,
                p.max_descriptor_set_update_after_bind_storage_images,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03042",
            ),
            (
                INPUT_ATTACHMENTS,
                false,
                false,
                p.max_descriptor_set_update_after_bind_input_attachments,
                "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03043",
            ),
        ]);
    }
    out.extend([
        (
            SAMPLERS,
            true,
            true,
            l.max_per_stage_descriptor_samplers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03016",
        ),
        (
            UNIFORM_BUFFERS,
            true,
            true,
            l.max_per_stage_descriptor_uniform_buffers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03017",
        ),
        (
            STORAGE_BUFFERS,
            true,
            true,
            l.max_per_stage_descriptor_storage_buffers,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03018",
        ),
        (
            SAMPLED_IMAGES,
            true,
            true,
            l.max_per_stage_descriptor_sampled_images,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03019",
        ),
        (
            STORAGE_IMAGES,
            true,
            true,
            l.max_per_stage_descriptor_storage_images,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03020",
        ),
        (
            INPUT_ATTACHMENTS,
            true,
            true,
            l.max_per_stage_descriptor_input_attachments,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-03021",
        ),
    ]);
    if let Some(p) = uab {
        out.extend([
            (
                SAMPLERS,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_samplers,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03022",
            ),
            (
                UNIFORM_BUFFERS,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_uniform_buffers,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03023",
            ),
            (
                STORAGE_BUFFERS,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_storage_buffers,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03024",
            ),
            (
                SAMPLED_IMAGES,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_sampled_images,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03025",
            ),
            (
                STORAGE_IMAGES,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_storage_images,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03026",
            ),
            (
                INPUT_ATTACHMENTS,
                true,
                false,
                p.max_per_stage_descriptor_update_after_bind_input_attachments,
                "VUID-VkPipelineLayoutCreateInfo-descriptorType-03027",
            ),
        ]);
    }
    out
}

/// Refuses a pipeline layout past the device's limits: more set layouts than
/// `maxBoundDescriptorSets` (00286), two push-constant ranges for one stage (00292),
/// or more descriptors of a kind, in one stage or across all of them, than the
/// limit on that kind (03016 to 03043).
pub(crate) fn create_pipeline_layout_checks(
    device: &Device,
    create_info: &PipelineLayoutCreateInfo<'_>,
) -> Result<()> {
    let raw = create_info.as_raw();
    let limits = *device
        .live()
        .limits(|| device.parent().get_properties().limits);
    if raw.set_layout_count > limits.max_bound_descriptor_sets {
        refuse(
            "VUID-VkPipelineLayoutCreateInfo-setLayoutCount-00286",
            format!(
                "setLayoutCount must be at most maxBoundDescriptorSets ({}) (setLayoutCount = {})",
                limits.max_bound_descriptor_sets, raw.set_layout_count
            ),
        )?;
    }
    // SAFETY: the safe setters stored both arrays with their counts.
    let (ranges, sets) = unsafe {
        (
            crate::state::raw_slice(raw.p_push_constant_ranges, raw.push_constant_range_count),
            crate::state::raw_slice(raw.p_set_layouts, raw.set_layout_count),
        )
    };
    for (i, r) in ranges.iter().enumerate() {
        if ranges[..i]
            .iter()
            .any(|o| o.stage_flags.intersects(r.stage_flags))
        {
            refuse(
                "VUID-VkPipelineLayoutCreateInfo-pPushConstantRanges-00292",
                format!(
                    "pPushConstantRanges[{i}] names a stage an earlier range names ({:?})",
                    r.stage_flags
                ),
            )?;
        }
    }
    let records: Vec<Vrc<SetLayoutRecord>> = sets
        .iter()
        .filter_map(|s| device.live().set_layout(*s))
        .collect();
    let uab = vulkan12_properties(device);
    // Every stage bit a binding can name, one at a time.
    let stages = (0..32)
        .map(|b| vk::ShaderStageFlags::from_raw(1 << b))
        .filter(|s| {
            records
                .iter()
                .any(|r| r.bindings.iter().any(|b| b.stages.contains(*s)))
        });
    let stages: Vec<vk::ShaderStageFlags> = stages.collect();
    for (types, per_stage, plain_only, limit, vuid) in descriptor_limits(&limits, uab.as_ref()) {
        let count = |stage: Option<vk::ShaderStageFlags>| -> u64 {
            records
                .iter()
                .filter(|r| !(plain_only && r.update_after_bind))
                .flat_map(|r| r.bindings.iter())
                .filter(|b| types.contains(&b.ty) && stage.is_none_or(|s| b.stages.contains(s)))
                .map(|b| u64::from(b.count))
                .sum()
        };
        let worst = if per_stage {
            stages
                .iter()
                .map(|s| (count(Some(*s)), Some(*s)))
                .max_by_key(|(c, _)| *c)
        } else {
            Some((count(None), None))
        };
        if let Some((total, stage)) = worst.filter(|(c, _)| *c > u64::from(limit)) {
            let where_ = stage.map_or("across all stages".to_owned(), |s| {
                format!("in stage {s:?}")
            });
            refuse(
                vuid,
                format!("the layout has {total} descriptors of types {types:?} {where_}, past the limit of {limit}"),
            )?;
        }
    }
    // Inline uniform blocks count by binding (their descriptor count is in bytes),
    // against the Vulkan 1.3 limits.
    let Some(p13) = vulkan13_properties(device) else {
        return Ok(());
    };
    let blocks = |stage: Option<vk::ShaderStageFlags>, plain_only: bool| -> u64 {
        records
            .iter()
            .filter(|r| !(plain_only && r.update_after_bind))
            .flat_map(|r| r.bindings.iter())
            .filter(|b| {
                b.ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK
                    && stage.is_none_or(|s| b.stages.contains(s))
            })
            .count() as u64
    };
    let block_limits = [
        (
            true,
            true,
            p13.max_per_stage_descriptor_inline_uniform_blocks,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02214",
        ),
        (
            true,
            false,
            p13.max_per_stage_descriptor_update_after_bind_inline_uniform_blocks,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02215",
        ),
        (
            false,
            true,
            p13.max_descriptor_set_inline_uniform_blocks,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02216",
        ),
        (
            false,
            false,
            p13.max_descriptor_set_update_after_bind_inline_uniform_blocks,
            "VUID-VkPipelineLayoutCreateInfo-descriptorType-02217",
        ),
    ];
    for (per_stage, plain_only, limit, vuid) in block_limits {
        let worst = if per_stage {
            stages.iter().map(|s| blocks(Some(*s), plain_only)).max()
        } else {
            Some(blocks(None, plain_only))
        };
        if let Some(total) = worst.filter(|&c| c > u64::from(limit)) {
            refuse(
                vuid,
                format!("the layout has {total} inline uniform block bindings, past the limit of {limit}"),
            )?;
        }
    }
    Ok(())
}
