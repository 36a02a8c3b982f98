//! Queries through the safe methods: a query is begun or written only while
//! unavailable (reset since its pool's creation and since its last use), followed
//! through the recording, the secondaries a primary executes, each submission in
//! order and the host's resets; timestamps on a timestamp pool, one stage, inside
//! the pool; host resets inside the pool and of no query a pending submission uses.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID;
//! beside each, programs that keep the rules run with the layer silent.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips; the driver never sees it.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, vuid, Setup};
use vulkan::assert_silent;

/// Runs `unchecked` with the layer told to skip erroring calls, and fails unless it
/// named `expected`.
fn layer_names(messages: &tuff::MessageLog, expected: &str, unchecked: impl FnOnce()) {
    messages.take();
    messages.abort_on_error(true);
    unchecked();
    messages.abort_on_error(false);
    let said = messages.take();
    assert!(
        said.iter().any(|m| m.contains(expected)),
        "the validation layer did not report {expected}; it said:\n{}",
        said.join("\n")
    );
}

fn pool(s: &Setup, ty: vk::QueryType, count: u32) -> tuff::QueryPool {
    s.device
        .create_query_pool(
            &tuff::QueryPoolCreateInfo::new()
                .query_type(ty)
                .query_count(count),
        )
        .expect("query pool")
}

/// Submits `cbs` in one batch and waits for it.
fn submit(s: &Setup, cbs: &[&tuff::CommandBuffer]) -> tuff::Result<()> {
    let fence = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let handles = tuff::HandleSlice::new(cbs);
    s.queue.submit(
        &[tuff::SubmitInfo::new().command_buffers(&handles)],
        Some(&fence),
    )?;
    let waited = s
        .device
        .wait_for_fences(&fence, true, u64::MAX)
        .expect("wait");
    assert_eq!(waited, tuff::SuccessOrTimeout::Success);
    Ok(())
}

/// As [`submit`], through the `_unchecked` twin, which the layer may skip.
fn submit_unchecked(s: &Setup, cbs: &[&tuff::CommandBuffer]) {
    let handles = tuff::HandleSlice::new(cbs);
    // SAFETY: the caller's case breaks only the rule under test, which the layer
    // reports and skips.
    let _ = unsafe {
        s.queue
            .submit_unchecked(&[tuff::SubmitInfo::new().command_buffers(&handles)], None)
    };
    s.queue.wait_idle().expect("idle");
}

/// The name the 1.3.239 layer gives the rules that need a query unavailable (it
/// checks them at each submission).
const QUERY_NOT_RESET: &str = "UNASSIGNED-CoreValidation-DrawState-QueryNotReset";

const TIMESTAMP: vk::QueryType = vk::QueryType::TIMESTAMP;
const OCCLUSION: vk::QueryType = vk::QueryType::OCCLUSION;
const BOTTOM: vk::PipelineStageFlags = vk::PipelineStageFlags::BOTTOM_OF_PIPE;
const BOTTOM2: vk::PipelineStageFlags2 = vk::PipelineStageFlags2::BOTTOM_OF_PIPE;

/// How a case uses query 0 of a pool.
#[derive(Clone, Copy, Debug)]
enum Use {
    /// `vkCmdBeginQuery` and `vkCmdEndQuery` on an occlusion pool.
    Begin,
    /// `vkCmdWriteTimestamp` on a timestamp pool.
    Timestamp,
    /// `vkCmdWriteTimestamp2` on a timestamp pool.
    Timestamp2,
}

impl Use {
    const ALL: [Use; 3] = [Use::Begin, Use::Timestamp, Use::Timestamp2];

    fn pool_type(self) -> vk::QueryType {
        match self {
            Use::Begin => OCCLUSION,
            _ => TIMESTAMP,
        }
    }

    /// The rule that needs the query unavailable.
    fn rule(self) -> &'static str {
        match self {
            Use::Begin => "VUID-vkCmdBeginQuery-None-00807",
            Use::Timestamp => "VUID-vkCmdWriteTimestamp-None-00830",
            Use::Timestamp2 => "VUID-vkCmdWriteTimestamp2-None-03864",
        }
    }

    fn record(
        self,
        rec: &mut tuff::Recorder<'_, tuff::Outside>,
        pool: &tuff::QueryPool,
    ) -> tuff::Result<()> {
        match self {
            Use::Begin => {
                rec.begin_query(pool, 0, vk::QueryControlFlags::empty())?;
                rec.end_query(pool, 0)
            }
            Use::Timestamp => rec.write_timestamp(BOTTOM, pool, 0),
            Use::Timestamp2 => rec.write_timestamp2(BOTTOM2, pool, 0),
        }
    }

    /// # Safety
    ///
    /// As the `_unchecked` methods it calls.
    unsafe fn record_unchecked(
        self,
        rec: &mut tuff::Recorder<'_, tuff::Outside>,
        pool: &tuff::QueryPool,
    ) {
        // SAFETY: the caller's promise.
        unsafe {
            match self {
                Use::Begin => {
                    rec.begin_query_unchecked(pool, 0, vk::QueryControlFlags::empty())
                        .expect("recorded");
                    rec.end_query(pool, 0).expect("end");
                }
                Use::Timestamp => rec
                    .write_timestamp_unchecked(BOTTOM, pool, 0)
                    .expect("recorded"),
                Use::Timestamp2 => rec
                    .write_timestamp2_unchecked(BOTTOM2, pool, 0)
                    .expect("recorded"),
            }
        }
    }
}

/// A second use of a query in one recording, with no reset between, is refused at
/// the command; the layer names the rule when the recording is submitted.
#[test]
fn a_query_is_used_once_between_resets_in_a_recording() {
    let _serial = vulkan::serial();
    let s = setup(true);
    for u in Use::ALL {
        let pool = pool(&s, u.pool_type(), 2);
        let (_cp, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.reset_query_pool(&pool, 0, 2).expect("reset");
        u.record(&mut rec, &pool).expect("first use");
        assert_eq!(vuid(u.record(&mut rec, &pool)), u.rule(), "{u:?}");
        drop(rec);
        // A reset between the uses makes the second one valid, and the recording
        // can be submitted again: it resets before its first use.
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.reset_query_pool(&pool, 0, 2).expect("reset");
        u.record(&mut rec, &pool).expect("first use");
        rec.reset_query_pool(&pool, 0, 1).expect("reset again");
        u.record(&mut rec, &pool).expect("use after the reset");
        rec.end().expect("end");
        submit(&s, &[&cb]).expect("submit");
        submit(&s, &[&cb]).expect("submit again");
        // The unchecked twin records the second use; the layer reports it at the
        // submission, by the name the 1.3.239 layer gives the rule there.
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.reset_query_pool(&pool, 0, 2).expect("reset");
        u.record(&mut rec, &pool).expect("first use");
        // SAFETY: see the module docs.
        unsafe { u.record_unchecked(&mut rec, &pool) };
        rec.end().expect("end");
        layer_names(&s.messages, QUERY_NOT_RESET, || {
            submit_unchecked(&s, &[&cb])
        });
    }
    assert_silent(&s.messages);
}

/// A recording that uses a query before resetting it is checked at each submission
/// against the states the submissions before it (the earlier command buffers of the
/// same batch included) and the host's resets leave.
#[test]
fn queries_are_followed_across_submissions_and_host_resets() {
    let _serial = vulkan::serial();
    let s = setup(true);
    for u in Use::ALL {
        let pool = pool(&s, u.pool_type(), 2);
        let (_cp, mut reset) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = reset
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.reset_query_pool(&pool, 0, 2).expect("reset");
        rec.end().expect("end");
        let (_cp2, mut uses) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = uses
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        u.record(&mut rec, &pool)
            .expect("a use the recording leaves to its submission");
        rec.end().expect("end");

        // Never reset since the pool's creation.
        assert_eq!(vuid(submit(&s, &[&uses])), u.rule(), "{u:?}");
        layer_names(&s.messages, QUERY_NOT_RESET, || {
            submit_unchecked(&s, &[&uses])
        });
        // Reset by the command buffer before it in the same batch.
        submit(&s, &[&reset, &uses]).expect("reset, then used");
        // Used since.
        assert_eq!(vuid(submit(&s, &[&uses])), u.rule(), "{u:?}");
        // Reset by an earlier submission.
        submit(&s, &[&reset]).expect("reset");
        submit(&s, &[&uses]).expect("used after a reset");
        // Reset on the host.
        s.device.reset_query_pool(&pool, 0, 2).expect("host reset");
        submit(&s, &[&uses]).expect("used after a host reset");
        assert_eq!(vuid(submit(&s, &[&uses])), u.rule(), "{u:?}");
        // A new pool's queries are not reset, whatever the handle.
        drop(pool);
        let pool = self::pool(&s, u.pool_type(), 2);
        let (_cp3, mut fresh) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = fresh
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        u.record(&mut rec, &pool).expect("use");
        rec.end().expect("end");
        assert_eq!(vuid(submit(&s, &[&fresh])), u.rule(), "{u:?}");
    }
    assert_silent(&s.messages);
}

/// A secondary that uses a query before resetting it is refused where the primary
/// executes it after using the query itself, and accepted after the primary's reset.
#[test]
fn a_secondary_is_checked_against_the_queries_its_primary_leaves() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let pool = pool(&s, TIMESTAMP, 1);
    let (_cp, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let inheritance = tuff::CommandBufferInheritanceInfo::new();
    let mut rec = secondary
        .begin(&tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance)))
        .expect("begin");
    rec.write_timestamp(BOTTOM, &pool, 0).expect("timestamp");
    rec.end().expect("end");
    let (_cp2, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.reset_query_pool(&pool, 0, 1).expect("reset");
    rec.write_timestamp(BOTTOM, &pool, 0).expect("timestamp");
    assert_eq!(
        vuid(rec.execute_commands(&secondary)),
        "VUID-vkCmdWriteTimestamp-None-00830"
    );
    rec.reset_query_pool(&pool, 0, 1).expect("reset");
    rec.execute_commands(&secondary)
        .expect("execute after the reset");
    rec.end().expect("end");
    submit(&s, &[&primary]).expect("submit");
    // The primary leaves the query used, as the secondary left it.
    let (_cp3, mut again) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = again
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.execute_commands(&secondary).expect("execute");
    rec.end().expect("end");
    assert_eq!(
        vuid(submit(&s, &[&again])),
        "VUID-vkCmdWriteTimestamp-None-00830"
    );
    assert_silent(&s.messages);
}

/// A timestamp is written to a timestamp pool (01416, 03861), at a query inside it
/// (04904, 04903), and the second version names one stage (03859).
#[test]
fn timestamps_are_written_to_one_query_of_a_timestamp_pool_at_one_stage() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let timestamps = pool(&s, TIMESTAMP, 2);
    let occlusion = pool(&s, OCCLUSION, 2);
    type Case<'a> = (
        &'static str,
        &'a dyn Fn(&mut tuff::Recorder<'_, tuff::Outside>) -> tuff::Result<()>,
        &'a dyn Fn(&mut tuff::Recorder<'_, tuff::Outside>),
    );
    let two = BOTTOM2 | vk::PipelineStageFlags2::TOP_OF_PIPE;
    // SAFETY (of each unchecked call): see the module docs.
    let cases: [Case<'_>; 5] = [
        (
            "VUID-vkCmdWriteTimestamp-queryPool-01416",
            &|r| r.write_timestamp(BOTTOM, &occlusion, 0),
            &|r| unsafe { r.write_timestamp_unchecked(BOTTOM, &occlusion, 0) }.expect("recorded"),
        ),
        (
            "VUID-vkCmdWriteTimestamp2-queryPool-03861",
            &|r| r.write_timestamp2(BOTTOM2, &occlusion, 0),
            &|r| unsafe { r.write_timestamp2_unchecked(BOTTOM2, &occlusion, 0) }.expect("recorded"),
        ),
        (
            "VUID-vkCmdWriteTimestamp-query-04904",
            &|r| r.write_timestamp(BOTTOM, &timestamps, 2),
            &|r| unsafe { r.write_timestamp_unchecked(BOTTOM, &timestamps, 2) }.expect("recorded"),
        ),
        (
            "VUID-vkCmdWriteTimestamp2-query-04903",
            &|r| r.write_timestamp2(BOTTOM2, &timestamps, 2),
            &|r| {
                unsafe { r.write_timestamp2_unchecked(BOTTOM2, &timestamps, 2) }.expect("recorded")
            },
        ),
        (
            "VUID-vkCmdWriteTimestamp2-stage-03859",
            &|r| r.write_timestamp2(two, &timestamps, 0),
            &|r| unsafe { r.write_timestamp2_unchecked(two, &timestamps, 0) }.expect("recorded"),
        ),
    ];
    let (_cp, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (rule, safe, unchecked) in cases {
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.reset_query_pool(&timestamps, 0, 2).expect("reset");
        rec.reset_query_pool(&occlusion, 0, 2).expect("reset");
        assert_eq!(vuid(safe(&mut rec)), rule);
        drop(rec);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.reset_query_pool(&timestamps, 0, 2).expect("reset");
        rec.reset_query_pool(&occlusion, 0, 2).expect("reset");
        layer_names(&s.messages, rule, || unchecked(&mut rec));
        drop(rec);
    }
    // Each stage alone, at each query, reads back as a timestamp.
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.reset_query_pool(&timestamps, 0, 2).expect("reset");
    rec.write_timestamp(vk::PipelineStageFlags::TOP_OF_PIPE, &timestamps, 0)
        .expect("timestamp");
    rec.write_timestamp2(vk::PipelineStageFlags2::ALL_COMMANDS, &timestamps, 1)
        .expect("timestamp2");
    rec.end().expect("end");
    submit(&s, &[&cb]).expect("submit");
    let mut data = [0u64; 2];
    let ready = s
        .device
        .get_query_pool_results(
            &timestamps,
            0,
            2,
            bytemuck_u64(&mut data),
            8,
            vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
        )
        .expect("results");
    assert_eq!(ready, tuff::SuccessOrNotReady::Success);
    assert!(data[1] >= data[0], "timestamps in order: {data:?}");
    assert_silent(&s.messages);
}

/// The bytes of `data`.
fn bytemuck_u64(data: &mut [u64]) -> &mut [u8] {
    // SAFETY: u8 has no alignment and every bit pattern is a u8; the length covers
    // exactly the u64s.
    unsafe { core::slice::from_raw_parts_mut(data.as_mut_ptr().cast(), data.len() * 8) }
}

/// A host reset names queries inside the pool (02666, 02667), none of which a
/// submission that may still be executing uses (02741).
#[test]
fn host_resets_stay_inside_the_pool_and_wait_for_pending_submissions() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let pool = pool(&s, TIMESTAMP, 4);
    for (rule, first, count) in [
        ("VUID-vkResetQueryPool-firstQuery-02666", 4, 1),
        ("VUID-vkResetQueryPool-firstQuery-02667", 2, 3),
    ] {
        assert_eq!(vuid(d.reset_query_pool(&pool, first, count)), rule);
        layer_names(&s.messages, rule, || {
            // SAFETY: see the module docs.
            unsafe { d.reset_query_pool_unchecked(&pool, first, count) }
        });
    }
    d.reset_query_pool(&pool, 0, 4).expect("every query");
    // A batch that writes query 1 after waiting for the host's signal: pending
    // until then.
    let (_cp, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.write_timestamp(BOTTOM, &pool, 1).expect("timestamp");
    rec.end().expect("end");
    let pending = tuff_setup::Pending::submit(&s, &cb);
    let rule = "VUID-vkResetQueryPool-firstQuery-02741";
    assert_eq!(vuid(d.reset_query_pool(&pool, 0, 2)), rule);
    // The 1.3.239 layer does not check the rule: tuff's error alone proves it
    // (lavapipe resets the query's slot in host memory). A layer that starts
    // checking it fails here.
    s.messages.take();
    // SAFETY: lavapipe's reset writes the query's slot only; the test reads no
    // result of it.
    unsafe { d.reset_query_pool_unchecked(&pool, 1, 1) };
    let said = s.messages.take();
    assert!(said.is_empty(), "the layer now checks {rule}: {said:?}");
    // Queries the pending batch does not use can be reset.
    d.reset_query_pool(&pool, 2, 2)
        .expect("queries no submission uses");
    pending.release();
    d.reset_query_pool(&pool, 0, 2)
        .expect("the batch is complete");
    assert_silent(&s.messages);
}
