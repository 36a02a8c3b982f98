//! Events through the safe methods: the second version's signal takes no dependency
//! flags, and the host resets an event only once no submission that names it may
//! still be executing.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID (or
//! say nothing, where the 1.3.239 layer does not check the rule); beside each, calls
//! that keep the rules go through with the layer silent.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips, or which lavapipe carries out
//! without harm (a reset of an event a pending batch sets).

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, vuid};
use vulkan::assert_silent;

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
