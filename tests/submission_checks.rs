//! Queue submissions: timeline values that only rise, protected batches only on
//! protected queues, and no suspended render pass instance in a safe recording.
//!
//! Each case breaks one rule: tuff must refuse the safe call with the rule's VUID,
//! and the validation layer, for the `_unchecked` twin (told to skip the call it
//! reports), must name the same VUID.
//!
//! SAFETY of the `unsafe` blocks: the methods called are `unsafe` for rules their
//! `# Safety` sections list, which these calls keep but for the one each case
//! breaks on purpose, which tuff refuses and the layer skips.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, vuid, Setup};
use vulkan::assert_silent;

/// Runs `unchecked` with the layer told to skip what it reports, and asserts it
/// named `rule`.
fn layer_names(s: &Setup, rule: &str, unchecked: impl FnOnce()) {
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    assert!(
        said.iter().any(|m| m.contains(rule)),
        "the layer did not name {rule}; it said {said:?}"
    );
}

fn timeline(s: &Setup, initial: u64) -> tuff::Semaphore {
    let mut timeline_type = tuff::SemaphoreTypeCreateInfo::new()
        .semaphore_type(vk::SemaphoreType::TIMELINE)
        .initial_value(initial);
    s.device
        .create_semaphore(&tuff::SemaphoreCreateInfo::new().push_next(&mut timeline_type))
        .expect("timeline semaphore")
}

/// A timeline signal must be above the value the semaphore has when it executes:
/// below one the host signalled, or one an earlier submission signals, is refused.
#[test]
fn timeline_signals_rise() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let semaphore = timeline(&s, 0);
    d.signal_semaphore(&tuff::SemaphoreSignalInfo::new(&semaphore).value(5))
        .expect("host signal");
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let signals = tuff::HandleSlice::new(&[&semaphore]);
    let rule = "VUID-VkSubmitInfo-pSignalSemaphores-03242";
    let mut below = tuff::TimelineSemaphoreSubmitInfo::new().signal_semaphore_values(&[3]);
    let submit = [tuff::SubmitInfo::new()
        .signal_semaphores(&signals)
        .push_next(&mut below)];
    assert_eq!(vuid(s.queue.submit(&submit, Some(&fence))), rule);
    layer_names(&s, rule, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { s.queue.submit_unchecked(&submit, Some(&fence)) };
    });
    // Above it: submitted; a second submission below that pending signal is refused
    // too, though the semaphore's value is still 5 on the host.
    let mut above = tuff::TimelineSemaphoreSubmitInfo::new().signal_semaphore_values(&[8]);
    let submit = [tuff::SubmitInfo::new()
        .signal_semaphores(&signals)
        .push_next(&mut above)];
    s.queue
        .submit(&submit, Some(&fence))
        .expect("a signal above");
    let other = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let mut between = tuff::TimelineSemaphoreSubmitInfo::new().signal_semaphore_values(&[7]);
    let submit = [tuff::SubmitInfo::new()
        .signal_semaphores(&signals)
        .push_next(&mut between)];
    assert_eq!(vuid(s.queue.submit(&submit, Some(&other))), rule);
    assert_eq!(
        d.wait_for_fences(&fence, true, u64::MAX).expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    assert_eq!(d.get_semaphore_counter_value(&semaphore).expect("value"), 8);
    assert_silent(&s.messages);
}

/// A protected batch needs a queue created protected.
#[test]
fn protected_batches_need_protected_queues() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let fence = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let rule = "VUID-vkQueueSubmit-queue-06448";
    let mut protected = tuff::ProtectedSubmitInfo::new().protected_submit(true);
    let submit = [tuff::SubmitInfo::new().push_next(&mut protected)];
    assert_eq!(vuid(s.queue.submit(&submit, Some(&fence))), rule);
    layer_names(&s, rule, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { s.queue.submit_unchecked(&submit, Some(&fence)) };
    });
}

/// The safe recorder does not suspend or resume a render pass instance, whose
/// submission rules it does not follow.
#[test]
fn render_pass_instances_are_not_suspended() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(8, vk::ImageUsageFlags::empty());
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for flags in [vk::RenderingFlags::SUSPENDING, vk::RenderingFlags::RESUMING] {
        let attachments = [tuff::RenderingAttachmentInfo::new()
            .image_view(Some(&target.view))
            .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::DONT_CARE)
            .store_op(vk::AttachmentStoreOp::DONT_CARE)];
        let info = tuff::RenderingInfo::new()
            .flags(flags)
            .render_area(vk::Rect2D {
                offset: vk::Offset2D::default(),
                extent: vk::Extent2D {
                    width: 8,
                    height: 8,
                },
            })
            .layer_count(1)
            .color_attachments(&attachments);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let rec = rec.begin_rendering(&info);
        let rec = rec.end_rendering();
        match rec.end() {
            Err(tuff::Error::Misuse(_)) => {}
            other => panic!("expected the suspending or resuming begin refused, got {other:?}"),
        }
    }
    assert_silent(&s.messages);
}

/// `vkQueueSubmit2`'s batches by the rules of their own structs: a protected batch
/// on a queue not created protected, a command buffer's device mask and a
/// semaphore's device index past the device's one physical device, a timeline
/// semaphore waited on for a value its own signal does not exceed, and a signal not
/// above the semaphore's value. The safe call names each rule, and the layer names
/// it for the unchecked one, which it skips; the correct batch runs.
#[test]
fn submit2_batches_are_checked_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let semaphore = timeline(&s, 4);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    cb.begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin")
        .end()
        .expect("end");
    let wait = |value| {
        [tuff::SemaphoreSubmitInfo::new(&semaphore)
            .value(value)
            .stage_mask(vk::PipelineStageFlags2::ALL_COMMANDS)]
    };
    let signal = |value, device_index| {
        [tuff::SemaphoreSubmitInfo::new(&semaphore)
            .value(value)
            .stage_mask(vk::PipelineStageFlags2::ALL_COMMANDS)
            .device_index(device_index)]
    };
    let cbs = |device_mask| [tuff::CommandBufferSubmitInfo::new(&cb).device_mask(device_mask)];
    let (signal_6, signal_6_index_1, signal_3) = (signal(6, 0), signal(6, 1), signal(3, 0));
    let (wait_6, no_wait) = (wait(6), []);
    let (one, mask_2) = (cbs(0), cbs(2));
    let batch = |flags, waits, buffers, signals| {
        tuff::SubmitInfo2::new()
            .flags(flags)
            .wait_semaphore_infos(waits)
            .command_buffer_infos(buffers)
            .signal_semaphore_infos(signals)
    };
    let none = vk::SubmitFlags::empty();
    let protected = vk::SubmitFlags::PROTECTED;
    let cases = [
        (
            "VUID-vkQueueSubmit2-queue-06447",
            batch(protected, &no_wait[..], &one[..], &signal_6[..]),
        ),
        (
            "VUID-VkCommandBufferSubmitInfo-deviceMask-03891",
            batch(none, &no_wait, &mask_2, &signal_6),
        ),
        (
            "VUID-VkSemaphoreSubmitInfo-device-03888",
            batch(none, &no_wait, &one, &signal_6_index_1),
        ),
        (
            "VUID-VkSubmitInfo2-semaphore-03881",
            batch(none, &wait_6, &one, &signal_6),
        ),
        (
            "VUID-VkSubmitInfo2-semaphore-03882",
            batch(none, &no_wait, &one, &signal_3),
        ),
    ];
    for (rule, b) in cases {
        let submits = [b];
        assert_eq!(vuid(s.queue.submit2(&submits, Some(&fence))), rule);
        // The 1.3.239 layer does not check a semaphore's device index: the error
        // alone proves it (and the unchecked call would run).
        if rule.ends_with("-03888") {
            continue;
        }
        layer_names(&s, rule, || {
            // SAFETY: the layer names the rule and skips the call.
            let _ = unsafe { s.queue.submit2_unchecked(&submits, Some(&fence)) };
        });
    }
    let submits = [batch(none, &no_wait, &one, &signal_6)];
    s.queue
        .submit2(&submits, Some(&fence))
        .expect("a correct batch");
    assert_eq!(
        d.wait_for_fences(&fence, true, u64::MAX).expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    assert_eq!(d.get_semaphore_counter_value(&semaphore).expect("value"), 6);
    assert_silent(&s.messages);
}

/// A host signal of a timeline semaphore is above its value (03258) and below every
/// pending signal (03259). Below a pending signal it is safe only where that signal
/// waits for the host's (the wait-before-signal pattern); where a pending signal
/// could run first, the safe method signals nothing.
#[test]
fn host_signals_rise_above_the_value_and_stay_below_pending_signals() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let semaphore = timeline(&s, 5);
    let signal = |value| tuff::SemaphoreSignalInfo::new(&semaphore).value(value);
    let rule = "VUID-VkSemaphoreSignalInfo-value-03258";
    for value in [3, 5] {
        assert_eq!(vuid(d.signal_semaphore(&signal(value))), rule);
    }
    layer_names(&s, rule, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { d.signal_semaphore_unchecked(&signal(5)) };
    });
    d.signal_semaphore(&signal(6))
        .expect("a host signal above the value");
    assert_eq!(d.get_semaphore_counter_value(&semaphore).expect("value"), 6);
    // A batch that waits for 7 and then signals 10: pending until the host signals 7.
    let semaphores = tuff::HandleSlice::new(&[&semaphore]);
    let stages = [vk::PipelineStageFlags::ALL_COMMANDS];
    let mut wait_then_signal = tuff::TimelineSemaphoreSubmitInfo::new()
        .wait_semaphore_values(&[7])
        .signal_semaphore_values(&[10]);
    let submit = [tuff::SubmitInfo::new()
        .wait_semaphores(&semaphores, &stages)
        .expect("one stage mask a semaphore")
        .signal_semaphores(&semaphores)
        .push_next(&mut wait_then_signal)];
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    s.queue.submit(&submit, Some(&fence)).expect("submit");
    let rule = "VUID-VkSemaphoreSignalInfo-value-03259";
    assert_eq!(vuid(d.signal_semaphore(&signal(12))), rule);
    layer_names(&s, rule, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { d.signal_semaphore_unchecked(&signal(12)) };
    });
    d.signal_semaphore(&signal(7))
        .expect("the host's signal that the batch waits for");
    assert_eq!(
        d.wait_for_fences(&fence, true, u64::MAX).expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    assert_eq!(
        d.get_semaphore_counter_value(&semaphore).expect("value"),
        10
    );
    // A batch that signals 20 without waiting could run before a host signal below
    // it: refused until its fence shows it done (for the value it reads, where the
    // batch has already run).
    let mut signal_only = tuff::TimelineSemaphoreSubmitInfo::new().signal_semaphore_values(&[20]);
    let submit = [tuff::SubmitInfo::new()
        .signal_semaphores(&semaphores)
        .push_next(&mut signal_only)];
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    s.queue.submit(&submit, Some(&fence)).expect("submit");
    match d.signal_semaphore(&signal(15)) {
        Err(tuff::Error::Misuse(_)) => {}
        Err(tuff::Error::Validation { vuid, .. }) => {
            assert_eq!(vuid, "VUID-VkSemaphoreSignalInfo-value-03258")
        }
        other => panic!("a host signal below a pending one: {other:?}"),
    }
    assert_eq!(
        d.wait_for_fences(&fence, true, u64::MAX).expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    d.signal_semaphore(&signal(21))
        .expect("a host signal after the submission");
    assert_silent(&s.messages);
}
