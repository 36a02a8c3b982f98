//! Shader modules and the stages of a pipeline: entry points, specialization data,
//! subgroup sizes, built-ins and the layout the module's resources need.

use super::{ask_properties2, chained, limits, refuse, vulkan13_properties};
use crate::handles::*;
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;
use tuff_runtime::Vrc;

/// A shader stage's specialization map entries lie inside its data, which drivers read
/// each constant from.
pub(super) fn check_specialization_data(
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    // SAFETY: the safe struct's setter stores a reference that outlives the create info.
    let Some(info) = (unsafe { stage.p_specialization_info.as_ref() }) else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the entries with their count.
    let entries = unsafe { crate::state::raw_slice(info.p_map_entries, info.map_entry_count) };
    let size = info.data_size as u64;
    for (i, e) in entries.iter().enumerate() {
        let offset = u64::from(e.offset);
        if offset >= size {
            refuse(
                "VUID-VkSpecializationInfo-offset-00773",
                format!("{at}: pMapEntries[{i}].offset must be less than dataSize (offset = {offset}, dataSize = {size})"),
            )?;
        }
        if e.size as u64 > size - offset {
            refuse(
                "VUID-VkSpecializationInfo-pMapEntries-00774",
                format!("{at}: pMapEntries[{i}].size must be at most dataSize minus offset (size = {}, offset = {offset}, dataSize = {size})", e.size),
            )?;
        }
    }
    Ok(())
}

/// A shader stage's subgroup size control: its flags need the features they name
/// (02784, 02785), and a chained `VkPipelineShaderStageRequiredSubgroupSizeCreateInfo`
/// names a power of two within the device's subgroup sizes (02760 to 02762), without
/// a varying size (02754), with `subgroupSizeControl` on and for a stage in
/// `requiredSubgroupSizeStages` (02755).
pub(super) fn check_stage_subgroups(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    type F = vk::PipelineShaderStageCreateFlags;
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let required: Option<&vk::PipelineShaderStageRequiredSubgroupSizeCreateInfo<'_>> = unsafe {
        chained(
            stage.p_next,
            vk::StructureType::PIPELINE_SHADER_STAGE_REQUIRED_SUBGROUP_SIZE_CREATE_INFO,
        )
    };
    let varying = stage.flags.contains(F::ALLOW_VARYING_SUBGROUP_SIZE);
    let full = stage.flags.contains(F::REQUIRE_FULL_SUBGROUPS);
    if !varying && !full && required.is_none() {
        return Ok(());
    }
    let (control, full_subgroups) = device
        .live()
        .with_features(|f| (f.v13.subgroup_size_control, f.v13.compute_full_subgroups));
    if varying && control != vk::TRUE {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-flags-02784",
            format!("{at}: flags include ALLOW_VARYING_SUBGROUP_SIZE, and the device has not enabled subgroupSizeControl"),
        )?;
    }
    if full && full_subgroups != vk::TRUE {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-flags-02785",
            format!("{at}: flags include REQUIRE_FULL_SUBGROUPS, and the device has not enabled computeFullSubgroups"),
        )?;
    }
    check_workgroup_subgroups(
        device,
        stage,
        required.map(|r| r.required_subgroup_size),
        at,
    )?;
    let Some(required) = required else {
        return Ok(());
    };
    let size = required.required_subgroup_size;
    if !size.is_power_of_two() {
        refuse(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02760",
            format!("{at}: requiredSubgroupSize ({size}) is not a power of two"),
        )?;
    }
    let properties = vulkan13_properties(device);
    let (min, max) = properties.map_or((0, 0), |p| (p.min_subgroup_size, p.max_subgroup_size));
    if size < min {
        refuse(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02761",
            format!("{at}: requiredSubgroupSize ({size}) is below minSubgroupSize ({min})"),
        )?;
    }
    if size > max {
        refuse(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02762",
            format!("{at}: requiredSubgroupSize ({size}) is above maxSubgroupSize ({max}; 0 where the device has no Vulkan 1.3 properties)"),
        )?;
    }
    if varying {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-pNext-02754",
            format!("{at}: a required subgroup size is chained, and flags include ALLOW_VARYING_SUBGROUP_SIZE"),
        )?;
    }
    let stages = properties.map_or(vk::ShaderStageFlags::empty(), |p| {
        p.required_subgroup_size_stages
    });
    if control != vk::TRUE || !stages.contains(stage.stage) {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-pNext-02755",
            format!("{at}: a required subgroup size is chained, and the device has not enabled subgroupSizeControl or {:?} is not among its requiredSubgroupSizeStages ({stages:?})", stage.stage),
        )?;
    }
    Ok(())
}

/// A stage's workgroup against the subgroups its flags and a chained required size
/// ask for, from the `LocalSize` execution mode of the entry point it names: no more
/// invocations than `maxComputeWorkgroupSubgroups` subgroups of the required size
/// (02756); with full subgroups, a width that is a multiple of the required size
/// (02757), of `maxSubgroupSize` with a varying size (02758), or else of the
/// device's `subgroupSize` (02759). A workgroup size the module gives otherwise
/// (`LocalSizeId`, the `WorkgroupSize` built-in) is not read: where one of these
/// rules applies, the stage is refused.
fn check_workgroup_subgroups(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    required: Option<u32>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    type F = vk::PipelineShaderStageCreateFlags;
    const LOCAL_SIZE: u32 = 17;
    let full = stage.flags.contains(F::REQUIRE_FULL_SUBGROUPS);
    let varying = stage.flags.contains(F::ALLOW_VARYING_SUBGROUP_SIZE);
    let compute_required = required.filter(|_| stage.stage == vk::ShaderStageFlags::COMPUTE);
    if !full && compute_required.is_none() {
        return Ok(());
    }
    let size: Option<[u32; 3]> =
        stage_entry_point(device, stage).and_then(|e| match e.mode(LOCAL_SIZE)? {
            [x, y, z, ..] => Some([*x, *y, *z]),
            _ => None,
        });
    let p13 = vulkan13_properties(device);
    if let Some(required) = compute_required {
        let max = p13.map_or(0, |p| p.max_compute_workgroup_subgroups);
        let invocations = size.map(|[x, y, z]| u64::from(x) * u64::from(y) * u64::from(z));
        if invocations.is_none_or(|n| n > u64::from(max) * u64::from(required)) {
            refuse(
                "VUID-VkPipelineShaderStageCreateInfo-pNext-02756",
                format!("{at}: the workgroup's invocations ({invocations:?}, None where the module does not give them as LocalSize) are more than maxComputeWorkgroupSubgroups ({max}) subgroups of the required size ({required})"),
            )?;
        }
    }
    if !full {
        return Ok(());
    }
    let (multiple, vuid, of) = match (required, varying) {
        (Some(r), _) => (
            r,
            "VUID-VkPipelineShaderStageCreateInfo-pNext-02757",
            "the required subgroup size",
        ),
        (None, true) => (
            p13.map_or(0, |p| p.max_subgroup_size),
            "VUID-VkPipelineShaderStageCreateInfo-flags-02758",
            "maxSubgroupSize",
        ),
        (None, false) => (
            subgroup_size(device),
            "VUID-VkPipelineShaderStageCreateInfo-flags-02759",
            "the device's subgroupSize",
        ),
    };
    let width = size.map(|[x, _, _]| x);
    if !width.is_some_and(|x| multiple != 0 && x % multiple == 0) {
        refuse(
            vuid,
            format!("{at}: with full subgroups, the workgroup's width ({width:?}, None where the module does not give it as LocalSize) must be a multiple of {of} ({multiple})"),
        )?;
    }
    Ok(())
}

/// The device's default `subgroupSize` (Vulkan 1.1), or 0 where it cannot be asked.
fn subgroup_size(device: &Device) -> u32 {
    let version = device.parent().get_properties().api_version;
    let mut subgroup = vk::PhysicalDeviceSubgroupProperties::default();
    if vk::api_version_minor(version) < 1 || !ask_properties2(device, &mut subgroup) {
        return 0;
    }
    subgroup.subgroup_size
}

/// The built-in variables of the entry point a stage names: clip and cull distance
/// arrays within `maxClipDistances` (00708), `maxCullDistances` (00709) and together
/// `maxCombinedClipAndCullDistances` (00710, per storage class), a sample mask within
/// `maxSampleMaskWords` (00711), no cull distance read by a vertex stage (00712) or
/// written by a fragment stage (00718).
pub(super) fn check_stage_builtins(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    const CLIP: u32 = 3;
    const CULL: u32 = 4;
    const SAMPLE_MASK: u32 = 20;
    const INPUT: u32 = 1;
    const OUTPUT: u32 = 3;
    let Some(entry) = stage_entry_point(device, stage) else {
        return Ok(());
    };
    if entry.builtins.is_empty() {
        return Ok(());
    }
    let limits = limits(device);
    let of = |builtin: u32, storage: Option<u32>| {
        entry
            .builtins
            .iter()
            .filter(move |(b, s, _)| *b == builtin && storage.is_none_or(|w| w == *s))
    };
    let bounds = [
        (
            CLIP,
            limits.max_clip_distances,
            "VUID-VkPipelineShaderStageCreateInfo-maxClipDistances-00708",
            "ClipDistance",
            "maxClipDistances",
        ),
        (
            CULL,
            limits.max_cull_distances,
            "VUID-VkPipelineShaderStageCreateInfo-maxCullDistances-00709",
            "CullDistance",
            "maxCullDistances",
        ),
        (
            SAMPLE_MASK,
            limits.max_sample_mask_words,
            "VUID-VkPipelineShaderStageCreateInfo-maxSampleMaskWords-00711",
            "SampleMask",
            "maxSampleMaskWords",
        ),
    ];
    for (builtin, max, vuid, name, limit) in bounds {
        if let Some((_, _, len)) = of(builtin, None).find(|(_, _, len)| *len > max) {
            refuse(
                vuid,
                format!(
                    "{at}: the entry point's {name} array has {len} elements, past {limit} ({max})"
                ),
            )?;
        }
    }
    let combined = limits.max_combined_clip_and_cull_distances;
    for storage in [INPUT, OUTPUT] {
        let sum: u32 = of(CLIP, Some(storage))
            .chain(of(CULL, Some(storage)))
            .map(|(_, _, len)| *len)
            .sum();
        if sum > combined {
            refuse(
                "VUID-VkPipelineShaderStageCreateInfo-maxCombinedClipAndCullDistances-00710",
                format!("{at}: the entry point's ClipDistance and CullDistance arrays have {sum} elements together, past maxCombinedClipAndCullDistances ({combined})"),
            )?;
        }
    }
    if stage.stage == vk::ShaderStageFlags::VERTEX && of(CULL, Some(INPUT)).next().is_some() {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-stage-00712",
            format!("{at}: a vertex entry point reads a CullDistance input"),
        )?;
    }
    if stage.stage == vk::ShaderStageFlags::FRAGMENT && of(CULL, Some(OUTPUT)).next().is_some() {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-stage-00718",
            format!("{at}: a fragment entry point writes a CullDistance output"),
        )?;
    }
    Ok(())
}

/// Each specialization map entry of a stage that names a constant its module
/// declares gives it as many bytes as the constant's type has, four for a boolean
/// (`VUID-VkSpecializationMapEntry-constantID-00776`).
pub(super) fn check_constant_sizes(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    at: &dyn core::fmt::Display,
) -> Result<()> {
    // SAFETY: the safe struct's setter stores a reference that outlives the create info.
    let Some(info) = (unsafe { stage.p_specialization_info.as_ref() }) else {
        return Ok(());
    };
    let Some(interface) = device.live().shader_module(stage.module) else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the entries with their count.
    let entries = unsafe { crate::state::raw_slice(info.p_map_entries, info.map_entry_count) };
    for (k, e) in entries.iter().enumerate() {
        let declared = interface
            .spec_constants
            .iter()
            .find(|(id, _)| *id == e.constant_id);
        if let Some((id, size)) = declared {
            if e.size != *size as usize {
                refuse(
                    "VUID-VkSpecializationMapEntry-constantID-00776",
                    format!("{at}: pMapEntries[{k}] gives specialization constant {id} {} bytes, and its type has {size}", e.size),
                )?;
            }
        }
    }
    Ok(())
}

/// The device remembers what the module's shaders need from a pipeline layout.
pub(crate) fn shader_module_created(
    device: &Device,
    module: ShaderModule,
    create_info: &ShaderModuleCreateInfo<'_>,
) -> ShaderModule {
    let raw = create_info.as_raw();
    // SAFETY: the safe setter stores the code slice with its size in bytes.
    let words = unsafe { crate::state::raw_slice(raw.p_code, (raw.code_size / 4) as u32) };
    device
        .live()
        .shader_module_created(module.raw(), crate::spirv::interface(words));
    module
}

/// The entry point a stage names in its module, for the stage's execution model
/// (none where the module is not the wrappers' or has no such entry point).
pub(crate) fn stage_entry_point(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
) -> Option<crate::spirv::EntryPoint> {
    let name = stage_name(stage)?;
    let interface = device.live().shader_module(stage.module)?;
    interface.entry_point(name.to_bytes(), stage.stage).cloned()
}

/// The entry point name a stage gives.
fn stage_name<'s>(stage: &'s vk::PipelineShaderStageCreateInfo<'_>) -> Option<&'s core::ffi::CStr> {
    if stage.p_name.is_null() {
        return None;
    }
    // SAFETY: the safe struct's constructor and `name` setter take the name as a
    // `&CStr` the struct borrows, so it is a nul-terminated string that outlives it.
    Some(unsafe { core::ffi::CStr::from_ptr(stage.p_name) })
}

/// A stage's shader against the pipeline layout: every resource variable its module
/// declares has a binding in the layout's set, of a descriptor type that can back
/// it, visible to the stage and with as many descriptors, and its push-constant
/// block lies inside a range for the stage. A shader that reads a descriptor the
/// layout lacks has the driver index past its tables.
pub(super) fn check_shader_layout(
    device: &Device,
    stage: &vk::PipelineShaderStageCreateInfo<'_>,
    layout: vk::PipelineLayout,
    vuid: &'static str,
    at: &dyn std::fmt::Display,
) -> Result<()> {
    if stage.module == vk::ShaderModule::null() {
        // Without the extensions that let a stage name its code another way (not
        // emitted), a stage needs a module: it is how its code got the shader promise.
        return refuse(
            "VUID-VkPipelineShaderStageCreateInfo-module-06716",
            format!("{at}: module is not set"),
        );
    }
    let live = device.live();
    if live.shader_module(stage.module).is_some() && stage_entry_point(device, stage).is_none() {
        refuse(
            "VUID-VkPipelineShaderStageCreateInfo-pName-00707",
            format!(
                "{at}: the module has no entry point {:?} with the {:?} stage's execution model",
                stage_name(stage),
                stage.stage
            ),
        )?;
    }
    let (Some(interface), Some(layout)) = (
        live.shader_module(stage.module),
        live.pipeline_layout(layout),
    ) else {
        return Ok(());
    };
    let stage_flags = stage.stage;
    for r in &interface.resources {
        let found = layout
            .sets
            .get(r.set as usize)
            .and_then(|set| set.bindings.iter().find(|b| b.binding == r.binding));
        match found {
            None => refuse(
                vuid,
                format!(
                    "{at}: the shader uses set {} binding {}, which the pipeline layout does not have",
                    r.set, r.binding
                ),
            )?,
            Some(b) if !b.stages.contains(stage_flags) => refuse(
                vuid,
                format!(
                    "{at}: set {} binding {} is not visible to the {stage_flags:?} stage (its stages are {:?})",
                    r.set, r.binding, b.stages
                ),
            )?,
            Some(b) if !r.kind.accepts(b.ty) => refuse(
                vuid,
                format!(
                    "{at}: the shader reads set {} binding {} as {:?}, which a {:?} descriptor cannot back",
                    r.set, r.binding, r.kind, b.ty
                ),
            )?,
            Some(b) if r.count > b.count => refuse(
                vuid,
                format!(
                    "{at}: the shader uses {} descriptors at set {} binding {}, which has {}",
                    r.count, r.set, r.binding, b.count
                ),
            )?,
            Some(_) => {}
        }
    }
    if let Some((start, end)) = interface.push_constants {
        let covered = layout.push_ranges.iter().any(|p| {
            p.stage_flags.contains(stage_flags)
                && p.offset <= start
                && u64::from(p.offset) + u64::from(p.size) >= u64::from(end)
        });
        if !covered {
            refuse(
                vuid,
                format!("{at}: the shader's push constants span bytes {start}..{end}, which no push-constant range of the pipeline layout for the {stage_flags:?} stage covers"),
            )?;
        }
    }
    Ok(())
}

/// What the modules of a pipeline's stages declare: their resource variables (every
/// one, as which of them the entry points use is not read), by set and binding, the
/// bytes of their push-constant blocks, and what each stage reads and writes
/// through its descriptors.
pub(crate) struct Declared {
    /// The resource variables.
    pub resources: Vrc<[crate::spirv::Resource]>,
    /// The push-constant bytes `start..end`, if any module has a block.
    pub push: Option<(u32, u32)>,
    /// The descriptor accesses, for the hazard tracker.
    pub uses: Vrc<[crate::state::DescriptorUse]>,
}

/// [`Declared`] for a pipeline's stages.
pub(super) fn declared_resources<'a>(
    device: &Device,
    stages: impl Iterator<Item = &'a vk::PipelineShaderStageCreateInfo<'a>>,
) -> Declared {
    let live = device.live();
    let mut resources = Vec::new();
    let mut uses = Vec::new();
    let mut push: Option<(u32, u32)> = None;
    for stage in stages {
        if let Some(interface) = live.shader_module(stage.module) {
            resources.extend_from_slice(&interface.resources);
            if let Some((start, end)) = interface.push_constants {
                push = Some(push.map_or((start, end), |(s, e)| (s.min(start), e.max(end))));
            }
            // A stage the tables give no pipeline stage for is not tracked.
            if let Some((_, at)) = crate::sync_tables::SHADER_STAGES
                .iter()
                .find(|(s, _)| *s == stage.stage)
            {
                for r in &interface.resources {
                    descriptor_uses(r, *at, &mut uses);
                }
            }
        }
    }
    resources.sort_unstable_by_key(|r| (r.set, r.binding));
    resources.dedup();
    uses.sort_unstable_by_key(|u: &crate::state::DescriptorUse| (u.set, u.binding, u.stage));
    uses.dedup();
    Declared {
        resources: resources.into(),
        push,
        uses: uses.into(),
    }
}

/// What a shader stage (at pipeline stage `stage`) reads and writes through a
/// resource variable, by its kind and what the module's instructions do with it: a
/// variable no instruction reaches is not accessed. An input attachment is the
/// render pass's to order, a sampler reaches no memory.
fn descriptor_uses(
    r: &crate::spirv::Resource,
    stage: u64,
    out: &mut Vec<crate::state::DescriptorUse>,
) {
    use crate::spirv::{ops, ResourceKind as K};
    let d = crate::sync_tables::DESCRIPTORS;
    let (read, write) = match r.kind {
        K::UniformBuffer => ((r.ops & ops::LOAD != 0).then_some(d.uniform), None),
        K::StorageBuffer => (
            (r.ops & ops::LOAD != 0).then_some(d.storage_read),
            (r.ops & ops::STORE != 0).then_some(d.storage_write),
        ),
        K::SampledImage | K::CombinedImageSampler | K::UniformTexelBuffer => (
            (r.ops & (ops::SAMPLE | ops::READ) != 0).then_some(d.sampled),
            None,
        ),
        K::StorageImage | K::StorageTexelBuffer => (
            (r.ops & (ops::READ | ops::ATOMIC) != 0).then_some(d.storage_read),
            (r.ops & (ops::WRITE | ops::ATOMIC) != 0).then_some(d.storage_write),
        ),
        K::Sampler | K::InputAttachment | K::Other => (None, None),
    };
    let at = |access: u64, write: bool| crate::state::DescriptorUse {
        set: r.set,
        binding: r.binding,
        count: r.count,
        stage,
        access,
        write,
    };
    out.extend(read.map(|a| at(a, false)));
    out.extend(write.map(|a| at(a, true)));
}
