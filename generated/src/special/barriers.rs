//! Pipeline barriers and event waits: each buffer and image barrier against the
//! resource it names (its usage, format, sharing mode) and the queue families it
//! transfers between, and a pipeline barrier's stages and access types against
//! each other, the queue family and the render pass instance it is recorded in.

use super::{pool_family, refuse};
use crate::recorder::{Recorder, Scope};
use crate::structs::{BufferMemoryBarrier, ImageMemoryBarrier, MemoryBarrier};
use crate::Result;
use ash::vk;

type L = vk::ImageLayout;

type U = vk::ImageUsageFlags;

/// For each layout whose transition needs a usage: the layouts, the usage bits of
/// which the image needs one, and the rule (`VkImageMemoryBarrier`).
const LAYOUT_USAGE: &[(&[L], U, &str)] = &[
    (
        &[L::COLOR_ATTACHMENT_OPTIMAL],
        U::COLOR_ATTACHMENT,
        "VUID-VkImageMemoryBarrier-oldLayout-01208",
    ),
    (
        &[L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        "VUID-VkImageMemoryBarrier-oldLayout-01209",
    ),
    (
        &[L::DEPTH_STENCIL_READ_ONLY_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        "VUID-VkImageMemoryBarrier-oldLayout-01210",
    ),
    (
        &[L::SHADER_READ_ONLY_OPTIMAL],
        U::from_raw(U::SAMPLED.as_raw() | U::INPUT_ATTACHMENT.as_raw()),
        "VUID-VkImageMemoryBarrier-oldLayout-01211",
    ),
    (
        &[L::TRANSFER_SRC_OPTIMAL],
        U::TRANSFER_SRC,
        "VUID-VkImageMemoryBarrier-oldLayout-01212",
    ),
    (
        &[L::TRANSFER_DST_OPTIMAL],
        U::TRANSFER_DST,
        "VUID-VkImageMemoryBarrier-oldLayout-01213",
    ),
    (
        &[L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        "VUID-VkImageMemoryBarrier-oldLayout-01658",
    ),
    (
        &[L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        "VUID-VkImageMemoryBarrier-oldLayout-01659",
    ),
    (
        &[L::DEPTH_READ_ONLY_OPTIMAL],
        U::from_raw(
            U::DEPTH_STENCIL_ATTACHMENT.as_raw()
                | U::SAMPLED.as_raw()
                | U::INPUT_ATTACHMENT.as_raw(),
        ),
        "VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04065",
    ),
    (
        &[L::DEPTH_ATTACHMENT_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        "VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04066",
    ),
    (
        &[L::STENCIL_READ_ONLY_OPTIMAL],
        U::from_raw(
            U::DEPTH_STENCIL_ATTACHMENT.as_raw()
                | U::SAMPLED.as_raw()
                | U::INPUT_ATTACHMENT.as_raw(),
        ),
        "VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04067",
    ),
    (
        &[L::STENCIL_ATTACHMENT_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        "VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04068",
    ),
    (
        &[L::ATTACHMENT_OPTIMAL],
        U::from_raw(U::COLOR_ATTACHMENT.as_raw() | U::DEPTH_STENCIL_ATTACHMENT.as_raw()),
        "VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-03938",
    ),
    (
        &[L::READ_ONLY_OPTIMAL],
        U::from_raw(
            U::DEPTH_STENCIL_ATTACHMENT.as_raw()
                | U::SAMPLED.as_raw()
                | U::INPUT_ATTACHMENT.as_raw(),
        ),
        "VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-03939",
    ),
];

/// The special queue families reserved for external memory ownership transfers.
fn special(family: u32) -> bool {
    family == vk::QUEUE_FAMILY_EXTERNAL || family == vk::QUEUE_FAMILY_FOREIGN_EXT
}

/// The rules of a barrier's queue family indices, by what they check.
struct FamilyRules {
    both_special: &'static str,
    concurrent_special: &'static str,
    exclusive_valid: &'static str,
    concurrent_ignored: &'static str,
}

const BUFFER_FAMILIES: FamilyRules = FamilyRules {
    both_special: "VUID-VkBufferMemoryBarrier-srcQueueFamilyIndex-04087",
    concurrent_special: "VUID-VkBufferMemoryBarrier-buffer-04088",
    exclusive_valid: "VUID-VkBufferMemoryBarrier-buffer-04089",
    concurrent_ignored: "VUID-VkBufferMemoryBarrier-synchronization2-03853",
};

const IMAGE_FAMILIES: FamilyRules = FamilyRules {
    both_special: "VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04070",
    concurrent_special: "VUID-VkImageMemoryBarrier-image-04071",
    exclusive_valid: "VUID-VkImageMemoryBarrier-image-04072",
    concurrent_ignored: "VUID-VkImageMemoryBarrier-synchronization2-03857",
};

/// The queue family indices of barrier `at` of a resource shared as `sharing`.
fn check_families(
    (src, dst): (u32, u32),
    sharing: vk::SharingMode,
    (family_count, sync2): (u32, bool),
    rules: &FamilyRules,
    at: &str,
) -> Result<()> {
    let ignored = vk::QUEUE_FAMILY_IGNORED;
    if src != dst && special(src) && special(dst) {
        refuse(
            rules.both_special,
            format!("{at} transfers between two special queue families ({src:#x}, {dst:#x})"),
        )?;
    }
    let concurrent = sharing == vk::SharingMode::CONCURRENT;
    if concurrent
        && src != dst
        && (special(src) || special(dst))
        && src != ignored
        && dst != ignored
    {
        refuse(
            rules.concurrent_special,
            format!("{at} of a concurrent resource names a special queue family ({src:#x}, {dst:#x}) and not VK_QUEUE_FAMILY_IGNORED"),
        )?;
    }
    let valid = |f: u32| f < family_count || special(f);
    if !concurrent && src != dst && !(valid(src) && valid(dst)) {
        refuse(
            rules.exclusive_valid,
            format!("{at} of an exclusive resource names queue families {src:#x} and {dst:#x}; the device has {family_count}"),
        )?;
    }
    if concurrent && !sync2 && src != ignored && dst != ignored {
        refuse(
            rules.concurrent_ignored,
            format!("{at} of a concurrent resource names queue families {src:#x} and {dst:#x}, neither VK_QUEUE_FAMILY_IGNORED, and synchronization2 is not enabled"),
        )?;
    }
    Ok(())
}

/// The checks of the buffer and image barriers a pipeline barrier or an event
/// wait records, against the resources they name.
pub(crate) fn check_barrier_structs<S: Scope>(
    recorder: &Recorder<'_, S>,
    buffer_memory_barriers: &[BufferMemoryBarrier<'_>],
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) -> Result<()> {
    let device = recorder.device();
    let live = device.live();
    let sync2 = live.with_features(|f| f.v13.synchronization2) != vk::FALSE;
    let separate = live.with_features(|f| f.v12.separate_depth_stencil_layouts) != vk::FALSE;
    let family_count = super::family_count(device.parent());
    for (n, b) in buffer_memory_barriers.iter().enumerate() {
        let Some(record) = live.buffer(b.buffer) else {
            continue;
        };
        check_families(
            (b.src_queue_family_index, b.dst_queue_family_index),
            record.sharing,
            (family_count, sync2),
            &BUFFER_FAMILIES,
            &format!("pBufferMemoryBarriers[{n}]"),
        )?;
    }
    for (n, b) in image_memory_barriers.iter().enumerate() {
        let Some(image) = live.image(b.image) else {
            continue;
        };
        let at = format!("pImageMemoryBarriers[{n}]");
        check_families(
            (b.src_queue_family_index, b.dst_queue_family_index),
            image.sharing,
            (family_count, sync2),
            &IMAGE_FAMILIES,
            &at,
        )?;
        let (src, dst) = (b.src_queue_family_index, b.dst_queue_family_index);
        let transfer =
            src != dst && src != vk::QUEUE_FAMILY_IGNORED && dst != vk::QUEUE_FAMILY_IGNORED;
        let changes = transfer || b.old_layout != b.new_layout;
        if changes {
            if b.new_layout == L::UNDEFINED || b.new_layout == L::PREINITIALIZED {
                refuse(
                    "VUID-VkImageMemoryBarrier-newLayout-01198",
                    format!("{at} moves to {:?}", b.new_layout),
                )?;
            }
            let usage = image.usage | image.stencil_usage.unwrap_or_default();
            for (layouts, needs, vuid) in LAYOUT_USAGE {
                // Without synchronization2 its two layouts are refused by their own
                // rules (VUID-VkImageMemoryBarrier-synchronization2-07793, -07794).
                if !sync2
                    && (layouts[0] == L::ATTACHMENT_OPTIMAL || layouts[0] == L::READ_ONLY_OPTIMAL)
                {
                    continue;
                }
                let named = layouts.contains(&b.old_layout) || layouts.contains(&b.new_layout);
                if named && !usage.intersects(*needs) {
                    refuse(
                        vuid,
                        format!(
                            "{at} moves between {:?} and {:?}, and the image's usage {usage:?} has none of {needs:?}",
                            b.old_layout, b.new_layout
                        ),
                    )?;
                }
            }
        }
        let aspect = b.subresource_range.aspect_mask;
        let has = crate::formats::aspects(image.format).unwrap_or(vk::ImageAspectFlags::COLOR);
        let planes = vk::ImageAspectFlags::PLANE_0
            | vk::ImageAspectFlags::PLANE_1
            | vk::ImageAspectFlags::PLANE_2;
        let disjoint = image.flags.contains(vk::ImageCreateFlags::DISJOINT);
        let depth_stencil = vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL;
        if has.intersects(planes) && disjoint {
            if !aspect.intersects(planes | vk::ImageAspectFlags::COLOR) {
                refuse(
                    "VUID-VkImageMemoryBarrier-image-01672",
                    format!("{at} names aspects {aspect:?} of a disjoint multi-planar image"),
                )?;
            }
            if !has.contains(vk::ImageAspectFlags::PLANE_2)
                && aspect.contains(vk::ImageAspectFlags::PLANE_2)
            {
                refuse(
                    "VUID-VkImageMemoryBarrier-image-01673",
                    format!("{at} names PLANE_2 of a two-plane image"),
                )?;
            }
        } else if !has.intersects(depth_stencil) && aspect != vk::ImageAspectFlags::COLOR {
            refuse(
                "VUID-VkImageMemoryBarrier-image-01671",
                format!("{at} names aspects {aspect:?} of a color (or not disjoint) image"),
            )?;
        }
        if has.contains(depth_stencil) {
            if separate && !aspect.intersects(depth_stencil) {
                refuse(
                    "VUID-VkImageMemoryBarrier-image-03319",
                    format!("{at} names neither depth nor stencil of a depth/stencil image"),
                )?;
            }
            if !separate && !aspect.contains(depth_stencil) {
                refuse(
                    "VUID-VkImageMemoryBarrier-image-03320",
                    format!("{at} names {aspect:?} of a depth/stencil image, and separateDepthStencilLayouts is not enabled"),
                )?;
            }
        }
    }
    Ok(())
}

/// The checks of `vkCmdPipelineBarrier` of its own: the stages against the queue
/// family and the access types, the dependency flags and barriers against the
/// render pass instance it is recorded in, or outside one.
#[allow(clippy::too_many_arguments)]
pub(crate) fn check_pipeline_barrier<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_stage_mask: vk::PipelineStageFlags,
    dst_stage_mask: vk::PipelineStageFlags,
    dependency_flags: vk::DependencyFlags,
    memory_barriers: &[MemoryBarrier<'_>],
    buffer_memory_barriers: &[BufferMemoryBarrier<'_>],
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) -> Result<()> {
    let family = pool_family(recorder);
    let sync2 = recorder
        .device()
        .live()
        .with_features(|f| f.v13.synchronization2)
        != vk::FALSE;
    for (mask, zero, unsupported) in [
        (
            src_stage_mask,
            "VUID-vkCmdPipelineBarrier-srcStageMask-03937",
            "VUID-vkCmdPipelineBarrier-srcStageMask-06461",
        ),
        (
            dst_stage_mask,
            "VUID-vkCmdPipelineBarrier-dstStageMask-03937",
            "VUID-vkCmdPipelineBarrier-dstStageMask-06462",
        ),
    ] {
        if mask.is_empty() && !sync2 {
            refuse(
                zero,
                "a stage mask is 0, and synchronization2 is not enabled",
            )?;
        }
        // The host stage needs no queue capability (the specification's table of
        // supported stages); a barrier may name it.
        if let Some(s) =
            super::stages::unsupported_stage(mask & !vk::PipelineStageFlags::HOST, family.flags)
        {
            refuse(
                unsupported,
                format!(
                    "a stage mask includes {s:?}, which the pool's queue family ({:?}) does not support",
                    family.flags
                ),
            )?;
        }
    }
    let access = |access: vk::AccessFlags, stages: vk::PipelineStageFlags, vuid, at: &str| {
        match super::stages::unsupported_access(access, stages) {
            Some(a) => refuse(
                vuid,
                format!("{at} includes {a:?}, which no stage of {stages:?} supports"),
            ),
            None => Ok(()),
        }
    };
    for (n, b) in memory_barriers.iter().enumerate() {
        let at = format!("pMemoryBarriers[{n}]");
        access(
            b.src_access_mask,
            src_stage_mask,
            "VUID-vkCmdPipelineBarrier-srcAccessMask-02815",
            &at,
        )?;
        access(
            b.dst_access_mask,
            dst_stage_mask,
            "VUID-vkCmdPipelineBarrier-dstAccessMask-02816",
            &at,
        )?;
    }
    // A release's source scope and an acquire's destination scope are those of the
    // queue family on the other side.
    let ours = |f: u32| f == family.index;
    let scopes = |(src, dst): (u32, u32)| (src == dst || ours(src), src == dst || ours(dst));
    for (n, b) in buffer_memory_barriers.iter().enumerate() {
        let at = format!("pBufferMemoryBarriers[{n}]");
        let (first, second) = scopes((b.src_queue_family_index, b.dst_queue_family_index));
        if first {
            access(
                b.src_access_mask,
                src_stage_mask,
                "VUID-vkCmdPipelineBarrier-pBufferMemoryBarriers-02817",
                &at,
            )?;
        }
        if second {
            access(
                b.dst_access_mask,
                dst_stage_mask,
                "VUID-vkCmdPipelineBarrier-pBufferMemoryBarriers-02818",
                &at,
            )?;
        }
    }
    for (n, b) in image_memory_barriers.iter().enumerate() {
        let at = format!("pImageMemoryBarriers[{n}]");
        let (first, second) = scopes((b.src_queue_family_index, b.dst_queue_family_index));
        if first {
            access(
                b.src_access_mask,
                src_stage_mask,
                "VUID-vkCmdPipelineBarrier-pImageMemoryBarriers-02819",
                &at,
            )?;
        }
        if second {
            access(
                b.dst_access_mask,
                dst_stage_mask,
                "VUID-vkCmdPipelineBarrier-pImageMemoryBarriers-02820",
                &at,
            )?;
        }
    }
    match &recorder.instance {
        None => {
            if dependency_flags.contains(vk::DependencyFlags::VIEW_LOCAL) {
                refuse(
                    "VUID-vkCmdPipelineBarrier-dependencyFlags-01186",
                    "VK_DEPENDENCY_VIEW_LOCAL_BIT outside a render pass instance",
                )?;
            }
        }
        Some(instance) => {
            if instance.dynamic {
                refuse(
                    "VUID-vkCmdPipelineBarrier-None-06191",
                    "a pipeline barrier inside a render pass instance begun with vkCmdBeginRendering",
                )?;
            }
            let record = (instance.render_pass != vk::RenderPass::null())
                .then(|| recorder.device().live().render_pass(instance.render_pass))
                .flatten();
            let Some(record) = record else {
                return refuse(
                    "VUID-vkCmdPipelineBarrier-pDependencies-02285",
                    "the recorder does not know the render pass of this instance (one a secondary continues), so it cannot check the barrier against the subpass's dependencies on itself",
                );
            };
            let src_access = memory_barriers
                .iter()
                .map(|b| b.src_access_mask)
                .chain(buffer_memory_barriers.iter().map(|b| b.src_access_mask))
                .chain(image_memory_barriers.iter().map(|b| b.src_access_mask))
                .fold(vk::AccessFlags::empty(), |a, b| a | b);
            let dst_access = memory_barriers
                .iter()
                .map(|b| b.dst_access_mask)
                .chain(buffer_memory_barriers.iter().map(|b| b.dst_access_mask))
                .chain(image_memory_barriers.iter().map(|b| b.dst_access_mask))
                .fold(vk::AccessFlags::empty(), |a, b| a | b);
            let fits = record.self_dependencies.iter().any(|d| {
                d.subpass == instance.subpass
                    && super::stages::expand(d.stages.0)
                        .contains(super::stages::expand(src_stage_mask))
                    && super::stages::expand(d.stages.1)
                        .contains(super::stages::expand(dst_stage_mask))
                    && d.access.0.contains(src_access)
                    && d.access.1.contains(dst_access)
            });
            if !fits {
                refuse(
                    "VUID-vkCmdPipelineBarrier-pDependencies-02285",
                    format!("subpass {} has no dependency on itself whose stages and access types hold the barrier's ({src_stage_mask:?} / {src_access:?} to {dst_stage_mask:?} / {dst_access:?})", instance.subpass),
                )?;
            }
            let used: Vec<vk::Image> =
                record
                    .used
                    .get(instance.subpass as usize)
                    .map_or(Vec::new(), |u| {
                        u.iter()
                            .filter_map(|a| recorder.pass_images.get(*a as usize).copied())
                            .collect()
                    });
            for (n, b) in image_memory_barriers.iter().enumerate() {
                if !used.contains(&b.image) {
                    refuse(
                        "VUID-vkCmdPipelineBarrier-image-04073",
                        format!("pImageMemoryBarriers[{n}] names an image that is no attachment of subpass {}", instance.subpass),
                    )?;
                }
            }
            if !buffer_memory_barriers.is_empty() {
                refuse(
                    "VUID-vkCmdPipelineBarrier-bufferMemoryBarrierCount-01178",
                    "a buffer memory barrier inside a render pass instance",
                )?;
            }
            for (n, b) in image_memory_barriers.iter().enumerate() {
                if b.old_layout != b.new_layout {
                    refuse(
                        "VUID-vkCmdPipelineBarrier-oldLayout-01181",
                        format!("pImageMemoryBarriers[{n}] changes the layout inside a render pass instance"),
                    )?;
                }
                if b.src_queue_family_index != b.dst_queue_family_index {
                    refuse(
                        "VUID-vkCmdPipelineBarrier-srcQueueFamilyIndex-01182",
                        format!("pImageMemoryBarriers[{n}] transfers queue family ownership inside a render pass instance"),
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// The checks of a pipeline barrier: its own, its barriers', and the layouts its
/// image barriers move from.
#[allow(clippy::too_many_arguments)]
pub(crate) fn pipeline_barrier_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_stage_mask: vk::PipelineStageFlags,
    dst_stage_mask: vk::PipelineStageFlags,
    dependency_flags: vk::DependencyFlags,
    memory_barriers: &[MemoryBarrier<'_>],
    buffer_memory_barriers: &[BufferMemoryBarrier<'_>],
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) -> Result<()> {
    check_pipeline_barrier(
        recorder,
        src_stage_mask,
        dst_stage_mask,
        dependency_flags,
        memory_barriers,
        buffer_memory_barriers,
        image_memory_barriers,
    )?;
    check_barrier_structs(recorder, buffer_memory_barriers, image_memory_barriers)?;
    super::image_layouts::cmd_pipeline_barrier_checks(recorder, image_memory_barriers)
}
