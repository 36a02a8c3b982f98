//! Pipeline barriers and event waits: each buffer and image barrier against the
//! resource it names (its usage, format, sharing mode) and the queue families it
//! transfers between, and a pipeline barrier's stages and access types against
//! each other, the queue family and the render pass instance it is recorded in.
//!
//! Both versions' barriers (`VkImageMemoryBarrier` with the command's stage masks,
//! `VkImageMemoryBarrier2` with its own) are read into one shape, [`Barriers`], and
//! each rule is written once, naming the VUID of the version it was read from.

use super::{pool_family, refuse};
use crate::recorder::{Recorder, Scope};
use crate::structs::{BufferMemoryBarrier, DependencyInfo, ImageMemoryBarrier, MemoryBarrier};
use crate::Result;
use ash::vk;
use smallvec::SmallVec;

type S2 = vk::PipelineStageFlags2;
type A2 = vk::AccessFlags2;

/// Which version's structs barriers were read from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Version {
    /// `VkMemoryBarrier`, `VkBufferMemoryBarrier`, `VkImageMemoryBarrier`, under the
    /// command's stage masks.
    One,
    /// `VkMemoryBarrier2`, `VkBufferMemoryBarrier2`, `VkImageMemoryBarrier2`.
    Two,
}

/// A rule of the barrier structs, by version (`""`: the version has no such rule).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rule {
    pub v1: &'static str,
    pub v2: &'static str,
}

impl Rule {
    fn of(self, version: Version) -> &'static str {
        match version {
            Version::One => self.v1,
            Version::Two => self.v2,
        }
    }
}

/// A rule whose VUIDs differ only in the struct's name.
macro_rules! both {
    ($structure:literal, $tail:literal) => {
        Rule {
            v1: concat!("VUID-Vk", $structure, "MemoryBarrier-", $tail),
            v2: concat!("VUID-Vk", $structure, "MemoryBarrier2-", $tail),
        }
    };
}

/// The stages and access types of one barrier: its own (second version) or the
/// command's stage masks (first version).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Scopes {
    pub src_stage: S2,
    pub dst_stage: S2,
    pub src_access: A2,
    pub dst_access: A2,
}

/// A buffer barrier of either version.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BufferBarrier {
    pub scopes: Scopes,
    pub buffer: vk::Buffer,
    pub families: (u32, u32),
    /// Its offset and size (`VK_WHOLE_SIZE`: to the buffer's end).
    pub range: (vk::DeviceSize, vk::DeviceSize),
}

/// An image barrier of either version.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ImageBarrier {
    pub scopes: Scopes,
    pub image: vk::Image,
    pub families: (u32, u32),
    pub layouts: (vk::ImageLayout, vk::ImageLayout),
    pub range: vk::ImageSubresourceRange,
}

/// The barriers of one command, read from either version's structs.
#[derive(Debug)]
pub(crate) struct Barriers {
    pub version: Version,
    // Inline for the few barriers a command most often has: read on every
    // barrier command, by its checks and the hazard tracker.
    pub memory: SmallVec<[Scopes; 1]>,
    pub buffers: SmallVec<[BufferBarrier; 1]>,
    pub images: SmallVec<[ImageBarrier; 1]>,
}

fn widen(stages: vk::PipelineStageFlags) -> S2 {
    S2::from_raw(u64::from(stages.as_raw()))
}

fn widen_access(access: vk::AccessFlags) -> A2 {
    A2::from_raw(u64::from(access.as_raw()))
}

impl Barriers {
    /// The first version's barriers, under the command's stage masks.
    pub(crate) fn of(
        (src_stage_mask, dst_stage_mask): (vk::PipelineStageFlags, vk::PipelineStageFlags),
        memory_barriers: &[MemoryBarrier<'_>],
        buffer_memory_barriers: &[BufferMemoryBarrier<'_>],
        image_memory_barriers: &[ImageMemoryBarrier<'_>],
    ) -> Self {
        let scopes = |src: vk::AccessFlags, dst: vk::AccessFlags| Scopes {
            src_stage: widen(src_stage_mask),
            dst_stage: widen(dst_stage_mask),
            src_access: widen_access(src),
            dst_access: widen_access(dst),
        };
        Barriers {
            version: Version::One,
            memory: memory_barriers
                .iter()
                .map(|b| scopes(b.src_access_mask, b.dst_access_mask))
                .collect(),
            buffers: buffer_memory_barriers
                .iter()
                .map(|b| BufferBarrier {
                    scopes: scopes(b.src_access_mask, b.dst_access_mask),
                    buffer: b.buffer,
                    families: (b.src_queue_family_index, b.dst_queue_family_index),
                    range: (b.offset, b.size),
                })
                .collect(),
            images: image_memory_barriers
                .iter()
                .map(|b| ImageBarrier {
                    scopes: scopes(b.src_access_mask, b.dst_access_mask),
                    image: b.image,
                    families: (b.src_queue_family_index, b.dst_queue_family_index),
                    layouts: (b.old_layout, b.new_layout),
                    range: b.subresource_range,
                })
                .collect(),
        }
    }

    /// The second version's barriers of a dependency info.
    pub(crate) fn of2(dependency_info: &DependencyInfo<'_>) -> Self {
        let (memory, buffers, images) = arrays(dependency_info.as_raw());
        let scopes = |src_stage, src_access, dst_stage, dst_access| Scopes {
            src_stage,
            dst_stage,
            src_access,
            dst_access,
        };
        Barriers {
            version: Version::Two,
            memory: memory
                .iter()
                .map(|b| {
                    scopes(
                        b.src_stage_mask,
                        b.src_access_mask,
                        b.dst_stage_mask,
                        b.dst_access_mask,
                    )
                })
                .collect(),
            buffers: buffers
                .iter()
                .map(|b| BufferBarrier {
                    scopes: scopes(
                        b.src_stage_mask,
                        b.src_access_mask,
                        b.dst_stage_mask,
                        b.dst_access_mask,
                    ),
                    buffer: b.buffer,
                    families: (b.src_queue_family_index, b.dst_queue_family_index),
                    range: (b.offset, b.size),
                })
                .collect(),
            images: images
                .iter()
                .map(|b| ImageBarrier {
                    scopes: scopes(
                        b.src_stage_mask,
                        b.src_access_mask,
                        b.dst_stage_mask,
                        b.dst_access_mask,
                    ),
                    image: b.image,
                    families: (b.src_queue_family_index, b.dst_queue_family_index),
                    layouts: (b.old_layout, b.new_layout),
                    range: b.subresource_range,
                })
                .collect(),
        }
    }

    /// Every barrier's scopes.
    pub(crate) fn scopes(&self) -> impl Iterator<Item = &Scopes> {
        self.memory
            .iter()
            .chain(self.buffers.iter().map(|b| &b.scopes))
            .chain(self.images.iter().map(|b| &b.scopes))
    }
}

type L = vk::ImageLayout;

type U = vk::ImageUsageFlags;

/// For each layout whose transition needs a usage: the layouts, the usage bits of
/// which the image needs one, and the rule.
const LAYOUT_USAGE: &[(&[L], U, Rule)] = &[
    (
        &[L::COLOR_ATTACHMENT_OPTIMAL],
        U::COLOR_ATTACHMENT,
        both!("Image", "oldLayout-01208"),
    ),
    (
        &[L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        both!("Image", "oldLayout-01209"),
    ),
    (
        &[L::DEPTH_STENCIL_READ_ONLY_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        both!("Image", "oldLayout-01210"),
    ),
    (
        &[L::SHADER_READ_ONLY_OPTIMAL],
        U::from_raw(U::SAMPLED.as_raw() | U::INPUT_ATTACHMENT.as_raw()),
        both!("Image", "oldLayout-01211"),
    ),
    (
        &[L::TRANSFER_SRC_OPTIMAL],
        U::TRANSFER_SRC,
        both!("Image", "oldLayout-01212"),
    ),
    (
        &[L::TRANSFER_DST_OPTIMAL],
        U::TRANSFER_DST,
        both!("Image", "oldLayout-01213"),
    ),
    (
        &[L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        both!("Image", "oldLayout-01658"),
    ),
    (
        &[L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        both!("Image", "oldLayout-01659"),
    ),
    (
        &[L::DEPTH_READ_ONLY_OPTIMAL],
        U::from_raw(
            U::DEPTH_STENCIL_ATTACHMENT.as_raw()
                | U::SAMPLED.as_raw()
                | U::INPUT_ATTACHMENT.as_raw(),
        ),
        both!("Image", "srcQueueFamilyIndex-04065"),
    ),
    (
        &[L::DEPTH_ATTACHMENT_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        both!("Image", "srcQueueFamilyIndex-04066"),
    ),
    (
        &[L::STENCIL_READ_ONLY_OPTIMAL],
        U::from_raw(
            U::DEPTH_STENCIL_ATTACHMENT.as_raw()
                | U::SAMPLED.as_raw()
                | U::INPUT_ATTACHMENT.as_raw(),
        ),
        both!("Image", "srcQueueFamilyIndex-04067"),
    ),
    (
        &[L::STENCIL_ATTACHMENT_OPTIMAL],
        U::DEPTH_STENCIL_ATTACHMENT,
        both!("Image", "srcQueueFamilyIndex-04068"),
    ),
    (
        &[L::ATTACHMENT_OPTIMAL],
        U::from_raw(U::COLOR_ATTACHMENT.as_raw() | U::DEPTH_STENCIL_ATTACHMENT.as_raw()),
        both!("Image", "srcQueueFamilyIndex-03938"),
    ),
    (
        &[L::READ_ONLY_OPTIMAL],
        U::from_raw(
            U::DEPTH_STENCIL_ATTACHMENT.as_raw()
                | U::SAMPLED.as_raw()
                | U::INPUT_ATTACHMENT.as_raw(),
        ),
        both!("Image", "srcQueueFamilyIndex-03939"),
    ),
];

/// The special queue families reserved for external memory ownership transfers.
fn special(family: u32) -> bool {
    family == vk::QUEUE_FAMILY_EXTERNAL || family == vk::QUEUE_FAMILY_FOREIGN_EXT
}

/// The rules of a barrier's queue family indices, by what they check.
struct FamilyRules {
    both_special: Rule,
    concurrent_special: Rule,
    exclusive_valid: Rule,
    concurrent_ignored: Rule,
    host_same: Rule,
}

const BUFFER_FAMILIES: FamilyRules = FamilyRules {
    both_special: both!("Buffer", "srcQueueFamilyIndex-04087"),
    concurrent_special: both!("Buffer", "buffer-04088"),
    exclusive_valid: both!("Buffer", "buffer-04089"),
    // synchronization2 is enabled wherever the second version is recorded.
    concurrent_ignored: Rule {
        v1: "VUID-VkBufferMemoryBarrier-synchronization2-03853",
        v2: "",
    },
    host_same: Rule {
        v1: "",
        v2: "VUID-VkBufferMemoryBarrier2-srcStageMask-03851",
    },
};

const IMAGE_FAMILIES: FamilyRules = FamilyRules {
    both_special: both!("Image", "srcQueueFamilyIndex-04070"),
    concurrent_special: both!("Image", "image-04071"),
    exclusive_valid: both!("Image", "image-04072"),
    concurrent_ignored: Rule {
        v1: "VUID-VkImageMemoryBarrier-synchronization2-03857",
        v2: "",
    },
    host_same: Rule {
        v1: "",
        v2: "VUID-VkImageMemoryBarrier2-srcStageMask-03854",
    },
};

/// Where a barrier is, for a message: written out only when a check refuses it,
/// so a barrier that passes formats nothing.
enum At {
    /// Element `n` of an array: `pImageMemoryBarriers[0]`.
    Item(&'static str, usize),
    /// The stage mask of barrier `n`.
    StageMask(usize),
    /// The command's own stage masks.
    Masks,
}

impl core::fmt::Display for At {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            At::Item(array, n) => write!(f, "{array}[{n}]"),
            At::StageMask(n) => write!(f, "barrier {n}'s stage mask"),
            At::Masks => f.write_str("a stage mask"),
        }
    }
}

/// The queue family indices of barrier `at` of a resource shared as `sharing`.
fn check_families(
    (src, dst): (u32, u32),
    scopes: &Scopes,
    sharing: vk::SharingMode,
    (family_count, sync2): (u32, bool),
    (rules, version): (&FamilyRules, Version),
    at: &At,
) -> Result<()> {
    let ignored = vk::QUEUE_FAMILY_IGNORED;
    let host = (scopes.src_stage | scopes.dst_stage).contains(S2::HOST);
    if version == Version::Two && host && src != dst {
        refuse(
            rules.host_same.of(version),
            format!("{at} names the host stage and transfers between queue families {src:#x} and {dst:#x}"),
        )?;
    }
    if src != dst && special(src) && special(dst) {
        refuse(
            rules.both_special.of(version),
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
            rules.concurrent_special.of(version),
            format!("{at} of a concurrent resource names a special queue family ({src:#x}, {dst:#x}) and not VK_QUEUE_FAMILY_IGNORED"),
        )?;
    }
    let valid = |f: u32| f < family_count || special(f);
    if !concurrent && src != dst && !(valid(src) && valid(dst)) {
        refuse(
            rules.exclusive_valid.of(version),
            format!("{at} of an exclusive resource names queue families {src:#x} and {dst:#x}; the device has {family_count}"),
        )?;
    }
    if version == Version::One && concurrent && !sync2 && src != ignored && dst != ignored {
        refuse(
            rules.concurrent_ignored.of(version),
            format!("{at} of a concurrent resource names queue families {src:#x} and {dst:#x}, neither VK_QUEUE_FAMILY_IGNORED, and synchronization2 is not enabled"),
        )?;
    }
    Ok(())
}

/// The checks of the buffer and image barriers a pipeline barrier or an event
/// wait records, against the resources they name.
pub(crate) fn check_barrier_structs<S: Scope>(
    recorder: &Recorder<'_, S>,
    barriers: &Barriers,
) -> Result<()> {
    let device = recorder.device();
    let live = device.live();
    let version = barriers.version;
    let sync2 = live.with_features(|f| f.v13.synchronization2) != vk::FALSE;
    let separate = live.with_features(|f| f.v12.separate_depth_stencil_layouts) != vk::FALSE;
    let family_count = super::family_count(device.parent());
    for (n, b) in barriers.buffers.iter().enumerate() {
        let Some(record) = live.buffer(b.buffer) else {
            continue;
        };
        check_families(
            b.families,
            &b.scopes,
            record.sharing,
            (family_count, sync2),
            (&BUFFER_FAMILIES, version),
            &At::Item("pBufferMemoryBarriers", n),
        )?;
    }
    for (n, b) in barriers.images.iter().enumerate() {
        let Some(image) = live.image(b.image) else {
            continue;
        };
        let at = At::Item("pImageMemoryBarriers", n);
        check_families(
            b.families,
            &b.scopes,
            image.sharing,
            (family_count, sync2),
            (&IMAGE_FAMILIES, version),
            &at,
        )?;
        let (src, dst) = b.families;
        let (old, new) = b.layouts;
        let transfer =
            src != dst && src != vk::QUEUE_FAMILY_IGNORED && dst != vk::QUEUE_FAMILY_IGNORED;
        let changes = transfer || old != new;
        if changes {
            if new == L::UNDEFINED || new == L::PREINITIALIZED {
                refuse(
                    both!("Image", "newLayout-01198").of(version),
                    format!("{at} moves to {new:?}"),
                )?;
            }
            // The host writes only linear images in a layout it can access.
            let host_layouts = [L::PREINITIALIZED, L::UNDEFINED, L::GENERAL];
            if version == Version::Two
                && b.scopes.src_stage.contains(S2::HOST)
                && !host_layouts.contains(&old)
            {
                refuse(
                    "VUID-VkImageMemoryBarrier2-srcStageMask-03855",
                    format!("{at} names the host stage as its source, and moves from {old:?}"),
                )?;
            }
            let usage = image.usage | image.stencil_usage.unwrap_or_default();
            for (layouts, needs, rule) in LAYOUT_USAGE {
                // Without synchronization2 its two layouts are refused by their own
                // rules (VUID-VkImageMemoryBarrier-synchronization2-07793, -07794).
                if !sync2
                    && (layouts[0] == L::ATTACHMENT_OPTIMAL || layouts[0] == L::READ_ONLY_OPTIMAL)
                {
                    continue;
                }
                let named = layouts.contains(&old) || layouts.contains(&new);
                if named && !usage.intersects(*needs) {
                    refuse(
                        rule.of(version),
                        format!(
                            "{at} moves between {old:?} and {new:?}, and the image's usage {usage:?} has none of {needs:?}",
                        ),
                    )?;
                }
            }
        }
        let aspect = b.range.aspect_mask;
        let has = crate::formats::aspects(image.format).unwrap_or(vk::ImageAspectFlags::COLOR);
        let planes = vk::ImageAspectFlags::PLANE_0
            | vk::ImageAspectFlags::PLANE_1
            | vk::ImageAspectFlags::PLANE_2;
        let disjoint = image.flags.contains(vk::ImageCreateFlags::DISJOINT);
        let depth_stencil = vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL;
        if has.intersects(planes) && disjoint {
            if !aspect.intersects(planes | vk::ImageAspectFlags::COLOR) {
                refuse(
                    both!("Image", "image-01672").of(version),
                    format!("{at} names aspects {aspect:?} of a disjoint multi-planar image"),
                )?;
            }
            if !has.contains(vk::ImageAspectFlags::PLANE_2)
                && aspect.contains(vk::ImageAspectFlags::PLANE_2)
            {
                refuse(
                    both!("Image", "image-01673").of(version),
                    format!("{at} names PLANE_2 of a two-plane image"),
                )?;
            }
        } else if !has.intersects(depth_stencil) && aspect != vk::ImageAspectFlags::COLOR {
            refuse(
                both!("Image", "image-01671").of(version),
                format!("{at} names aspects {aspect:?} of a color (or not disjoint) image"),
            )?;
        }
        if has.contains(depth_stencil) {
            if separate && !aspect.intersects(depth_stencil) {
                refuse(
                    both!("Image", "image-03319").of(version),
                    format!("{at} names neither depth nor stencil of a depth/stencil image"),
                )?;
            }
            if !separate && !aspect.contains(depth_stencil) {
                refuse(
                    both!("Image", "image-03320").of(version),
                    format!("{at} names {aspect:?} of a depth/stencil image, and separateDepthStencilLayouts is not enabled"),
                )?;
            }
        }
    }
    Ok(())
}

/// The rules of a pipeline barrier command of its own, by what they check (`""`: the
/// version has none: synchronization2 is enabled wherever the second is recorded,
/// and its structs' access types are their own rules, which the emitted checks hold).
pub(crate) struct PipelineBarrierRules {
    pub src_zero: &'static str,
    pub dst_zero: &'static str,
    pub src_unsupported: &'static str,
    pub dst_unsupported: &'static str,
    pub memory_src_access: &'static str,
    pub memory_dst_access: &'static str,
    pub buffer_src_access: &'static str,
    pub buffer_dst_access: &'static str,
    pub image_src_access: &'static str,
    pub image_dst_access: &'static str,
    pub view_local: &'static str,
    pub dynamic_rendering: &'static str,
    pub self_dependency: &'static str,
    pub image_attachment: &'static str,
    pub buffer_in_pass: &'static str,
    pub layout_in_pass: &'static str,
    pub transfer_in_pass: &'static str,
}

/// `vkCmdPipelineBarrier`'s rules.
pub(crate) const PIPELINE_BARRIER: PipelineBarrierRules = PipelineBarrierRules {
    src_zero: "VUID-vkCmdPipelineBarrier-srcStageMask-03937",
    dst_zero: "VUID-vkCmdPipelineBarrier-dstStageMask-03937",
    src_unsupported: "VUID-vkCmdPipelineBarrier-srcStageMask-06461",
    dst_unsupported: "VUID-vkCmdPipelineBarrier-dstStageMask-06462",
    memory_src_access: "VUID-vkCmdPipelineBarrier-srcAccessMask-02815",
    memory_dst_access: "VUID-vkCmdPipelineBarrier-dstAccessMask-02816",
    buffer_src_access: "VUID-vkCmdPipelineBarrier-pBufferMemoryBarriers-02817",
    buffer_dst_access: "VUID-vkCmdPipelineBarrier-pBufferMemoryBarriers-02818",
    image_src_access: "VUID-vkCmdPipelineBarrier-pImageMemoryBarriers-02819",
    image_dst_access: "VUID-vkCmdPipelineBarrier-pImageMemoryBarriers-02820",
    view_local: "VUID-vkCmdPipelineBarrier-dependencyFlags-01186",
    dynamic_rendering: "VUID-vkCmdPipelineBarrier-None-06191",
    self_dependency: "VUID-vkCmdPipelineBarrier-pDependencies-02285",
    image_attachment: "VUID-vkCmdPipelineBarrier-image-04073",
    buffer_in_pass: "VUID-vkCmdPipelineBarrier-bufferMemoryBarrierCount-01178",
    layout_in_pass: "VUID-vkCmdPipelineBarrier-oldLayout-01181",
    transfer_in_pass: "VUID-vkCmdPipelineBarrier-srcQueueFamilyIndex-01182",
};

/// `vkCmdPipelineBarrier2`'s rules.
pub(crate) const PIPELINE_BARRIER2: PipelineBarrierRules = PipelineBarrierRules {
    src_zero: "",
    dst_zero: "",
    src_unsupported: "VUID-vkCmdPipelineBarrier2-srcStageMask-03849",
    dst_unsupported: "VUID-vkCmdPipelineBarrier2-dstStageMask-03850",
    memory_src_access: "",
    memory_dst_access: "",
    buffer_src_access: "",
    buffer_dst_access: "",
    image_src_access: "",
    image_dst_access: "",
    view_local: "VUID-vkCmdPipelineBarrier2-dependencyFlags-01186",
    dynamic_rendering: "VUID-vkCmdPipelineBarrier2-None-06191",
    self_dependency: "VUID-vkCmdPipelineBarrier2-pDependencies-02285",
    image_attachment: "VUID-vkCmdPipelineBarrier2-image-04073",
    buffer_in_pass: "VUID-vkCmdPipelineBarrier2-bufferMemoryBarrierCount-01178",
    layout_in_pass: "VUID-vkCmdPipelineBarrier2-oldLayout-01181",
    transfer_in_pass: "VUID-vkCmdPipelineBarrier2-srcQueueFamilyIndex-01182",
};

/// The second version's stages a first-version mask covers: its own bits (with the
/// meta stages spelled out), and the stages synchronization2 split out of them.
fn covered_stages(stages: vk::PipelineStageFlags) -> S2 {
    type S = vk::PipelineStageFlags;
    let stages = super::stages::expand(stages);
    let mut out = widen(stages);
    if stages.contains(S::TRANSFER) {
        out |= S2::COPY | S2::RESOLVE | S2::BLIT | S2::CLEAR;
    }
    if stages.contains(S::VERTEX_INPUT) {
        out |= S2::INDEX_INPUT | S2::VERTEX_ATTRIBUTE_INPUT;
    }
    let pre_rasterization = S::VERTEX_SHADER
        | S::TESSELLATION_CONTROL_SHADER
        | S::TESSELLATION_EVALUATION_SHADER
        | S::GEOMETRY_SHADER;
    if stages.contains(pre_rasterization) {
        out |= S2::PRE_RASTERIZATION_SHADERS;
    }
    out
}

/// The second version's access types a first-version mask covers.
fn covered_access(access: vk::AccessFlags) -> A2 {
    let mut out = widen_access(access);
    if access.contains(vk::AccessFlags::SHADER_READ) {
        out |= A2::SHADER_SAMPLED_READ | A2::SHADER_STORAGE_READ;
    }
    if access.contains(vk::AccessFlags::SHADER_WRITE) {
        out |= A2::SHADER_STORAGE_WRITE;
    }
    out
}

/// The stages a mask names, its meta stages spelled out in its first-version bits.
fn expanded(stages: S2) -> S2 {
    let low = vk::PipelineStageFlags::from_raw(stages.as_raw() as u32);
    stages | widen(super::stages::expand(low))
}

/// Every stage a mask of either version names: its meta stages spelled out, and
/// the stages synchronization2 split out of the first version's (as events order
/// waits and resets).
pub(crate) fn every_stage(stages: S2) -> S2 {
    let stages = expanded(stages);
    stages | covered_stages(vk::PipelineStageFlags::from_raw(stages.as_raw() as u32))
}

/// [`every_stage`] of a first-version mask.
pub(crate) fn every_stage1(stages: vk::PipelineStageFlags) -> S2 {
    every_stage(widen(stages))
}

/// The checks of a pipeline barrier command of its own: the stages against the queue
/// family and the access types, the dependency flags and barriers against the
/// render pass instance it is recorded in, or outside one. `masks` are the first
/// version's command stage masks (the second's barriers carry their own).
pub(crate) fn check_pipeline_barrier<S: Scope>(
    recorder: &Recorder<'_, S>,
    masks: Option<(vk::PipelineStageFlags, vk::PipelineStageFlags)>,
    dependency_flags: vk::DependencyFlags,
    barriers: &Barriers,
    rules: &PipelineBarrierRules,
) -> Result<()> {
    check_barrier_scopes(recorder, masks, barriers, rules)?;
    check_in_pass(recorder, masks, dependency_flags, barriers, rules)
}

/// The checks of a barrier command's scopes, which event waits share with pipeline
/// barriers: the stages against the queue family (the host stage aside) and, without
/// synchronization2, not empty; each access type against its stages.
pub(crate) fn check_barrier_scopes<S: Scope>(
    recorder: &Recorder<'_, S>,
    masks: Option<(vk::PipelineStageFlags, vk::PipelineStageFlags)>,
    barriers: &Barriers,
    rules: &PipelineBarrierRules,
) -> Result<()> {
    let family = pool_family(recorder);
    let sync2 = recorder
        .device()
        .live()
        .with_features(|f| f.v13.synchronization2)
        != vk::FALSE;
    // The host stage needs no queue capability (the specification's table of
    // supported stages); a barrier may name it.
    let unsupported =
        |mask: S2, vuid: &'static str, at: &At| match super::stages::unsupported_stage2(
            mask & !S2::HOST,
            family.flags,
        ) {
            Some(s) => refuse(
                vuid,
                format!(
                    "{at} includes {s:?}, which the pool's queue family ({:?}) does not support",
                    family.flags
                ),
            ),
            None => Ok(()),
        };
    match masks {
        Some((src, dst)) => {
            for (mask, zero, vuid) in [
                (src, rules.src_zero, rules.src_unsupported),
                (dst, rules.dst_zero, rules.dst_unsupported),
            ] {
                if mask.is_empty() && !sync2 {
                    refuse(
                        zero,
                        "a stage mask is 0, and synchronization2 is not enabled",
                    )?;
                }
                unsupported(widen(mask), vuid, &At::Masks)?;
            }
        }
        None => {
            for (n, b) in barriers.scopes().enumerate() {
                let at = At::StageMask(n);
                unsupported(b.src_stage, rules.src_unsupported, &at)?;
                unsupported(b.dst_stage, rules.dst_unsupported, &at)?;
            }
        }
    }
    let access = |access: A2, stages: S2, vuid: &'static str, at: &At| {
        if vuid.is_empty() {
            return Ok(());
        }
        let (access, stages) = (
            vk::AccessFlags::from_raw(access.as_raw() as u32),
            vk::PipelineStageFlags::from_raw(stages.as_raw() as u32),
        );
        match super::stages::unsupported_access(access, stages) {
            Some(a) => refuse(
                vuid,
                format!("{at} includes {a:?}, which no stage of {stages:?} supports"),
            ),
            None => Ok(()),
        }
    };
    for (n, b) in barriers.memory.iter().enumerate() {
        let at = At::Item("pMemoryBarriers", n);
        access(b.src_access, b.src_stage, rules.memory_src_access, &at)?;
        access(b.dst_access, b.dst_stage, rules.memory_dst_access, &at)?;
    }
    // A release's source scope and an acquire's destination scope are those of the
    // queue family on the other side.
    let ours = |f: u32| f == family.index;
    let scopes = |(src, dst): (u32, u32)| (src == dst || ours(src), src == dst || ours(dst));
    let resources = barriers
        .buffers
        .iter()
        .map(|b| {
            (
                b.families,
                &b.scopes,
                "pBufferMemoryBarriers",
                rules.buffer_src_access,
                rules.buffer_dst_access,
            )
        })
        .chain(barriers.images.iter().map(|b| {
            (
                b.families,
                &b.scopes,
                "pImageMemoryBarriers",
                rules.image_src_access,
                rules.image_dst_access,
            )
        }));
    let mut counts = [0usize; 2];
    for (families, b, array, src_vuid, dst_vuid) in resources {
        let n = &mut counts[usize::from(array.starts_with("pImage"))];
        let at = At::Item(array, *n);
        *n += 1;
        let (first, second) = scopes(families);
        if first {
            access(b.src_access, b.src_stage, src_vuid, &at)?;
        }
        if second {
            access(b.dst_access, b.dst_stage, dst_vuid, &at)?;
        }
    }
    Ok(())
}

/// The checks of a pipeline barrier against the render pass instance it is
/// recorded in (its subpass's dependency on itself, the attachments), or outside one.
fn check_in_pass<S: Scope>(
    recorder: &Recorder<'_, S>,
    masks: Option<(vk::PipelineStageFlags, vk::PipelineStageFlags)>,
    dependency_flags: vk::DependencyFlags,
    barriers: &Barriers,
    rules: &PipelineBarrierRules,
) -> Result<()> {
    match &recorder.instance {
        None => {
            if dependency_flags.contains(vk::DependencyFlags::VIEW_LOCAL) {
                refuse(
                    rules.view_local,
                    "VK_DEPENDENCY_VIEW_LOCAL_BIT outside a render pass instance",
                )?;
            }
        }
        Some(instance) => {
            if instance.dynamic {
                refuse(
                    rules.dynamic_rendering,
                    "a pipeline barrier inside a render pass instance begun with vkCmdBeginRendering",
                )?;
            }
            let record = (instance.render_pass != vk::RenderPass::null())
                .then(|| recorder.device().live().render_pass(instance.render_pass))
                .flatten();
            let Some(record) = record else {
                return refuse(
                    rules.self_dependency,
                    "the recorder does not know the render pass of this instance (one a secondary continues), so it cannot check the barrier against the subpass's dependencies on itself",
                );
            };
            let union = |f: fn(&Scopes) -> u64| barriers.scopes().fold(0, |a, b| a | f(b));
            let (command_src, command_dst) =
                masks.map_or((S2::empty(), S2::empty()), |(s, d)| (widen(s), widen(d)));
            let src_stage = expanded(command_src | S2::from_raw(union(|b| b.src_stage.as_raw())));
            let dst_stage = expanded(command_dst | S2::from_raw(union(|b| b.dst_stage.as_raw())));
            let src_access = A2::from_raw(union(|b| b.src_access.as_raw()));
            let dst_access = A2::from_raw(union(|b| b.dst_access.as_raw()));
            let fits = record.self_dependencies.iter().any(|d| {
                d.subpass == instance.subpass
                    && covered_stages(d.stages.0).contains(src_stage)
                    && covered_stages(d.stages.1).contains(dst_stage)
                    && covered_access(d.access.0).contains(src_access)
                    && covered_access(d.access.1).contains(dst_access)
            });
            if !fits {
                refuse(
                    rules.self_dependency,
                    format!("subpass {} has no dependency on itself whose stages and access types hold the barrier's ({src_stage:?} / {src_access:?} to {dst_stage:?} / {dst_access:?})", instance.subpass),
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
            for (n, b) in barriers.images.iter().enumerate() {
                if !used.contains(&b.image) {
                    refuse(
                        rules.image_attachment,
                        format!("pImageMemoryBarriers[{n}] names an image that is no attachment of subpass {}", instance.subpass),
                    )?;
                }
            }
            if !barriers.buffers.is_empty() {
                refuse(
                    rules.buffer_in_pass,
                    "a buffer memory barrier inside a render pass instance",
                )?;
            }
            for (n, b) in barriers.images.iter().enumerate() {
                if b.layouts.0 != b.layouts.1 {
                    refuse(
                        rules.layout_in_pass,
                        format!("pImageMemoryBarriers[{n}] changes the layout inside a render pass instance"),
                    )?;
                }
                if b.families.0 != b.families.1 {
                    refuse(
                        rules.transfer_in_pass,
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
    let masks = (src_stage_mask, dst_stage_mask);
    let barriers = Barriers::of(
        masks,
        memory_barriers,
        buffer_memory_barriers,
        image_memory_barriers,
    );
    check_pipeline_barrier(
        recorder,
        Some(masks),
        dependency_flags,
        &barriers,
        &PIPELINE_BARRIER,
    )?;
    check_barrier_structs(recorder, &barriers)?;
    super::image_layouts::cmd_pipeline_barrier_checks(recorder, image_memory_barriers)
}

/// The checks of `vkCmdPipelineBarrier2`: as the first version's, each barrier under
/// its own stages, and the layouts its image barriers move from.
pub(crate) fn pipeline_barrier2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    dependency_info: &DependencyInfo<'_>,
) -> Result<()> {
    let barriers = Barriers::of2(dependency_info);
    check_pipeline_barrier(
        recorder,
        None,
        dependency_info.dependency_flags,
        &barriers,
        &PIPELINE_BARRIER2,
    )?;
    check_barrier_structs(recorder, &barriers)?;
    super::image_layouts::dependency_checks(recorder, core::slice::from_ref(dependency_info))
}

/// After `vkCmdPipelineBarrier`: the event waits it orders before later resets,
/// and the layouts its image barriers leave.
pub(crate) fn pipeline_barrier_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    src_stage_mask: vk::PipelineStageFlags,
    dst_stage_mask: vk::PipelineStageFlags,
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) {
    recorder
        .event_states
        .barrier(every_stage1(src_stage_mask), every_stage1(dst_stage_mask));
    super::image_layouts::cmd_pipeline_barrier_done(recorder, image_memory_barriers);
}

/// The memory, buffer and image barriers of a safe struct's dependency info.
pub(crate) fn arrays<'i>(
    info: &'i vk::DependencyInfo<'i>,
) -> (
    &'i [vk::MemoryBarrier2<'i>],
    &'i [vk::BufferMemoryBarrier2<'i>],
    &'i [vk::ImageMemoryBarrier2<'i>],
) {
    // SAFETY: the safe struct's setters store each array with its length, borrowed
    // for as long as the info.
    unsafe {
        (
            crate::state::raw_slice(info.p_memory_barriers, info.memory_barrier_count),
            crate::state::raw_slice(
                info.p_buffer_memory_barriers,
                info.buffer_memory_barrier_count,
            ),
            crate::state::raw_slice(
                info.p_image_memory_barriers,
                info.image_memory_barrier_count,
            ),
        )
    }
}

/// The stage masks of each barrier of a dependency info (source, destination).
pub(crate) fn stage_pairs(info: &vk::DependencyInfo<'_>) -> Vec<(S2, S2)> {
    let (memory, buffers, images) = arrays(info);
    memory
        .iter()
        .map(|b| (b.src_stage_mask, b.dst_stage_mask))
        .chain(buffers.iter().map(|b| (b.src_stage_mask, b.dst_stage_mask)))
        .chain(images.iter().map(|b| (b.src_stage_mask, b.dst_stage_mask)))
        .collect()
}

/// After `vkCmdPipelineBarrier2`: as the first version's.
pub(crate) fn pipeline_barrier2_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    dependency_info: &DependencyInfo<'_>,
) {
    for (src, dst) in stage_pairs(dependency_info.as_raw()) {
        recorder
            .event_states
            .barrier(every_stage(src), every_stage(dst));
    }
    super::image_layouts::dependency_done(recorder, core::slice::from_ref(dependency_info));
}
