//! What the device records of a command buffer: its lifecycle state (initial,
//! recording, executable, pending, invalid), the submissions that use it, the
//! secondaries it executes, and what its last recording needs and leaves (image
//! layouts, descriptor sets, events), shared with the device's registry so a
//! submission naming the raw handle finds it.

use super::Submission;
use crate::handles::Device;
use ash::vk;
use smallvec::SmallVec;
use tuff_runtime::{Vrc, Vutex, Vweak};

/// The sets a submission's command buffers bound, each with its generation then:
/// a frame's few inline.
pub(crate) type SetsUsed = SmallVec<[(u64, u64); 8]>;

/// The events a submission's command buffers name: a frame's few inline.
pub(crate) type EventsUsed = SmallVec<[u64; 4]>;

/// The lifecycle state of a command buffer, shared with the device's registry so a
/// submission naming the raw handle finds it.
pub(crate) struct Uses {
    state: Vutex<UsesState>,
}

impl Default for Uses {
    fn default() -> Self {
        Uses {
            state: Vutex::new(UsesState::default()),
        }
    }
}

/// What the last render pass begin of the buffer that passed its checks named,
/// each object by its record (held, so no new object's record can take its
/// address): a begin of the same render pass, framebuffer, render area and clear
/// count, by the same command, passes the same checks. Every one of them reads
/// only these records, the begin's parameters and the buffer's pool; the image
/// layouts the begin needs are checked every time. That rests on what the checks
/// read never changing while the key is equal, which a change to any of these
/// must revisit:
/// - a render pass's and a framebuffer's records are written once, and a
///   framebuffer keeps its views alive (`Reached::keeping` at its creation), a view
///   its image;
/// - a view's record is written once, and an image's memory binding once (a second
///   bind is refused; a sparse image records none);
/// - a command buffer's pool, and the pool's record, never change;
/// - a chain (device group, imageless views) turns the memo off.
#[derive(Clone)]
pub(crate) struct BeginChecked {
    /// The render pass's record.
    pub(crate) pass: Vrc<crate::state::RenderPassRecord>,
    /// The framebuffer's attachments, as its record holds them: one list per
    /// framebuffer created.
    pub(crate) views: Vrc<[vk::ImageView]>,
    pub(crate) area: vk::Rect2D,
    pub(crate) clears: u32,
    /// The address of the command's rules (`vkCmdBeginRenderPass` or its second
    /// version).
    pub(crate) rules: usize,
}

impl BeginChecked {
    fn same(&self, o: &BeginChecked) -> bool {
        Vrc::ptr_eq(&self.pass, &o.pass)
            && Vrc::ptr_eq(&self.views, &o.views)
            && self.area == o.area
            && self.clears == o.clears
            && self.rules == o.rules
    }
}

#[derive(Default)]
struct UsesState {
    /// The last render pass begin that passed its checks.
    begin_checked: Option<BeginChecked>,
    /// Begun since allocation (or the last reset).
    begun: bool,
    /// Begun and not ended: a recorder was dropped or forgotten, or is alive.
    recording: bool,
    /// A `Recorder` of the buffer is alive: a pool reset would pull the buffer out of
    /// the recording state under it.
    recorder: bool,
    secondary: bool,
    executable: bool,
    simultaneous: bool,
    one_time: bool,
    /// Bumped by every begin, so a primary sees when a secondary it executes was
    /// recorded again.
    generation: u64,
    /// The submissions that use the buffer, directly or through a primary.
    subs: Vec<Vweak<Submission>>,
    /// Bumped each time a primary records this secondary: without SIMULTANEOUS_USE
    /// a secondary belongs to the last primary that recorded it, and the earlier
    /// ones are invalid.
    links: u64,
    /// The secondaries the current recording executes, with their generation and
    /// link count then.
    secondaries: Vec<(Vrc<Uses>, u64, u64)>,
    /// The image layouts the last recording needs at its start and leaves at its
    /// end; `None` while recording, or when it names none.
    layouts: Option<Vrc<crate::state::layouts::Recording>>,
    /// The last recording's layouts once a new recording began, for the next end
    /// to write its own into the same allocation where nothing else holds it.
    spare_layouts: Option<Vrc<crate::state::layouts::Recording>>,
    /// The box the last recording kept its image layouts in, empty.
    layouts_box: Option<Box<crate::state::layouts::Recording>>,
    /// What the last recording did to memory, for its submissions to replay; `None`
    /// while recording, or when it did nothing the hazard tracker saw.
    hazards: Option<Vrc<Vec<crate::state::hazards::Event>>>,
    /// How many barriers automatic synchronization recorded into the last recording.
    auto_barriers: u32,
    /// The last recording's hazard tracker, emptied, for the next one to fill
    /// without allocating its tables again.
    spare: Option<Box<crate::state::hazards::Recording>>,
    /// The descriptor sets the last recording bound, each with its generation then.
    sets: Vec<(u64, u64)>,
    /// The queue family of the buffer's pool and whether the pool is protected, as
    /// the pool's creation recorded them (read at each begin).
    pool: Option<(u32, bool)>,
    /// The events the last recording's event commands name.
    events: Vec<u64>,
    /// The queries the last recording needs reset at its start and what it leaves
    /// them; `None` while recording, or when it names none.
    queries: Option<Vrc<crate::state::queries::Recording>>,
    /// What the last recording does to events, if it names any.
    event_states: Option<Vrc<crate::state::events::Recording>>,
    /// What a secondary's current or last recording was begun for.
    inheritance: Option<Vrc<Inheritance>>,
    /// The query types the last recording begins.
    query_types: Vec<vk::QueryType>,
    /// Whether the last recording suspends or resumes a render pass instance.
    suspends: bool,
}

/// What a secondary was recorded for: its begin info's flags and inheritance info,
/// read when it was begun. A primary that executes it checks these against its own
/// state (`special/secondaries.rs`).
#[derive(Clone, Debug, Default)]
pub(crate) struct Inheritance {
    /// `VkCommandBufferBeginInfo::flags`.
    pub flags: vk::CommandBufferUsageFlags,
    /// The render pass it continues (null for none, or dynamic rendering).
    pub render_pass: vk::RenderPass,
    /// That render pass's record, where the wrappers made it.
    pub record: Option<Vrc<crate::state::RenderPassRecord>>,
    /// The subpass it continues.
    pub subpass: u32,
    /// The framebuffer it names (null for none).
    pub framebuffer: vk::Framebuffer,
    /// Whether it may execute while an occlusion query is active, and with which
    /// control flags.
    pub occlusion_query_enable: bool,
    pub query_flags: vk::QueryControlFlags,
    /// The pipeline statistics it may execute while a query counts.
    pub pipeline_statistics: vk::QueryPipelineStatisticFlags,
    /// A chained `VkCommandBufferInheritanceRenderingInfo`.
    pub rendering: Option<InheritedRendering>,
}

/// The dynamic rendering a secondary continues, as its chained
/// `VkCommandBufferInheritanceRenderingInfo` gives it.
#[derive(Clone, Debug)]
pub(crate) struct InheritedRendering {
    /// Its flags.
    pub flags: vk::RenderingFlags,
    /// Its view mask and attachment formats.
    pub formats: Vrc<crate::state::RenderingFormats>,
    /// Its rasterization samples (empty where it gives none).
    pub samples: vk::SampleCountFlags,
}

/// Where a command buffer stands, as the submission checks read it.
#[derive(Clone, Copy)]
pub(crate) struct Standing {
    pub secondary: bool,
    pub executable: bool,
    pub simultaneous: bool,
    /// Bumped by every begin.
    pub generation: u64,
    /// Bumped each time a primary records this secondary.
    pub links: u64,
}

impl Uses {
    /// Where the buffer stands now.
    pub(crate) fn standing(&self) -> Standing {
        let s = self.state.lock();
        Standing {
            secondary: s.secondary,
            executable: s.executable,
            simultaneous: s.simultaneous,
            generation: s.generation,
            links: s.links,
        }
    }

    /// The secondaries the current recording executes, with their generation and
    /// link count when it recorded them.
    pub(crate) fn secondaries(&self) -> Vec<(Vrc<Uses>, u64, u64)> {
        self.state.lock().secondaries.clone()
    }

    /// Records whether the buffer was allocated as a secondary.
    pub(crate) fn set_secondary(&self, secondary: bool) {
        self.state.lock().secondary = secondary;
    }

    /// Marks the buffer executable or not (a frame ring's buffer needs a new
    /// recording for each submission).
    pub(crate) fn set_executable(&self, executable: bool) {
        self.state.lock().executable = executable;
    }

    /// Whether a submission that uses the buffer may still be executing.
    pub(crate) fn is_pending(&self, device: &Device) -> bool {
        let subs: SmallVec<[Vrc<Submission>; 4]> = {
            let mut state = self.state.lock();
            state
                .subs
                .retain(|w| w.upgrade().is_some_and(|s| !s.is_complete()));
            state.subs.iter().filter_map(Vweak::upgrade).collect()
        };
        // Polled outside this lock: a signalled fence retires submissions.
        subs.iter().any(|s| !s.poll(device))
    }

    /// Whether the buffer was begun since allocation (or the last reset), and whether
    /// it is still recording.
    pub(crate) fn lifecycle(&self) -> (bool, bool) {
        let state = self.state.lock();
        (state.begun, state.recording)
    }

    /// Whether the buffer was allocated as a secondary.
    pub(crate) fn is_secondary(&self) -> bool {
        self.state.lock().secondary
    }

    /// Whether the buffer has been ended and may be submitted.
    pub(crate) fn is_executable(&self) -> bool {
        self.state.lock().executable
    }

    /// The buffer went back to the initial state (its reset, or its pool's).
    pub(crate) fn reset(&self) {
        let old = {
            let mut state = self.state.lock();
            state.begun = false;
            state.recording = false;
            state.executable = false;
            state.generation += 1;
            state.layouts = None;
            state.queries = None;
            state.event_states = None;
            state.sets.clear();
            state.events.clear();
            state.inheritance = None;
            state.query_types.clear();
            state.suspends = false;
            core::mem::take(&mut state.secondaries)
        };
        drop(old);
    }

    /// A recorder of the buffer is alive (`true`) or went (`false`).
    pub(crate) fn set_recorder(&self, alive: bool) {
        self.state.lock().recorder = alive;
    }

    /// Whether a recorder of the buffer is alive.
    pub(crate) fn has_recorder(&self) -> bool {
        self.state.lock().recorder
    }

    /// Recording began with `flags`.
    pub(crate) fn began(&self, flags: vk::CommandBufferUsageFlags) {
        let old = {
            let mut state = self.state.lock();
            state.begun = true;
            state.recording = true;
            state.executable = false;
            state.generation += 1;
            state.simultaneous = flags.contains(vk::CommandBufferUsageFlags::SIMULTANEOUS_USE);
            state.one_time = flags.contains(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            state.spare_layouts = state.layouts.take();
            state.queries = None;
            core::mem::take(&mut state.secondaries)
        };
        drop(old);
    }

    /// What the recording just begun continues or inherits (a secondary's), or
    /// nothing (a primary's).
    pub(crate) fn set_inheritance(&self, inheritance: Option<Vrc<Inheritance>>) {
        self.state.lock().inheritance = inheritance;
    }

    /// What the secondary's last recording was begun for.
    pub(crate) fn inheritance(&self) -> Option<Vrc<Inheritance>> {
        self.state.lock().inheritance.clone()
    }

    /// The query types the recording that just ended begins, and whether it
    /// suspends or resumes a render pass instance.
    pub(crate) fn set_query_types(&self, types: Vec<vk::QueryType>, suspends: bool) {
        let mut state = self.state.lock();
        state.query_types = types;
        state.suspends = suspends;
    }

    /// Whether the last recording suspends or resumes a render pass instance.
    pub(crate) fn suspends(&self) -> bool {
        self.state.lock().suspends
    }

    /// The query types the last recording begins.
    pub(crate) fn query_types(&self) -> Vec<vk::QueryType> {
        self.state.lock().query_types.clone()
    }

    /// Whether the current recording already executes `secondary`.
    pub(crate) fn executes_already(&self, secondary: &Vrc<Uses>) -> bool {
        self.state
            .lock()
            .secondaries
            .iter()
            .any(|(s, _, _)| Vrc::ptr_eq(s, secondary))
    }

    /// Recording ended; the buffer is executable unless a check failed while it was
    /// recorded.
    pub(crate) fn ended(&self, executable: bool) {
        let mut state = self.state.lock();
        state.recording = false;
        state.executable = executable;
    }

    /// The image layouts of the recording that just ended (its box, emptied, waits
    /// for the next recording).
    pub(crate) fn set_layouts(&self, mut boxed: Box<crate::state::layouts::Recording>) {
        let layouts = core::mem::take(&mut *boxed);
        let mut state = self.state.lock();
        state.layouts_box = Some(boxed);
        let spare = state.spare_layouts.take();
        if layouts.is_empty() {
            state.layouts = None;
            return;
        }
        state.layouts = Some(match spare {
            // A recording per frame: the last one's allocation, unless a check
            // still reads it.
            Some(mut shell) => match Vrc::get_mut(&mut shell) {
                Some(slot) => {
                    *slot = layouts;
                    shell
                }
                None => Vrc::new(layouts),
            },
            None => Vrc::new(layouts),
        });
    }

    /// Whether the last render pass begin that passed its checks was `begin`.
    pub(crate) fn begin_checked(&self, begin: &BeginChecked) -> bool {
        let state = self.state.lock();
        state.begin_checked.as_ref().is_some_and(|b| b.same(begin))
    }

    /// A render pass begin passed its checks.
    pub(crate) fn set_begin_checked(&self, begin: BeginChecked) {
        self.state.lock().begin_checked = Some(begin);
    }

    /// An empty box for a new recording's image layouts: the last recording's
    /// (boxed: the recorder that holds it is moved whole between its states).
    pub(crate) fn spare_layouts_box(&self) -> Box<crate::state::layouts::Recording> {
        self.state.lock().layouts_box.take().unwrap_or_default()
    }

    /// What the recording that just ended did to memory (its log, for its
    /// submissions), how many barriers automatic synchronization recorded into it,
    /// and its tables (to be emptied and filled again by the next recording).
    pub(crate) fn set_hazards(&self, mut recording: Box<crate::state::hazards::Recording>) {
        let log = recording.take_log();
        let mut state = self.state.lock();
        state.hazards = (!log.is_empty()).then(|| Vrc::new(log));
        state.auto_barriers = recording.auto_barriers;
        state.spare = Some(recording);
    }

    /// How many barriers automatic synchronization recorded into the last
    /// recording.
    pub(crate) fn auto_barriers(&self) -> u32 {
        self.state.lock().auto_barriers
    }

    /// What the last recording did to memory, if anything the tracker saw.
    pub(crate) fn hazards(&self) -> Option<Vrc<Vec<crate::state::hazards::Event>>> {
        self.state.lock().hazards.clone()
    }

    /// An empty hazard tracker for a new recording, in the last recording's
    /// allocations where it can (its log, unless a submission check still holds
    /// it, and its tables). The last recording is over: a new one begins.
    pub(crate) fn spare_recording(&self) -> Box<crate::state::hazards::Recording> {
        let (taken, spare) = {
            let mut state = self.state.lock();
            state.auto_barriers = 0;
            (state.hazards.take(), state.spare.take())
        };
        let log = taken
            .and_then(|log| Vrc::try_unwrap(log).ok())
            .unwrap_or_default();
        // Boxed: the recorder that holds it is moved whole between its states.
        let mut recording = spare.unwrap_or_default();
        recording.recycle(log);
        recording
    }

    /// The image layouts the last recording needs at its start and leaves.
    pub(crate) fn layouts(&self) -> Option<Vrc<crate::state::layouts::Recording>> {
        self.state.lock().layouts.clone()
    }

    /// Records the queue family of the buffer's pool and whether it is protected.
    pub(crate) fn set_pool(&self, pool: Option<(u32, bool)>) {
        self.state.lock().pool = pool;
    }

    /// The queue family of the buffer's pool and whether it is protected, if known.
    pub(crate) fn pool(&self) -> Option<(u32, bool)> {
        self.state.lock().pool
    }

    /// The query states of the recording that just ended.
    pub(crate) fn set_queries(&self, queries: crate::state::queries::Recording) {
        let queries = (!queries.is_empty()).then(|| Vrc::new(queries));
        self.state.lock().queries = queries;
    }

    /// The queries the last recording needs reset at its start and what it leaves.
    pub(crate) fn queries(&self) -> Option<Vrc<crate::state::queries::Recording>> {
        self.state.lock().queries.clone()
    }

    /// What the recording that just ended does to events.
    pub(crate) fn set_event_states(&self, events: crate::state::events::Recording) {
        let events = (!events.is_empty()).then(|| Vrc::new(events));
        self.state.lock().event_states = events;
    }

    /// What the last recording does to events: the states it leaves, the waits
    /// that read states from before it, and its resets.
    pub(crate) fn event_states(&self) -> Option<Vrc<crate::state::events::Recording>> {
        self.state.lock().event_states.clone()
    }

    /// An empty list of bound sets for a new recording, in the last recording's
    /// allocation (the last recording is over: a new one begins).
    pub(crate) fn spare_sets(&self) -> Vec<(u64, u64)> {
        let mut sets = core::mem::take(&mut self.state.lock().sets);
        sets.clear();
        sets
    }

    /// The descriptor sets the recording that just ended bound (raw set, generation).
    pub(crate) fn set_sets(&self, sets: Vec<(u64, u64)>) {
        self.state.lock().sets = sets;
    }

    /// The events the recording that just ended names.
    pub(crate) fn set_events(&self, events: Vec<u64>) {
        self.state.lock().events = events;
    }

    /// Appends the descriptor sets this buffer's recording bound and the events it
    /// names, and those of the secondaries it executes, to `sets` and `events`.
    pub(crate) fn used(&self, sets: &mut SetsUsed, events: &mut EventsUsed) {
        let secondaries: SmallVec<[Vrc<Uses>; 2]> = {
            let state = self.state.lock();
            sets.extend_from_slice(&state.sets);
            events.extend_from_slice(&state.events);
            state
                .secondaries
                .iter()
                .map(|(s, _, _)| s.clone())
                .collect()
        };
        for s in secondaries {
            s.used(sets, events);
        }
    }

    /// The current recording executes `secondary`.
    pub(crate) fn executes(&self, secondary: &Vrc<Uses>) {
        let (generation, links) = {
            let mut s = secondary.state.lock();
            s.links += 1;
            (s.generation, s.links)
        };
        self.state
            .lock()
            .secondaries
            .push((secondary.clone(), generation, links));
    }

    /// `sub` uses this buffer and the secondaries its recording executes.
    pub(crate) fn mark(&self, sub: &Vrc<Submission>) {
        let secondaries: Vec<Vrc<Uses>> = {
            let mut state = self.state.lock();
            state.subs.push(Vrc::downgrade(sub));
            if state.one_time {
                // A one-time buffer goes to the invalid state once submitted.
                state.executable = false;
            }
            state
                .secondaries
                .iter()
                .map(|(s, _, _)| s.clone())
                .collect()
        };
        for s in secondaries {
            s.mark(sub);
        }
    }
}
