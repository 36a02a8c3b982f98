//! Memory hazards inside one recording: for each buffer range and image subresource
//! the recording touches, its last write and the reads since, and which later
//! stages and access types the barriers recorded since have made them available and
//! visible to. A command whose access is not ordered after a conflicting earlier one
//! (read after write, write after read, write after write, a layout transition after
//! either) by those barriers is a hazard.
//!
//! The model is the specification's, as the validation layer's synchronization
//! validation writes it: a barrier's first scope is its source stages and every stage
//! logically earlier (the registry's `<syncpipeline>` orders), its first access scope
//! only the access types of the stages it names; an access is in a barrier's scope
//! when its own stage and access type are, or when an earlier barrier already chained
//! it to one of those stages. Stages and access types that stand for others (`ALL_TRANSFER`,
//! `SHADER_READ`) are expanded through the registry's `syncequivalent`
//! (`generated/sync_tables.rs`).
//!
//! What the recording found at its start (writes of earlier submissions) is not
//! known here: the first access of each range is never a hazard.

use super::small_map::SmallMap;
use crate::state::layouts::{Sel, Shape};
use crate::state::Live;
use crate::sync_tables::{ACCESSES, EVERY_STAGE, STAGES};
use ash::vk::{self, Handle as _};
use smallvec::{smallvec, SmallVec};
use std::sync::OnceLock;
use tuff_runtime::{Vrc, Vweak};

/// The stage and access-type relations, indexed by bit, built once from the tables.
struct Relations {
    /// For each stage bit: the stages it stands for (itself if none).
    stage: [u64; 64],
    /// For each stage bit: the stages logically earlier.
    earlier: [u64; 64],
    /// For each stage bit: the stages logically later.
    later: [u64; 64],
    /// For each access bit: the access types it stands for (itself if none).
    access: [u64; 64],
    /// For each access bit: the stages it may be used with.
    access_stages: [u64; 64],
    /// Every access type that writes.
    writes: u64,
    /// Every access type that reads.
    reads: u64,
}

fn relations() -> &'static Relations {
    static R: OnceLock<Relations> = OnceLock::new();
    R.get_or_init(|| {
        let mut r = Relations {
            stage: [0; 64],
            earlier: [0; 64],
            later: [0; 64],
            access: [0; 64],
            access_stages: [0; 64],
            writes: 0,
            reads: 0,
        };
        for s in STAGES.iter().filter(|s| s.bit != 0) {
            let i = s.bit.trailing_zeros() as usize;
            r.stage[i] = if s.stands_for != 0 {
                s.stands_for
            } else {
                s.bit
            };
            r.earlier[i] = s.earlier;
            r.later[i] = s.later;
        }
        for a in ACCESSES.iter().filter(|a| a.bit != 0) {
            let i = a.bit.trailing_zeros() as usize;
            r.access[i] = if a.stands_for != 0 {
                a.stands_for
            } else {
                a.bit
            };
            r.access_stages[i] = a.stages;
            if a.stands_for == 0 {
                if a.write {
                    r.writes |= a.bit;
                } else {
                    r.reads |= a.bit;
                }
            }
        }
        // MEMORY_READ and MEMORY_WRITE stand for every read and every write.
        for a in ACCESSES.iter().filter(|a| a.bit != 0 && a.stands_for == 0) {
            if a.name.ends_with("_MEMORY_READ_BIT") {
                r.access[a.bit.trailing_zeros() as usize] = r.reads;
            } else if a.name.ends_with("_MEMORY_WRITE_BIT") {
                r.access[a.bit.trailing_zeros() as usize] = r.writes;
            }
        }
        r
    })
}

/// The positions of the set bits of `mask`, lowest first.
fn bits(mut mask: u64) -> impl Iterator<Item = usize> {
    core::iter::from_fn(move || {
        let i = mask.trailing_zeros() as usize;
        mask &= mask.checked_sub(1)?;
        Some(i)
    })
}

/// The real stages a mask names: the stages each stands for. `TOP_OF_PIPE` and
/// `BOTTOM_OF_PIPE` name none; `ALL_COMMANDS` every one.
pub(crate) fn expand_stages(mask: u64) -> u64 {
    let r = relations();
    bits(mask).fold(0, |m, i| m | r.stage[i]) & EVERY_STAGE
}

/// The access types a mask names, those that stand for others expanded.
pub(crate) fn expand_access(mask: u64) -> u64 {
    let r = relations();
    bits(mask).fold(0, |m, i| m | r.access[i])
}

/// The parameters of a draw, for the tracker's check that a run of draws with the
/// same parameters on one state reads what the first read: compared field by field,
/// on every draw.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct DrawKey {
    /// 0: `vkCmdDraw` (vertices); 1: `vkCmdDrawIndexed` (indices).
    pub(crate) kind: u32,
    pub(crate) first: u32,
    pub(crate) count: u32,
    pub(crate) first_instance: u32,
    pub(crate) instances: u32,
}

impl DrawKey {
    #[inline]
    pub(crate) fn new(kind: u32, (first, count): (u32, u32), instances: (u32, u32)) -> Self {
        DrawKey {
            kind,
            first,
            count,
            first_instance: instances.0,
            instances: instances.1,
        }
    }
}

/// The first version's stages a second version's mask needs (the bits past 31 are
/// the first version's meta stages split up).
pub(crate) fn narrow_stages(mask: u64) -> vk::PipelineStageFlags {
    type S1 = vk::PipelineStageFlags;
    let low = S1::from_raw(mask as u32);
    let high = mask >> 32;
    let mut out = low;
    // COPY, RESOLVE, BLIT, CLEAR: TRANSFER.
    if high & 0xf != 0 {
        out |= S1::TRANSFER;
    }
    // INDEX_INPUT, VERTEX_ATTRIBUTE_INPUT: VERTEX_INPUT.
    if high & 0x30 != 0 {
        out |= S1::VERTEX_INPUT;
    }
    if high & !0x3f != 0 {
        out |= S1::ALL_COMMANDS;
    }
    out
}

/// The first version's access types a second version's mask needs.
pub(crate) fn narrow_access(mask: u64) -> vk::AccessFlags {
    type A1 = vk::AccessFlags;
    let mut out = A1::from_raw(mask as u32);
    let high = mask >> 32;
    // SHADER_SAMPLED_READ, SHADER_STORAGE_READ: SHADER_READ.
    if high & 0x3 != 0 {
        out |= A1::SHADER_READ;
    }
    // SHADER_STORAGE_WRITE: SHADER_WRITE.
    if high & 0x4 != 0 {
        out |= A1::SHADER_WRITE;
    }
    if high & !0x7 != 0 {
        out |= A1::MEMORY_READ | A1::MEMORY_WRITE;
    }
    out
}

/// A command of the recording, for the messages: its name and its number.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Cmd {
    /// `vkCmdCopyBuffer`.
    pub(crate) name: &'static str,
    /// Its place in the recording, from 0.
    pub(crate) index: u32,
    /// The submission to its queue it was replayed in (numbered from 1), or 0 for
    /// the recording being checked.
    pub(crate) submission: u32,
}

impl core::fmt::Display for Cmd {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.submission {
            0 => write!(f, "{} (command {} of the recording)", self.name, self.index),
            u32::MAX => write!(f, "{} (command {} of a secondary)", self.name, self.index),
            n => write!(
                f,
                "{} (command {} of submission {n} to the queue)",
                self.name, self.index
            ),
        }
    }
}

/// One access by a command: one real stage and one access type (`0`, `0`: a layout
/// transition, which happens between a barrier's two scopes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Usage {
    /// The stage: a single bit, or more for a command the specification can be read
    /// to run in either (a barrier naming any of them orders it).
    pub(crate) stage: u64,
    /// The access type, a single bit.
    pub(crate) access: u64,
    /// Whether the access writes.
    pub(crate) write: bool,
    /// The command.
    pub(crate) cmd: Cmd,
}

impl Usage {
    fn describe(&self) -> String {
        if self.stage == 0 {
            return format!("the layout transition of {}", self.cmd);
        }
        format!(
            "{} at {} by {}",
            name_of(ACCESSES.iter().map(|a| (a.name, a.bit)), self.access),
            name_of(STAGES.iter().map(|s| (s.name, s.bit)), self.stage),
            self.cmd
        )
    }
}

/// The names of the bits of `mask`, joined with " or ".
fn name_of(items: impl Iterator<Item = (&'static str, u64)>, mask: u64) -> String {
    let names: Vec<&str> = items
        .filter(|i| i.1 != 0 && i.1 & mask == i.1 && i.1.is_power_of_two())
        .map(|i| i.0)
        .collect();
    match names.is_empty() {
        true => format!("0x{mask:x}"),
        false => names.join(" or "),
    }
}

/// The scopes of one barrier (or subpass dependency), expanded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Barrier {
    /// The first execution scope: the source stages and every stage logically earlier.
    src_exec: u64,
    /// The source stages named, expanded: the first access scope's stages.
    src_stages: u64,
    /// The first access scope's access types, expanded.
    src_access: u64,
    /// The second execution scope: the destination stages and every stage logically later.
    dst_exec: u64,
    /// The destination stages named, expanded.
    dst_stages: u64,
    /// The second access scope's access types, expanded.
    dst_access: u64,
}

impl Barrier {
    /// The scopes of a barrier with these masks (synchronization2's bits; the first
    /// version's are the same numbers).
    pub(crate) fn new(src_stages: u64, src_access: u64, dst_stages: u64, dst_access: u64) -> Self {
        let r = relations();
        const TOP: u64 = 0x1;
        const BOTTOM: u64 = 0x2000;
        let src = expand_stages(src_stages);
        let dst = expand_stages(dst_stages);
        // BOTTOM_OF_PIPE in the first scope waits for every stage; TOP_OF_PIPE in the
        // second blocks every stage (both with no access).
        let mut src_exec = bits(src).fold(src, |m, i| m | r.earlier[i]);
        if src_stages & BOTTOM != 0 {
            src_exec = EVERY_STAGE;
        }
        let mut dst_exec = bits(dst).fold(dst, |m, i| m | r.later[i]);
        if dst_stages & TOP != 0 {
            dst_exec = EVERY_STAGE;
        }
        Barrier {
            src_exec,
            src_stages: src,
            src_access: expand_access(src_access),
            dst_exec,
            dst_stages: dst,
            dst_access: expand_access(dst_access),
        }
    }

    /// The barrier of both: each scope the union of theirs.
    pub(crate) fn union(&self, o: &Barrier) -> Barrier {
        Barrier {
            src_exec: self.src_exec | o.src_exec,
            src_stages: self.src_stages | o.src_stages,
            src_access: self.src_access | o.src_access,
            dst_exec: self.dst_exec | o.dst_exec,
            dst_stages: self.dst_stages | o.dst_stages,
            dst_access: self.dst_access | o.dst_access,
        }
    }

    /// Whether the barrier orders an access at `earlier` (stage, access type, whether
    /// it writes) before one at `later` (stage, access type): the first in its first
    /// scope and the second in its second, and for a write, made available and
    /// visible between them.
    pub(crate) fn orders(&self, earlier: (u64, u64, bool), later: (u64, u64)) -> bool {
        let (es, ea, write) = earlier;
        let (ls, la) = (expand_stages(later.0), expand_access(later.1));
        let es = expand_stages(es);
        let executes = es & self.src_exec != 0 && ls & self.dst_exec != 0;
        executes
            && (!write
                || (es & self.src_stages != 0
                    && expand_access(ea) & self.src_access != 0
                    && ls & self.dst_stages != 0
                    && la & self.dst_access != 0))
    }

    /// An execution dependency alone: the same stages, no access.
    pub(crate) fn execution(&self) -> Barrier {
        Barrier {
            src_access: 0,
            dst_access: 0,
            ..*self
        }
    }
}

/// The texels of a subresource an access touches: x, y and z as `start..end`.
/// Buffer ranges and whole subresources touch [`EVERY_TEXEL`].
pub(crate) type Texels = [(i64, i64); 3];

/// Every texel.
pub(crate) const EVERY_TEXEL: Texels = [(i64::MIN, i64::MAX); 3];

fn meet(a: &Texels, b: &Texels) -> bool {
    (0..3).all(|i| a[i].0 < b[i].1 && b[i].0 < a[i].1)
}

fn holds(outer: &Texels, inner: &Texels) -> bool {
    (0..3).all(|i| outer[i].0 <= inner[i].0 && inner[i].1 <= outer[i].1)
}

/// The last write of a range and what barriers have made it visible to.
#[derive(Clone, Debug)]
struct Write {
    usage: Usage,
    /// The texels it wrote.
    texels: Texels,
    /// Each `(stages, access types)` the write is visible to (a union of products;
    /// a frame's few barriers stay inline).
    visible: SmallVec<[(u64, u64); 4]>,
    /// The stages ordered after the write by the barriers so far.
    chain: u64,
}

impl Write {
    fn visible_to(&self, u: &Usage) -> bool {
        self.visible
            .iter()
            .any(|&(s, a)| s & u.stage != 0 && a & u.access != 0)
    }
}

/// A read since the last write, the texels it read, and the stages ordered after it.
#[derive(Clone, Debug)]
struct Read {
    usage: Usage,
    texels: Texels,
    after: u64,
}

/// What the recording has done to one buffer range or image subresource. Of an
/// image's subresource, accesses to texels that do not meet are not compared (two
/// copies into disjoint regions of one level need no barrier); a write keeps the
/// reads of texels it does not cover, and forgets the write before it (so a hazard
/// with a write it did not cover goes unseen: never a false refusal).
#[derive(Clone, Debug, Default)]
pub(crate) struct State {
    write: Option<Write>,
    /// Inline for two: a uniform block read by two shader stages.
    reads: SmallVec<[Read; 2]>,
}

/// Two accesses the recording does not order.
#[derive(Clone, Debug)]
pub(crate) struct Hazard {
    /// `READ_AFTER_WRITE`, `WRITE_AFTER_READ` or `WRITE_AFTER_WRITE`, as the
    /// validation layer's `SYNC-HAZARD-...` names them.
    pub(crate) kind: &'static str,
    /// The earlier access.
    pub(crate) earlier: Usage,
    /// The later one.
    pub(crate) later: Usage,
}

impl Hazard {
    /// The message: what, the two commands, and the barrier that would order them.
    pub(crate) fn message(&self, resource: &str) -> String {
        let fix = if self.earlier.write {
            let src = if self.earlier.stage == 0 {
                "the stages of the transition's barrier".to_owned()
            } else {
                format!(
                    "{} with {}",
                    name_of(STAGES.iter().map(|s| (s.name, s.bit)), self.earlier.stage),
                    name_of(
                        ACCESSES.iter().map(|a| (a.name, a.bit)),
                        self.earlier.access
                    )
                )
            };
            match self.later.stage {
                // A layout transition happens in its barrier or dependency: the
                // write must be in that one's first scope.
                0 => format!("the transition's barrier or dependency to wait for {src}"),
                stage => format!(
                    "a barrier from {src} to {} with {} between them",
                    name_of(STAGES.iter().map(|s| (s.name, s.bit)), stage),
                    name_of(ACCESSES.iter().map(|a| (a.name, a.bit)), self.later.access)
                ),
            }
        } else {
            format!(
                "an execution dependency from {} to {} between them",
                name_of(STAGES.iter().map(|s| (s.name, s.bit)), self.earlier.stage),
                if self.later.stage == 0 {
                    "the transition's stages".to_owned()
                } else {
                    name_of(STAGES.iter().map(|s| (s.name, s.bit)), self.later.stage)
                }
            )
        };
        format!(
            "{}: {} of {resource} is not ordered after {}; it needs {fix}",
            self.kind,
            self.later.describe(),
            self.earlier.describe()
        )
    }
}

impl State {
    /// The hazard of `u`, touching `texels`, after what the state holds, if any
    /// (accesses of submissions numbered below `floor` are complete: none).
    fn hazard(&self, u: &Usage, texels: &Texels, floor: u32) -> Option<Hazard> {
        let found = |kind, earlier: &Usage| {
            Some(Hazard {
                kind,
                earlier: *earlier,
                later: *u,
            })
        };
        let write = self
            .write
            .as_ref()
            .filter(|w| w.usage.cmd.submission >= floor && meet(&w.texels, texels));
        if !u.write {
            return match write {
                Some(w) if !w.visible_to(u) => found("READ_AFTER_WRITE", &w.usage),
                _ => None,
            };
        }
        let mut reads = self
            .reads
            .iter()
            .filter(|r| r.usage.cmd.submission >= floor && meet(&r.texels, texels))
            .peekable();
        if reads.peek().is_some() {
            return reads
                .find(|r| u.stage & r.after == 0)
                .and_then(|r| found("WRITE_AFTER_READ", &r.usage));
        }
        match write {
            Some(w) if !w.visible_to(u) => found("WRITE_AFTER_WRITE", &w.usage),
            _ => None,
        }
    }

    /// The hazard of a layout transition between `b`'s scopes, if any: every earlier
    /// access (of a submission numbered `floor` or later) must be in its first scope.
    fn transition_hazard(&self, b: &Barrier, cmd: Cmd, floor: u32) -> Option<Hazard> {
        let later = Usage {
            stage: 0,
            access: 0,
            write: true,
            cmd,
        };
        let alive = |c: &Cmd| c.submission >= floor;
        let mut reads = self.reads.iter().filter(|r| alive(&r.usage.cmd)).peekable();
        let any_read = reads.peek().is_some();
        if let Some(r) = reads.find(|r| (r.usage.stage | r.after) & b.src_exec == 0) {
            return Some(Hazard {
                kind: "WRITE_AFTER_READ",
                earlier: r.usage,
                later,
            });
        }
        if !any_read {
            if let Some(w) = self.write.as_ref().filter(|w| alive(&w.usage.cmd)) {
                if !in_first_scope(w, b) {
                    return Some(Hazard {
                        kind: "WRITE_AFTER_WRITE",
                        earlier: w.usage,
                        later,
                    });
                }
            }
        }
        None
    }

    fn record(&mut self, u: Usage, texels: Texels) {
        if u.write {
            self.reads.retain(|r| !holds(&texels, &r.texels));
            self.write = Some(Write {
                usage: u,
                texels,
                visible: SmallVec::new(),
                chain: 0,
            });
        } else if let Some(r) = self
            .reads
            .iter_mut()
            .find(|r| r.usage.stage == u.stage && r.texels == texels)
        {
            r.usage = u;
            r.after = 0;
        } else {
            self.reads.push(Read {
                usage: u,
                texels,
                after: 0,
            });
        }
    }

    /// Applies the barriers of one command, all against the state before any of them.
    fn apply(&mut self, barriers: &[Barrier]) {
        if let Some(w) = &mut self.write {
            // Whether the write is in a barrier's first scope depends on its usage
            // and on the chain before this command only.
            let (usage, before) = (w.usage, w.chain);
            for b in barriers {
                let in_scope = (usage.stage & b.src_stages != 0
                    && usage.access & b.src_access != 0)
                    || before & b.src_exec != 0;
                if !in_scope {
                    continue;
                }
                w.chain |= b.dst_exec;
                if b.dst_access != 0 {
                    match w.visible.iter_mut().find(|v| v.0 == b.dst_stages) {
                        Some(v) => v.1 |= b.dst_access,
                        None => w.visible.push((b.dst_stages, b.dst_access)),
                    }
                }
            }
        }
        for r in &mut self.reads {
            let from = r.usage.stage | r.after;
            r.after |= barriers
                .iter()
                .filter(|b| from & b.src_exec != 0)
                .fold(0, |m, b| m | b.dst_exec);
        }
    }

    /// A layout transition between `b`'s scopes: a write, visible to its second scope.
    fn transition(&mut self, b: &Barrier, cmd: Cmd) {
        self.reads.clear();
        self.write = Some(Write {
            usage: Usage {
                stage: 0,
                access: 0,
                write: true,
                cmd,
            },
            texels: EVERY_TEXEL,
            visible: if b.dst_access != 0 {
                smallvec![(b.dst_stages, b.dst_access)]
            } else {
                SmallVec::new()
            },
            chain: b.dst_exec,
        });
    }
}

/// Whether a write is in a barrier's first scope: its stage and access type are, or a
/// barrier before chained it to one of its stages.
fn in_first_scope(w: &Write, b: &Barrier) -> bool {
    (w.usage.stage & b.src_stages != 0 && w.usage.access & b.src_access != 0)
        || w.chain & b.src_exec != 0
}

/// One buffer's ranges, each with its state, sorted and disjoint.
#[derive(Clone, Debug, Default)]
struct Ranges(Vec<(u64, u64, State)>);

impl Ranges {
    /// Splits the ranges at `at`.
    fn split(&mut self, at: u64) {
        if let Some(i) = self.0.iter().position(|r| r.0 < at && at < r.1) {
            let mut right = self.0[i].clone();
            right.0 = at;
            self.0[i].1 = at;
            self.0.insert(i + 1, right);
        }
    }

    /// The states of `start..end`, the range made whole (untouched parts added).
    fn cover(&mut self, start: u64, end: u64) -> impl Iterator<Item = &mut State> {
        // The ranges are sorted and disjoint, so their ends rise too.
        let first = |v: &Vec<(u64, u64, State)>| v.partition_point(|r| r.1 <= start);
        // Most accesses touch a range an earlier one made whole (the same bytes
        // read again): nothing to split or add.
        if self.0.is_empty() {
            // A buffer's first access in the recording: one whole range.
            self.0.push((start, end, State::default()));
        }
        let at = first(&self.0);
        let exact = self.0.get(at).is_some_and(|r| r.0 == start && r.1 == end);
        let (lo, hi) = if exact {
            (at, at + 1)
        } else {
            self.make_whole(start, end);
            (first(&self.0), self.0.partition_point(|r| r.0 < end))
        };
        self.0[lo..hi].iter_mut().map(|r| &mut r.2)
    }

    /// Splits the ranges at `start` and `end` and adds the untouched parts between.
    fn make_whole(&mut self, start: u64, end: u64) {
        self.split(start);
        self.split(end);
        let mut at = start;
        let mut gaps: SmallVec<[(u64, u64); 4]> = SmallVec::new();
        for r in self.0.iter().filter(|r| r.1 > start && r.0 < end) {
            if r.0 > at {
                gaps.push((at, r.0));
            }
            at = r.1;
        }
        if at < end {
            gaps.push((at, end));
        }
        for (s, e) in gaps {
            let i = self.0.partition_point(|r| r.0 < s);
            self.0.insert(i, (s, e, State::default()));
        }
    }

    fn states(&self, start: u64, end: u64) -> impl Iterator<Item = &State> {
        self.0
            .iter()
            .filter(move |r| r.1 > start && r.0 < end)
            .map(|r| &r.2)
    }
}

/// One image's subresources, each with its state.
#[derive(Clone, Debug)]
struct Subresources {
    shape: Shape,
    states: Vec<State>,
}

/// Some memory a command touches: a buffer range or an image's subresources.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Memory {
    /// A buffer and a range of its bytes (`start..end`).
    Buffer(vk::Buffer, u64, u64),
    /// An image, some of its subresources, and the texels of each.
    Image(vk::Image, Sel, Texels),
}

impl Memory {
    /// How a message names it.
    pub(crate) fn describe(&self) -> String {
        match self {
            Memory::Buffer(b, s, e) => format!("bytes {s}..{e} of buffer 0x{:x}", b.as_raw()),
            Memory::Image(i, sel, _) => {
                // A range to VK_REMAINING_* reaches the image's end, whatever it is.
                let span = |(start, end): (u32, u32), what: &str| match (start, end) {
                    (0, u32::MAX) => format!("every {what}"),
                    (start, u32::MAX) => format!("{what}s {start}.."),
                    (start, end) => format!("{what}s {start}..{end}"),
                };
                format!(
                    "{:?} of {}, {} of image 0x{:x}",
                    sel.aspect,
                    span(sel.mips, "mip level"),
                    span(sel.layers, "array layer"),
                    i.as_raw()
                )
            }
        }
    }
}

/// What one recording has done to the memory it touched.
#[derive(Clone, Debug, Default)]
pub(crate) struct Recording {
    buffers: SmallMap<Ranges>,
    images: SmallMap<Subresources>,
    /// How many commands the recording has recorded that the tracker saw.
    commands: u32,
    /// Whether a hazard gets the barrier that orders it, rather than an error.
    pub(crate) auto: bool,
    /// Counts every change that could change a verdict: a write or a barrier recorded,
    /// or what the recording did forgotten.
    generation: u64,
    /// The reads of the last draws recorded (memory, stage) while the generation
    /// was the second value: a draw reading within them adds nothing.
    drawn: (Vec<(Memory, u64)>, u64),
    /// The stages and access types of every write recorded since automatic
    /// synchronization last made them visible to a render pass instance's commands.
    pub(crate) pending: (u64, u64),
    /// The stages and access types of every buffer write the recording made, for
    /// automatic synchronization to make visible to the host at its end.
    pub(crate) buffer_writes: (u64, u64),
    /// How many barriers automatic synchronization recorded.
    pub(crate) auto_barriers: u32,
    /// The parameters of the last draw whose reads were recorded, with the
    /// generation after it.
    last_draw: (DrawKey, u64),
    /// Whether automatic synchronization has ordered everything before the recording
    /// (earlier submissions' accesses) with one barrier.
    pub(crate) started: bool,
    /// Every change the recording made, in order, for its submissions to replay on
    /// their queue's state; none is kept for a queue's own state.
    log: Vec<Event>,
    /// A queue's state: nothing is logged.
    unlogged: bool,
    /// A queue's state: the accesses of submissions numbered below this are
    /// complete, and no check sees them (they are dropped at the next prune). A
    /// recording's is 0: every access counts.
    floor: u32,
    /// Emptied subresource tables of the images an earlier recording touched, for
    /// the images this one touches first (a recording per frame touches the same).
    spare_states: Vec<Vec<State>>,
}

/// One change a recording made to what it tracks: an access, or a barrier's
/// effect (on everything, a buffer range, or an image's subresources, with its
/// layout transition), or everything forgotten.
#[derive(Clone, Debug)]
pub(crate) enum Event {
    /// An access, and whether it was checked (a render pass's store operations
    /// follow what its instance ordered, and are not).
    Access(Memory, Usage, bool),
    Global(SmallVec<[Barrier; 1]>),
    Buffer(vk::Buffer, u64, u64, Barrier),
    Image(vk::Image, Sel, Barrier, Option<Cmd>),
    Forget,
}

impl Recording {
    /// This recording emptied for a new one that logs into `log`: its tables and
    /// the log keep their allocations.
    pub(crate) fn recycled(mut self, log: Vec<Event>) -> Self {
        self.recycle(log);
        self
    }

    /// Empties this recording, in place, for a new one that logs into `log`: its
    /// tables and the log keep their allocations.
    pub(crate) fn recycle(&mut self, mut log: Vec<Event>) {
        // Every field named: a new one must say how a new recording starts.
        let Recording {
            buffers,
            images,
            commands,
            auto,
            generation,
            drawn,
            pending,
            buffer_writes,
            auto_barriers,
            last_draw,
            started,
            log: old_log,
            unlogged,
            floor,
            spare_states,
        } = self;
        // A buffer's ranges keep their allocation for the next recording, which
        // most often touches the same buffers (a bounded number: a recording of
        // many short-lived buffers starts empty). An image's states depend on its
        // shape, and a destroyed image's handle may name a new one: they go.
        if buffers.len() <= 64 {
            buffers.values_mut().for_each(|r| r.0.clear());
        } else {
            buffers.clear();
        }
        // Their tables' allocations stay, a bounded number.
        for (_, sub) in images.drain() {
            if spare_states.len() < 16 {
                let mut states = sub.states;
                states.clear();
                spare_states.push(states);
            }
        }
        drawn.0.clear();
        drawn.1 = 0;
        log.clear();
        *old_log = log;
        *commands = 0;
        *auto = false;
        *generation = 0;
        *pending = (0, 0);
        *buffer_writes = (0, 0);
        *auto_barriers = 0;
        *last_draw = Default::default();
        *started = false;
        *unlogged = false;
        *floor = 0;
    }

    /// The next command's place in the recording.
    pub(crate) fn next(&mut self, name: &'static str) -> Cmd {
        let cmd = Cmd {
            name,
            index: self.commands,
            submission: 0,
        };
        self.commands += 1;
        cmd
    }

    /// Whether the last draw recorded had parameters `key` and nothing changed
    /// since (the caller knows no state did).
    #[inline]
    pub(crate) fn last_draw(&self, key: DrawKey) -> bool {
        self.last_draw.1 == self.generation && self.last_draw.0 == key
    }

    /// The last draw recorded had parameters `key`.
    pub(crate) fn set_last_draw(&mut self, key: DrawKey) {
        self.last_draw = (key, self.generation);
    }

    /// Whether the tracker already holds each of these reads, recorded by a draw
    /// with nothing changed since.
    pub(crate) fn holds_reads<'m>(
        &self,
        mut reads: impl Iterator<Item = (&'m Memory, u64)>,
    ) -> bool {
        self.drawn.1 == self.generation
            && reads.all(|(m, stage)| {
                self.drawn.0.iter().any(|(d, st)| {
                    *st == stage
                        && match (d, m) {
                            (Memory::Buffer(db, ds, de), Memory::Buffer(b, s, e)) => {
                                db == b && ds <= s && e <= de
                            }
                            (Memory::Image(di, dsel, dt), Memory::Image(i, sel, t)) => {
                                di == i && dsel.same(sel) && dt == t
                            }
                            _ => false,
                        }
                })
            })
    }

    /// Remembers reads a draw recorded.
    pub(crate) fn remember_reads(&mut self, reads: impl Iterator<Item = (Memory, u64)>) {
        if self.drawn.1 != self.generation {
            self.drawn.0.clear();
            self.drawn.1 = self.generation;
        }
        for (m, stage) in reads {
            let Memory::Buffer(b, s, e) = m else {
                self.drawn.0.push((m, stage));
                continue;
            };
            let same = |d: &&mut (Memory, u64)| {
                d.1 == stage && matches!(d.0, Memory::Buffer(db, ..) if db == b)
            };
            match self.drawn.0.iter_mut().find(same) {
                // One range per buffer and stage: the union where they touch.
                Some((Memory::Buffer(_, ds, de), _)) if s <= *de && *ds <= e => {
                    *ds = (*ds).min(s);
                    *de = (*de).max(e);
                }
                Some(d) => *d = (m, stage),
                None => self.drawn.0.push((m, stage)),
            }
        }
    }

    /// What [`Recording::next`] will return, without counting it.
    pub(crate) fn peek(&self, name: &'static str) -> Cmd {
        Cmd {
            name,
            index: self.commands,
            submission: 0,
        }
    }

    fn image(&mut self, live: &Live, image: vk::Image) -> Option<&mut Subresources> {
        let spare = &mut self.spare_states;
        self.images.get_or_try_insert(image.as_raw(), || {
            let shape = Shape::of(&live.image(image)?);
            let mut states = spare.pop().unwrap_or_default();
            states.extend((0..shape.len()).map(|_| State::default()));
            Some(Subresources { shape, states })
        })
    }

    /// The first hazard of an access to `memory`, if any.
    pub(crate) fn hazard(&self, memory: &Memory, u: &Usage) -> Option<Hazard> {
        match memory {
            Memory::Buffer(b, s, e) => self
                .buffers
                .get(b.as_raw())?
                .states(*s, *e)
                .find_map(|st| st.hazard(u, &EVERY_TEXEL, self.floor)),
            Memory::Image(i, sel, texels) => {
                let sub = self.images.get(i.as_raw())?;
                sub.shape
                    .indices(sel)
                    .find_map(|k| sub.states[k].hazard(u, texels, self.floor))
            }
        }
    }

    /// The stages and access types a barrier out of `image`'s subresources `sel`
    /// waits for: of each subresource, its last write (stage and access type) and the
    /// reads since (stages: after a read an execution dependency is enough). `None`
    /// when the recording has not touched one of them, or last transitioned it:
    /// what came before is then not known here.
    pub(crate) fn last_uses(&self, image: vk::Image, sel: &Sel) -> Option<(u64, u64)> {
        let sub = self.images.get(image.as_raw())?;
        let (mut stages, mut access) = (0, 0);
        for k in sub.shape.indices(sel) {
            let st = &sub.states[k];
            match &st.write {
                Some(w) if w.usage.stage == 0 => return None,
                Some(w) => {
                    stages |= w.usage.stage;
                    access |= w.usage.access;
                }
                None if st.reads.is_empty() => return None,
                None => {}
            }
            stages = st.reads.iter().fold(stages, |m, r| m | r.usage.stage);
        }
        (stages != 0).then_some((stages, access))
    }

    /// Records an access to `memory`.
    pub(crate) fn record(&mut self, live: &Live, memory: &Memory, u: Usage) {
        self.record_as(live, memory, u, true);
    }

    /// Records an access to `memory` the caller did not check (a render pass's
    /// store operations, which follow what its instance ordered).
    pub(crate) fn record_ordered(&mut self, live: &Live, memory: &Memory, u: Usage) {
        self.record_as(live, memory, u, false);
    }

    fn record_as(&mut self, live: &Live, memory: &Memory, u: Usage, checked: bool) {
        if !self.unlogged {
            self.log.push(Event::Access(*memory, u, checked));
        }
        if u.write {
            self.generation += 1;
            self.pending.0 |= u.stage;
            self.pending.1 |= u.access;
        }
        match memory {
            Memory::Buffer(b, s, e) => {
                if u.write {
                    self.buffer_writes.0 |= u.stage;
                    self.buffer_writes.1 |= u.access;
                }
                if s < e {
                    for st in self
                        .buffers
                        .get_or_insert_with(b.as_raw(), Ranges::default)
                        .cover(*s, *e)
                    {
                        st.record(u, EVERY_TEXEL);
                    }
                }
            }
            Memory::Image(i, sel, texels) => {
                if let Some(sub) = self.image(live, *i) {
                    let Subresources { shape, states } = sub;
                    for k in shape.indices(sel) {
                        states[k].record(u, *texels);
                    }
                }
            }
        }
    }

    /// The hazard of a layout transition of `image`'s subresources `sel` between
    /// `b`'s scopes, if any.
    pub(crate) fn transition_hazard(
        &self,
        image: vk::Image,
        sel: &Sel,
        b: &Barrier,
        cmd: Cmd,
    ) -> Option<Hazard> {
        let sub = self.images.get(image.as_raw())?;
        sub.shape
            .indices(sel)
            .find_map(|k| sub.states[k].transition_hazard(b, cmd, self.floor))
    }

    /// Applies barriers to everything the recording touched (memory barriers and
    /// execution dependencies).
    pub(crate) fn apply_global(&mut self, barriers: &[Barrier]) {
        self.generation += 1;
        if !self.unlogged {
            self.log.push(Event::Global(SmallVec::from_slice(barriers)));
        }
        for r in self.buffers.values_mut() {
            for st in &mut r.0 {
                st.2.apply(barriers);
            }
        }
        for sub in self.images.values_mut() {
            for st in &mut sub.states {
                st.apply(barriers);
            }
        }
    }

    /// Applies a barrier to a buffer range.
    pub(crate) fn apply_buffer(&mut self, buffer: vk::Buffer, start: u64, end: u64, b: &Barrier) {
        self.generation += 1;
        if !self.unlogged {
            self.log.push(Event::Buffer(buffer, start, end, *b));
        }
        if let Some(r) = self.buffers.get_mut(buffer.as_raw()) {
            if start < end {
                for st in r.cover(start, end) {
                    st.apply(core::slice::from_ref(b));
                }
            }
        }
    }

    /// Applies a barrier to an image's subresources, with a layout transition
    /// between its scopes when `transition`.
    pub(crate) fn apply_image(
        &mut self,
        live: &Live,
        image: vk::Image,
        sel: &Sel,
        b: &Barrier,
        transition: Option<Cmd>,
    ) {
        self.generation += 1;
        if !self.unlogged {
            self.log.push(Event::Image(image, *sel, *b, transition));
        }
        if transition.is_some() {
            // A layout transition writes; a barrier from ALL_COMMANDS orders it
            // whatever stages it chained to.
            self.pending.0 |= 0x10000;
        }
        let Some(sub) = (match transition {
            Some(_) => self.image(live, image),
            None => self.images.get_mut(image.as_raw()),
        }) else {
            return;
        };
        let Subresources { shape, states } = sub;
        for k in shape.indices(sel) {
            match transition {
                Some(cmd) => states[k].transition(b, cmd),
                None => states[k].apply(core::slice::from_ref(b)),
            }
        }
    }

    /// Forgets everything: what the recording did before is no longer known (a
    /// command the tracker cannot see into ran).
    pub(crate) fn forget(&mut self) {
        self.generation += 1;
        if !self.unlogged {
            self.log.push(Event::Forget);
        }
        self.buffers.clear();
        self.images.clear();
    }
}

impl Recording {
    /// The changes the recording made, for its submissions (empty when it made
    /// none).
    pub(crate) fn take_log(&mut self) -> Vec<Event> {
        core::mem::take(&mut self.log)
    }

    /// Replays a recording's changes on this (a queue's) state as the commands of
    /// submission `submission`: the first hazard, with its memory, stops it.
    /// Unless `check`, nothing is compared: the changes are only made (a queue's
    /// state rebuilt from submissions already checked).
    pub(crate) fn replay(
        &mut self,
        live: &Live,
        log: &[Event],
        submission: u32,
        check: bool,
    ) -> Result<(), Box<(Hazard, Memory)>> {
        let at = |c: Cmd| Cmd { submission, ..c };
        for e in log {
            match e {
                Event::Access(m, u, checked) => {
                    let u = Usage {
                        cmd: at(u.cmd),
                        ..*u
                    };
                    if let Some(h) = (check && *checked).then(|| self.hazard(m, &u)).flatten() {
                        return Err(Box::new((h, *m)));
                    }
                    self.record_as(live, m, u, *checked);
                }
                Event::Global(b) => self.apply_global(b),
                Event::Buffer(buffer, s, e, b) => self.apply_buffer(*buffer, *s, *e, b),
                Event::Image(image, sel, b, transition) => {
                    let transition = transition.map(at);
                    if let Some(cmd) = transition.filter(|_| check) {
                        if let Some(h) = self.transition_hazard(*image, sel, b, cmd) {
                            return Err(Box::new((h, Memory::Image(*image, *sel, EVERY_TEXEL))));
                        }
                    }
                    self.apply_image(live, *image, sel, b, transition);
                }
                Event::Forget => self.forget(),
            }
        }
        Ok(())
    }

    /// Drops every access of a submission `done` says is complete: of images
    /// alone, or of buffers too (`buffers`).
    fn prune(&mut self, done: impl Fn(u32) -> bool, buffers: bool) {
        let keep = |st: &mut State| {
            if st
                .write
                .as_ref()
                .is_some_and(|w| done(w.usage.cmd.submission))
            {
                st.write = None;
            }
            st.reads.retain(|r| !done(r.usage.cmd.submission));
            st.write.is_some() || !st.reads.is_empty()
        };
        // A buffer none of whose ranges is left stays, with its list's allocation,
        // for the next submission, which most often touches it again (a bounded
        // number: no range is no state, as if it were not there).
        let small = self.buffers.len() <= 64;
        if buffers {
            self.buffers.retain(|_, r| {
                r.0.retain_mut(|(_, _, st)| keep(st));
                small || !r.0.is_empty()
            });
        }
        // An image's states depend on its shape, and its handle may name another
        // image later: it goes, and its table's allocation waits for the next.
        let spare = &mut self.spare_states;
        self.images.retain(|_, sub| {
            let mut any = false;
            for st in &mut sub.states {
                any |= keep(st);
            }
            if !any && spare.len() < 16 {
                let mut states = core::mem::take(&mut sub.states);
                states.clear();
                spare.push(states);
            }
            any
        });
    }
}

/// What a queue's submissions not yet known complete have done to memory, for
/// each new submission to be checked against (submission order, with the
/// semaphore waits between its batches, as the specification orders them).
///
/// A submission is checked by replaying its command buffers on the queue's state
/// itself: nothing is copied on the way that succeeds. A refused submission, or a
/// checked one that was not made after all (a later rule refused it), leaves the
/// state to be rebuilt from the submissions still running, which are kept for that.
#[derive(Default)]
pub(crate) struct QueueHazards {
    state: Recording,
    /// The number of the next submission.
    next: u32,
    /// The submissions made and replayed on the state, while not known complete.
    subs: Vec<Replayed>,
    /// The last submission checked and replayed on the state, until it is made.
    staged: Option<Replayed>,
    /// Submissions begun since the state's complete accesses were last dropped.
    since_prune: u32,
}

/// How many submissions a queue's state may keep the accesses of complete ones
/// (hidden by its floor) before it drops them: a frame loop's next submission
/// overwrites most of them anyway, and walking every state to drop them cost as
/// much as replaying the submission.
const PRUNE_EVERY: u32 = 32;

/// A submission replayed on a queue's state: its number, its submission once made,
/// its command buffers, and for each batch the barriers of its semaphore waits and
/// its command buffers' logs (held weakly: a command buffer is recorded again only
/// once its submissions are complete, and its log's allocation is then reused).
/// Its lists hold a frame's usual one batch of a command buffer or two inline: a
/// submission of a frame allocates nothing for them.
pub(crate) struct Replayed {
    number: u32,
    sub: Option<Vweak<crate::state::Submission>>,
    cbs: SmallVec<[vk::CommandBuffer; 2]>,
    batches: SmallVec<[ReplayedBatch; 1]>,
}

/// One batch of a [`Replayed`] submission.
struct ReplayedBatch {
    /// The barriers its semaphore waits make.
    waits: SmallVec<[Barrier; 1]>,
    /// Its command buffers' logs.
    logs: SmallVec<[Vweak<Vec<Event>>; 2]>,
}

impl Replayed {
    /// A submission numbered `number` of `cbs`, not yet replayed.
    pub(crate) fn new(number: u32, cbs: SmallVec<[vk::CommandBuffer; 2]>) -> Self {
        Replayed {
            number,
            sub: None,
            cbs,
            batches: SmallVec::new(),
        }
    }
}

impl QueueHazards {
    /// Readies the state for a new submission and returns its number: the
    /// accesses of complete submissions dropped, and the state rebuilt if the last
    /// submission checked was not made.
    pub(crate) fn begin(&mut self, live: &Live) -> u32 {
        let before = self.subs.len();
        let mut last_done = 0;
        self.subs.retain(|r| {
            let running = r
                .sub
                .as_ref()
                .and_then(Vweak::upgrade)
                .is_some_and(|s| !s.is_complete());
            if !running {
                last_done = last_done.max(r.number);
            }
            running
        });
        // The submissions are in number order: the first running one is the floor.
        let floor = self.subs.first().map_or(self.next + 1, |r| r.number);
        self.since_prune += 1;
        if self.staged.take().is_some() {
            self.rebuild(live);
            self.since_prune = 0;
        } else if self.subs.len() < before || self.since_prune >= PRUNE_EVERY {
            // A queue's submissions complete in order (a fence covers every earlier
            // submission), so those below the floor are the complete ones, and the
            // floor hides their buffer accesses. Should one above it have completed,
            // or the state have kept them long enough, they are dropped. An image's
            // go at once: its states follow its shape, and once its accesses are
            // complete it may be destroyed and its handle name an image of another.
            let all = last_done > floor || self.since_prune >= PRUNE_EVERY;
            let running: SmallVec<[u32; 4]> = self.subs.iter().map(|r| r.number).collect();
            self.state.prune(|n| !running.contains(&n), all);
            if all {
                self.since_prune = 0;
            }
        }
        self.state.floor = floor;
        self.state.unlogged = true;
        self.next += 1;
        self.next
    }

    /// Applies a batch's semaphore waits (`waits`: the barriers they make) as part
    /// of the submission `replayed`.
    pub(crate) fn wait(&mut self, replayed: &mut Replayed, waits: SmallVec<[Barrier; 1]>) {
        if !waits.is_empty() {
            self.state.apply_global(&waits);
        }
        replayed.batches.push(ReplayedBatch {
            waits,
            logs: SmallVec::new(),
        });
    }

    /// Replays one command buffer's log as part of the submission `replayed`, in
    /// its last batch: the first hazard stops it, and the state is rebuilt without
    /// the submission.
    pub(crate) fn replay(
        &mut self,
        live: &Live,
        replayed: &mut Replayed,
        log: &Vrc<Vec<Event>>,
    ) -> Result<(), Box<(Hazard, Memory)>> {
        if let Err(found) = self.state.replay(live, log, replayed.number, true) {
            self.rebuild(live);
            return Err(found);
        }
        if let Some(batch) = replayed.batches.last_mut() {
            batch.logs.push(Vrc::downgrade(log));
        }
        Ok(())
    }

    /// The submission checked and replayed, kept until it is made.
    pub(crate) fn stage(&mut self, replayed: Replayed) {
        self.staged = Some(replayed);
    }

    /// A submission of `cbs` was made as `sub`: the one checked is the queue's (a
    /// submission that was not checked leaves nothing; one checked but not made is
    /// undone at the next).
    pub(crate) fn made(
        &mut self,
        live: &Live,
        sub: &Vrc<crate::state::Submission>,
        cbs: &[vk::CommandBuffer],
    ) {
        match self.staged.take() {
            Some(mut r) if r.cbs.as_slice() == cbs => {
                r.sub = Some(Vrc::downgrade(sub));
                self.subs.push(r);
            }
            Some(_) => self.rebuild(live),
            None => {}
        }
    }

    /// The state again from the submissions still running, replayed in order (they
    /// were checked when made: nothing is compared).
    fn rebuild(&mut self, live: &Live) {
        let mut state = core::mem::take(&mut self.state).recycled(Vec::new());
        state.unlogged = true;
        for r in &self.subs {
            for batch in &r.batches {
                if !batch.waits.is_empty() {
                    state.apply_global(&batch.waits);
                }
                for log in batch.logs.iter().filter_map(Vweak::upgrade) {
                    // Unchecked: a replay that checks nothing finds nothing.
                    let _ = state.replay(live, &log, r.number, false);
                }
            }
        }
        self.state = state;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Ranges::cover` keeps the ranges sorted and disjoint, and hands out exactly
    /// the states of the bytes asked for, over many overlapping covers (a fixed
    /// pseudo-random sequence, so a failure repeats).
    #[test]
    fn cover_keeps_ranges_sorted_disjoint_and_exact() {
        let mut ranges = Ranges::default();
        let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
        let mut next = move |n: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % n
        };
        for _ in 0..2000 {
            let start = next(256);
            let end = start + 1 + next(64);
            let count = ranges.cover(start, end).count();
            let sorted = ranges.0.windows(2).all(|w| w[0].1 <= w[1].0);
            assert!(sorted, "unsorted or overlapping after {start}..{end}");
            assert!(ranges.0.iter().all(|r| r.0 < r.1), "an empty range");
            let inside: Vec<_> = ranges
                .0
                .iter()
                .filter(|r| r.1 > start && r.0 < end)
                .collect();
            assert_eq!(inside.len(), count, "{start}..{end}");
            assert_eq!(inside.first().map(|r| r.0), Some(start));
            assert_eq!(inside.last().map(|r| r.1), Some(end));
            assert!(inside.windows(2).all(|w| w[0].1 == w[1].0), "a gap");
        }
    }
}
