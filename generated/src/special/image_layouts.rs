//! The image layouts recorded commands name: checked by the safe methods against
//! what the recording's earlier commands leave, and recorded by every method for
//! the submission that checks the rest ([`crate::state::layouts`]).

use crate::handles::CommandBuffer;
use crate::recorder::{Recorder, Scope};
use crate::state::hazards::{Texels, EVERY_TEXEL};
use crate::state::layouts::Sel;
use crate::structs::{
    BlitImageInfo2, CopyBufferToImageInfo2, CopyImageInfo2, CopyImageToBufferInfo2, DependencyInfo,
    ImageMemoryBarrier, RenderPassBeginInfo, ResolveImageInfo2,
};
use crate::Result;
use ash::vk;
use smallvec::SmallVec;
use tuff_runtime::Vrc;

/// The rule of a barrier's `oldLayout` (`VkImageMemoryBarrier`).
pub(crate) const BARRIER: &str = "VUID-VkImageMemoryBarrier-oldLayout-01197";

/// As [`BARRIER`], for `VkImageMemoryBarrier2`.
pub(crate) const BARRIER2: &str = "VUID-VkImageMemoryBarrier2-oldLayout-01197";

/// One image layout a command names: the image, its subresources, the layout
/// they must be in (`UNDEFINED`: any), the layout they are left in, and the rule.
type Named = (
    vk::Image,
    Sel,
    vk::ImageLayout,
    vk::ImageLayout,
    &'static str,
);

/// The layouts a command names: a command's few inline.
type NamedList = SmallVec<[Named; 4]>;

/// Whether a barrier recorded for queue family `ours` acquires ownership from
/// another family: the release named the same `oldLayout` and made the transition,
/// so the acquire follows the new layout without needing the old one.
fn acquires(src: u32, dst: u32, ours: u32) -> bool {
    src != dst && src != vk::QUEUE_FAMILY_IGNORED && dst != vk::QUEUE_FAMILY_IGNORED && src != ours
}

pub(super) fn barrier(b: &vk::ImageMemoryBarrier<'_>, ours: u32) -> Named {
    let old = if acquires(b.src_queue_family_index, b.dst_queue_family_index, ours) {
        vk::ImageLayout::UNDEFINED
    } else {
        b.old_layout
    };
    let new = if b.old_layout == b.new_layout {
        // No transition: the layout stays whatever it is.
        UNCHANGED
    } else {
        b.new_layout
    };
    (b.image, Sel::range(&b.subresource_range), old, new, BARRIER)
}

fn barrier2(b: &vk::ImageMemoryBarrier2<'_>, ours: u32) -> Named {
    let (image, sel, old, new, _) = barrier(
        &vk::ImageMemoryBarrier {
            src_queue_family_index: b.src_queue_family_index,
            dst_queue_family_index: b.dst_queue_family_index,
            old_layout: b.old_layout,
            new_layout: b.new_layout,
            image: b.image,
            subresource_range: b.subresource_range,
            ..Default::default()
        },
        ours,
    );
    (image, sel, old, new, BARRIER2)
}

/// A `new` layout that leaves the subresources as they are.
const UNCHANGED: vk::ImageLayout = vk::ImageLayout::UNDEFINED;

/// The image barriers of dependency infos.
fn dependency_barriers<'i>(
    infos: impl Iterator<Item = &'i DependencyInfo<'i>>,
    ours: u32,
) -> NamedList {
    infos
        .flat_map(|d| {
            // SAFETY: the safe struct stores the array with its length.
            unsafe {
                crate::state::raw_slice(d.p_image_memory_barriers, d.image_memory_barrier_count)
            }
        })
        .map(|b| barrier2(b, ours))
        .collect()
}

/// Refuses layouts that the recording's earlier commands leave otherwise.
fn check<S: Scope>(recorder: &Recorder<'_, S>, named: &[Named]) -> Result<()> {
    for (image, sel, need, _, vuid) in named {
        recorder.layouts.check(*image, *sel, *need, vuid)?;
    }
    Ok(())
}

/// Records what the layouts need and become.
pub(super) fn record<S: Scope>(recorder: &mut Recorder<'_, S>, named: &[Named]) {
    let (live, layouts) = recorder.layouts_mut();
    for (image, sel, need, leave, vuid) in named {
        layouts.require(live, *image, *sel, *need, vuid);
        if *leave != UNCHANGED {
            layouts.set(live, *image, *sel, *leave);
        }
    }
}

fn barriers(image_memory_barriers: &[ImageMemoryBarrier<'_>], ours: u32) -> NamedList {
    image_memory_barriers
        .iter()
        .map(|b| barrier(b, ours))
        .collect()
}

/// Refuses image barriers whose `oldLayout` is not the layout the recording leaves.
pub(crate) fn cmd_pipeline_barrier_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) -> Result<()> {
    let ours = super::pool_family(recorder).index;
    check(recorder, &barriers(image_memory_barriers, ours))
}

/// The recording follows the layout transitions of image barriers.
pub(crate) fn cmd_pipeline_barrier_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) {
    let ours = super::pool_family(recorder).index;
    record(recorder, &barriers(image_memory_barriers, ours));
}

/// As [`cmd_pipeline_barrier_checks`], for the barriers of dependency infos.
pub(crate) fn dependency_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    infos: &[DependencyInfo<'_>],
) -> Result<()> {
    let ours = super::pool_family(recorder).index;
    check(recorder, &dependency_barriers(infos.iter(), ours))
}

/// As [`cmd_pipeline_barrier_done`], for the barriers of dependency infos.
pub(crate) fn dependency_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    infos: &[DependencyInfo<'_>],
) {
    let ours = super::pool_family(recorder).index;
    record(recorder, &dependency_barriers(infos.iter(), ours));
}

/// What a command that reads or writes an image in a layout it names needs.
pub(super) fn uses(
    image: vk::Image,
    layout: vk::ImageLayout,
    sels: impl Iterator<Item = Sel>,
    vuid: &'static str,
) -> impl Iterator<Item = Named> {
    sels.map(move |sel| (image, sel, layout, UNCHANGED, vuid))
}

/// The layouts a copy, blit or resolve between two images names.
fn two_images<'r, R: 'r>(
    (src, src_layout, src_vuid): (vk::Image, vk::ImageLayout, &'static str),
    (dst, dst_layout, dst_vuid): (vk::Image, vk::ImageLayout, &'static str),
    regions: &'r [R],
    subresources: impl Fn(&R) -> (vk::ImageSubresourceLayers, vk::ImageSubresourceLayers),
) -> NamedList {
    let src_sels = regions.iter().map(|r| Sel::layers(&subresources(r).0));
    let dst_sels = regions.iter().map(|r| Sel::layers(&subresources(r).1));
    uses(src, src_layout, src_sels, src_vuid)
        .chain(uses(dst, dst_layout, dst_sels, dst_vuid))
        .collect()
}

/// A command's layouts, named by what the command is.
pub(crate) enum Names<'a> {
    /// `vkCmdCopyImage`.
    CopyImage(
        vk::Image,
        vk::ImageLayout,
        vk::Image,
        vk::ImageLayout,
        &'a [vk::ImageCopy],
    ),
    /// `vkCmdBlitImage`.
    BlitImage(
        vk::Image,
        vk::ImageLayout,
        vk::Image,
        vk::ImageLayout,
        &'a [vk::ImageBlit],
    ),
    /// `vkCmdResolveImage`.
    ResolveImage(
        vk::Image,
        vk::ImageLayout,
        vk::Image,
        vk::ImageLayout,
        &'a [vk::ImageResolve],
    ),
    /// `vkCmdCopyImage2`.
    CopyImage2(&'a CopyImageInfo2<'a>),
    /// `vkCmdBlitImage2`.
    BlitImage2(&'a BlitImageInfo2<'a>),
    /// `vkCmdResolveImage2`.
    ResolveImage2(&'a ResolveImageInfo2<'a>),
    /// `vkCmdCopyBufferToImage`.
    BufferToImage(vk::Image, vk::ImageLayout, &'a [vk::BufferImageCopy]),
    /// `vkCmdCopyImageToBuffer`.
    ImageToBuffer(vk::Image, vk::ImageLayout, &'a [vk::BufferImageCopy]),
    /// `vkCmdCopyBufferToImage2`.
    BufferToImage2(&'a CopyBufferToImageInfo2<'a>),
    /// `vkCmdCopyImageToBuffer2`.
    ImageToBuffer2(&'a CopyImageToBufferInfo2<'a>),
    /// `vkCmdClearColorImage`.
    ClearColor(vk::Image, vk::ImageLayout, &'a [vk::ImageSubresourceRange]),
    /// `vkCmdClearDepthStencilImage`.
    ClearDepthStencil(vk::Image, vk::ImageLayout, &'a [vk::ImageSubresourceRange]),
}

/// The subresources a command reads and writes, each with the texels it touches.
pub(crate) struct Sides {
    /// Its source side.
    pub read: Vec<(vk::Image, Sel, Texels)>,
    /// Its destination side, or the image it clears.
    pub written: Vec<(vk::Image, Sel, Texels)>,
}

/// The texels of a region from its offset and extent.
pub(crate) fn boxed(o: vk::Offset3D, e: vk::Extent3D) -> Texels {
    let axis = |o: i32, e: u32| (i64::from(o), i64::from(o) + i64::from(e));
    [axis(o.x, e.width), axis(o.y, e.height), axis(o.z, e.depth)]
}

/// The texels between a blit region's two corners.
fn cornered(c: [vk::Offset3D; 2]) -> Texels {
    let axis = |a: i32, b: i32| (i64::from(a.min(b)), i64::from(a.max(b)));
    [
        axis(c[0].x, c[1].x),
        axis(c[0].y, c[1].y),
        axis(c[0].z, c[1].z),
    ]
}

impl Names<'_> {
    /// The texels each of [`Names::named`]'s subresources is touched at, in its order
    /// (a two-image command's sources first).
    fn texels(&self) -> Vec<Texels> {
        fn two<R>(r: &[R], side: impl Fn(&R) -> (Texels, Texels)) -> Vec<Texels> {
            let (src, dst): (Vec<Texels>, Vec<Texels>) = r.iter().map(side).unzip();
            src.into_iter().chain(dst).collect()
        }
        // SAFETY (each `raw_slice`): the safe structs store their arrays with their lengths.
        match self {
            Names::CopyImage(.., r) => two(r, |r| {
                (boxed(r.src_offset, r.extent), boxed(r.dst_offset, r.extent))
            }),
            Names::BlitImage(.., r) => {
                two(r, |r| (cornered(r.src_offsets), cornered(r.dst_offsets)))
            }
            Names::ResolveImage(.., r) => two(r, |r| {
                (boxed(r.src_offset, r.extent), boxed(r.dst_offset, r.extent))
            }),
            Names::CopyImage2(i) => two(
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) },
                |r| (boxed(r.src_offset, r.extent), boxed(r.dst_offset, r.extent)),
            ),
            Names::BlitImage2(i) => two(
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) },
                |r| (cornered(r.src_offsets), cornered(r.dst_offsets)),
            ),
            Names::ResolveImage2(i) => two(
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) },
                |r| (boxed(r.src_offset, r.extent), boxed(r.dst_offset, r.extent)),
            ),
            Names::BufferToImage(_, _, r) | Names::ImageToBuffer(_, _, r) => r
                .iter()
                .map(|r| boxed(r.image_offset, r.image_extent))
                .collect(),
            Names::BufferToImage2(i) => {
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) }
                    .iter()
                    .map(|r| boxed(r.image_offset, r.image_extent))
                    .collect()
            }
            Names::ImageToBuffer2(i) => {
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) }
                    .iter()
                    .map(|r| boxed(r.image_offset, r.image_extent))
                    .collect()
            }
            Names::ClearColor(_, _, r) | Names::ClearDepthStencil(_, _, r) => {
                vec![EVERY_TEXEL; r.len()]
            }
        }
    }

    /// The subresources the command reads and writes, with their texels.
    pub(crate) fn sides(&self) -> Sides {
        let named: Vec<(vk::Image, Sel, Texels)> = self
            .named()
            .into_iter()
            .zip(self.texels())
            .map(|(n, t)| (n.0, n.1, t))
            .collect();
        match self {
            // Two images: the source's subresources first, as many as the destination's.
            Names::CopyImage(..)
            | Names::BlitImage(..)
            | Names::ResolveImage(..)
            | Names::CopyImage2(_)
            | Names::BlitImage2(_)
            | Names::ResolveImage2(_) => {
                let mut read = named;
                let written = read.split_off(read.len() / 2);
                Sides { read, written }
            }
            Names::ImageToBuffer(..) | Names::ImageToBuffer2(_) => Sides {
                read: named,
                written: Vec::new(),
            },
            Names::BufferToImage(..)
            | Names::BufferToImage2(_)
            | Names::ClearColor(..)
            | Names::ClearDepthStencil(..) => Sides {
                read: Vec::new(),
                written: named,
            },
        }
    }

    fn named(&self) -> NamedList {
        // SAFETY (each `raw_slice`): the safe structs store their arrays with their lengths.
        match self {
            Names::CopyImage(s, sl, d, dl, r) => two_images(
                (*s, *sl, "VUID-vkCmdCopyImage-srcImageLayout-00128"),
                (*d, *dl, "VUID-vkCmdCopyImage-dstImageLayout-00133"),
                r,
                |r| (r.src_subresource, r.dst_subresource),
            ),
            Names::BlitImage(s, sl, d, dl, r) => two_images(
                (*s, *sl, "VUID-vkCmdBlitImage-srcImageLayout-00221"),
                (*d, *dl, "VUID-vkCmdBlitImage-dstImageLayout-00226"),
                r,
                |r| (r.src_subresource, r.dst_subresource),
            ),
            Names::ResolveImage(s, sl, d, dl, r) => two_images(
                (*s, *sl, "VUID-vkCmdResolveImage-srcImageLayout-00260"),
                (*d, *dl, "VUID-vkCmdResolveImage-dstImageLayout-00262"),
                r,
                |r| (r.src_subresource, r.dst_subresource),
            ),
            Names::CopyImage2(i) => two_images(
                (
                    i.src_image,
                    i.src_image_layout,
                    "VUID-VkCopyImageInfo2-srcImageLayout-00128",
                ),
                (
                    i.dst_image,
                    i.dst_image_layout,
                    "VUID-VkCopyImageInfo2-dstImageLayout-00133",
                ),
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) },
                |r| (r.src_subresource, r.dst_subresource),
            ),
            Names::BlitImage2(i) => two_images(
                (
                    i.src_image,
                    i.src_image_layout,
                    "VUID-VkBlitImageInfo2-srcImageLayout-00221",
                ),
                (
                    i.dst_image,
                    i.dst_image_layout,
                    "VUID-VkBlitImageInfo2-dstImageLayout-00226",
                ),
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) },
                |r| (r.src_subresource, r.dst_subresource),
            ),
            Names::ResolveImage2(i) => two_images(
                (
                    i.src_image,
                    i.src_image_layout,
                    "VUID-VkResolveImageInfo2-srcImageLayout-00260",
                ),
                (
                    i.dst_image,
                    i.dst_image_layout,
                    "VUID-VkResolveImageInfo2-dstImageLayout-00262",
                ),
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) },
                |r| (r.src_subresource, r.dst_subresource),
            ),
            Names::BufferToImage(image, layout, r) => uses(
                *image,
                *layout,
                r.iter().map(|r| Sel::layers(&r.image_subresource)),
                "VUID-vkCmdCopyBufferToImage-dstImageLayout-00180",
            )
            .collect(),
            Names::ImageToBuffer(image, layout, r) => uses(
                *image,
                *layout,
                r.iter().map(|r| Sel::layers(&r.image_subresource)),
                "VUID-vkCmdCopyImageToBuffer-srcImageLayout-00189",
            )
            .collect(),
            Names::BufferToImage2(i) => uses(
                i.dst_image,
                i.dst_image_layout,
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) }
                    .iter()
                    .map(|r| Sel::layers(&r.image_subresource)),
                "VUID-VkCopyBufferToImageInfo2-dstImageLayout-00180",
            )
            .collect(),
            Names::ImageToBuffer2(i) => uses(
                i.src_image,
                i.src_image_layout,
                unsafe { crate::state::raw_slice(i.p_regions, i.region_count) }
                    .iter()
                    .map(|r| Sel::layers(&r.image_subresource)),
                "VUID-VkCopyImageToBufferInfo2-srcImageLayout-00189",
            )
            .collect(),
            Names::ClearColor(image, layout, ranges) => uses(
                *image,
                *layout,
                ranges.iter().map(Sel::range),
                "VUID-vkCmdClearColorImage-imageLayout-00004",
            )
            .collect(),
            Names::ClearDepthStencil(image, layout, ranges) => uses(
                *image,
                *layout,
                ranges.iter().map(Sel::range),
                "VUID-vkCmdClearDepthStencilImage-imageLayout-00011",
            )
            .collect(),
        }
    }
}

/// Refuses a command that names a layout the recording's earlier commands leave
/// its subresources out of, or (for the commands that name subresources with
/// `VkImageSubresourceLayers`) color with depth or stencil.
pub(crate) fn image_layout_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    names: Names<'_>,
) -> Result<()> {
    let named = names.named();
    if recorder.is_auto_sync() {
        let needs: SmallVec<[_; 2]> = named.iter().map(|n| (n.0, n.1, n.2)).collect();
        crate::special::hazards::auto_transitions(recorder, &needs);
    }
    if !matches!(names, Names::ClearColor(..) | Names::ClearDepthStencil(..)) {
        // The others name their subresources with `VkImageSubresourceLayers`.
        for (_, sel, _, _, _) in &named {
            let a = sel.aspect;
            if a.contains(vk::ImageAspectFlags::COLOR)
                && a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL)
            {
                return Err(crate::Error::Validation {
                    vuid: "VUID-VkImageSubresourceLayers-aspectMask-00167",
                    message: format!("an aspectMask of {a:?} names color with depth or stencil"),
                });
            }
        }
    }
    check(recorder, &named)
}

/// The recording needs the layouts a command names.
pub(crate) fn image_layouts_named<S: Scope>(recorder: &mut Recorder<'_, S>, names: Names<'_>) {
    record(recorder, &names.named());
}

/// Refuses secondaries that need layouts the recording leaves otherwise.
pub(crate) fn execute_layout_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) -> Result<()> {
    let mut so_far = recorder.layouts.clone();
    for cb in command_buffers {
        if let Some(theirs) = cb.uses().layouts() {
            so_far.check_then(&theirs)?;
            so_far.then(&theirs);
        }
    }
    Ok(())
}

/// The recording executes the secondaries' commands, and their layouts.
pub(crate) fn execute_layouts_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) {
    for cb in command_buffers {
        if let Some(theirs) = cb.uses().layouts() {
            recorder.layouts.then(&theirs);
        }
    }
    // Everything the primary bound and set is undefined after the secondaries ran:
    // pipelines, sets, vertex and index buffers, push constants and dynamic state.
    recorder.dynamic = (0, 0);
    recorder.bound = Default::default();
    recorder.pushed = None;
    recorder.counts = (None, None);
    recorder.depth_stencil = Default::default();
}

/// The image views a render pass instance renders to: its framebuffer's, or those
/// an imageless framebuffer's begin info chains (a framebuffer's shared with its
/// record: a begin copies nothing).
pub(crate) fn pass_views(
    live: &crate::state::Live,
    render_pass_begin: &RenderPassBeginInfo<'_>,
) -> Vrc<[vk::ImageView]> {
    let raw = render_pass_begin.as_raw();
    let views = live.framebuffer_views(raw.framebuffer);
    if !views.is_empty() {
        return views;
    }
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let imageless: Option<&vk::RenderPassAttachmentBeginInfo<'_>> = unsafe {
        super::chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_ATTACHMENT_BEGIN_INFO,
        )
    };
    imageless.map_or_else(
        || Vrc::from([]),
        |i| {
            // SAFETY: the safe setter stores the views with their count.
            unsafe { crate::state::raw_slice(i.p_attachments, i.attachment_count) }.into()
        },
    )
}

/// The layouts a render pass instance needs its attachments in (`vuid` names the
/// rule) and leaves them in: each attachment's view, split by aspect where the
/// stencil aspect has layouts of its own.
pub(super) fn attachments(
    live: &crate::state::Live,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    vuid: &'static str,
) -> NamedList {
    let raw = render_pass_begin.as_raw();
    let Some(pass) = live.render_pass(raw.render_pass) else {
        return NamedList::new();
    };
    let views = pass_views(live, render_pass_begin);
    let depth_stencil = vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL;
    let mut named = NamedList::new();
    for (view, layouts) in views.iter().zip(&pass.layouts) {
        let Some(v) = live.view(*view) else {
            continue;
        };
        let sel = |aspect| Sel {
            aspect,
            mips: (v.base_level, v.base_level.saturating_add(1)),
            layers: (v.base_layer, v.base_layer.saturating_add(v.layers)),
        };
        if v.aspect.intersects(depth_stencil) {
            let depth = v.aspect & vk::ImageAspectFlags::DEPTH;
            let stencil = v.aspect & vk::ImageAspectFlags::STENCIL;
            if !depth.is_empty() {
                named.push((v.image, sel(depth), layouts.initial, layouts.last, vuid));
            }
            if !stencil.is_empty() {
                named.push((
                    v.image,
                    sel(stencil),
                    layouts.stencil_initial,
                    layouts.stencil_last,
                    vuid,
                ));
            }
        } else {
            named.push((v.image, sel(v.aspect), layouts.initial, layouts.last, vuid));
        }
    }
    named
}

/// Refuses a render pass instance whose attachments' initial layouts are not the
/// layouts the recording's earlier commands leave them in.
pub(crate) fn render_pass_layout_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    vuid: &'static str,
) -> Result<()> {
    let named = attachments(recorder.device().live(), render_pass_begin, vuid);
    check(recorder, &named)
}

/// The recording needs the attachments in their initial layouts, and leaves them
/// in their final ones.
pub(crate) fn render_pass_layouts<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    vuid: &'static str,
) {
    let named = attachments(recorder.device().live(), render_pass_begin, vuid);
    record(recorder, &named);
}
