//! Events through the safe methods: the second version's signal takes no dependency
//! flags, the host resets an event only once no submission that names it may
//! still be executing, a wait finds each event signaled as it says (by the stage
//! masks of the first version's set, the very dependency info of the second's, or
//! the host), in its own recording or, at the submission, as the submissions before
//! it and the host leave it, and a reset comes after the waits on its event.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID (or
//! say nothing, where the 1.3.239 layer does not check the rule); beside each, calls
//! that keep the rules go through with the layer silent.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips, or which lavapipe carries out
//! without harm (a reset of an event a pending batch sets, a wait on an event set
//! otherwise than the wait says, or not set until the host sets it after the
//! submission).

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{breaks, setup, vuid, Layer, Setup};
use vulkan::assert_silent;

/// The 1.3.239 layer reports a wait's mask that is not its events' (01158, in its
/// text; for the second version too, where the host set the event: 03839) under
/// this VUID.
const MISNAMED_01158: &str = "VUID-vkCmdWaitEvents-srcStageMask-parameter";

/// The 1.3.239 layer's synchronization validation reports a reset that races a
/// wait (03834 and its kin, either version) under this name.
const RACE: &str = "SYNC-vkCmdResetEvent-missingbarrier-wait";

type Rec<'c> = tuff::Recorder<'c, tuff::Outside>;
type S1 = vk::PipelineStageFlags;
type S2 = vk::PipelineStageFlags2;

fn event(s: &Setup) -> tuff::Event {
    s.device
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event")
}

/// Records `cb` with `f`, returning what `f` returns; `end` runs where it passed.
fn record(
    cb: &mut tuff::CommandBuffer,
    f: impl FnOnce(&mut Rec<'_>) -> tuff::Result<()>,
) -> tuff::Result<()> {
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    f(&mut rec)?;
    rec.end()
}

/// Submits `cb` (through `submit_unchecked` where `unchecked`) and, where the
/// submission was made, sets `unblock` from the host (a wait the check refused
/// would otherwise wait forever) and waits for it.
fn run(
    s: &Setup,
    cb: &tuff::CommandBuffer,
    unchecked: bool,
    unblock: Option<&tuff::Event>,
) -> tuff::Result<()> {
    let cbs = tuff::HandleSlice::new(&[cb]);
    let submit = [tuff::SubmitInfo::new().command_buffers(&cbs)];
    let fence = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    if unchecked {
        // SAFETY: see the module docs.
        unsafe { s.queue.submit_unchecked(&submit, Some(&fence)) }?;
    } else {
        s.queue.submit(&submit, Some(&fence))?;
    }
    if let Some(e) = unblock {
        // SAFETY: the host's set of an event takes no rule the tests break.
        unsafe { s.device.set_event_unchecked(e) }.expect("set");
    }
    let waited = s
        .device
        .wait_for_fences(&fence, true, u64::MAX)
        .expect("wait");
    assert_eq!(waited, tuff::SuccessOrTimeout::Success);
    Ok(())
}

fn memory2(src: S2, dst: S2) -> [tuff::MemoryBarrier2<'static>; 1] {
    [tuff::MemoryBarrier2::new()
        .src_stage_mask(src)
        .dst_stage_mask(dst)]
}

/// `vkCmdSetEvent2` takes a dependency info without flags (03825).
#[test]
fn a_second_version_signal_has_no_dependency_flags() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let event = s
        .device
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    let memory = [tuff::MemoryBarrier2::new()
        .src_stage_mask(vk::PipelineStageFlags2::TRANSFER)
        .src_access_mask(vk::AccessFlags2::TRANSFER_WRITE)
        .dst_stage_mask(vk::PipelineStageFlags2::FRAGMENT_SHADER)
        .dst_access_mask(vk::AccessFlags2::SHADER_READ)];
    let flagged = tuff::DependencyInfo::new()
        .dependency_flags(vk::DependencyFlags::BY_REGION)
        .memory_barriers(&memory);
    let plain = tuff::DependencyInfo::new().memory_barriers(&memory);
    let rule = "VUID-vkCmdSetEvent2-dependencyFlags-03825";
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    assert_eq!(vuid(rec.set_event2(&event, &flagged)), rule);
    drop(rec);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    s.messages.take();
    s.messages.abort_on_error(true);
    // SAFETY: see the module docs.
    let _ = unsafe { rec.set_event2_unchecked(&event, &flagged) };
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    assert!(
        said.iter().any(|m| m.contains(rule)),
        "the layer did not name {rule}: {said:?}"
    );
    drop(rec);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.set_event2(&event, &plain)
        .expect("a signal without flags");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// The host resets an event only once every submission whose command buffers name
/// it is known complete (03821): a wait there needs an execution dependency with
/// the reset.
#[test]
fn the_host_resets_an_event_no_pending_submission_names() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let event = d
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    d.reset_event(&event)
        .expect("a reset nothing pending names");
    // A batch that sets the event after waiting for the host's signal: pending
    // until then.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.set_event(&event, vk::PipelineStageFlags::TRANSFER)
        .expect("set");
    rec.end().expect("end");
    let pending = tuff_setup::Pending::submit(&s, &cb);
    let rule = "VUID-vkResetEvent-event-03821";
    assert_eq!(vuid(d.reset_event(&event)), rule);
    // The 1.3.239 layer does not check the rule: tuff's error alone proves it. A
    // layer that starts checking it fails here.
    s.messages.take();
    // SAFETY: see the module docs.
    let _ = unsafe { d.reset_event_unchecked(&event) };
    let said = s.messages.take();
    assert!(said.is_empty(), "the layer now checks {rule}: {said:?}");
    pending.release();
    d.reset_event(&event).expect("the batch is complete");
    assert_silent(&s.messages);
}

/// The first version's wait names the stage masks its events were set with (01158),
/// in the recording that set them and, at the submission, as earlier submissions
/// left them; an event the second version set is not its to wait on (03847).
#[test]
fn a_first_version_wait_names_how_its_events_were_set() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let e = event(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let wait = |rec: &mut Rec<'_>, unchecked: bool, src: S1| {
        if unchecked {
            // SAFETY: see the module docs.
            unsafe { rec.wait_events_unchecked(&e, src, S1::TRANSFER, &[], &[], &[]) }
        } else {
            rec.wait_events(&e, src, S1::TRANSFER, &[], &[], &[])
        }
    };
    // In one recording: the layer checks the masks when the buffer is submitted.
    let rule = "VUID-vkCmdWaitEvents-srcStageMask-01158";
    assert_eq!(
        vuid(record(&mut cb, |rec| {
            rec.set_event(&e, S1::TRANSFER)?;
            wait(rec, false, S1::COMPUTE_SHADER)
        })),
        rule
    );
    record(&mut cb, |rec| {
        rec.set_event(&e, S1::TRANSFER)?;
        wait(rec, true, S1::COMPUTE_SHADER)
    })
    .expect("recorded unchecked");
    s.messages.take();
    s.messages.abort_on_error(true);
    let _ = run(&s, &cb, true, None);
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    assert!(
        said.iter()
            .any(|m| m.contains(rule) || m.contains(MISNAMED_01158)),
        "the layer did not name {rule}: {said:?}"
    );
    record(&mut cb, |rec| {
        rec.set_event(&e, S1::TRANSFER)?;
        wait(rec, false, S1::TRANSFER)
    })
    .expect("the set's own mask");
    run(&s, &cb, false, None).expect("a wait on a set event");
    // Across submissions: the event stays set with TRANSFER.
    let (_pool2, mut waits) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    record(&mut waits, |rec| wait(rec, false, S1::COMPUTE_SHADER))
        .expect("known only at the submission");
    breaks(&s, rule, Layer::NamesOr(MISNAMED_01158), |unchecked| {
        run(&s, &waits, unchecked, None)
    });
    record(&mut waits, |rec| wait(rec, false, S1::TRANSFER)).expect("recorded");
    run(&s, &waits, false, None).expect("the mask the earlier submission set it with");
    // The second version's signal.
    let rule = "VUID-vkCmdWaitEvents-pEvents-03847";
    let dep = memory2(S2::TRANSFER, S2::TRANSFER);
    let info = tuff::DependencyInfo::new().memory_barriers(&dep);
    assert_eq!(
        vuid(record(&mut cb, |rec| {
            rec.set_event2(&e, &info)?;
            wait(rec, false, S1::TRANSFER)
        })),
        rule
    );
    record(&mut cb, |rec| rec.set_event2(&e, &info)).expect("set2");
    run(&s, &cb, false, None).expect("set2 submitted");
    breaks(&s, rule, Layer::Silent, |unchecked| {
        run(&s, &waits, unchecked, None)
    });
    assert_silent(&s.messages);
}

/// The second version's wait finds its event set by the second version's signal
/// with the very same dependency info (03837, 03838, 03841), or by the host with
/// barriers of host operations only (03839, 03840).
#[test]
fn a_second_version_wait_names_its_signal() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let e = event(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let ours = memory2(S2::TRANSFER, S2::TRANSFER);
    let ours = tuff::DependencyInfo::new().memory_barriers(&ours);
    let other = memory2(S2::TRANSFER, S2::COMPUTE_SHADER);
    let other = tuff::DependencyInfo::new().memory_barriers(&other);
    let host = memory2(S2::HOST, S2::TRANSFER);
    let host = tuff::DependencyInfo::new().memory_barriers(&host);
    let (_pool2, mut waits) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let wait = |cb: &mut tuff::CommandBuffer, info: &tuff::DependencyInfo<'_>| {
        record(cb, |rec| rec.wait_events2(&e, core::slice::from_ref(info)))
    };
    // In one recording.
    assert_eq!(
        vuid(record(&mut cb, |rec| {
            rec.set_event(&e, S1::TRANSFER)?;
            rec.wait_events2(&e, core::slice::from_ref(&ours))
        })),
        "VUID-vkCmdWaitEvents2-pEvents-03837"
    );
    assert_eq!(
        vuid(record(&mut cb, |rec| {
            rec.set_event2(&e, &ours)?;
            rec.wait_events2(&e, core::slice::from_ref(&other))
        })),
        "VUID-vkCmdWaitEvents2-pEvents-03838"
    );
    record(&mut cb, |rec| {
        rec.set_event2(&e, &ours)?;
        rec.wait_events2(&e, core::slice::from_ref(&ours))
    })
    .expect("the same dependency info");
    run(&s, &cb, false, None).expect("a wait on its signal");
    // At the submission: the event is set with `ours`.
    wait(&mut waits, &other).expect("known only at the submission");
    breaks(
        &s,
        "VUID-vkCmdWaitEvents2-pEvents-03838",
        Layer::Silent,
        |unchecked| run(&s, &waits, unchecked, None),
    );
    // Unset: nothing signals it.
    s.device.reset_event(&e).expect("host reset");
    wait(&mut waits, &ours).expect("recorded");
    breaks(
        &s,
        "VUID-vkCmdWaitEvents2-pEvents-03841",
        Layer::Silent,
        |unchecked| run(&s, &waits, unchecked, Some(&e)),
    );
    s.device.reset_event(&e).expect("host reset");
    wait(&mut waits, &host).expect("recorded");
    breaks(
        &s,
        "VUID-vkCmdWaitEvents2-pEvents-03840",
        Layer::Silent,
        |unchecked| run(&s, &waits, unchecked, Some(&e)),
    );
    // Set by the host: only host operations come before the wait.
    s.device.set_event(&e).expect("host set");
    wait(&mut waits, &ours).expect("recorded");
    breaks(
        &s,
        "VUID-vkCmdWaitEvents2-pEvents-03839",
        Layer::NamesOr(MISNAMED_01158),
        |unchecked| run(&s, &waits, unchecked, None),
    );
    wait(&mut waits, &host).expect("recorded");
    run(&s, &waits, false, None).expect("a wait on the host's signal");
    assert_silent(&s.messages);
}

/// A reset after a wait on its event needs a barrier between them that orders it
/// after the wait (03834, 03832), in the recording, and at the submission after a
/// wait of an earlier command buffer that may still be executing.
#[test]
fn a_reset_comes_after_the_waits_on_its_event() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let e = event(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rule = "VUID-vkCmdResetEvent-event-03834";
    let reset_after_wait = |cb: &mut tuff::CommandBuffer, unchecked: bool, barrier: bool| {
        record(cb, |rec| {
            rec.set_event(&e, S1::TRANSFER)?;
            rec.wait_events(&e, S1::TRANSFER, S1::COMPUTE_SHADER, &[], &[], &[])?;
            if barrier {
                rec.pipeline_barrier(
                    S1::COMPUTE_SHADER,
                    S1::TRANSFER,
                    vk::DependencyFlags::empty(),
                    &[],
                    &[],
                    &[],
                )?;
            }
            if unchecked {
                // SAFETY: see the module docs.
                unsafe { rec.reset_event_unchecked(&e, S1::TRANSFER) }
            } else {
                rec.reset_event(&e, S1::TRANSFER)
            }
        })
    };
    breaks(&s, rule, Layer::NamesOr(RACE), |unchecked| {
        reset_after_wait(&mut cb, unchecked, false)
    });
    reset_after_wait(&mut cb, false, true)
        .expect("a barrier from the wait's stages to the reset's");
    run(&s, &cb, false, None).expect("submitted");
    // The second version, against the second version's wait.
    let dep = memory2(S2::TRANSFER, S2::COMPUTE_SHADER);
    let info = tuff::DependencyInfo::new().memory_barriers(&dep);
    let rule = "VUID-vkCmdResetEvent2-event-03832";
    breaks(&s, rule, Layer::NamesOr(RACE), |unchecked| {
        record(&mut cb, |rec| {
            rec.set_event2(&e, &info)?;
            rec.wait_events2(&e, core::slice::from_ref(&info))?;
            if unchecked {
                // SAFETY: see the module docs.
                unsafe { rec.reset_event2_unchecked(&e, S2::TRANSFER) }
            } else {
                rec.reset_event2(&e, S2::TRANSFER)
            }
        })
    });
    // A wait of a pending submission: the reset of a later one races it.
    let (_pool2, mut waits) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    record(&mut waits, |rec| {
        rec.set_event(&e, S1::TRANSFER)?;
        rec.wait_events(&e, S1::TRANSFER, S1::COMPUTE_SHADER, &[], &[], &[])
    })
    .expect("recorded");
    let pending = tuff_setup::Pending::submit(&s, &waits);
    let (_pool3, mut resets) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    record(&mut resets, |rec| rec.reset_event(&e, S1::TRANSFER))
        .expect("known only at the submission");
    assert_eq!(
        vuid(run(&s, &resets, false, None)),
        "VUID-vkCmdResetEvent-event-03834"
    );
    record(&mut resets, |rec| {
        rec.pipeline_barrier(
            S1::ALL_COMMANDS,
            S1::ALL_COMMANDS,
            vk::DependencyFlags::empty(),
            &[],
            &[],
            &[],
        )?;
        rec.reset_event(&e, S1::TRANSFER)
    })
    .expect("recorded");
    pending.release();
    run(&s, &resets, false, None).expect("after a barrier from all commands");
    record(&mut resets, |rec| rec.reset_event(&e, S1::TRANSFER)).expect("recorded");
    run(&s, &resets, false, None).expect("the wait's submission is complete");
    assert_silent(&s.messages);
}
