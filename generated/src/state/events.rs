//! Event states, followed as the device will see them.
//!
//! A wait on events needs each signaled as the wait says: the first version's
//! `srcStageMask` is the OR of the stage masks `vkCmdSetEvent` gave them, with the
//! host stage for one the host set (`VUID-vkCmdWaitEvents-srcStageMask-01158`), and
//! none was signaled by `vkCmdSetEvent2` (03847); the second version's dependency
//! info is the very one `vkCmdSetEvent2` gave the event, or one of host operations
//! for an event the host set (03837 to 03841). A reset must not race a wait on the
//! event (`VUID-vkCmdResetEvent-event-03834` and its kin): an execution dependency
//! orders the two.
//!
//! A recording knows what its own sets and resets leave ([`Recording`]); the waits
//! on events it has not set or reset, and its resets that nothing in it orders after
//! the commands before it, it keeps, and each submission checks them against what
//! the submissions before it and the host left ([`Overlay`]), in submission order, as
//! queries are followed (`state/queries.rs`). Events order the commands of one
//! queue: a submission naming an event that a pending submission to another queue
//! names is refused before this is asked (`special/queue.rs`).

use super::live::Live;
use super::queue::Submission;
use crate::{Error, Result};
use ash::vk;
// Looked up on every event command: a fast hash for handles.
use super::HashMap;
use std::sync::Arc;
use tuff_runtime::{Vrc, Vweak};

type S2 = vk::PipelineStageFlags2;

/// Where one event stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Signal {
    /// Unsignaled: reset, or not set since its creation.
    Unset,
    /// Set by `vkCmdSetEvent` with this stage mask.
    Set1(vk::PipelineStageFlags),
    /// Set by `vkCmdSetEvent2` with the dependency info of this digest.
    Set2(Arc<[u64]>),
    /// Set by the host.
    Host,
    /// Set or reset by the host while a submission that sets or resets it may still
    /// run: either, by timing.
    Unknown,
}

/// A wait whose events' states come, at least in part, from before the recording.
#[derive(Clone, Debug)]
pub(crate) enum Need {
    /// A `vkCmdWaitEvents` with this `srcStageMask`: each event with the state the
    /// recording left it in before the wait, or `None` where that comes from before.
    Wait1 {
        src: vk::PipelineStageFlags,
        events: Vec<(u64, Option<Signal>)>,
    },
    /// A `vkCmdWaitEvents2`'s wait on one event with the dependency info of this
    /// digest; `host_scope`: its barriers' first scopes hold only host operations;
    /// `barriers`: it has any.
    Wait2 {
        event: u64,
        digest: Arc<[u64]>,
        host_scope: bool,
        barriers: bool,
    },
}

/// Judges a first-version wait with `src` over events in these states.
pub(crate) fn judge1<'s>(
    src: vk::PipelineStageFlags,
    states: impl IntoIterator<Item = (u64, &'s Signal)>,
) -> Result<()> {
    let mut want = vk::PipelineStageFlags::empty();
    for (event, state) in states {
        match state {
            Signal::Set2(_) => {
                return Err(Error::Validation {
                    vuid: "VUID-vkCmdWaitEvents-pEvents-03847",
                    message: format!("event 0x{event:x} was signaled by vkCmdSetEvent2, which only vkCmdWaitEvents2 waits on"),
                })
            }
            Signal::Unknown => return Err(unknown("VUID-vkCmdWaitEvents-srcStageMask-01158", event)),
            Signal::Set1(mask) => want |= *mask,
            Signal::Host => want |= vk::PipelineStageFlags::HOST,
            Signal::Unset => {}
        }
    }
    // An event the host sets after the submission is waited on with the host stage.
    if src != want && src != want | vk::PipelineStageFlags::HOST {
        return Err(Error::Validation {
            vuid: "VUID-vkCmdWaitEvents-srcStageMask-01158",
            message: format!("srcStageMask {src:?} must be the OR of the stage masks vkCmdSetEvent signaled the events with, and the host stage for an event the host set ({want:?}, as the commands before the wait leave them)"),
        });
    }
    Ok(())
}

/// Judges a second-version wait on `event` (as [`Need::Wait2`] says) in `state`.
pub(crate) fn judge2(
    event: u64,
    digest: &[u64],
    host_scope: bool,
    barriers: bool,
    state: &Signal,
) -> Result<()> {
    let (vuid, why) = match state {
        Signal::Set1(_) => (
            "VUID-vkCmdWaitEvents2-pEvents-03837",
            "was signaled by vkCmdSetEvent, which only vkCmdWaitEvents waits on",
        ),
        Signal::Set2(d) if **d != *digest => (
            "VUID-vkCmdWaitEvents2-pEvents-03838",
            "was signaled by vkCmdSetEvent2 with a dependency info other than the wait's (they must be exactly equal)",
        ),
        Signal::Host if !host_scope => (
            "VUID-vkCmdWaitEvents2-pEvents-03839",
            "was signaled by the host, so the wait's barriers must hold only host operations in their first scopes",
        ),
        Signal::Set2(_) | Signal::Host => return Ok(()),
        Signal::Unset if host_scope && barriers => (
            "VUID-vkCmdWaitEvents2-pEvents-03840",
            "is not signaled, and the wait's barriers hold only host operations: the host must set it before the submission",
        ),
        Signal::Unset => (
            "VUID-vkCmdWaitEvents2-pEvents-03841",
            "is not signaled by a vkCmdSetEvent2 earlier in submission order",
        ),
        Signal::Unknown => return Err(unknown("VUID-vkCmdWaitEvents2-pEvents-03841", event)),
    };
    Err(Error::Validation {
        vuid,
        message: format!("event 0x{event:x} {why}"),
    })
}

fn unknown(vuid: &'static str, event: u64) -> Error {
    Error::Validation {
        vuid,
        message: format!("event 0x{event:x} was set or reset by the host while a submission that sets or resets it may still have been executing: which came last is not known, so a wait on it cannot be checked (reset it once the submission completes)"),
    }
}

/// Whether stages `a` come after everything in `b` (`a` names every command, or
/// holds `b`); both with their meta stages spelled out.
fn covers(a: S2, b: S2) -> bool {
    a.contains(S2::ALL_COMMANDS) || (!b.is_empty() && a.contains(b))
}

/// The rule a reset of the given version breaks against a wait of the given version.
fn race(reset2: bool, wait2: bool) -> &'static str {
    match (reset2, wait2) {
        (false, false) => "VUID-vkCmdResetEvent-event-03834",
        (false, true) => "VUID-vkCmdResetEvent-event-03835",
        (true, false) => "VUID-vkCmdResetEvent2-event-03831",
        (true, true) => "VUID-vkCmdResetEvent2-event-03832",
    }
}

/// Waits on one event that later resets must come after.
#[derive(Clone, Copy, Debug)]
struct Waited {
    /// The stages the waits block (their `dstStageMask`s).
    stages: S2,
    /// Whether a wait was of the second version.
    v2: bool,
    /// The stages that barriers since the waits order after them.
    after: S2,
}

/// What one recording does to events: the states it leaves, and what it needs of
/// the states before it.
#[derive(Clone, Debug, Default)]
pub(crate) struct Recording {
    /// The state the recording's sets and resets leave each event in.
    now: HashMap<u64, Signal>,
    /// Its waits on events whose state comes from before it.
    needs: Vec<Need>,
    /// Its waits on each event, for the resets after them.
    waits: HashMap<u64, Waited>,
    /// Its resets (event, stage mask, second version) that no barrier of its own
    /// orders after every command before it.
    early_resets: Vec<(u64, S2, bool)>,
    /// The stages that its barriers order after every command before them.
    ordered_all: S2,
}

impl Recording {
    /// The state the recording's commands so far leave `event` in, if they set or
    /// reset it.
    pub(crate) fn signal(&self, event: u64) -> Option<&Signal> {
        self.now.get(&event)
    }

    /// A set of `event` (by `vkCmdSetEvent` or `vkCmdSetEvent2`).
    pub(crate) fn set(&mut self, event: u64, signal: Signal) {
        self.now.insert(event, signal);
    }

    /// Refuses a reset of `event` at `stages` that no barrier orders after a wait
    /// on it that the recording's commands made.
    pub(crate) fn check_reset(&self, event: u64, stages: S2, reset2: bool) -> Result<()> {
        match self.waits.get(&event) {
            Some(w) if !covers(w.after, stages) => Err(Error::Validation {
                vuid: race(reset2, w.v2),
                message: format!("event 0x{event:x} is reset after a wait on it with no barrier between that orders the reset's stages ({stages:?}) after the wait's ({:?}): record a pipeline barrier from the wait's stages to the reset's", w.stages),
            }),
            _ => Ok(()),
        }
    }

    /// A reset of `event` at `stages`.
    pub(crate) fn reset(&mut self, event: u64, stages: S2, reset2: bool) {
        self.now.insert(event, Signal::Unset);
        if !covers(self.ordered_all, stages) {
            self.early_resets.push((event, stages, reset2));
        }
    }

    /// A first-version wait with `src` on `events`: what the recording knows of
    /// each, or `None` where the state comes from before it.
    pub(crate) fn known(&self, events: &[u64]) -> Vec<(u64, Option<Signal>)> {
        events
            .iter()
            .map(|e| (*e, self.now.get(e).cloned()))
            .collect()
    }

    /// A wait blocking `stages` on `events` (of the second version: `v2`), after
    /// its checks; `need` is kept where it depends on states before the recording.
    pub(crate) fn waited(&mut self, events: &[u64], stages: S2, v2: bool, need: Option<Need>) {
        for e in events {
            let w = self.waits.entry(*e).or_insert(Waited {
                stages: S2::empty(),
                v2,
                after: S2::empty(),
            });
            w.stages |= stages;
            w.v2 |= v2;
            // A new wait is not ordered before anything yet.
            w.after = S2::empty();
        }
        self.needs.extend(need);
    }

    /// A barrier from stages `src` to `dst` (meta stages spelled out): it orders
    /// `dst` after the waits whose stages `src` holds.
    pub(crate) fn barrier(&mut self, src: S2, dst: S2) {
        for w in self.waits.values_mut() {
            if covers(src, w.stages) {
                w.after |= dst;
            }
        }
        if src.contains(S2::ALL_COMMANDS) {
            self.ordered_all |= dst;
        }
    }

    /// Whether the recording names no event.
    pub(crate) fn is_empty(&self) -> bool {
        self.now.is_empty() && self.needs.is_empty() && self.waits.is_empty()
    }

    /// `need` with what this recording leaves filled in: `Ok(None)` where that
    /// settles it (and it holds), the need still open otherwise.
    fn resolve(&self, need: &Need) -> Result<Option<Need>> {
        match need {
            Need::Wait1 { src, events } => {
                let events: Vec<_> = events
                    .iter()
                    .map(|(e, s)| (*e, s.clone().or_else(|| self.now.get(e).cloned())))
                    .collect();
                if events.iter().all(|(_, s)| s.is_some()) {
                    judge1(*src, events.iter().map(|(e, s)| (*e, s.as_ref().unwrap())))?;
                    Ok(None)
                } else {
                    Ok(Some(Need::Wait1 { src: *src, events }))
                }
            }
            Need::Wait2 {
                event,
                digest,
                host_scope,
                barriers,
            } => match self.now.get(event) {
                Some(s) => judge2(*event, digest, *host_scope, *barriers, s).map(|_| None),
                None => Ok(Some(need.clone())),
            },
        }
    }

    /// Refuses to execute `other` (a secondary) after this recording's commands
    /// where its waits break on the states they leave, or its resets race their
    /// waits.
    pub(crate) fn check_then(&self, other: &Recording) -> Result<()> {
        for need in &other.needs {
            self.resolve(need)?;
        }
        for (event, stages, reset2) in &other.early_resets {
            self.check_reset(*event, *stages, *reset2)?;
        }
        Ok(())
    }

    /// This recording executes `other` (a secondary) after its commands so far
    /// (checked by [`Recording::check_then`]).
    pub(crate) fn then(&mut self, other: &Recording) {
        for need in &other.needs {
            if let Ok(Some(open)) = self.resolve(need) {
                self.needs.push(open);
            }
        }
        for (event, stages, reset2) in &other.early_resets {
            if !covers(self.ordered_all, *stages) {
                self.early_resets.push((*event, *stages, *reset2));
            }
        }
        for (event, w) in &other.waits {
            let ours = self.waits.entry(*event).or_insert(*w);
            ours.stages |= w.stages;
            ours.v2 |= w.v2;
            ours.after = w.after;
        }
        for (event, s) in &other.now {
            self.now.insert(*event, s.clone());
        }
        self.ordered_all |= other.ordered_all;
    }
}

/// What the device records of one event: its state as the submissions and the host
/// so far leave it, the last submission that sets or resets it, and the last that
/// waits on it (with whether a wait there is of the second version).
#[derive(Default)]
pub(crate) struct EventRecord {
    signal: Option<Signal>,
    writer: Option<Vweak<Submission>>,
    waiter: Option<(Vweak<Submission>, bool)>,
}

/// The event states a run of submissions leaves, over those the device's earlier
/// submissions and the host left: checked and applied one recording at a time, and
/// written to the device only once the submission is made.
pub(crate) struct Overlay<'a> {
    live: &'a Live,
    signals: HashMap<u64, Signal>,
    /// The events the run's recordings so far wait on, and whether a wait was of
    /// the second version.
    waited: HashMap<u64, bool>,
    /// The events the run's recordings set or reset.
    written: Vec<u64>,
}

impl<'a> Overlay<'a> {
    /// No submission yet, over the device's event states.
    pub(crate) fn new(live: &'a Live) -> Self {
        Overlay {
            live,
            signals: HashMap::default(),
            waited: HashMap::default(),
            written: Vec::new(),
        }
    }

    fn signal(&self, event: u64) -> Signal {
        self.signals
            .get(&event)
            .cloned()
            .unwrap_or_else(|| self.live.event_signal(event))
    }

    /// Refuses a recording whose waits break on the states the submissions before
    /// it leave, or whose resets race a wait of one of them that `pending` says may
    /// still be executing.
    pub(crate) fn check(
        &self,
        recording: &Recording,
        pending: impl Fn(&Vrc<Submission>) -> bool,
    ) -> Result<()> {
        for need in &recording.needs {
            match need {
                Need::Wait1 { src, events } => {
                    let states: Vec<(u64, Signal)> = events
                        .iter()
                        .map(|(e, s)| (*e, s.clone().unwrap_or_else(|| self.signal(*e))))
                        .collect();
                    judge1(*src, states.iter().map(|(e, s)| (*e, s)))?;
                }
                Need::Wait2 {
                    event,
                    digest,
                    host_scope,
                    barriers,
                } => judge2(*event, digest, *host_scope, *barriers, &self.signal(*event))?,
            }
        }
        for (event, stages, reset2) in &recording.early_resets {
            let waiter = self.waited.get(event).copied().or_else(|| {
                let (sub, v2) = self.live.event_waiter(*event)?;
                pending(&sub).then_some(v2)
            });
            if let Some(v2) = waiter {
                return Err(Error::Validation {
                    vuid: race(*reset2, v2),
                    message: format!("event 0x{event:x} is reset (at {stages:?}) while a wait on it that an earlier submission made may still be executing, and no barrier of the command buffer from all commands orders the reset after it: wait for that submission first, or record a pipeline barrier from VK_PIPELINE_STAGE_ALL_COMMANDS_BIT before the reset"),
                });
            }
        }
        Ok(())
    }

    /// The event states after `recording` executes.
    pub(crate) fn apply(&mut self, recording: &Recording) {
        for (event, s) in &recording.now {
            self.signals.insert(*event, s.clone());
            self.written.push(*event);
        }
        for (event, w) in &recording.waits {
            if !w.after.contains(S2::ALL_COMMANDS) {
                let v2 = self.waited.entry(*event).or_insert(false);
                *v2 |= w.v2;
            }
        }
    }

    /// The submission `sub` was made: the device's event states are this
    /// overlay's, and `sub` is the last to set, reset or wait on the events its
    /// recordings do.
    pub(crate) fn commit(self, sub: &Vrc<Submission>) {
        let mut all = self.live.event_records.lock();
        for (event, s) in self.signals {
            let r = all.entry(event).or_default();
            r.signal = Some(s);
        }
        for event in self.written {
            if let Some(r) = all.get_mut(&event) {
                r.writer = Some(Vrc::downgrade(sub));
            }
        }
        for (event, v2) in self.waited {
            all.entry(event).or_default().waiter = Some((Vrc::downgrade(sub), v2));
        }
    }
}

impl Live {
    /// An event's state as the submissions and the host so far leave it.
    pub(crate) fn event_signal(&self, event: u64) -> Signal {
        self.event_records
            .lock()
            .get(&event)
            .and_then(|r| r.signal.clone())
            .unwrap_or(Signal::Unset)
    }

    /// The last submission that waits on `event`, while it is held, and whether a
    /// wait there is of the second version.
    fn event_waiter(&self, event: u64) -> Option<(Vrc<Submission>, bool)> {
        let all = self.event_records.lock();
        let (w, v2) = all.get(&event)?.waiter.as_ref()?;
        Some((w.upgrade()?, *v2))
    }

    /// The last submission that sets or resets `event`, while it is held.
    pub(crate) fn event_writer(&self, event: u64) -> Option<Vrc<Submission>> {
        self.event_records
            .lock()
            .get(&event)?
            .writer
            .as_ref()?
            .upgrade()
    }

    /// The host set or reset `event`, leaving it in `signal`.
    pub(crate) fn event_signaled_on_host(&self, event: u64, signal: Signal) {
        self.event_records.lock().entry(event).or_default().signal = Some(signal);
    }

    /// An event was destroyed: a raw handle used again names a new event.
    pub(crate) fn forget_event(&self, event: u64) {
        self.event_records.lock().remove(&event);
    }
}
