//! Query states, followed as the device will see them.
//!
//! A command that begins or writes a query needs it unavailable when it executes:
//! reset (by `vkCmdResetQueryPool` or the host's `vkResetQueryPool`) since its pool's
//! creation and since its last use (`VUID-vkCmdBeginQuery-None-00807`, the
//! timestamps' `-00828` and `-00830`). A recording knows what its own resets and
//! uses leave ([`Recording`]); the queries it uses before resetting them it lists,
//! with the rule that needs them reset. Each submission compares those lists with
//! the states the submissions before it left ([`Overlay`]), in submission order, as
//! the image layouts are followed (`state/layouts.rs`).

use super::live::Live;
use super::queue::Submission;
use crate::{Error, Result};
use ash::vk::{self, Handle as _};
// Looked up on every query command: a fast hash for handles.
use super::HashMap;
use tuff_runtime::{Vrc, Vweak};

/// Where one query stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Query {
    /// In a recording: no command of it names the query yet. On the device: not
    /// reset since its pool's creation (a new query's state is undefined).
    Untouched,
    /// Reset, and not used since: unavailable.
    Reset,
    /// Begun or written since its last reset.
    Used,
}

/// What a recording does to one pool's queries.
#[derive(Clone, Debug)]
struct Track {
    /// For each query: the rule that needs it reset when the recording starts
    /// (`""`: none).
    first: Vec<&'static str>,
    /// For each query: where the recording's commands so far leave it.
    now: Vec<Query>,
}

impl Track {
    fn new(count: usize) -> Self {
        Track {
            first: vec![""; count],
            now: vec![Query::Untouched; count],
        }
    }
}

/// The queries one recording needs reset at its start, and what it leaves.
#[derive(Clone, Debug, Default)]
pub(crate) struct Recording {
    pools: HashMap<u64, Track>,
}

/// The queries `first..first + count` of a pool of `len`, clipped to the pool (a
/// range past it is another rule's to refuse).
fn range(first: u32, count: u32, len: usize) -> core::ops::Range<usize> {
    let start = (first as usize).min(len);
    start..(first as usize).saturating_add(count as usize).min(len)
}

/// The error of a query used while not reset.
fn not_reset(vuid: &'static str, pool: u64, query: usize, when: &str) -> Error {
    Error::Validation {
        vuid,
        message: format!(
            "query {query} of pool 0x{pool:x} must be unavailable, but it is not reset {when}: reset it (vkCmdResetQueryPool before the command, or vkResetQueryPool on the host) after its pool's creation and after each use"
        ),
    }
}

impl Recording {
    fn track(&mut self, live: &Live, pool: vk::QueryPool) -> Option<&mut Track> {
        use std::collections::hash_map::Entry;
        match self.pools.entry(pool.as_raw()) {
            Entry::Occupied(e) => Some(e.into_mut()),
            Entry::Vacant(e) => {
                let count = live.query_pool(pool)?.count as usize;
                Some(e.insert(Track::new(count)))
            }
        }
    }

    /// A reset of queries `first..first + count`.
    pub(crate) fn reset(&mut self, live: &Live, pool: vk::QueryPool, first: u32, count: u32) {
        let Some(t) = self.track(live, pool) else {
            return;
        };
        let r = range(first, count, t.now.len());
        t.now[r].fill(Query::Reset);
    }

    /// Refuses a use of queries `first..first + count` that the recording's earlier
    /// commands used since they reset them (`vuid` names the rule).
    pub(crate) fn check_use(
        &self,
        pool: vk::QueryPool,
        first: u32,
        count: u32,
        vuid: &'static str,
    ) -> Result<()> {
        let Some(t) = self.pools.get(&pool.as_raw()) else {
            return Ok(());
        };
        for i in range(first, count, t.now.len()) {
            if t.now[i] == Query::Used {
                return Err(not_reset(
                    vuid,
                    pool.as_raw(),
                    i,
                    "since an earlier command of the recording used it",
                ));
            }
        }
        Ok(())
    }

    /// A use of queries `first..first + count`: those the recording has not reset
    /// need it at its start (`vuid` names the rule).
    pub(crate) fn used(
        &mut self,
        live: &Live,
        pool: vk::QueryPool,
        first: u32,
        count: u32,
        vuid: &'static str,
    ) {
        let Some(t) = self.track(live, pool) else {
            return;
        };
        for i in range(first, count, t.now.len()) {
            if t.now[i] == Query::Untouched {
                t.first[i] = vuid;
            }
            t.now[i] = Query::Used;
        }
    }

    /// Refuses to execute `other` (a secondary) after this recording's commands
    /// where it uses a query they used since its reset.
    pub(crate) fn check_then(&self, other: &Recording) -> Result<()> {
        for (pool, theirs) in &other.pools {
            let Some(ours) = self.pools.get(pool) else {
                continue;
            };
            for (i, vuid) in theirs.first.iter().enumerate() {
                if !vuid.is_empty() && ours.now.get(i) == Some(&Query::Used) {
                    return Err(not_reset(
                        vuid,
                        *pool,
                        i,
                        "after the commands recorded before the secondary that uses it",
                    ));
                }
            }
        }
        Ok(())
    }

    /// This recording executes `other` (a secondary) after its commands so far.
    pub(crate) fn then(&mut self, other: &Recording) {
        for (pool, theirs) in &other.pools {
            let ours = self
                .pools
                .entry(*pool)
                .or_insert_with(|| Track::new(theirs.now.len()));
            for (i, vuid) in theirs.first.iter().enumerate() {
                if !vuid.is_empty() && ours.now[i] == Query::Untouched {
                    ours.first[i] = vuid;
                }
            }
            for (i, now) in theirs.now.iter().enumerate() {
                if *now != Query::Untouched {
                    ours.now[i] = *now;
                }
            }
        }
    }

    /// Whether the recording names no query.
    pub(crate) fn is_empty(&self) -> bool {
        self.pools.is_empty()
    }
}

/// The query states a run of submissions leaves, over those the device's earlier
/// submissions and host resets left: checked and applied one recording at a time,
/// and written to the device only once the submission is made.
pub(crate) struct Overlay<'a> {
    live: &'a Live,
    pools: HashMap<u64, Vec<Query>>,
    /// The queries each pool's recordings name, as `first..end`.
    touched: HashMap<u64, (u32, u32)>,
}

impl<'a> Overlay<'a> {
    /// No submission yet, over the device's query states.
    pub(crate) fn new(live: &'a Live) -> Self {
        Overlay {
            live,
            pools: HashMap::default(),
            touched: HashMap::default(),
        }
    }

    fn states(&mut self, pool: u64, len: usize) -> &mut Vec<Query> {
        let live = self.live;
        self.pools
            .entry(pool)
            .or_insert_with(|| live.query_states(pool, len))
    }

    /// Refuses a recording that uses a query the submissions before it leave
    /// other than reset.
    pub(crate) fn check(&mut self, recording: &Recording) -> Result<()> {
        for (pool, t) in &recording.pools {
            let states = self.states(*pool, t.now.len());
            for (i, vuid) in t.first.iter().enumerate() {
                if !vuid.is_empty() && states[i] != Query::Reset {
                    return Err(not_reset(
                        vuid,
                        *pool,
                        i,
                        "when the submission executes the command (as the earlier submissions and host resets leave it)",
                    ));
                }
            }
        }
        Ok(())
    }

    /// The query states after `recording` executes.
    pub(crate) fn apply(&mut self, recording: &Recording) {
        for (pool, t) in &recording.pools {
            let states = self.states(*pool, t.now.len());
            let mut lo = u32::MAX;
            let mut hi = 0;
            for (i, now) in t.now.iter().enumerate() {
                if *now != Query::Untouched {
                    states[i] = *now;
                    lo = lo.min(i as u32);
                    hi = hi.max(i as u32 + 1);
                }
            }
            if lo < hi {
                let span = self.touched.entry(*pool).or_insert((lo, hi));
                *span = (span.0.min(lo), span.1.max(hi));
            }
        }
    }

    /// The submission `sub` was made: the device's query states are this
    /// overlay's, and `sub` names the queries its recordings touched until it
    /// completes.
    pub(crate) fn commit(self, sub: &Vrc<Submission>) {
        for (pool, states) in self.pools {
            let span = self.touched.get(&pool).copied();
            self.live.set_query_states(pool, states, span, sub);
        }
    }
}

/// What the device records of one pool's queries.
#[derive(Default)]
pub(crate) struct PoolQueries {
    /// Each query's state as the submissions and host resets so far leave it.
    states: Vec<Query>,
    /// The submissions whose recordings touch the pool, each with the span of
    /// queries they touch (`first..end`), until they are known complete.
    subs: Vec<(u32, u32, Vweak<Submission>)>,
}

impl Live {
    /// The states of a pool's `len` queries as the submissions and host resets so
    /// far leave them.
    pub(crate) fn query_states(&self, pool: u64, len: usize) -> Vec<Query> {
        match self.query_states.lock().get(&pool) {
            Some(p) if p.states.len() == len => p.states.clone(),
            _ => vec![Query::Untouched; len],
        }
    }

    /// Records the states a submission leaves a pool's queries in, and that it
    /// touches `span` of them.
    fn set_query_states(
        &self,
        pool: u64,
        states: Vec<Query>,
        span: Option<(u32, u32)>,
        sub: &Vrc<Submission>,
    ) {
        // Only a listed pool: one destroyed since the check keeps no entry.
        if !self.query_pools.lock().contains_key(&pool) {
            return;
        }
        let mut all = self.query_states.lock();
        let p = all.entry(pool).or_default();
        p.states = states;
        if let Some((lo, hi)) = span {
            p.subs
                .retain(|(_, _, w)| w.upgrade().is_some_and(|s| !s.is_complete()));
            p.subs.push((lo, hi, Vrc::downgrade(sub)));
        }
    }

    /// A submission not known complete whose recordings touch queries
    /// `first..first + count` of the pool.
    pub(crate) fn query_submissions(
        &self,
        pool: vk::QueryPool,
        first: u32,
        count: u32,
    ) -> Vec<Vrc<Submission>> {
        let end = first.saturating_add(count);
        self.query_states
            .lock()
            .get(&pool.as_raw())
            .map_or(Vec::new(), |p| {
                p.subs
                    .iter()
                    .filter(|(lo, hi, _)| *lo < end && first < *hi)
                    .filter_map(|(_, _, w)| w.upgrade())
                    .filter(|s| !s.is_complete())
                    .collect()
            })
    }

    /// The host reset queries `first..first + count` of a pool of `len` queries.
    pub(crate) fn queries_reset_on_host(
        &self,
        pool: vk::QueryPool,
        len: u32,
        first: u32,
        count: u32,
    ) {
        let mut all = self.query_states.lock();
        let p = all.entry(pool.as_raw()).or_default();
        if p.states.len() != len as usize {
            p.states = vec![Query::Untouched; len as usize];
        }
        let r = range(first, count, p.states.len());
        p.states[r].fill(Query::Reset);
    }

    /// Held by the host's reads and resets of queries, which may not run at once.
    pub(crate) fn query_host(&self) -> tuff_runtime::VutexGuard<'_, ()> {
        self.query_host.lock()
    }

    /// A pool was created or destroyed: a raw handle used again names new queries.
    pub(crate) fn forget_query_states(&self, pool: u64) {
        self.query_states.lock().remove(&pool);
    }
}
