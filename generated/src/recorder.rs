//! Command-buffer recording as types: commands exist only on a [`Recorder`], which
//! only [`CommandBuffer::begin`] makes, and render-pass-only commands exist only on a
//! recorder inside a render pass (video coding commands likewise inside a video
//! coding scope). Whatever a recorded command refers to is kept
//! alive by the command buffer, and by the fence of every submission of it.

use crate::handles::{CommandBuffer, Device};
use crate::state::Uses;
use crate::state::{dynamic_bit, DepthStencil};
use crate::{Error, Handle, Result};
use ash::vk;
use core::marker::PhantomData;
use smallvec::SmallVec;
use tuff_runtime::{Retained, Vrc};

/// Any recording state, inside a video coding scope or not: the commands Vulkan
/// allows in both exist on a recorder in any [`Scope`].
pub trait Scope {}
/// A recording state outside any video coding scope: every state but
/// [`InVideoCoding`]. Most commands exist only here (`VUID-*-videocoding`), so code
/// generic over the state a draw or a bind is recorded in names this bound.
pub trait State: Scope {}
/// A state inside a render pass instance (a render pass or dynamic rendering).
pub trait Inside: State {}
/// A state outside any render pass instance: [`Outside`], or inside a video coding
/// scope, which is never in a render pass instance.
pub trait OutsideRenderPass: Scope {}

/// Recording, outside any render pass instance.
///
/// ```no_run
/// # fn f(cb: &mut tuff::CommandBuffer, begin: &tuff::RenderPassBeginInfo<'_>) -> tuff::Result<()> {
/// let rec: tuff::Recorder<'_, tuff::Outside> = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
/// // Beginning a render pass moves the recorder into the other state, and ending
/// // it moves it back: a draw outside one does not compile.
/// let inside: tuff::Recorder<'_, tuff::InRenderPass> =
///     rec.begin_render_pass(begin, tuff::vk::SubpassContents::INLINE);
/// let rec = inside.end_render_pass();
/// rec.end()?;
/// # Ok(()) }
/// ```
#[derive(Debug)]
pub struct Outside;
/// Recording inside a render pass begun with `begin_render_pass` (see
/// [`Outside`]'s example).
#[derive(Debug)]
pub struct InRenderPass;
/// Recording inside dynamic rendering begun with `begin_rendering`.
#[derive(Debug)]
pub struct InRendering;
/// Recording inside a video coding scope begun with `begin_video_coding_khr`:
/// video commands, and those Vulkan allows in both.
#[derive(Debug)]
pub struct InVideoCoding;
/// Recording a secondary command buffer that continues a render pass instance begun
/// in the primary that executes it ([`CommandBuffer::begin_continuing`]): commands
/// of a render pass instance, but neither its end nor its next subpass.
#[derive(Debug)]
pub struct Continuing;

impl State for Outside {}
impl State for InRenderPass {}
impl State for InRendering {}
impl State for Continuing {}
impl Scope for Outside {}
impl Scope for InRenderPass {}
impl Scope for InRendering {}
impl Scope for Continuing {}
impl Scope for InVideoCoding {}
impl Inside for InRenderPass {}
impl Inside for InRendering {}
impl Inside for Continuing {}
impl OutsideRenderPass for Outside {}
impl OutsideRenderPass for InVideoCoding {}

/// The [`Recorder::verified`] bit of the hazard tracker's last draw: set when a
/// draw's reads were recorded, cleared with the others by any change of state.
const HAZARD_DRAW: u8 = 1 << 4;

/// The [`Recorder::verified`] bit of the last draw's parameter checks (its index,
/// vertex and instance ranges): set when they passed, cleared with the others by any
/// change of state.
const DRAW_PARAMS: u8 = 1 << 5;

/// The [`Recorder::verified`] bits of the descriptor layouts the last draw (bit 6)
/// or dispatch (bit 7) required: a run on one state requires the same.
const LAYOUTS_USED: u8 = 1 << 6;

/// A draw's parameters, as its range checks read them: the command (its range rule's
/// identifier), the first and count of its indices or vertices, its first instance
/// and instance count, and its vertex offset.
pub(crate) type DrawParams = (&'static str, [u32; 4], i32);

/// Tells the buffer's lifecycle state when its recorder goes, however it goes.
struct Alive(Vrc<Uses>);

impl Drop for Alive {
    fn drop(&mut self) {
        self.0.set_recorder(false);
    }
}

/// What a recorder has bound at one bind point. Its lists hold the first few sets
/// and vertex bindings inline: a recorder is made per recording, and a frame that
/// binds one set and one vertex buffer then allocates nothing for them.
#[derive(Default)]
pub(crate) struct Bound {
    /// The pipeline's record.
    pub pipeline: Option<Vrc<crate::state::PipelineRecord>>,
    /// The set layouts of the sets bound, by set number.
    pub sets: SmallVec<[Option<Vrc<crate::state::SetLayoutRecord>>; 4]>,
    /// The image descriptors of the sets bound when they were bound, by set number:
    /// an update after that leaves the recording invalid, so they stay what a draw
    /// or dispatch reads.
    pub images: SmallVec<[Option<crate::state::SetImages>; 4]>,
    /// The written slots of the sets bound when they were bound, by set number.
    pub written: SmallVec<[Option<crate::state::SetWritten>; 4]>,
    /// The index buffer bound (graphics only): its size, the offset and index type.
    pub index: Option<(vk::DeviceSize, vk::DeviceSize, vk::IndexType)>,
    /// The index buffer bound, for the hazard tracker.
    pub index_buffer: vk::Buffer,
    /// The vertex-buffer bindings bound (graphics only; the first 64), one bit each.
    pub vertex: u64,
    /// Each binding's bound vertex buffer range, by binding.
    pub vertex_ranges: SmallVec<[Option<VertexRange>; 2]>,
}

/// The range of a bound vertex buffer.
#[derive(Clone, Copy, Debug)]
pub(crate) struct VertexRange {
    /// The buffer bound, and the offset.
    pub buffer: (vk::Buffer, u64),
    /// The bytes past the bound offset (the bound size, if one was given).
    pub bytes: u64,
    /// The stride bound with it (`vkCmdBindVertexBuffers2`), if any.
    pub stride: Option<u64>,
}

impl Bound {
    /// The index of a bind point in [`Recorder::bound`], if the recorder tracks it.
    pub(crate) fn index(bind_point: vk::PipelineBindPoint) -> Option<usize> {
        match bind_point {
            vk::PipelineBindPoint::GRAPHICS => Some(0),
            vk::PipelineBindPoint::COMPUTE => Some(1),
            _ => None,
        }
    }
}

/// The push constants a recording set, as the checks of its draws and dispatches
/// need them.
pub(crate) struct Pushed {
    /// The layout they were pushed with: they are the values of every layout with
    /// the same push-constant ranges (compatible for push constants).
    pub layout: Vrc<crate::state::LayoutRecord>,
    /// The bytes set, one bit each (inline up to 256 bytes, the largest
    /// `maxPushConstantsSize` devices report in practice).
    bytes: SmallVec<[u64; 4]>,
    /// The last push (layout, offset, size): a repeat of it sets nothing new.
    pub last: (vk::PipelineLayout, u32, usize),
}

impl Pushed {
    /// No bytes pushed yet with `layout`.
    pub(crate) fn new(layout: Vrc<crate::state::LayoutRecord>) -> Self {
        Pushed {
            layout,
            bytes: SmallVec::new(),
            last: (vk::PipelineLayout::null(), 0, 0),
        }
    }

    /// Bytes `offset..offset + size` are set.
    pub(crate) fn set(&mut self, offset: u32, size: u32) {
        let end = offset.saturating_add(size) as usize;
        set_bits(&mut self.bytes, offset as usize, end);
    }

    /// The first byte of `start..end` not set, if any.
    pub(crate) fn first_unset(&self, start: u32, end: u32) -> Option<u32> {
        first_clear(&self.bytes, start as usize, end as usize).map(|b| b as u32)
    }
}

/// The first bit of `start..end` clear in `words` (bits past them are clear), a
/// word at a time: a draw reading 128 bytes of push constants tests two words, not
/// 128 bits.
fn first_clear(words: &[u64], start: usize, end: usize) -> Option<usize> {
    let mut at = start;
    while at < end {
        let w = at / 64;
        // Bits `lo..hi` of word `w`.
        let lo = at - w * 64;
        let hi = end.min(w * 64 + 64) - w * 64;
        let clear = !words.get(w).copied().unwrap_or(0) & bit_range(lo, hi);
        if clear != 0 {
            return Some(w * 64 + clear.trailing_zeros() as usize);
        }
        at = w * 64 + hi;
    }
    None
}

/// Bits `lo..hi` of a word (`lo < hi <= 64`) set.
fn bit_range(lo: usize, hi: usize) -> u64 {
    if hi - lo == 64 {
        !0
    } else {
        ((1u64 << (hi - lo)) - 1) << lo
    }
}

/// Sets bits `start..end` of `words` (64 to a word, grown as needed), a word at a
/// time: a push of 128 bytes is two word writes, not 128 bit writes.
fn set_bits(words: &mut SmallVec<[u64; 4]>, start: usize, end: usize) {
    if start >= end {
        return;
    }
    if words.len() * 64 < end {
        words.resize(end.div_ceil(64), 0);
    }
    for w in start / 64..end.div_ceil(64) {
        // Bits `lo..hi` of word `w`.
        let lo = start.max(w * 64) - w * 64;
        let hi = end.min(w * 64 + 64) - w * 64;
        words[w] |= bit_range(lo, hi);
    }
}

/// A dynamic depth, stencil or rasterizer discard value a recording set.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Set {
    /// `vkCmdSetDepthTestEnable`.
    DepthTest(vk::Bool32),
    /// `vkCmdSetDepthWriteEnable`.
    DepthWrite(vk::Bool32),
    /// `vkCmdSetStencilTestEnable`.
    StencilTest(vk::Bool32),
    /// `vkCmdSetStencilOp`: the faces, and the fail, pass and depth-fail operations.
    StencilOp(vk::StencilFaceFlags, [vk::StencilOp; 3]),
    /// `vkCmdSetStencilWriteMask`.
    WriteMask(vk::StencilFaceFlags, u32),
    /// `vkCmdSetRasterizerDiscardEnable`.
    Discard(vk::Bool32),
}

impl Default for DepthStencil {
    /// Values that write both aspects: what a check assumes of a value not set.
    fn default() -> Self {
        DepthStencil {
            depth_test: true,
            depth_write: true,
            stencil_test: true,
            ops: [[vk::StencilOp::REPLACE; 3]; 2],
            masks: [!0; 2],
            discard: false,
        }
    }
}

impl DepthStencil {
    /// Takes a value a recording set.
    pub(crate) fn set(&mut self, value: Set) {
        let faces = |f: vk::StencilFaceFlags| {
            [
                f.contains(vk::StencilFaceFlags::FRONT),
                f.contains(vk::StencilFaceFlags::BACK),
            ]
        };
        match value {
            Set::DepthTest(on) => self.depth_test = on != vk::FALSE,
            Set::DepthWrite(on) => self.depth_write = on != vk::FALSE,
            Set::StencilTest(on) => self.stencil_test = on != vk::FALSE,
            Set::Discard(on) => self.discard = on != vk::FALSE,
            Set::StencilOp(f, ops) => {
                for (i, on) in faces(f).into_iter().enumerate() {
                    if on {
                        self.ops[i] = ops;
                    }
                }
            }
            Set::WriteMask(f, mask) => {
                for (i, on) in faces(f).into_iter().enumerate() {
                    if on {
                        self.masks[i] = mask;
                    }
                }
            }
        }
    }

    /// A pipeline that has the states not in `dynamic` static was bound: the values
    /// set for them before are gone, and a later pipeline that has them dynamic
    /// needs them set again (a partial set, of one stencil face, leaves the other
    /// face at the value that writes).
    pub(crate) fn forget_static(&mut self, dynamic: u32) {
        self.take(&DepthStencil::default(), !dynamic);
    }

    /// Takes from `from` the values of the states in `states` ([`dynamic_bit`]
    /// bits).
    pub(crate) fn take(&mut self, from: &DepthStencil, states: u32) {
        use vk::DynamicState as D;
        let has = |state| states & dynamic_bit(state) != 0;
        if has(D::DEPTH_TEST_ENABLE) {
            self.depth_test = from.depth_test;
        }
        if has(D::DEPTH_WRITE_ENABLE) {
            self.depth_write = from.depth_write;
        }
        if has(D::STENCIL_TEST_ENABLE) {
            self.stencil_test = from.stencil_test;
        }
        if has(D::STENCIL_OP) {
            self.ops = from.ops;
        }
        if has(D::STENCIL_WRITE_MASK) {
            self.masks = from.masks;
        }
        if has(D::RASTERIZER_DISCARD_ENABLE) {
            self.discard = from.discard;
        }
    }

    /// Whether a draw with these values writes depth.
    pub(crate) fn writes_depth(&self) -> bool {
        !self.discard && self.depth_test && self.depth_write
    }

    /// Whether a draw with these values may write stencil: the test enabled, and a
    /// face with a write mask and an operation other than `KEEP`.
    pub(crate) fn writes_stencil(&self) -> bool {
        !self.discard
            && self.stencil_test
            && (0..2).any(|i| {
                self.masks[i] != 0 && self.ops[i].iter().any(|o| *o != vk::StencilOp::KEEP)
            })
    }
}

/// The render pass instance a recorder is inside, as its checks need it.
#[derive(Clone, Debug, Default)]
pub(crate) struct PassInstance {
    /// The current subpass (0 in dynamic rendering).
    pub subpass: u32,
    /// The render pass's subpass count; 0 where it is not known (a render pass the
    /// wrappers did not create, dynamic rendering, a continuing secondary).
    pub subpasses: u32,
    /// The current subpass's view mask (0 without multiview).
    pub view_mask: u32,
    /// The render pass (null in dynamic rendering or a continuing secondary).
    pub render_pass: vk::RenderPass,
    /// Whether the current subpass uses no attachment.
    pub no_attachments: bool,
    /// The sample count of the first graphics pipeline bound in the current subpass.
    pub samples: Option<vk::SampleCountFlags>,
    /// Whether the instance was begun with `vkCmdBeginRendering` (for a continuing
    /// secondary: whether it inherits dynamic rendering).
    pub dynamic: bool,
    /// The render pass's record, which a draw's pipeline must be compatible with.
    pub record: Option<Vrc<crate::state::RenderPassRecord>>,
    /// In dynamic rendering (begun in this recording, or the one a continuing
    /// secondary inherits): its view mask and attachment formats, which a draw's
    /// pipeline must have been made for.
    pub rendering: Option<Vrc<crate::state::RenderingFormats>>,
    /// In dynamic rendering begun in this recording: the layouts of its depth and
    /// stencil attachments that have a view (`None` in a continuing secondary,
    /// whose inheritance info does not give them).
    pub rendering_layouts: Option<(Option<vk::ImageLayout>, Option<vk::ImageLayout>)>,
    /// In dynamic rendering: the sample count of its attachments (the images of
    /// their views, in this recording; the inheritance info's rasterization samples
    /// in a continuing secondary), if it has any.
    pub rendering_samples: Option<vk::SampleCountFlags>,
    /// In dynamic rendering begun in this recording: the images of its attachments'
    /// views and resolve views (`None` in a continuing secondary, whose inheritance
    /// info does not give them).
    pub rendering_images: Option<Vec<vk::Image>>,
    /// The render area and the layer count of the instance (the framebuffer's, or
    /// dynamic rendering's), where the recording began it (`None` in a continuing
    /// secondary, whose inheritance info does not give them).
    pub area: Option<(vk::Rect2D, u32)>,
    /// The device mask of a chained `VkDeviceGroupRenderPassBeginInfo`, where the
    /// recording began the instance with one (otherwise the command buffer's initial
    /// device mask is the instance's).
    pub device_mask: Option<u32>,
    /// How the current subpass's commands are given (a render pass begun in this
    /// recording): inline, or by executing secondaries.
    pub contents: vk::SubpassContents,
    /// The framebuffer of a render pass begun in this recording.
    pub framebuffer: vk::Framebuffer,
    /// The flags of dynamic rendering begun in this recording.
    pub rendering_flags: vk::RenderingFlags,
}

impl PassInstance {
    /// The sample count of the current subpass's color and depth/stencil
    /// attachments, if it uses any and it is known.
    pub(crate) fn attachment_samples(&self) -> Option<vk::SampleCountFlags> {
        if self.dynamic {
            return self.rendering_samples;
        }
        self.record
            .as_ref()?
            .subpass_samples
            .get(self.subpass as usize)
            .copied()
            .flatten()
    }

    /// The layouts of the current subpass's depth/stencil attachment (depth aspect,
    /// stencil aspect; `None` for an aspect it has not), or `None` where they are
    /// not known.
    pub(crate) fn depth_stencil_layouts(
        &self,
    ) -> Option<(Option<vk::ImageLayout>, Option<vk::ImageLayout>)> {
        if self.dynamic {
            return self.rendering_layouts;
        }
        let record = self.record.as_ref()?;
        let layouts = record.depth_layouts.get(self.subpass as usize)?;
        Some(layouts.map_or((None, None), |(d, s)| (Some(d), Some(s))))
    }
}

/// A query begun in the recording and not yet ended.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ActiveQuery {
    /// Its pool.
    pub pool: vk::QueryPool,
    /// Its index in the pool.
    pub query: u32,
    /// The pool's query type.
    pub ty: vk::QueryType,
    /// The subpass it was begun in, or `None` outside a render pass instance.
    pub subpass: Option<u32>,
    /// The control flags it was begun with.
    pub flags: vk::QueryControlFlags,
}

/// A command buffer in the recording state `S`.
///
/// ```no_run
/// # fn f(cb: &mut tuff::CommandBuffer) -> tuff::Result<()> {
/// let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
/// rec.set_line_width(1.0);
/// rec.end()?;
/// # Ok(()) }
/// ```
#[must_use = "a command buffer must be ended before it is submitted"]
pub struct Recorder<'c, S: Scope> {
    cb: &'c mut CommandBuffer,
    /// The command buffer's device and raw handle, held here so a recorded command
    /// reaches ash's table in one step instead of through the pool.
    device: Device,
    raw: vk::CommandBuffer,
    kept: Vec<Retained>,
    /// The address of the last object kept, so a run of commands on one object
    /// (push constants before every draw) keeps it once.
    last: usize,
    /// The record of the pipeline layout last used, so a run of push constants on
    /// one layout looks it up once. The recording keeps the layout alive, so its raw
    /// handle names it for the whole recording.
    layout: Option<(vk::PipelineLayout, Vrc<crate::state::LayoutRecord>)>,
    /// The last push-constant write that passed its checks (layout, stages, offset,
    /// size): the checks depend on nothing else, so a run of equal writes (one before
    /// every draw) is checked once.
    pub(crate) last_push: Option<(vk::PipelineLayout, vk::ShaderStageFlags, u32, usize)>,
    /// The queue flags of the pool's family, read once for the `cmdpool` check of
    /// every recorded command.
    queue_flags: vk::QueueFlags,
    /// What is bound at each bind point (graphics, compute): the pipeline and the
    /// layouts of the sets bound by number.
    pub(crate) bound: [Bound; 2],
    /// The first failed check; later commands are not recorded and `end` returns it.
    poisoned: Option<Error>,
    /// Whether the open render pass instance was not begun because of a failed
    /// check, so its end is not recorded either.
    skipped_begin: bool,
    /// The render pass instance the recorder is inside, if any.
    pub(crate) instance: Option<PassInstance>,
    /// The queries begun and not yet ended.
    pub(crate) queries: Vec<ActiveQuery>,
    /// The types of the queries the recording begins (a primary executing it as a
    /// secondary must have none of them active).
    pub(crate) query_types: Vec<vk::QueryType>,
    /// Whether the recording begins dynamic rendering that suspends or resumes
    /// (only through `begin_rendering_unchecked`).
    pub(crate) suspends: bool,
    /// The image layouts the recording needs at its start and leaves so far.
    pub(crate) layouts: Box<crate::state::layouts::Recording>,
    /// What the recording's commands read and write, and the barriers between.
    pub(crate) hazards: Box<crate::state::hazards::Recording>,
    /// The queries the recording needs reset at its start and leaves so far.
    pub(crate) query_states: crate::state::queries::Recording,
    /// What the recording does to events so far.
    pub(crate) event_states: crate::state::events::Recording,
    /// The images of the render pass instance's attachments, by attachment index.
    pub(crate) pass_images: SmallVec<[vk::Image; 4]>,
    /// The framebuffer's attachments of the render pass instance the recording
    /// began, for the hazard tracker's subpass edges and end (the render pass's
    /// record is the instance's).
    pub(crate) pass_memory: Option<crate::state::AttachmentMemory>,
    /// The descriptor sets bound so far, each with its generation then: an update
    /// that changes it leaves the buffer invalid.
    pub(crate) sets: Vec<(u64, u64)>,
    /// The events the recording's event commands name (set, reset, wait).
    pub(crate) events: Vec<u64>,
    /// The dynamic states set and still valid (no graphics pipeline bound since with
    /// the state static), and those set since the last graphics pipeline was bound,
    /// as [`dynamic_bit`] bits.
    pub(crate) dynamic: (u32, u32),
    /// The dynamic states set since the last compute pipeline was bound, which has
    /// every state static, as [`dynamic_bit`] bits.
    pub(crate) compute_dynamic: u32,
    /// The push constants set so far.
    pub(crate) pushed: Option<Pushed>,
    /// The depth, stencil and rasterizer discard values the recording set.
    pub(crate) depth_stencil: DepthStencil,
    /// The counts last given to `vkCmdSetViewportWithCount` and
    /// `vkCmdSetScissorWithCount`.
    pub(crate) counts: (Option<u32>, Option<u32>),
    /// The bind points (one bit each, as [`Bound::index`] numbers them) whose draw
    /// or dispatch state checks passed with nothing they read changed since: a run
    /// of draws on one state is checked once. Cleared by every recorded command but
    /// the draws, dispatches and push constants, and by every change of state.
    verified: u8,
    /// The parameters of the last draw whose range checks passed ([`DRAW_PARAMS`]).
    draw_params: DrawParams,
    /// The command buffer's initial device mask (`VkDeviceGroupCommandBufferBeginInfo`,
    /// or every physical device of the device).
    pub(crate) device_mask: u32,
    /// Its current device mask: the initial one until `vkCmdSetDeviceMask` sets
    /// another.
    pub(crate) current_device_mask: u32,
    alive: Alive,
    /// The command pool is externally synchronized by every command recorded into
    /// any of its buffers: held for the whole recording.
    pool_sync: tuff_runtime::HostSyncGuard,
    _state: PhantomData<S>,
}

impl<S: Scope> core::fmt::Debug for Recorder<'_, S> {
    /// The command buffer and the state it records in.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let state = core::any::type_name::<S>();
        f.debug_struct("Recorder")
            .field("command_buffer", &self.raw)
            .field("state", &state.rsplit("::").next().unwrap_or(state))
            .field("poisoned", &self.poisoned.is_some())
            .finish_non_exhaustive()
    }
}

impl<'c> Recorder<'c, Outside> {
    /// The recorder of `cb`, whose recording `vkBeginCommandBuffer` just began
    /// (`special/command_buffers.rs`): holding its pool's lock, keeping `kept`, with
    /// `device_mask` as its initial device mask.
    pub(crate) fn began(
        cb: &'c mut CommandBuffer,
        pool_sync: tuff_runtime::HostSyncGuard,
        kept: Vec<Retained>,
        device_mask: u32,
    ) -> Self {
        let queue_flags = cb.parent().queue_flags();
        let hazards = cb.uses().spare_recording();
        let layouts = cb.uses().spare_layouts_box();
        let sets = cb.uses().spare_sets();
        Recorder {
            device: cb.device().clone(),
            raw: cb.raw(),
            alive: Alive(cb.uses().clone()),
            pool_sync,
            cb,
            kept,
            last: 0,
            layout: None,
            last_push: None,
            queue_flags,
            bound: Default::default(),
            poisoned: None,
            skipped_begin: false,
            instance: None,
            queries: Vec::new(),
            query_types: Vec::new(),
            suspends: false,
            layouts,
            hazards,
            query_states: Default::default(),
            event_states: Default::default(),
            pass_images: SmallVec::new(),
            pass_memory: None,
            sets,
            events: Vec::new(),
            dynamic: (0, 0),
            compute_dynamic: 0,
            pushed: None,
            counts: (None, None),
            depth_stencil: DepthStencil::default(),
            verified: 0,
            draw_params: ("", [0; 4], 0),
            device_mask,
            current_device_mask: device_mask,
            _state: PhantomData,
        }
    }
}

impl<'c, S: Scope> Recorder<'c, S> {
    /// The raw command buffer.
    #[inline]
    pub fn raw(&self) -> vk::CommandBuffer {
        self.raw
    }

    /// The device the command buffer belongs to.
    #[inline]
    pub fn device(&self) -> &Device {
        &self.device
    }

    /// The command buffer being recorded.
    #[inline]
    pub fn command_buffer(&self) -> &CommandBuffer {
        self.cb
    }

    /// A command that may change what draw and dispatch checks read was recorded.
    #[inline]
    pub(crate) fn state_changed(&mut self) {
        self.verified = 0;
    }

    /// Whether a draw with these parameters (`key`) would read what the last draw
    /// the hazard tracker recorded read, with nothing recorded since that could
    /// change the verdict: no state changed (the bound pipeline, sets and buffers),
    /// nothing written and no barrier recorded.
    #[inline]
    pub(crate) fn hazard_draw_unchanged(&self, key: crate::state::hazards::DrawKey) -> bool {
        self.verified & HAZARD_DRAW != 0 && self.hazards.last_draw(key)
    }

    /// The hazard tracker recorded a draw's reads (and no write) under `key`.
    #[inline]
    pub(crate) fn hazard_draw_recorded(&mut self, key: crate::state::hazards::DrawKey) {
        self.verified |= HAZARD_DRAW;
        self.hazards.set_last_draw(key);
    }

    /// Runs a draw's checks of its parameters (`params`: the ranges it reads),
    /// unless the last draw's passed with the same parameters and nothing changed
    /// since: they read the parameters and the state only.
    #[inline]
    pub(crate) fn verify_draw_params(
        &mut self,
        params: DrawParams,
        checks: impl FnOnce(&Self) -> Result<()>,
    ) -> Result<()> {
        // The command by its identifier's address: one comparison, not the text's.
        let same =
            |a: &DrawParams, b: &DrawParams| core::ptr::eq(a.0, b.0) && a.1 == b.1 && a.2 == b.2;
        if self.verified & DRAW_PARAMS != 0 && same(&self.draw_params, &params) {
            return Ok(());
        }
        checks(self)?;
        self.verified |= DRAW_PARAMS;
        self.draw_params = params;
        Ok(())
    }

    /// Whether the descriptor layouts a draw (`index` 0) or dispatch (1) requires
    /// were required with nothing changed since; marks them required.
    #[inline]
    pub(crate) fn layouts_used_again(&mut self, index: usize) -> bool {
        let bit = LAYOUTS_USED << index;
        let again = self.verified & bit != 0;
        self.verified |= bit;
        again
    }

    /// Runs `checks` of the state at bind point `index`, unless they passed with
    /// nothing changed since.
    #[inline]
    pub(crate) fn verify_state(
        &mut self,
        index: usize,
        checks: impl FnOnce(&Self) -> Result<()>,
    ) -> Result<()> {
        let bit = 1 << index;
        if self.verified & bit == 0 {
            checks(self)?;
            self.verified |= bit;
        }
        Ok(())
    }

    /// Takes the result of a command's checks: true when the command may be
    /// recorded, false when this or an earlier check failed.
    pub(crate) fn accept(&mut self, r: Result<()>) -> bool {
        if self.poisoned.is_some() {
            return false;
        }
        match r {
            Ok(()) => true,
            Err(e) => {
                self.poisoned = Some(e);
                false
            }
        }
    }

    pub(crate) fn skip_begin(&mut self, skipped: bool) {
        self.skipped_begin = skipped;
    }

    pub(crate) fn begin_skipped(&self) -> bool {
        self.skipped_begin
    }

    /// Keeps an object alive until the command buffer is recorded again or freed.
    #[inline]
    pub fn retain(&mut self, object: Retained) {
        self.last = Retained::as_ptr(&object) as *const () as usize;
        self.kept.push(object);
    }

    /// Keeps the object at `address` alive, unless it is the one kept last; `make`
    /// clones the reference only when it is needed.
    #[inline]
    pub fn retain_with(&mut self, address: usize, make: impl FnOnce() -> Retained) {
        if address != self.last {
            self.retain(make());
        }
    }

    /// The device's records and the recording's image layouts, borrowed together
    /// for a command that changes the layouts.
    pub(crate) fn layouts_mut(
        &mut self,
    ) -> (&crate::state::Live, &mut crate::state::layouts::Recording) {
        (self.device.live(), &mut self.layouts)
    }

    /// Turns automatic synchronization on or off for the commands recorded from now
    /// on. Off (the default), a command that reads or writes memory an earlier
    /// command of the recording wrote or read, with no barrier between that orders
    /// the two, is refused with the hazard (`SYNC-HAZARD-READ-AFTER-WRITE`, ...),
    /// naming both commands and the barrier that would order them. On, tuff records
    /// that barrier itself, one global memory barrier just before the command
    /// (`vkCmdPipelineBarrier2` where synchronization2 is enabled), from the earlier
    /// accesses' stages to the command's. Barriers the recording names itself count
    /// in both modes. On, a copy, blit, resolve or clear that names a transfer
    /// layout (or `GENERAL`) for subresources the recording left in another layout
    /// gets the layout transition before it, and [`Recorder::end`] makes the buffer
    /// writes of the recording visible to the host (one barrier to `HOST`), which a
    /// fence alone does not. Which commands the tracker knows, and what each reads and
    /// writes, is the crate's `sync_tables` (from the registry's sync tables and the
    /// generator's table of per-command facts); the report lists the others.
    ///
    /// ```no_run
    /// # fn f(cb: &mut tuff::CommandBuffer, a: &tuff::Buffer, b: &tuff::Buffer, c: &tuff::Buffer) -> tuff::Result<()> {
    /// let region = [tuff::vk::BufferCopy { src_offset: 0, dst_offset: 0, size: 64 }];
    /// let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
    /// rec.auto_sync(true);
    /// rec.copy_buffer(a, b, &region)?;
    /// // Reads what the copy above wrote: tuff records the barrier between.
    /// rec.copy_buffer(b, c, &region)?;
    /// rec.end()?;
    /// # Ok(()) }
    /// ```
    pub fn auto_sync(&mut self, on: bool) {
        self.hazards.auto = on;
    }

    /// Whether automatic synchronization is on ([`Recorder::auto_sync`]).
    #[inline]
    pub fn is_auto_sync(&self) -> bool {
        self.hazards.auto
    }

    /// Records one global memory barrier with these masks (synchronization2's,
    /// `(src stages, src access, dst stages, dst access)`, as
    /// `vkCmdPipelineBarrier2` where the device enabled synchronization2, else the
    /// first version's masks that cover them) and applies it to the hazard tracker:
    /// automatic synchronization's barrier, outside a render pass instance.
    pub(crate) fn record_memory_barrier(&mut self, (ss, sa, ds, da): (u64, u64, u64, u64)) {
        let live = self.device().live();
        let sync2 = live.with_features(|f| f.v13.synchronization2) != vk::FALSE;
        let fns = self.device().fns();
        let raw = self.raw();
        let recorded = if sync2 {
            let m = [vk::MemoryBarrier2::default()
                .src_stage_mask(vk::PipelineStageFlags2::from_raw(ss))
                .src_access_mask(vk::AccessFlags2::from_raw(sa))
                .dst_stage_mask(vk::PipelineStageFlags2::from_raw(ds))
                .dst_access_mask(vk::AccessFlags2::from_raw(da))];
            let info = vk::DependencyInfo::default().memory_barriers(&m);
            // SAFETY: a recording command buffer outside a render pass instance (the
            // caller's check), synchronization2 enabled (VUID-vkCmdPipelineBarrier2-synchronization2-03848);
            // the stages and access types are those of commands the recording just
            // recorded or is about to, so the queue family supports them and each access
            // type belongs to its stage (VUID-VkMemoryBarrier2-srcAccessMask-03900...).
            unsafe { (fns.fp_v1_3().cmd_pipeline_barrier2)(raw, &info) };
            (ss, sa, ds, da)
        } else {
            let (ss1, sa1) = (
                crate::state::hazards::narrow_stages(ss),
                crate::state::hazards::narrow_access(sa),
            );
            let (ds1, da1) = (
                crate::state::hazards::narrow_stages(ds),
                crate::state::hazards::narrow_access(da),
            );
            let m = [vk::MemoryBarrier::default()
                .src_access_mask(sa1)
                .dst_access_mask(da1)];
            // SAFETY: as above, in the first version's masks, which are not empty
            // (VUID-vkCmdPipelineBarrier-srcStageMask-03937): every hazard has a stage on
            // both sides.
            unsafe {
                (fns.fp_v1_0().cmd_pipeline_barrier)(
                    raw,
                    ss1,
                    ds1,
                    vk::DependencyFlags::empty(),
                    1,
                    m.as_ptr(),
                    0,
                    core::ptr::null(),
                    0,
                    core::ptr::null(),
                )
            };
            (
                u64::from(ss1.as_raw()),
                u64::from(sa1.as_raw()),
                u64::from(ds1.as_raw()),
                u64::from(da1.as_raw()),
            )
        };
        let (_, hazards) = self.hazards_mut();
        hazards.auto_barriers += 1;
        hazards.next("a barrier tuff recorded");
        hazards.apply_global(&[crate::state::hazards::Barrier::new(
            recorded.0, recorded.1, recorded.2, recorded.3,
        )]);
    }

    /// With automatic synchronization on, at the end of a recording: makes the
    /// buffer writes it made visible to the host with one barrier to `HOST`, since a
    /// fence's memory dependency covers device accesses only and a host read of what
    /// the device wrote needs this barrier (the specification's fence signal
    /// operation).
    fn make_visible_to_host(&mut self) {
        // HOST; HOST_READ, HOST_WRITE.
        const HOST: u64 = 0x4000;
        const HOST_ACCESS: u64 = 0x2000 | 0x4000;
        let (stages, access) = self.hazards.buffer_writes;
        if cfg!(tuff_untracked) || !self.hazards.auto || stages == 0 {
            return;
        }
        self.record_memory_barrier((stages, access, HOST, HOST_ACCESS));
        self.hazards.buffer_writes = (0, 0);
    }

    /// The device's records and the recording's hazard tracker, borrowed together.
    pub(crate) fn hazards_mut(
        &mut self,
    ) -> (&crate::state::Live, &mut crate::state::hazards::Recording) {
        (self.device.live(), &mut self.hazards)
    }

    /// The device's records and the recording's query states, borrowed together
    /// for a command that resets or uses queries.
    pub(crate) fn query_states_mut(
        &mut self,
    ) -> (&crate::state::Live, &mut crate::state::queries::Recording) {
        (self.device.live(), &mut self.query_states)
    }

    /// The queue flags of the family of the command buffer's pool.
    #[inline]
    pub(crate) fn pool_queue_flags(&self) -> vk::QueueFlags {
        self.queue_flags
    }

    /// Refuses a command in a primary's subpass begun with
    /// `VK_SUBPASS_CONTENTS_SECONDARY_COMMAND_BUFFERS`, which takes only executing
    /// secondaries and leaving the subpass (a continuing secondary's instance is
    /// inline). The specification says so in prose, with no VUID; the error names
    /// the validation layer's identifier.
    #[inline]
    pub(crate) fn inline_contents_check(&self) -> Result<()> {
        match &self.instance {
            Some(i) if !i.dynamic && i.contents == vk::SubpassContents::SECONDARY_COMMAND_BUFFERS => {
                Err(crate::Error::Validation {
                    vuid: "UNASSIGNED-CoreValidation-DrawState-InvalidCommandBuffer",
                    message: "the current subpass was begun with SECONDARY_COMMAND_BUFFERS contents: only execute_commands, next_subpass and end_render_pass may be recorded in it; record this command in the secondaries it executes".into(),
                })
            }
            _ => Ok(()),
        }
    }

    /// The record of a pipeline layout made through the wrappers.
    pub(crate) fn layout_record(
        &mut self,
        layout: &crate::PipelineLayout,
    ) -> Result<Vrc<crate::state::LayoutRecord>> {
        if let Some((raw, record)) = &self.layout {
            if *raw == layout.raw() {
                return Ok(record.clone());
            }
        }
        let record = self
            .device
            .live()
            .pipeline_layout(layout.raw())
            .ok_or(Error::Misuse(
                "the pipeline layout was not created through the wrappers",
            ))?;
        self.layout = Some((layout.raw(), record.clone()));
        Ok(record)
    }

    pub(crate) fn into_state<T: Scope>(self) -> Recorder<'c, T> {
        Recorder {
            cb: self.cb,
            device: self.device,
            raw: self.raw,
            kept: self.kept,
            last: self.last,
            layout: self.layout,
            last_push: self.last_push,
            queue_flags: self.queue_flags,
            bound: self.bound,
            poisoned: self.poisoned,
            skipped_begin: self.skipped_begin,
            instance: self.instance,
            queries: self.queries,
            query_types: self.query_types,
            suspends: self.suspends,
            layouts: self.layouts,
            hazards: self.hazards,
            query_states: self.query_states,
            event_states: self.event_states,
            pass_images: self.pass_images,
            pass_memory: self.pass_memory,
            sets: self.sets,
            events: self.events,
            dynamic: self.dynamic,
            compute_dynamic: self.compute_dynamic,
            pushed: self.pushed,
            counts: self.counts,
            depth_stencil: self.depth_stencil,
            verified: 0,
            draw_params: self.draw_params,
            device_mask: self.device_mask,
            current_device_mask: self.current_device_mask,
            alive: self.alive,
            pool_sync: self.pool_sync,
            _state: PhantomData,
        }
    }

    /// `vkEndCommandBuffer`, in a state where ending is valid.
    fn finish(self) -> Result<()> {
        // SAFETY: the recorder proves the buffer is recording, and its callers are
        // the states outside a render pass instance begun in this buffer
        // (VUID-vkEndCommandBuffer-commandBuffer-00060).
        let r = unsafe { (self.cb.device().fns().fp_v1_0().end_command_buffer)(self.cb.raw()) };
        if r != vk::Result::SUCCESS {
            return Err(Error::Vk(r));
        }
        self.cb.keep_alive(self.kept);
        if let Some(e) = self.poisoned {
            // The buffer holds only the commands before the failed check: it is
            // ended but not submittable.
            self.cb.uses().ended(false);
            return Err(e);
        }
        self.cb.uses().ended(true);
        self.cb.uses().set_layouts(self.layouts);
        self.cb.uses().set_hazards(self.hazards);
        self.cb.uses().set_queries(self.query_states);
        self.cb.uses().set_event_states(self.event_states);
        self.cb
            .uses()
            .set_query_types(self.query_types, self.suspends);
        self.cb.uses().set_sets(self.sets);
        self.cb.uses().set_events(self.events);
        Ok(())
    }
}

impl<'c> Recorder<'c, Outside> {
    /// `vkEndCommandBuffer`: ends recording; the command buffer can be submitted.
    /// A check of an implicit rule that failed during recording is
    /// returned here, and the buffer cannot be submitted; so is a query of a primary
    /// buffer still active (`VUID-vkEndCommandBuffer-commandBuffer-00061`).
    pub fn end(mut self) -> Result<()> {
        if self.poisoned.is_none()
            && self.cb.level() == vk::CommandBufferLevel::PRIMARY
            && !self.queries.is_empty()
        {
            self.poisoned = Some(Error::Validation {
                vuid: "VUID-vkEndCommandBuffer-commandBuffer-00061",
                message: format!(
                    "If `commandBuffer` is a primary command buffer, there must not be any \
                     active queries ({} begun and not ended)",
                    self.queries.len()
                ),
            });
            // The buffer is not submittable now; its queries are ended so that the
            // driver sees a valid end.
            let end_query = self.device.fns().fp_v1_0().cmd_end_query;
            for q in core::mem::take(&mut self.queries) {
                // SAFETY: the query was begun in this recording, outside a render pass
                // instance (one begun inside was ended with its instance), and is
                // still active.
                unsafe { end_query(self.raw, q.pool, q.query) };
            }
        }
        if self.poisoned.is_none() {
            self.make_visible_to_host();
        }
        self.finish()
    }
}

impl<'c> Recorder<'c, Continuing> {
    /// `vkEndCommandBuffer`: ends recording of a secondary that continues a render
    /// pass instance; a primary inside a compatible instance can execute it.
    pub fn end(self) -> Result<()> {
        self.finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Word-wise setting sets exactly the bits one at a time would, for every
    /// range up to 200 bits into words that already hold some.
    #[test]
    fn set_bits_sets_exactly_the_range() {
        for start in 0..200 {
            for end in 0..200 {
                let mut words: SmallVec<[u64; 4]> = SmallVec::from_slice(&[1 << 63]);
                set_bits(&mut words, start, end);
                for b in 0..256 {
                    let set = words.get(b / 64).is_some_and(|w| w & (1 << (b % 64)) != 0);
                    assert_eq!(
                        set,
                        b == 63 || (start..end).contains(&b),
                        "{start}..{end}: bit {b}"
                    );
                }
            }
        }
    }

    /// Word-wise search finds the first clear bit a bit-by-bit one would, for
    /// every range up to 200 bits over words with a pattern of set runs.
    #[test]
    fn first_clear_finds_the_first_clear_bit() {
        let mut words: SmallVec<[u64; 4]> = SmallVec::new();
        for (s, e) in [(0, 10), (12, 70), (71, 140), (150, 190)] {
            set_bits(&mut words, s, e);
        }
        let bit = |b: usize| words.get(b / 64).is_some_and(|w| w & (1 << (b % 64)) != 0);
        for start in 0..200 {
            for end in 0..200 {
                let want = (start..end).find(|b| !bit(*b));
                assert_eq!(first_clear(&words, start, end), want, "{start}..{end}");
            }
        }
    }
}
