//! Memory hazards between the commands of one recording: each command the tracker
//! knows declares what it reads and writes (the stage and access type from the
//! registry's sync tables, per the generator's reviewed table of per-command facts,
//! `generator/src/plan/accesses.rs`; the memory from its parameters), is refused
//! when that access is not ordered after a conflicting earlier one by the barriers
//! recorded between, and is recorded; barriers, event waits and render pass
//! dependencies order what came before ([`crate::state::hazards`]).
//!
//! The error names the two commands, the memory and the barrier that would order
//! them, under the validation layer's synchronization-validation identifier
//! (`SYNC-HAZARD-READ-AFTER-WRITE`, ...).

use crate::handles::{Buffer, Image};
use crate::recorder::{Recorder, Scope};
use crate::special::barriers::Barriers;
use crate::special::image_layouts::Names;
use crate::state::hazards::{Barrier, Cmd, DrawKey, Hazard, Memory, Replayed, Usage, EVERY_TEXEL};
use crate::state::layouts::Sel;
use crate::structs::{
    BufferMemoryBarrier, CopyBufferInfo2, CopyBufferToImageInfo2, CopyImageToBufferInfo2,
    DependencyInfo, ImageMemoryBarrier, MemoryBarrier, RenderPassBeginInfo,
};
use crate::sync_tables::{Facts, Use};
use crate::{Error, Handle, Result};
use ash::vk::{self, Handle as _};
use smallvec::SmallVec;
use tuff_runtime::Vrc;

/// Built with `--cfg tuff_untracked` (the stage benchmark's build without the
/// tracker, to measure what it costs): every entry point returns at once.
const UNTRACKED: bool = cfg!(tuff_untracked);

/// The identifier the validation layer's synchronization validation reports a hazard
/// of this kind under.
fn id(kind: &str) -> &'static str {
    match kind {
        "READ_AFTER_WRITE" => "SYNC-HAZARD-READ-AFTER-WRITE",
        "WRITE_AFTER_READ" => "SYNC-HAZARD-WRITE-AFTER-READ",
        _ => "SYNC-HAZARD-WRITE-AFTER-WRITE",
    }
}

fn refuse(h: &Hazard, memory: &Memory) -> Error {
    Error::Validation {
        vuid: id(h.kind),
        message: h.message(&memory.describe()),
    }
}

/// Checks every access of one command against what the recording did before, then
/// records them: none is recorded if one is refused. With automatic synchronization
/// on ([`Recorder::auto_sync`]), the hazards found are ordered by one barrier
/// recorded just before the command instead.
fn touch<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    name: &'static str,
    accesses: &[(Memory, Use)],
) -> Result<()> {
    order_what_came_before(recorder);
    let found = hazards_of(recorder, name, accesses);
    if let Some((h, m)) = found.first() {
        // A barrier inside a render pass instance needs a self-dependency of its
        // subpass: the tracker inserts none there.
        if !recorder.hazards.auto || recorder.instance.is_some() {
            return Err(refuse(h, m));
        }
        let needed = needed(&found);
        order(recorder, needed);
        if let Some((h, m)) = hazards_of(recorder, name, accesses).first() {
            return Err(refuse(h, m));
        }
    }
    let (live, hazards) = recorder.hazards_mut();
    let cmd = hazards.next(name);
    for (m, u) in accesses {
        hazards.record(live, m, usage(u, cmd));
    }
    Ok(())
}

fn usage(u: &Use, cmd: Cmd) -> Usage {
    Usage {
        stage: u.stage,
        access: u.access,
        write: u.write,
        cmd,
    }
}

/// With automatic synchronization on, orders everything before the recording (the
/// accesses of earlier submissions, which the recording cannot see) before its
/// first access, with one barrier from every stage's writes to every stage's
/// accesses; outside a render pass instance only.
fn order_what_came_before<S: Scope>(recorder: &mut Recorder<'_, S>) {
    // ALL_COMMANDS; MEMORY_READ, MEMORY_WRITE.
    const ALL: u64 = 0x10000;
    const READ: u64 = 0x8000;
    const WRITE: u64 = 0x10000;
    if recorder.hazards.auto && !recorder.hazards.started && recorder.instance.is_none() {
        recorder.hazards.started = true;
        order(recorder, (ALL, WRITE, ALL, READ | WRITE));
    }
}

/// The hazards of a command's accesses, each with the memory it is found in.
fn hazards_of<S: Scope>(
    recorder: &Recorder<'_, S>,
    name: &'static str,
    accesses: &[(Memory, Use)],
) -> Vec<(Hazard, Memory)> {
    let cmd = recorder.hazards.peek(name);
    accesses
        .iter()
        .filter_map(|(m, u)| Some((recorder.hazards.hazard(m, &usage(u, cmd))?, *m)))
        .collect()
}

/// The masks of the one barrier that orders every hazard found: from the earlier
/// accesses' stages (and, for a write, its access type) to the later ones'.
fn needed(found: &[(Hazard, Memory)]) -> (u64, u64, u64, u64) {
    const ALL_COMMANDS: u64 = 0x10000;
    found.iter().fold((0, 0, 0, 0), |(ss, sa, ds, da), (h, _)| {
        // A layout transition is ordered by a barrier its own chains into.
        let src_stage = if h.earlier.stage == 0 {
            ALL_COMMANDS
        } else {
            h.earlier.stage
        };
        let (src_access, dst_access) = match h.earlier.write {
            true => (h.earlier.access, h.later.access),
            // After a read, an execution dependency is enough.
            false => (0, 0),
        };
        (
            ss | src_stage,
            sa | src_access,
            ds | h.later.stage,
            da | dst_access,
        )
    })
}

/// Records one global memory barrier with these masks (synchronization2's where the
/// device enabled it, else the first version's that cover them) and applies it to the
/// tracker.
fn order<S: Scope>(recorder: &mut Recorder<'_, S>, masks: (u64, u64, u64, u64)) {
    recorder.record_memory_barrier(masks);
}

/// With automatic synchronization on, outside a render pass instance: moves
/// subresources a command names in a layout from the one the recording left them
/// in, with one image barrier each, waiting for the accesses the tracker followed
/// (every write where it followed none) and blocking every command after. Only
/// where the recording knows the layout (at an image's first use it is the
/// submission's to check), for the transfer layouts and `GENERAL` of an image with
/// the usage they need, and subresources inside the image with every aspect of
/// its format: a command whose names break a rule is refused by its own checks, and
/// the transition is not recorded. Recorded as the command is checked: a later
/// check that refuses the command leaves the subresources in the new layout.
pub(crate) fn auto_transitions<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    needs: &[(vk::Image, Sel, vk::ImageLayout)],
) {
    use vk::{ImageLayout as L, ImageUsageFlags as U};
    if UNTRACKED || !recorder.hazards.auto || recorder.instance.is_some() {
        return;
    }
    for (image, sel, need) in needs {
        let Some(old) = recorder.layouts.known(*image, sel) else {
            continue;
        };
        let Some(record) = recorder.device().live().image(*image) else {
            continue;
        };
        let usage = match *need {
            L::TRANSFER_SRC_OPTIMAL => U::TRANSFER_SRC,
            L::TRANSFER_DST_OPTIMAL => U::TRANSFER_DST,
            L::GENERAL => U::empty(),
            _ => continue,
        };
        let layers = match record.image_type {
            vk::ImageType::TYPE_3D => 1,
            _ => record.array_layers,
        };
        let inside = sel.mips.0 < sel.mips.1
            && sel.mips.1 <= record.mip_levels
            && sel.layers.0 < sel.layers.1
            && sel.layers.1 <= layers
            && !sel.aspect.is_empty()
            // Every aspect of the format: a depth/stencil image's two move together
            // unless separateDepthStencilLayouts is on, a multi-planar one's planes
            // only as COLOR unless it is disjoint; neither is tuff's to pick here.
            && crate::formats::aspects(record.format) == Some(sel.aspect);
        if old == *need || !record.usage.contains(usage) || !inside {
            continue;
        }
        const ALL_COMMANDS: u64 = 0x10000;
        const MEMORY_READ_WRITE: u64 = 0x8000 | 0x10000;
        let (ss1, sa1) = source_scope(recorder, *image, sel).unwrap_or((
            vk::PipelineStageFlags::ALL_COMMANDS,
            vk::AccessFlags::MEMORY_WRITE,
        ));
        let (ds1, da1) = (
            vk::PipelineStageFlags::ALL_COMMANDS,
            vk::AccessFlags::from_raw(MEMORY_READ_WRITE as u32),
        );
        let b = [vk::ImageMemoryBarrier::default()
            .src_access_mask(sa1)
            .dst_access_mask(da1)
            .old_layout(old)
            .new_layout(*need)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .image(*image)
            .subresource_range(vk::ImageSubresourceRange {
                aspect_mask: sel.aspect,
                base_mip_level: sel.mips.0,
                level_count: sel.mips.1 - sel.mips.0,
                base_array_layer: sel.layers.0,
                layer_count: sel.layers.1 - sel.layers.0,
            })];
        // SAFETY: outside a render pass instance (checked above); the image is live
        // (the command names it through its wrapper) and has the usage the new layout
        // needs (VUID-VkImageMemoryBarrier-oldLayout-01212, -01213); the old layout is
        // the one the recording's earlier commands leave every subresource in (01197);
        // the range lies inside the image (01486, 01488) with aspects of its format
        // (01671 and its siblings); the stages are those of accesses the recording
        // made, or every command, with access types of those stages.
        unsafe {
            (recorder.device().fns().fp_v1_0().cmd_pipeline_barrier)(
                recorder.raw(),
                ss1,
                ds1,
                vk::DependencyFlags::empty(),
                0,
                core::ptr::null(),
                0,
                core::ptr::null(),
                1,
                b.as_ptr(),
            )
        };
        let barrier = Barrier::new(
            u64::from(ss1.as_raw()),
            u64::from(sa1.as_raw()),
            ALL_COMMANDS,
            MEMORY_READ_WRITE,
        );
        let (live, hazards) = recorder.hazards_mut();
        hazards.auto_barriers += 1;
        let cmd = hazards.next("a layout transition tuff recorded");
        hazards.apply_image(live, *image, sel, &barrier, Some(cmd));
        let (live, layouts) = recorder.layouts_mut();
        layouts.set(live, *image, *sel, *need);
    }
}

/// The first scope of a barrier out of `image`'s subresources `sel` (the first
/// version's masks): the accesses the recording made to them last, when the tracker
/// followed every one ([`crate::state::hazards::Recording::last_uses`]).
pub(crate) fn source_scope<S: Scope>(
    recorder: &Recorder<'_, S>,
    image: vk::Image,
    sel: &Sel,
) -> Option<(vk::PipelineStageFlags, vk::AccessFlags)> {
    if UNTRACKED {
        return None;
    }
    let (stages, access) = recorder.hazards.last_uses(image, sel)?;
    Some((
        crate::state::hazards::narrow_stages(stages),
        crate::state::hazards::narrow_access(access),
    ))
}

/// A buffer range from an offset and a size (`VK_WHOLE_SIZE`: to the end).
fn bytes(buffer: vk::Buffer, offset: u64, size: u64) -> Memory {
    let end = if size == vk::WHOLE_SIZE {
        u64::MAX
    } else {
        offset.saturating_add(size)
    };
    Memory::Buffer(buffer, offset, end)
}

/// `vkCmdCopyBuffer`: reads each region of the source, writes each of the destination.
pub(crate) fn copy_buffer<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    src_buffer: &Buffer,
    dst_buffer: &Buffer,
    regions: &[vk::BufferCopy],
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let r = regions.iter().map(|r| (r.src_offset, r.dst_offset, r.size));
    buffer_copy(recorder, facts, (src_buffer.raw(), dst_buffer.raw()), r)
}

/// `vkCmdCopyBuffer2`.
pub(crate) fn copy_buffer2<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    info: &CopyBufferInfo2<'_>,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let raw = info.as_raw();
    // SAFETY: the safe struct stores the array with its length.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    let r = regions.iter().map(|r| (r.src_offset, r.dst_offset, r.size));
    buffer_copy(recorder, facts, (raw.src_buffer, raw.dst_buffer), r)
}

fn buffer_copy<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    (src, dst): (vk::Buffer, vk::Buffer),
    regions: impl Iterator<Item = (u64, u64, u64)>,
) -> Result<()> {
    let mut list = Vec::new();
    for (so, d, size) in regions {
        list.push((bytes(src, so, size), facts.src));
        list.push((bytes(dst, d, size), facts.dst));
    }
    touch(recorder, facts.name, &list)
}

/// A draw's reads, on the stack for the usual few bindings: a draw records no
/// allocation.
type Reads = smallvec::SmallVec<[(Memory, Use); 4]>;

/// The bytes of the vertex buffers a draw fetches: for each binding the bound
/// pipeline's vertex shader reads, from its first fetched element to the end of its
/// last (`vertices`: `None` for an indexed draw, whose vertices the indices pick: the
/// whole bound range).
fn vertex_memory<S: Scope>(
    recorder: &Recorder<'_, S>,
    vertices: Option<(u64, u64)>,
    (first_instance, instance_count): (u64, u64),
    out: &mut Reads,
    read: Use,
) {
    let bound = &recorder.bound[0];
    let Some(pipeline) = &bound.pipeline else {
        return;
    };
    let dynamic_stride = pipeline.dynamic
        & crate::state::dynamic_bit(vk::DynamicState::VERTEX_INPUT_BINDING_STRIDE)
        != 0;
    for v in &pipeline.vertex_reads {
        let Some(Some(range)) = bound.vertex_ranges.get(v.binding as usize) else {
            continue;
        };
        let (buffer, offset) = range.buffer;
        let stride = match (dynamic_stride, range.stride) {
            (true, Some(stride)) => stride,
            _ => u64::from(v.stride),
        };
        let fetched = if v.instance {
            Some((first_instance, instance_count))
        } else {
            vertices
        };
        let (start, end) = match fetched {
            Some((_, 0)) => continue,
            Some((first, count)) => {
                let last = first.saturating_add(count - 1);
                (
                    first.saturating_mul(stride),
                    last.saturating_mul(stride).saturating_add(v.end),
                )
            }
            None => (0, range.bytes),
        };
        let end = end.min(range.bytes);
        out.push((
            Memory::Buffer(
                buffer,
                offset.saturating_add(start),
                offset.saturating_add(end),
            ),
            read,
        ));
    }
}

/// `vkCmdDraw`: reads the vertices and instances it fetches.
#[inline]
pub(crate) fn draw<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    vertices: (u32, u32),
    instances: (u32, u32),
) -> Result<()> {
    let key = DrawKey::new(0, vertices, instances);
    unless_unchanged(recorder, facts, key, draw_tracked)
}

/// A draw's tracking (`tracked`), unless the last draw's verdict stands: the same
/// parameters with nothing changed since.
#[inline]
fn unless_unchanged<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    key: DrawKey,
    tracked: fn(&mut Recorder<'_, S>, &Facts, DrawKey) -> Result<()>,
) -> Result<()> {
    if UNTRACKED || recorder.hazard_draw_unchanged(key) {
        return Ok(());
    }
    tracked(recorder, facts, key)
}

/// [`draw`] past the check that the last draw's verdict stands.
#[inline(never)]
fn draw_tracked<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    key: DrawKey,
) -> Result<()> {
    let mut list = Reads::new();
    vertex_memory(
        recorder,
        Some((u64::from(key.first), u64::from(key.count))),
        (u64::from(key.first_instance), u64::from(key.instances)),
        &mut list,
        facts.vertex,
    );
    draw_reads(recorder, facts, list, key)
}

/// A draw's reads (its vertices and indices in `list`, then its descriptors):
/// checked and recorded, and the next draw with the same parameters and nothing
/// changed lets skip them, unless this one wrote (a second write after it would be
/// a hazard).
fn draw_reads<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    mut list: Reads,
    key: DrawKey,
) -> Result<()> {
    descriptor_memory(recorder, 0, &mut list);
    reads(recorder, facts.name, &list)?;
    if list.iter().all(|(_, u)| !u.write) {
        recorder.hazard_draw_recorded(key);
    }
    Ok(())
}

/// `vkCmdDrawIndexed`: reads its indices, and the vertices and instances it fetches.
#[inline]
pub(crate) fn draw_indexed<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    indices: (u32, u32),
    instances: (u32, u32),
) -> Result<()> {
    let key = DrawKey::new(1, indices, instances);
    unless_unchanged(recorder, facts, key, draw_indexed_tracked)
}

/// [`draw_indexed`] past the check that the last draw's verdict stands.
#[inline(never)]
fn draw_indexed_tracked<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    key: DrawKey,
) -> Result<()> {
    let mut list = Reads::new();
    let (first_index, index_count) = (u64::from(key.first), u64::from(key.count));
    if let Some((_, offset, ty)) = recorder.bound[0].index {
        let size: u64 = match ty {
            vk::IndexType::UINT16 => 2,
            vk::IndexType::UINT8_EXT => 1,
            _ => 4,
        };
        let start = offset.saturating_add(first_index.saturating_mul(size));
        let end = start.saturating_add(index_count.saturating_mul(size));
        let buffer = recorder.bound[0].index_buffer;
        if index_count > 0 {
            list.push((Memory::Buffer(buffer, start, end), facts.index));
        }
    }
    vertex_memory(
        recorder,
        None,
        (u64::from(key.first_instance), u64::from(key.instances)),
        &mut list,
        facts.vertex,
    );
    draw_reads(recorder, facts, list, key)
}

/// The memory a draw or dispatch reaches through the sets bound at bind point
/// `bind` (0: graphics, 1: compute), as the bound pipeline's shaders use it
/// (`PipelineRecord::descriptor_uses`): each image view's subresources, each buffer
/// descriptor's range. Input attachments are the render pass's to order; a
/// dynamic buffer descriptor is not tracked.
fn descriptor_memory<S: Scope>(recorder: &Recorder<'_, S>, bind: usize, out: &mut Reads) {
    use crate::state::SlotKind;
    let bound = &recorder.bound[bind];
    let Some(pipeline) = &bound.pipeline else {
        return;
    };
    for u in pipeline.descriptor_uses.iter() {
        let Some(Some(list)) = bound.images.get(u.set as usize) else {
            continue;
        };
        let slots = list
            .iter()
            .filter(|((b, e), _)| *b == u.binding && (u.count == 0 || *e < u.count));
        for (_, d) in slots {
            let m = match (d.kind, d.bytes) {
                (SlotKind::Image, _) => Memory::Image(d.image, d.sel, EVERY_TEXEL),
                (SlotKind::Buffer | SlotKind::TexelBuffer, Some((s, e))) => {
                    Memory::Buffer(d.buffer, s, e)
                }
                _ => continue,
            };
            let usage = Use {
                stage: u.stage,
                access: u.access,
                write: u.write,
            };
            out.push((m, usage));
        }
    }
}

/// `vkCmdDrawIndirect` and `vkCmdDrawIndexedIndirect` (`indexed`): read their
/// parameters, the whole bound index range and each bound vertex buffer the
/// pipeline fetches from (which vertices the parameters pick is not known here), and
/// their descriptors.
pub(crate) fn draw_indirect<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    buffer: &Buffer,
    (offset, draw_count, stride): (u64, u32, u32),
    indexed: bool,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let size: u64 = if indexed { 20 } else { 16 };
    let mut list = Reads::new();
    if draw_count > 0 {
        let last = u64::from(draw_count - 1).saturating_mul(u64::from(stride));
        let end = offset.saturating_add(last).saturating_add(size);
        list.push((Memory::Buffer(buffer.raw(), offset, end), facts.indirect));
    }
    if indexed {
        if let Some((bytes, offset, _)) = recorder.bound[0].index {
            let buffer = recorder.bound[0].index_buffer;
            list.push((Memory::Buffer(buffer, offset, bytes), facts.index));
        }
    }
    vertex_memory(recorder, None, (0, u64::MAX), &mut list, facts.vertex);
    descriptor_memory(recorder, 0, &mut list);
    reads(recorder, facts.name, &list)
}

/// `vkCmdDispatch` and `vkCmdDispatchBase`: what the bound compute pipeline's
/// shader reaches through its descriptors.
pub(crate) fn dispatch<S: Scope>(recorder: &mut Recorder<'_, S>, facts: &Facts) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let mut list = Reads::new();
    descriptor_memory(recorder, 1, &mut list);
    reads(recorder, facts.name, &list)
}

/// `vkCmdDispatchIndirect`: its parameters, and its descriptors.
pub(crate) fn dispatch_indirect<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    buffer: &Buffer,
    offset: u64,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let mut list = Reads::new();
    // VkDispatchIndirectCommand: three 32-bit counts.
    let params = Memory::Buffer(buffer.raw(), offset, offset.saturating_add(12));
    list.push((params, facts.indirect));
    descriptor_memory(recorder, 1, &mut list);
    reads(recorder, facts.name, &list)
}

/// A draw's or dispatch's accesses: checked and recorded, unless every one is a
/// read the tracker already holds with nothing changed since (the next draw of a run
/// on one state reads what the last one read, and the verdict is the same).
fn reads<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    name: &'static str,
    list: &[(Memory, Use)],
) -> Result<()> {
    if list.is_empty() {
        return Ok(());
    }
    if list.iter().all(|(_, u)| !u.write)
        && recorder
            .hazards
            .holds_reads(list.iter().map(|(m, u)| (m, u.stage)))
    {
        return Ok(());
    }
    touch(recorder, name, list)?;
    recorder.hazards.remember_reads(
        list.iter()
            .filter(|(_, u)| !u.write)
            .map(|(m, u)| (*m, u.stage)),
    );
    Ok(())
}

/// `vkCmdFillBuffer`: writes the range.
pub(crate) fn fill_buffer<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    dst_buffer: &Buffer,
    dst_offset: vk::DeviceSize,
    size: vk::DeviceSize,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let m = bytes(dst_buffer.raw(), dst_offset, size);
    touch(recorder, facts.name, &[(m, facts.dst)])
}

/// `vkCmdUpdateBuffer`: writes the range.
pub(crate) fn update_buffer<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    dst_buffer: &Buffer,
    dst_offset: vk::DeviceSize,
    data: &[u8],
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let m = bytes(dst_buffer.raw(), dst_offset, data.len() as u64);
    touch(recorder, facts.name, &[(m, facts.dst)])
}

/// A command between images, or one that clears one: reads the subresources its
/// source side names, writes those of its destination side.
pub(crate) fn images<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    names: Names<'_>,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let sides = names.sides();
    let list: Reads = sides
        .read
        .into_iter()
        .map(|(i, s, t)| (Memory::Image(i, s, t), facts.src))
        .chain(
            sides
                .written
                .into_iter()
                .map(|(i, s, t)| (Memory::Image(i, s, t), facts.dst)),
        )
        .collect();
    touch(recorder, facts.name, &list)
}

/// A copy between a buffer and an image, `to_image` saying which way: the bytes of
/// the buffer each region reaches (Buffer and Image Addressing over the image's
/// recorded format), and the image's texels.
fn buffer_image<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    (buffer, image, to_image): (vk::Buffer, vk::Image, bool),
    regions: impl Iterator<Item = crate::special::copies::Region> + Clone,
) -> Result<()> {
    let (buffer_use, image_use) = match to_image {
        true => (facts.src, facts.dst),
        false => (facts.dst, facts.src),
    };
    let mut list = Reads::new();
    if let Some(format) = recorder.device().live().image(image).map(|r| r.format) {
        list.extend(regions.clone().map(|r| {
            let end = r.buffer_end(format).unwrap_or(u64::MAX);
            (Memory::Buffer(buffer, r.offset, end), buffer_use)
        }));
    }
    list.extend(regions.map(|r| {
        let texels = crate::special::image_layouts::boxed(r.image_offset, r.extent);
        (
            Memory::Image(image, Sel::layers(&r.subresource), texels),
            image_use,
        )
    }));
    touch(recorder, facts.name, &list)
}

/// `vkCmdCopyBufferToImage`.
pub(crate) fn copy_buffer_to_image<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    src_buffer: &Buffer,
    dst_image: &Image,
    regions: &[vk::BufferImageCopy],
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let r = regions.iter().map(Into::into);
    buffer_image(
        recorder,
        facts,
        (src_buffer.raw(), dst_image.raw(), true),
        r,
    )
}

/// `vkCmdCopyImageToBuffer`.
pub(crate) fn copy_image_to_buffer<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    src_image: &Image,
    dst_buffer: &Buffer,
    regions: &[vk::BufferImageCopy],
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let r = regions.iter().map(Into::into);
    buffer_image(
        recorder,
        facts,
        (dst_buffer.raw(), src_image.raw(), false),
        r,
    )
}

/// `vkCmdCopyBufferToImage2`.
pub(crate) fn copy_buffer_to_image2<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    info: &CopyBufferToImageInfo2<'_>,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let raw = info.as_raw();
    // SAFETY: the safe struct stores the array with its length.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    let r = regions.iter().map(Into::into);
    buffer_image(recorder, facts, (raw.src_buffer, raw.dst_image, true), r)
}

/// `vkCmdCopyImageToBuffer2`.
pub(crate) fn copy_image_to_buffer2<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    info: &CopyImageToBufferInfo2<'_>,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let raw = info.as_raw();
    // SAFETY: the safe struct stores the array with its length.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    let r = regions.iter().map(Into::into);
    buffer_image(recorder, facts, (raw.dst_buffer, raw.src_image, false), r)
}

/// Applies one command's barriers: each image barrier's layout transition is checked
/// against what came before (it writes the image between the two scopes); the
/// memory barriers and every barrier's execution dependency order everything, each
/// buffer and image barrier its memory.
fn apply<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    name: &'static str,
    barriers: &Barriers,
    command_stages: Option<(u64, u64)>,
) -> Result<()> {
    let (live, hazards) = recorder.hazards_mut();
    let cmd = hazards.next(name);
    let of = |s: &crate::special::barriers::Scopes| {
        Barrier::new(
            s.src_stage.as_raw(),
            s.src_access.as_raw(),
            s.dst_stage.as_raw(),
            s.dst_access.as_raw(),
        )
    };
    // Each barrier's scopes, expanded once.
    let buffer_scopes: SmallVec<[Barrier; 2]> =
        barriers.buffers.iter().map(|b| of(&b.scopes)).collect();
    let image_scopes: SmallVec<[Barrier; 2]> =
        barriers.images.iter().map(|b| of(&b.scopes)).collect();
    let transitions = || {
        barriers
            .images
            .iter()
            .zip(&image_scopes)
            .filter(|(b, _)| b.layouts.0 != b.layouts.1)
    };
    for (b, scope) in transitions() {
        let sel = Sel::range(&b.range);
        if let Some(h) = hazards.transition_hazard(b.image, &sel, scope, cmd) {
            return Err(refuse(&h, &Memory::Image(b.image, sel, EVERY_TEXEL)));
        }
    }
    // Every barrier is an execution dependency of everything; a memory barrier a
    // memory dependency of all memory. The first version's barriers share the
    // command's stages: each distinct one is applied once (applying one twice
    // changes nothing).
    let mut global: SmallVec<[Barrier; 4]> = SmallVec::new();
    let executions = buffer_scopes
        .iter()
        .chain(&image_scopes)
        .map(Barrier::execution);
    let stages = command_stages.map(|(src, dst)| Barrier::new(src, 0, dst, 0));
    for b in barriers
        .memory
        .iter()
        .map(of)
        .chain(executions)
        .chain(stages)
    {
        if !global.contains(&b) {
            global.push(b);
        }
    }
    hazards.apply_global(&global);
    for (b, scope) in barriers.buffers.iter().zip(&buffer_scopes) {
        let (offset, size) = b.range;
        let end = if size == vk::WHOLE_SIZE {
            u64::MAX
        } else {
            offset.saturating_add(size)
        };
        hazards.apply_buffer(b.buffer, offset, end, scope);
    }
    for (b, scope) in barriers.images.iter().zip(&image_scopes) {
        let sel = Sel::range(&b.range);
        let transition = (b.layouts.0 != b.layouts.1).then_some(cmd);
        hazards.apply_image(live, b.image, &sel, scope, transition);
    }
    Ok(())
}

/// `vkCmdPipelineBarrier`, and `vkCmdWaitEvents` (whose wait orders what its events'
/// sets ordered before them, at most what the barrier's masks name).
pub(crate) fn pipeline_barrier<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    (src_stage_mask, dst_stage_mask): (vk::PipelineStageFlags, vk::PipelineStageFlags),
    memory_barriers: &[MemoryBarrier<'_>],
    buffer_memory_barriers: &[BufferMemoryBarrier<'_>],
    image_memory_barriers: &[ImageMemoryBarrier<'_>],
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let barriers = Barriers::of(
        (src_stage_mask, dst_stage_mask),
        memory_barriers,
        buffer_memory_barriers,
        image_memory_barriers,
    );
    let stages = (
        u64::from(src_stage_mask.as_raw()),
        u64::from(dst_stage_mask.as_raw()),
    );
    apply(recorder, facts.name, &barriers, Some(stages))
}

/// `vkCmdPipelineBarrier2`, and each dependency of `vkCmdWaitEvents2`.
pub(crate) fn pipeline_barrier2<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    dependency_infos: &[&DependencyInfo<'_>],
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    for d in dependency_infos {
        apply(recorder, facts.name, &Barriers::of2(d), None)?;
    }
    Ok(())
}

/// The access of a load (`store == false`) or store operation of an attachment's
/// color or depth (`depth`) or stencil aspect, if it makes one.
fn edge_access(
    depth: bool,
    (load, store): (vk::AttachmentLoadOp, vk::AttachmentStoreOp),
    is_store: bool,
) -> Option<(u64, u64, bool)> {
    // COLOR_ATTACHMENT_OUTPUT, EARLY and LATE_FRAGMENT_TESTS; the attachment access types.
    const OUTPUT: u64 = 0x400;
    const EARLY: u64 = 0x100;
    const LATE: u64 = 0x200;
    let (read, write) = match depth {
        false => (0x80, 0x100),
        true => (0x200, 0x400),
    };
    if is_store {
        if store == vk::AttachmentStoreOp::NONE {
            return None;
        }
        return Some((if depth { LATE } else { OUTPUT }, write, true));
    }
    let stage = if depth { EARLY } else { OUTPUT };
    match load {
        vk::AttachmentLoadOp::LOAD => Some((stage, read, false)),
        vk::AttachmentLoadOp::NONE_EXT => None,
        _ => Some((stage, write, true)),
    }
}

/// An attachment's subresources in two parts: the color or depth aspect, and the
/// stencil aspect (empty where the format has none), each with whether its access
/// types are the depth/stencil ones and whether it is the stencil part.
fn aspects(sel: Sel) -> [(Sel, bool, bool); 2] {
    let (d, st) = (vk::ImageAspectFlags::DEPTH, vk::ImageAspectFlags::STENCIL);
    let part = |aspect| Sel { aspect, ..sel };
    [
        (part(sel.aspect & !st), sel.aspect.contains(d), false),
        (part(sel.aspect & st), true, true),
    ]
}

/// The layout transitions and load operations of the attachments a subpass uses
/// first, under the dependencies into it: each transition and access is checked
/// against what came before, then recorded.
fn subpass_begins<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    name: &'static str,
    record: Option<Vrc<crate::state::RenderPassRecord>>,
    subpass: u32,
) -> Result<()> {
    let (Some(record), Some(memory)) = (record, recorder.pass_memory.clone()) else {
        return recorder_next(recorder, name);
    };
    let edges = &record.edges;
    let (Some(into), Some(transition_barrier)) = (
        edges.into.get(subpass as usize),
        edges.first_transitions.get(subpass as usize),
    ) else {
        return recorder_next(recorder, name);
    };
    let mut transitions: SmallVec<[(vk::Image, Sel); 4]> = SmallVec::new();
    let mut accesses: SmallVec<[(Memory, Use); 4]> = SmallVec::new();
    for (a, b) in record.boundaries.iter().enumerate() {
        let Some((_, layout, stencil_layout)) = b.first.filter(|f| f.0 == subpass) else {
            continue;
        };
        let Some(Some((image, sel))) = memory.get(a) else {
            continue;
        };
        let layouts = record.layouts[a];
        for (part, depth, stencil) in aspects(*sel) {
            if part.aspect.is_empty() {
                continue;
            }
            let (initial, now, load) = match stencil {
                false => (layouts.initial, layout, b.load.0),
                true => (layouts.stencil_initial, stencil_layout, b.load.1),
            };
            if initial != now {
                transitions.push((*image, part));
            }
            let op = (load, vk::AttachmentStoreOp::STORE);
            if let Some((stage, access, write)) = edge_access(depth || stencil, op, false) {
                accesses.push((
                    Memory::Image(*image, part, EVERY_TEXEL),
                    Use {
                        stage,
                        access,
                        write,
                    },
                ));
            }
        }
    }
    let (live, hazards) = recorder.hazards_mut();
    let cmd = hazards.next(name);
    for (image, sel) in &transitions {
        if let Some(h) = hazards.transition_hazard(*image, sel, transition_barrier, cmd) {
            return Err(refuse(&h, &Memory::Image(*image, *sel, EVERY_TEXEL)));
        }
    }
    if !into.is_empty() {
        hazards.apply_global(into);
    }
    for (image, sel) in &transitions {
        hazards.apply_image(live, *image, sel, transition_barrier, Some(cmd));
    }
    for (m, u) in &accesses {
        if let Some(h) = hazards.hazard(m, &usage(u, cmd)) {
            return Err(refuse(&h, m));
        }
    }
    for (m, u) in &accesses {
        hazards.record(live, m, usage(u, cmd));
    }
    Ok(())
}

/// Counts a command that touches nothing the tracker knows.
fn recorder_next<S: Scope>(recorder: &mut Recorder<'_, S>, name: &'static str) -> Result<()> {
    recorder.hazards.next(name);
    Ok(())
}

/// `vkCmdBeginRenderPass` and `vkCmdBeginRenderPass2`: the dependencies from outside
/// into the first subpass, the layout transitions and load operations of the
/// attachments it uses first.
pub(crate) fn begin_render_pass<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    begin: &RenderPassBeginInfo<'_>,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let raw = begin.as_raw();
    flush_before_instance(recorder);
    // The instance is not begun yet: its render pass's record is looked up here.
    let live = recorder.device().live();
    let record = live.render_pass(raw.render_pass);
    recorder.pass_memory = live.framebuffer_memory(raw.framebuffer);
    subpass_begins(recorder, facts.name, record, 0)
}

/// With automatic synchronization on, makes every write recorded since the last
/// such barrier visible to what a render pass instance's commands do (read
/// parameters, indices, vertices and descriptors, use attachments): inside the
/// instance no barrier can be recorded, and which memory its draws will read is not
/// known yet. One barrier, only when something was written.
fn flush_before_instance<S: Scope>(recorder: &mut Recorder<'_, S>) {
    // DRAW_INDIRECT, VERTEX_INPUT, VERTEX_SHADER, FRAGMENT_SHADER,
    // EARLY_FRAGMENT_TESTS, LATE_FRAGMENT_TESTS, COLOR_ATTACHMENT_OUTPUT.
    const STAGES: u64 = 0x2 | 0x4 | 0x8 | 0x80 | 0x100 | 0x200 | 0x400;
    // INDIRECT_COMMAND_READ to DEPTH_STENCIL_ATTACHMENT_WRITE: what those stages do.
    const ACCESS: u64 = 0x7ff;
    order_what_came_before(recorder);
    let (stages, access) = recorder.hazards.pending;
    if !recorder.hazards.auto || stages == 0 {
        return;
    }
    order(recorder, (stages, access, STAGES, ACCESS));
    recorder.hazards.pending = (0, 0);
}

/// `vkCmdNextSubpass` and `vkCmdNextSubpass2`: the dependencies into the next
/// subpass, and the attachments it uses first.
pub(crate) fn next_subpass<S: Scope>(recorder: &mut Recorder<'_, S>, facts: &Facts) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    match recorder.instance.as_ref() {
        Some(i) => {
            let (record, next) = (i.record.clone(), i.subpass + 1);
            subpass_begins(recorder, facts.name, record, next)
        }
        None => recorder_next(recorder, facts.name),
    }
}

/// `vkCmdEndRenderPass` and `vkCmdEndRenderPass2`: the store operations of the
/// attachments, their final layout transitions, and the dependencies out of the
/// render pass.
pub(crate) fn end_render_pass<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let record = recorder.instance.as_ref().and_then(|i| i.record.clone());
    let (Some(record), Some(memory)) = (record, recorder.pass_memory.take()) else {
        return recorder_next(recorder, facts.name);
    };
    let (out, transition_barrier) = (&record.edges.out, &record.edges.last_transition);
    let mut stores: SmallVec<[(Memory, Use); 4]> = SmallVec::new();
    let mut transitions: SmallVec<[(vk::Image, Sel); 4]> = SmallVec::new();
    for (a, b) in record.boundaries.iter().enumerate() {
        let Some((_, layout, stencil_layout)) = b.last else {
            continue;
        };
        let Some(Some((image, sel))) = memory.get(a) else {
            continue;
        };
        let layouts = record.layouts[a];
        for (part, depth, stencil) in aspects(*sel) {
            if part.aspect.is_empty() {
                continue;
            }
            let (last, now, store) = match stencil {
                false => (layouts.last, layout, b.store.0),
                true => (layouts.stencil_last, stencil_layout, b.store.1),
            };
            let op = (vk::AttachmentLoadOp::LOAD, store);
            if let Some((stage, access, write)) = edge_access(depth || stencil, op, true) {
                stores.push((
                    Memory::Image(*image, part, EVERY_TEXEL),
                    Use {
                        stage,
                        access,
                        write,
                    },
                ));
            }
            if last != now {
                transitions.push((*image, part));
            }
        }
    }
    let (live, hazards) = recorder.hazards_mut();
    let cmd = hazards.next(facts.name);
    // The stores follow the instance's own accesses of the attachment, which the
    // render pass orders: recorded, not checked.
    for (m, u) in &stores {
        hazards.record_ordered(live, m, usage(u, cmd));
    }
    for (image, sel) in &transitions {
        if let Some(h) = hazards.transition_hazard(*image, sel, transition_barrier, cmd) {
            return Err(refuse(&h, &Memory::Image(*image, *sel, EVERY_TEXEL)));
        }
    }
    if !out.is_empty() {
        hazards.apply_global(out);
    }
    for (image, sel) in &transitions {
        hazards.apply_image(live, *image, sel, transition_barrier, Some(cmd));
    }
    Ok(())
}

/// `vkCmdExecuteCommands`: replays what each secondary's recording did (its
/// accesses and barriers, in order) on the recording's, as if recorded here; a
/// hazard between a secondary's command and what came before refuses the command,
/// or (automatic synchronization, outside a render pass instance) gets the barrier
/// that orders it before the secondaries.
pub(crate) fn execute_commands<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    facts: &Facts,
    command_buffers: &[&crate::handles::CommandBuffer],
) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    let logs: Vec<_> = command_buffers
        .iter()
        .filter_map(|cb| cb.uses().hazards())
        .collect();
    order_what_came_before(recorder);
    let live = recorder.device().live();
    // Found on a copy first: a refused command changes nothing.
    let mut trial = recorder.hazards.clone();
    let mut found = logs
        .iter()
        .find_map(|log| trial.replay(live, log, SECONDARY, true).err());
    if let Some(f) = &found {
        if recorder.hazards.auto && recorder.instance.is_none() {
            let (h, m) = (**f).clone();
            order(recorder, needed(&[(h, m)]));
            let live = recorder.device().live();
            trial = recorder.hazards.clone();
            found = logs
                .iter()
                .find_map(|log| trial.replay(live, log, SECONDARY, true).err());
        }
    }
    if let Some(f) = found {
        let (h, m) = *f;
        return Err(refuse(&h, &m));
    }
    trial.next(facts.name);
    recorder.hazards = trial;
    Ok(())
}

/// The submission number that labels a secondary's commands replayed in a primary.
const SECONDARY: u32 = u32::MAX;

/// One batch of a submission, as the hazard checks read it: the stages its
/// semaphore waits block (synchronization2's bits; the first version's are the same
/// numbers), and its command buffers in order.
pub(crate) struct Batch {
    pub(crate) waits: SmallVec<[u64; 2]>,
    pub(crate) command_buffers: SmallVec<[vk::CommandBuffer; 2]>,
}

/// Before a submission to `queue`: replays what each of its command buffers did
/// (their recordings' accesses and barriers), batch by batch, on what the queue's
/// submissions not known complete did; a batch's semaphore waits order everything
/// before them (a signal covers every access before it, its wait makes them visible
/// to the stages it blocks). The first hazard refuses the submission.
///
/// Other queues' submissions are not seen: what they do is not compared.
pub(crate) fn submit_checks(queue: &crate::handles::Queue, batches: &[Batch]) -> Result<()> {
    if UNTRACKED {
        return Ok(());
    }
    // ALL_COMMANDS with MEMORY_WRITE; MEMORY_READ and MEMORY_WRITE.
    const ALL: u64 = 0x10000;
    const READ: u64 = 0x8000;
    const WRITE: u64 = 0x10000;
    let device = queue.parent();
    let live = device.live();
    let mut queues = live.hazard_queues.lock();
    let q = queues.entry(queue.raw().as_raw()).or_default();
    let number = q.begin(live);
    let cbs = batches
        .iter()
        .flat_map(|b| b.command_buffers.iter().copied())
        .collect();
    let mut replayed = Replayed::new(number, cbs);
    for (i, batch) in batches.iter().enumerate() {
        let waits: SmallVec<[Barrier; 1]> = batch
            .waits
            .iter()
            .map(|stages| Barrier::new(ALL, WRITE, *stages, READ | WRITE))
            .collect();
        q.wait(&mut replayed, waits);
        for (j, raw) in batch.command_buffers.iter().enumerate() {
            let Some(log) = device.command_buffer_uses(*raw).and_then(|u| u.hazards()) else {
                continue;
            };
            if let Err(found) = q.replay(live, &mut replayed, &log) {
                let (h, m) = *found;
                return Err(Error::Validation {
                    vuid: id(h.kind),
                    message: format!(
                        "batch {i}, command buffer {j}: {}",
                        h.message(&m.describe())
                    ),
                });
            }
        }
    }
    q.stage(replayed);
    Ok(())
}

/// A submission of `cbs` to `queue` was made as `sub`: what it does is now the
/// queue's, if its check passed.
pub(crate) fn submitted(
    queue: &crate::handles::Queue,
    sub: &tuff_runtime::Vrc<crate::state::Submission>,
    cbs: &[vk::CommandBuffer],
) {
    let live = queue.parent().live();
    if let Some(q) = live.hazard_queues.lock().get_mut(&queue.raw().as_raw()) {
        q.made(live, sub, cbs);
    }
}
