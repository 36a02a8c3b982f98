//! Adversarial programs: each uses only tuff's checked API (safe methods, and `unsafe`
//! checked methods whose listed rules it keeps), never an `_unchecked` twin, on
//! lavapipe with the validation layer and its synchronization validation on, and tries to make Vulkan
//! use or free something it must not. Each must either run with no message from the
//! layer, or get an error from tuff before Vulkan sees the call.
//!
//! A submission is held in flight for as long as a test needs by a host-set event:
//! its command buffer waits for the event, which the test sets when it is done
//! attacking, so "pending" never depends on timing.
//!
//! SAFETY of the `unsafe` blocks around checked methods: such a method is `unsafe`
//! because it leaves rules to its caller (its `# Safety` section lists them). The
//! calls here keep every rule so listed and break, on purpose, only rules the method
//! checks; that one argument covers every such block in this file.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use pipelines::{host_buffer, uniform_set};
use tuff::vk;
use tuff_setup::{setup, vuid, Setup};
use vulkan::assert_silent;

/// Fails unless the layer reported `vuid` (and takes its messages).
fn assert_layer_reports(s: &Setup, vuid: &str) {
    let messages = s.messages.take();
    assert!(
        messages.iter().any(|m| m.contains(vuid)),
        "the validation layer did not report {vuid}; it said:\n{}",
        messages.join("\n")
    );
}

fn fence(s: &Setup) -> tuff::Fence {
    s.device
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence")
}

fn event(s: &Setup) -> tuff::Event {
    s.device
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event")
}

fn semaphore(s: &Setup) -> tuff::Semaphore {
    s.device
        .create_semaphore(&tuff::SemaphoreCreateInfo::new())
        .expect("semaphore")
}

fn transfer_buffer(s: &Setup) -> (tuff::Buffer, tuff::DeviceMemory) {
    host_buffer(s, 1 << 16, vk::BufferUsageFlags::TRANSFER_DST)
}

/// Records into `cb`: wait for `gate` (set by the host), then fill `buffer`.
fn record_gated_fill(
    cb: &mut tuff::CommandBuffer,
    flags: vk::CommandBufferUsageFlags,
    gate: &tuff::Event,
    buffer: &tuff::Buffer,
) {
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new().flags(flags))
        .expect("begin");
    rec.wait_events(
        gate,
        vk::PipelineStageFlags::HOST,
        vk::PipelineStageFlags::TRANSFER,
        &[],
        &[],
        &[],
    )
    .expect("recorded");
    rec.fill_buffer(buffer, 0, vk::WHOLE_SIZE, 7).expect("fill");
    rec.end().expect("end");
}

fn submit(s: &Setup, cbs: &[&tuff::CommandBuffer], fence: &tuff::Fence) -> tuff::Result<()> {
    let handles = tuff::HandleSlice::new(cbs);
    s.queue.submit(
        &[tuff::SubmitInfo::new().command_buffers(&handles)],
        Some(fence),
    )
}

fn wait(s: &Setup, fence: &tuff::Fence) {
    let r = s
        .device
        .wait_for_fences(fence, true, u64::MAX)
        .expect("wait");
    assert_eq!(r, tuff::SuccessOrTimeout::Success);
}

/// A submission without a fence (Vulkan allows none): the queue holds what it uses
/// until an idle wait, or a later fence of the queue, shows it complete; the command
/// buffer stays pending until then, so it cannot be re-recorded under the GPU.
#[test]
fn a_submission_without_a_fence_is_held_by_its_queue() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let later = fence(&s);
    {
        let (buffer, memory) = transfer_buffer(&s);
        let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        record_gated_fill(
            &mut cb,
            vk::CommandBufferUsageFlags::empty(),
            &gate,
            &buffer,
        );
        s.queue
            .submit(&[tuff::SubmitInfo::new().command_buffers(&cb)], None)
            .expect("submit without a fence");
        // Pending: recording it again is refused.
        assert!(cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .is_err_and(|e| e.to_string().contains("pending")));
        // Everything the submission uses goes while it waits for the host.
        drop(cb);
        drop(pool);
        drop(buffer);
        drop(memory);
    }
    // A later fenced submission of the same queue completes the first with it.
    submit(&s, &[], &later).expect("a later submission with a fence");
    s.device.set_event(&gate).expect("set event");
    wait(&s, &later);
    // And an idle wait shows the rest complete.
    s.queue.wait_idle().expect("idle");
    assert_silent(&s.messages);
}

#[test]
fn submit2_holds_what_it_submits_until_its_fence_signals() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let done = fence(&s);
    let signalled = semaphore(&s);
    {
        let (buffer, memory) = transfer_buffer(&s);
        let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        record_gated_fill(
            &mut cb,
            vk::CommandBufferUsageFlags::empty(),
            &gate,
            &buffer,
        );
        let cb_infos = [tuff::CommandBufferSubmitInfo::new(&cb)];
        let signal_infos = [tuff::SemaphoreSubmitInfo::new(&signalled)
            .stage_mask(vk::PipelineStageFlags2::ALL_COMMANDS)];
        let submits = [tuff::SubmitInfo2::new()
            .command_buffer_infos(&cb_infos)
            .signal_semaphore_infos(&signal_infos)];
        s.queue.submit2(&submits, Some(&done)).expect("submit2");
        // Everything the submission uses goes while it waits for the host.
        drop(cb);
        drop(pool);
        drop(buffer);
        drop(memory);
    }
    drop(signalled);
    s.device.set_event(&gate).expect("set event");
    wait(&s, &done);
    assert_silent(&s.messages);
}

#[test]
fn a_pending_submission_cannot_be_reset_resubmitted_or_rerecorded() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let done = fence(&s);
    let other = fence(&s);
    let (buffer, memory) = transfer_buffer(&s);
    let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    record_gated_fill(
        &mut cb,
        vk::CommandBufferUsageFlags::empty(),
        &gate,
        &buffer,
    );
    submit(&s, &[&cb], &done).expect("submit");

    assert_eq!(
        vuid(s.device.reset_fences(&done)),
        "VUID-vkResetFences-pFences-01123"
    );
    assert_eq!(
        vuid(submit(&s, &[], &done)),
        "VUID-vkQueueSubmit-fence-00064"
    );
    assert_eq!(
        vuid(cb.begin(&tuff::CommandBufferBeginInfo::new())),
        "VUID-vkBeginCommandBuffer-commandBuffer-00049"
    );
    assert_eq!(
        vuid(submit(&s, &[&cb], &other)),
        "VUID-vkQueueSubmit-pCommandBuffers-00071"
    );
    // The buffer is still executable and its recording intact: the refused begin
    // changed nothing the pending submission uses.
    assert!(cb.is_executable());
    drop(buffer);
    drop(memory);
    drop(pool);
    assert_silent(&s.messages);

    s.device.set_event(&gate).expect("set event");
    wait(&s, &done);
    // Complete now: every refused call goes through.
    s.device.reset_fences(&done).expect("reset");
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin after completion");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

#[test]
fn a_fence_reset_or_dropped_while_pending_keeps_the_submission() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let (buffer, memory) = transfer_buffer(&s);
    let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    record_gated_fill(
        &mut cb,
        vk::CommandBufferUsageFlags::empty(),
        &gate,
        &buffer,
    );
    let done = fence(&s);
    submit(&s, &[&cb], &done).expect("submit");
    drop((cb, pool, buffer, memory));
    // The fence is the only owner of the submission now. The host sets the event
    // from another thread once the drop below has begun to wait for the fence.
    let setter = set_later(&s, &gate);
    drop(done);
    setter.join().expect("setter thread");
    assert_silent(&s.messages);
}

/// Sets `event` from another thread after a short delay, so that the caller can
/// block (in a wait it did not ask for) on work the event gates.
fn set_later(s: &Setup, event: &tuff::Event) -> std::thread::JoinHandle<()> {
    let (device, event) = (*s.device, **event);
    let set_event = s.device.fns().fp_v1_0().set_event;
    std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_millis(50));
        // SAFETY: the device and event outlive this thread, which is joined before
        // either goes, and nothing else sets or resets the event meanwhile.
        let r = unsafe { set_event(device, event) };
        assert_eq!(r, vk::Result::SUCCESS);
    })
}

#[test]
fn a_fence_without_command_buffers_and_semaphores_in_use_wait_for_the_queue() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let (buffer, _memory) = transfer_buffer(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    record_gated_fill(
        &mut cb,
        vk::CommandBufferUsageFlags::empty(),
        &gate,
        &buffer,
    );
    let first = fence(&s);
    let second = fence(&s);
    let signalled = semaphore(&s);
    {
        s.queue
            .submit(
                &[tuff::SubmitInfo::new()
                    .command_buffers(&cb)
                    .signal_semaphores(&signalled)],
                Some(&first),
            )
            .expect("first submit");
        s.queue
            .submit(&[], Some(&second))
            .expect("second submit, no command buffers");
    }
    // The semaphore is in use by the pending batch; the second fence has no command
    // buffer to keep alive but its wait is still owed before it goes.
    drop(signalled);
    let setter = set_later(&s, &gate);
    drop(second);
    setter.join().expect("setter thread");
    wait(&s, &first);
    assert_silent(&s.messages);
}

#[test]
fn a_signalled_fence_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let signalled = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new().flags(vk::FenceCreateFlags::SIGNALED))
        .expect("fence");
    assert_eq!(
        vuid(submit(&s, &[], &signalled)),
        "VUID-vkQueueSubmit-fence-00063"
    );
    assert_eq!(
        vuid(s.queue.submit2(&[], Some(&signalled))),
        "VUID-vkQueueSubmit2-fence-04894"
    );
    assert_silent(&s.messages);
    // The same call without tuff's checks: the layer names the same rule.
    // SAFETY: an empty submission with a signalled fence breaks only the rule under
    // test, which the layer reports; the fence is waited for before it goes.
    unsafe { s.queue.submit_unchecked(&[], Some(&signalled)) }.expect("unchecked submit");
    assert_layer_reports(&s, "VUID-vkQueueSubmit-fence-00063");
    s.queue.wait_idle().expect("idle");
    let signalled = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new().flags(vk::FenceCreateFlags::SIGNALED))
        .expect("fence");
    // SAFETY: as above.
    unsafe { s.queue.submit2_unchecked(&[], Some(&signalled)) }.expect("unchecked submit2");
    assert_layer_reports(&s, "VUID-vkQueueSubmit2-fence-04894");
    s.queue.wait_idle().expect("idle");
    let signalled = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new().flags(vk::FenceCreateFlags::SIGNALED))
        .expect("fence");
    assert_eq!(
        vuid(unsafe { s.queue.bind_sparse(&[], &signalled) }),
        "VUID-vkQueueBindSparse-fence-01113"
    );
    assert_silent(&s.messages);
    // SAFETY: as above; an empty bind binds nothing. Lavapipe has no sparse
    // binding and returns an error once the layer has seen the call.
    let _ = unsafe { s.queue.bind_sparse_unchecked(&[], &signalled) };
    assert_layer_reports(&s, "VUID-vkQueueBindSparse-fence-01113");
    s.queue.wait_idle().expect("idle");
    assert_silent(&s.messages);
}

#[test]
fn a_busy_fence_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let done = fence(&s);
    let (buffer, _memory) = transfer_buffer(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    record_gated_fill(
        &mut cb,
        vk::CommandBufferUsageFlags::empty(),
        &gate,
        &buffer,
    );
    submit(&s, &[&cb], &done).expect("submit");
    let opener = OpenOnDrop(&s, &gate);
    assert_eq!(
        vuid(submit(&s, &[], &done)),
        "VUID-vkQueueSubmit-fence-00064"
    );
    assert_eq!(
        vuid(s.queue.submit2(&[], Some(&done))),
        "VUID-vkQueueSubmit2-fence-04895"
    );
    assert_eq!(
        vuid(unsafe { s.queue.bind_sparse(&[], &done) }),
        "VUID-vkQueueBindSparse-fence-01114"
    );
    assert_eq!(
        vuid(s.device.reset_fences(&done)),
        "VUID-vkResetFences-pFences-01123"
    );
    assert_silent(&s.messages);
    // Only now may the gate open: until here the submission is pending for certain,
    // however slow the run (valgrind); a failed assertion above opens it on its way
    // out, so the fence's wait in the unwinding does not wait for ever.
    drop(opener);
    // The same calls without tuff's checks: the layer names the same rules. The
    // program keeps the buffer and the command buffer until the queue is idle.
    // SAFETY: an empty submission signals the fence after the pending one; the
    // reset only breaks the rule under test.
    unsafe { s.queue.submit_unchecked(&[], Some(&done)) }.expect("unchecked submit");
    assert_layer_reports(&s, "VUID-vkQueueSubmit-fence-00064");
    // SAFETY: as above.
    unsafe { s.queue.submit2_unchecked(&[], Some(&done)) }.expect("unchecked submit2");
    assert_layer_reports(&s, "VUID-vkQueueSubmit2-fence-04895");
    // SAFETY: as above; an empty bind binds nothing (and lavapipe refuses it).
    let _ = unsafe { s.queue.bind_sparse_unchecked(&[], &done) };
    assert_layer_reports(&s, "VUID-vkQueueBindSparse-fence-01114");
    // SAFETY: as above.
    unsafe { s.device.reset_fences_unchecked(&done) }.expect("unchecked reset");
    assert_layer_reports(&s, "VUID-vkResetFences-pFences-01123");
    s.queue.wait_idle().expect("idle");
    assert_silent(&s.messages);
}

/// Sets the event when dropped, on the way out of a failed assertion too, so that work
/// it gates completes and nothing waits for it for ever.
struct OpenOnDrop<'s>(&'s Setup, &'s tuff::Event);

impl Drop for OpenOnDrop<'_> {
    fn drop(&mut self) {
        let set_event = self.0.device.fns().fp_v1_0().set_event;
        // SAFETY: the device and event are live wrappers that outlive this guard, and
        // nothing else sets or resets the event meanwhile.
        let r = unsafe { set_event(*self.0.device, **self.1) };
        assert_eq!(r, vk::Result::SUCCESS);
    }
}

#[test]
fn command_buffers_in_the_wrong_state_are_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let (buffer, _memory) = transfer_buffer(&s);
    let done = fence(&s);

    // Never recorded.
    let (_pool, fresh) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    assert_eq!(
        vuid(submit(&s, &[&fresh], &done)),
        "VUID-vkQueueSubmit-pCommandBuffers-00070"
    );
    // A secondary, submitted directly.
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let inheritance = tuff::CommandBufferInheritanceInfo::new();
    let mut rec = secondary
        .begin(&tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance)))
        .expect("begin secondary");
    rec.fill_buffer(&buffer, 0, 256, 1).expect("fill");
    rec.end().expect("end secondary");
    assert_eq!(
        vuid(submit(&s, &[&secondary], &done)),
        "VUID-VkSubmitInfo-pCommandBuffers-00075"
    );
    // The same buffer twice in one submission, without SIMULTANEOUS_USE.
    let (_ppool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    record_gated_fill(
        &mut primary,
        vk::CommandBufferUsageFlags::empty(),
        &gate,
        &buffer,
    );
    assert_eq!(
        vuid(submit(&s, &[&primary, &primary], &done)),
        "VUID-vkQueueSubmit-pCommandBuffers-00071"
    );
    // A one-time buffer, submitted a second time after the first completed.
    let (_opool, mut once) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = once
        .begin(
            &tuff::CommandBufferBeginInfo::new()
                .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
        )
        .expect("begin once");
    rec.fill_buffer(&buffer, 0, 256, 2).expect("fill");
    rec.end().expect("end once");
    submit(&s, &[&once], &done).expect("first submission");
    wait(&s, &done);
    s.device.reset_fences(&done).expect("reset");
    assert_eq!(
        vuid(submit(&s, &[&once], &done)),
        "VUID-vkQueueSubmit-pCommandBuffers-00070"
    );
    assert_silent(&s.messages);

    // The same submissions without tuff's checks: the layer names the same rules.
    for (cb, rule) in [
        (&fresh, "VUID-vkQueueSubmit-pCommandBuffers-00070"),
        (&secondary, "VUID-VkSubmitInfo-pCommandBuffers-00075"),
    ] {
        // SAFETY: lavapipe runs a never-recorded buffer as an empty one and a
        // secondary's fill as a primary's; the program keeps everything until the
        // fence is waited for.
        unsafe {
            s.queue
                .submit_unchecked(&[tuff::SubmitInfo::new().command_buffers(cb)], Some(&done))
        }
        .expect("unchecked submit");
        assert_layer_reports(&s, rule);
        wait(&s, &done);
        s.device.reset_fences(&done).expect("reset");
    }
    assert_silent(&s.messages);
}

#[test]
fn a_secondary_executed_by_a_pending_primary_cannot_be_rerecorded() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let (buffer, _memory) = transfer_buffer(&s);
    let done = fence(&s);
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let inheritance = tuff::CommandBufferInheritanceInfo::new();
    let secondary_begin = tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance));
    let mut rec = secondary.begin(&secondary_begin).expect("begin secondary");
    rec.fill_buffer(&buffer, 0, 256, 3).expect("fill");
    rec.end().expect("end secondary");

    let (_ppool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin primary");
    rec.wait_events(
        &gate,
        vk::PipelineStageFlags::HOST,
        vk::PipelineStageFlags::TRANSFER,
        &[],
        &[],
        &[],
    )
    .expect("recorded");
    rec.execute_commands(&secondary).expect("execute");
    rec.end().expect("end primary");
    submit(&s, &[&primary], &done).expect("submit");

    assert_eq!(
        vuid(secondary.begin(&secondary_begin)),
        "VUID-vkBeginCommandBuffer-commandBuffer-00049"
    );
    s.device.set_event(&gate).expect("set event");
    wait(&s, &done);
    s.device.reset_fences(&done).expect("reset");

    // Recorded again once complete: the primary that executes it is now invalid.
    let mut rec = secondary.begin(&secondary_begin).expect("begin again");
    rec.fill_buffer(&buffer, 0, 256, 4).expect("fill");
    rec.end().expect("end again");
    assert_eq!(
        vuid(submit(&s, &[&primary], &done)),
        "VUID-vkQueueSubmit-pCommandBuffers-00072"
    );
    assert_silent(&s.messages);
}

#[test]
fn an_idle_queue_completes_what_was_submitted_to_it() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (buffer, _memory) = transfer_buffer(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.fill_buffer(&buffer, 0, 256, 5).expect("fill");
    rec.end().expect("end");
    let done = fence(&s);
    submit(&s, &[&cb], &done).expect("submit");
    s.queue.wait_idle().expect("idle");
    // Known complete without a look at the fence: the buffer may be recorded again
    // and the fence reset.
    s.device.reset_fences(&done).expect("reset after idle");
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin after idle");
    rec.end().expect("end");
    submit(&s, &[&cb], &done).expect("submit again");
    s.device.wait_idle().expect("device idle");
    s.device
        .reset_fences(&done)
        .expect("reset after device idle");
    assert_silent(&s.messages);
}

#[test]
fn a_buffer_of_a_pool_without_reset_is_recorded_once() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let pool = s
        .device
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
        .expect("pool");
    let mut cb = s
        .device
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1),
        )
        .expect("command buffer")
        .pop()
        .expect("one");
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("first begin");
    rec.end().expect("end");
    assert_eq!(
        vuid(cb.begin(&tuff::CommandBufferBeginInfo::new())),
        "VUID-vkBeginCommandBuffer-commandBuffer-00050"
    );
    assert_silent(&s.messages);
    // `begin` has no unchecked twin: the same call through ash, and the layer names
    // the same rule.
    let raw = tuff::Handle::raw(&cb);
    let begin = vk::CommandBufferBeginInfo::default();
    // SAFETY: the buffer is executable and not pending; lavapipe resets it, and the
    // layer reports only the rule under test. It is ended again at once.
    unsafe {
        let _ = s.device.fns().begin_command_buffer(raw, &begin);
        let _ = s.device.fns().end_command_buffer(raw);
    }
    assert_layer_reports(&s, "VUID-vkBeginCommandBuffer-commandBuffer-00050");
}

#[test]
fn reset_of_a_buffer_of_a_pool_without_reset_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let pool = s
        .device
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
        .expect("pool");
    let mut cb = s
        .device
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1),
        )
        .expect("command buffer")
        .pop()
        .expect("one");
    assert_eq!(
        vuid(cb.reset(vk::CommandBufferResetFlags::empty())),
        "VUID-vkResetCommandBuffer-commandBuffer-00046"
    );
    assert_silent(&s.messages);
    // SAFETY: none; the buffer is in the initial state, so the driver's reset is
    // harmless, and the layer reports the pool's missing flag.
    unsafe { cb.reset_unchecked(vk::CommandBufferResetFlags::empty()) }.expect("reset");
    assert_layer_reports(&s, "VUID-vkResetCommandBuffer-commandBuffer-00046");
}

// Class B: a reset of a pool, or of a buffer, never leaves a wrapper naming an object
// in a state its type does not allow.

#[test]
fn a_command_pool_is_not_reset_under_a_recorder_or_a_pending_buffer() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let done = fence(&s);
    let (buffer, _memory) = transfer_buffer(&s);
    let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let none = vk::CommandPoolResetFlags::empty();

    // A live recorder: the reset would pull its buffer out of the recording state.
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.fill_buffer(&buffer, 0, 256, 1).expect("fill");
    assert_eq!(
        vuid(s.device.reset_command_pool(&pool, none)),
        "VUID-vkEndCommandBuffer-commandBuffer-00059"
    );
    rec.end().expect("end");
    s.device
        .reset_command_pool(&pool, none)
        .expect("reset once the recorder is gone");
    assert!(
        !cb.is_executable(),
        "a pool reset returns its buffers to the initial state"
    );
    assert_eq!(
        vuid(submit(&s, &[&cb], &done)),
        "VUID-vkQueueSubmit-pCommandBuffers-00070"
    );

    // A pending buffer: neither its pool nor the buffer itself is reset.
    record_gated_fill(
        &mut cb,
        vk::CommandBufferUsageFlags::empty(),
        &gate,
        &buffer,
    );
    submit(&s, &[&cb], &done).expect("submit");
    assert_eq!(
        vuid(s.device.reset_command_pool(&pool, none)),
        "VUID-vkResetCommandPool-commandPool-00040"
    );
    assert_eq!(
        vuid(cb.reset(vk::CommandBufferResetFlags::empty())),
        "VUID-vkResetCommandBuffer-commandBuffer-00045"
    );
    s.device.set_event(&gate).expect("set");
    wait(&s, &done);
    cb.reset(vk::CommandBufferResetFlags::empty())
        .expect("reset once complete");
    s.device
        .reset_command_pool(&pool, none)
        .expect("pool reset once complete");
    assert_silent(&s.messages);
}

#[test]
fn a_descriptor_pool_is_not_reset_while_its_sets_are_alive() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let set = uniform_set(&s);
    let pipelines::OneSet { set, pool, layout } = set;
    assert_eq!(
        vuid(
            s.device
                .reset_descriptor_pool(&pool, vk::DescriptorPoolResetFlags::empty())
        ),
        "VUID-vkResetDescriptorPool-descriptorPool-00313"
    );
    drop(set);
    s.device
        .reset_descriptor_pool(&pool, vk::DescriptorPoolResetFlags::empty())
        .expect("reset once no set is left");
    // The pool gives sets again after its reset.
    let again = s
        .device
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layout),
        )
        .expect("allocate after reset");
    assert_eq!(again.len(), 1);
    assert_silent(&s.messages);
}

// Class C: the recorder's type state is the command buffer's.

#[test]
fn recorder_states_follow_the_begin_info() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(16, vk::ImageUsageFlags::empty());
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let continue_flags = vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE;

    // A secondary needs inheritance info.
    assert_eq!(
        vuid(secondary.begin(&tuff::CommandBufferBeginInfo::new())),
        "VUID-vkBeginCommandBuffer-commandBuffer-00051"
    );
    // One that continues a render pass instance is not recorded as outside one.
    let inheritance = tuff::CommandBufferInheritanceInfo::new()
        .render_pass(Some(&target.render_pass))
        .framebuffer(Some(&target.framebuffer));
    let info = tuff::CommandBufferBeginInfo::new()
        .flags(continue_flags)
        .inheritance_info(Some(&inheritance));
    assert!(matches!(
        secondary.begin(&info),
        Err(tuff::Error::Misuse(_))
    ));
    // Nor begun to continue an instance it cannot name.
    let nameless = tuff::CommandBufferInheritanceInfo::new();
    assert_eq!(
        vuid(
            secondary.begin_continuing(
                &tuff::CommandBufferBeginInfo::new()
                    .flags(continue_flags)
                    .inheritance_info(Some(&nameless))
            )
        ),
        "VUID-VkCommandBufferBeginInfo-flags-06002"
    );
    let (_ppool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    assert!(matches!(
        primary.begin_continuing(&info),
        Err(tuff::Error::Misuse(_))
    ));

    let rec = secondary.begin_continuing(&info).expect("begin continuing");
    rec.end().expect("end continuing");
    let rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin primary");
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: 16,
                height: 16,
            },
        })
        .clear_values(&clear);
    let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::SECONDARY_COMMAND_BUFFERS);
    rec.execute_commands(&secondary).expect("execute");
    rec.end_render_pass().end().expect("end primary");
    let done = fence(&s);
    submit(&s, &[&primary], &done).expect("submit");
    wait(&s, &done);
    assert_silent(&s.messages);
}

#[test]
fn a_recorder_dropped_without_end_leaves_nothing_to_submit_and_is_reset_at_begin() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (buffer, _memory) = transfer_buffer(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let done = fence(&s);
    {
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.fill_buffer(&buffer, 0, 256, 1).expect("fill");
        drop(rec);
    }
    assert_eq!(
        vuid(submit(&s, &[&cb], &done)),
        "VUID-vkQueueSubmit-pCommandBuffers-00070"
    );
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin after an abandoned recording");
    rec.fill_buffer(&buffer, 0, 256, 2).expect("fill");
    rec.end().expect("end");
    submit(&s, &[&cb], &done).expect("submit");
    wait(&s, &done);
    assert_silent(&s.messages);
}

#[test]
fn views_given_at_render_pass_begin_live_while_the_submission_is_pending() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let done = fence(&s);
    let target = s.color_target(16, vk::ImageUsageFlags::empty());
    let formats = [vk::Format::R8G8B8A8_UNORM];
    let image_infos = [tuff::FramebufferAttachmentImageInfo::new()
        .usage(vk::ImageUsageFlags::COLOR_ATTACHMENT)
        .width(16)
        .height(16)
        .layer_count(1)
        .view_formats(&formats)];
    let mut attachments_info =
        tuff::FramebufferAttachmentsCreateInfo::new().attachment_image_infos(&image_infos);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let live_with_view;
    let setter;
    {
        // A second view of the target's image, given only at render-pass begin.
        let view = s
            .device
            .create_image_view(
                &tuff::ImageViewCreateInfo::new(&target.image)
                    .view_type(vk::ImageViewType::TYPE_2D)
                    .format(vk::Format::R8G8B8A8_UNORM)
                    .subresource_range(vk::ImageSubresourceRange {
                        aspect_mask: vk::ImageAspectFlags::COLOR,
                        base_mip_level: 0,
                        level_count: 1,
                        base_array_layer: 0,
                        layer_count: 1,
                    }),
            )
            .expect("view");
        // An imageless framebuffer reads no view at creation, only the count: it is
        // given the target's own view, so that only the begin info names `view`.
        let framebuffer = s
            .device
            .create_framebuffer(
                &tuff::FramebufferCreateInfo::new(&target.render_pass)
                    .flags(vk::FramebufferCreateFlags::IMAGELESS)
                    .attachments(&target.view)
                    .width(16)
                    .height(16)
                    .layers(1)
                    .push_next(&mut attachments_info),
            )
            .expect("imageless framebuffer");
        live_with_view = s.device.live_object_count();
        let mut at_begin = tuff::RenderPassAttachmentBeginInfo::new().attachments(&view);
        let clear = [vk::ClearValue::default()];
        let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &framebuffer)
            .render_area(vk::Rect2D {
                offset: vk::Offset2D::default(),
                extent: vk::Extent2D {
                    width: 16,
                    height: 16,
                },
            })
            .clear_values(&clear)
            .push_next(&mut at_begin);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.wait_events(
            &gate,
            vk::PipelineStageFlags::HOST,
            vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            &[],
            &[],
            &[],
        )
        .expect("recorded");
        let rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
        rec.end_render_pass().end().expect("end");
        submit(&s, &[&cb], &done).expect("submit");
        // Set from another thread after a while, so that a failed assertion below
        // does not leave the queue waiting for ever.
        setter = set_later(&s, &gate);
        // The view and the framebuffer go here, while the submission waits; nothing
        // retires it before the wait below, however early the gate opens.
    }
    assert_eq!(
        s.device.live_object_count(),
        live_with_view,
        "the pending submission keeps the view and the framebuffer"
    );
    wait(&s, &done);
    setter.join().expect("setter");
    // The recording still holds them; a new recording lets them go.
    cb.reset(vk::CommandBufferResetFlags::empty())
        .expect("reset");
    assert_eq!(s.device.live_object_count(), live_with_view - 2);
    assert_silent(&s.messages);
}

#[test]
fn a_set_layout_keeps_its_immutable_samplers() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let sampler = s
        .device
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let samplers = tuff::HandleSlice::new(&[&sampler]);
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(vk::DescriptorType::SAMPLER)
        .immutable_samplers(&samplers)
        .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
    let layout = s
        .device
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let with_both = s.device.live_object_count();
    drop(samplers);
    drop(sampler);
    assert_eq!(
        s.device.live_object_count(),
        with_both,
        "the layout keeps the sampler its binding names"
    );
    drop(layout);
    assert_eq!(s.device.live_object_count(), with_both - 2);
    assert_silent(&s.messages);
}

// Class D: a count shared by several arrays. Every setter either refuses a length
// that disagrees with the arrays already set, or clears those arrays, so that no
// array a struct points at is shorter than its count.

#[test]
fn arrays_that_share_a_count_cannot_disagree() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let sem = semaphore(&s);
    let stages = [vk::PipelineStageFlags::TRANSFER; 3];
    assert_eq!(
        vuid(tuff::SubmitInfo::new().wait_semaphores(&sem, &stages)),
        "VUID-VkSubmitInfo-pWaitDstStageMask-parameter"
    );
    let info = tuff::SubmitInfo::new()
        .wait_semaphores(&sem, &stages[..1])
        .expect("equal lengths");
    assert_eq!(info.wait_semaphore_count, 1);

    let no_swapchains = tuff::HandleSlice::<tuff::SwapchainKHR>::new(&[]);
    assert_eq!(
        vuid(tuff::PresentInfoKHR::new().swapchains(&no_swapchains, &[0])),
        "VUID-VkPresentInfoKHR-pImageIndices-parameter"
    );
    assert_eq!(
        vuid(tuff::SemaphoreWaitInfo::new().semaphores(&sem, &[1, 2])),
        "VUID-VkSemaphoreWaitInfo-pValues-parameter"
    );

    // A follower must match what its lead set, and a lead of another length
    // clears it.
    let one = [vk::AttachmentReference::default()];
    let two = [vk::AttachmentReference::default(); 2];
    assert_eq!(
        vuid(tuff::SubpassDescription::new().resolve_attachments(&one)),
        "VUID-VkSubpassDescription-pResolveAttachments-parameter"
    );
    assert_eq!(
        vuid(
            tuff::SubpassDescription::new()
                .color_attachments(&two)
                .resolve_attachments(&one)
        ),
        "VUID-VkSubpassDescription-pResolveAttachments-parameter"
    );
    let subpass = tuff::SubpassDescription::new()
        .color_attachments(&one)
        .resolve_attachments(&one)
        .expect("equal lengths")
        .color_attachments(&two);
    assert_eq!(subpass.color_attachment_count, 2);
    assert!(subpass.p_resolve_attachments.is_null());
    let one2 = [tuff::AttachmentReference2::new()];
    assert_eq!(
        vuid(tuff::SubpassDescription2::new().resolve_attachments(&one2)),
        "VUID-VkSubpassDescription2-pResolveAttachments-parameter"
    );

    // Alternatives: the last one set decides the count and clears the others.
    let set = uniform_set(&s);
    let (buffer, _memory) = host_buffer(&s, 256, vk::BufferUsageFlags::UNIFORM_BUFFER);
    let infos = vec![
        tuff::DescriptorBufferInfo::new()
            .buffer(Some(&buffer))
            .range(256);
        1 << 20
    ];
    let no_views = tuff::HandleSlice::<tuff::BufferView>::new(&[]);
    let write = tuff::WriteDescriptorSet::new(&set.set)
        .texel_buffer_view(&no_views)
        .buffer_info(&infos);
    assert_eq!(write.descriptor_count, 1 << 20);
    assert!(write.p_texel_buffer_view.is_null());
    let write = write.texel_buffer_view(&no_views);
    assert_eq!(write.descriptor_count, 0);
    assert!(write.p_buffer_info.is_null());

    // A count that means something alone clears the array it no longer matches.
    let sampler = s
        .device
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let binding = tuff::DescriptorSetLayoutBinding::new()
        .immutable_samplers(&sampler)
        .descriptor_count(5);
    assert_eq!(binding.descriptor_count, 5);
    assert!(binding.p_immutable_samplers.is_null());
    let viewports = [vk::Viewport::default()];
    let state = tuff::PipelineViewportStateCreateInfo::new()
        .viewports(&viewports)
        .viewport_count(2);
    assert!(state.p_viewports.is_null());
    assert_silent(&s.messages);
}

#[test]
fn a_write_whose_type_selects_an_unset_array_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let set = uniform_set(&s);
    let sampler = s
        .device
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let target = s.color_target(4, vk::ImageUsageFlags::SAMPLED);
    let images = [tuff::DescriptorImageInfo::new()
        .sampler(Some(&sampler))
        .image_view(Some(&target.view))
        .image_layout(vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL)];
    // A uniform buffer binding written from image infos: pBufferInfo is null.
    let writes = [tuff::WriteDescriptorSet::new(&set.set)
        .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
        .image_info(&images)];
    assert_eq!(
        vuid(s.device.update_descriptor_sets(&writes, &[])),
        "VUID-VkWriteDescriptorSet-descriptorType-00324"
    );
    // The same write through `_unchecked` crashes inside the layer or the driver
    // (the layer reads the null array too), so no layer message proves the rule and
    // the report leaves it to the user.
    assert_silent(&s.messages);
}

// Class F: objects the registry marks externally synchronized. With `multi_thread`
// every wrapper of one object shares one lock, and a call holds the locks of every
// such object it names; the layer's thread-safety checks see no two calls at once.

#[cfg(feature = "multi_thread")]
#[test]
fn two_wrappers_of_one_queue_never_submit_at_once() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let other = s.device.get_queue(s.family, 0).expect("queue");
    let (buffer, _memory) = transfer_buffer(&s);
    std::thread::scope(|scope| {
        for queue in [&s.queue, &other] {
            let s = &s;
            let buffer = &buffer;
            scope.spawn(move || {
                let done = fence(s);
                let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
                let mut rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                // The other thread's submissions fill the same bytes: ordered after
                // them, or the fills race.
                let w = [tuff::MemoryBarrier::new()
                    .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                    .dst_access_mask(vk::AccessFlags::TRANSFER_WRITE)];
                let t = vk::PipelineStageFlags::TRANSFER;
                rec.pipeline_barrier(t, t, vk::DependencyFlags::empty(), &w, &[], &[])
                    .expect("barrier");
                rec.fill_buffer(buffer, 0, 256, 1).expect("fill");
                rec.end().expect("end");
                for _ in 0..200 {
                    queue
                        .submit(&[tuff::SubmitInfo::new().command_buffers(&cb)], Some(&done))
                        .expect("submit");
                    wait(s, &done);
                    s.device.reset_fences(&done).expect("reset");
                }
            });
        }
    });
    assert_silent(&s.messages);
}

#[cfg(feature = "multi_thread")]
#[test]
fn buffers_of_one_pool_are_recorded_and_freed_from_two_threads_one_at_a_time() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (buffer, _memory) = transfer_buffer(&s);
    let (pool, first) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut buffers = s
        .device
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1),
        )
        .expect("command buffers");
    buffers.push(first);
    std::thread::scope(|scope| {
        for mut cb in buffers {
            let buffer = &buffer;
            let s = &s;
            let pool = &pool;
            scope.spawn(move || {
                for i in 0..2000 {
                    let mut rec = cb
                        .begin(&tuff::CommandBufferBeginInfo::new())
                        .expect("begin");
                    rec.fill_buffer(buffer, 0, 256, i).expect("fill");
                    rec.end().expect("end");
                }
                // Freed while the other thread may be recording from the same pool.
                drop(cb);
                let more = s
                    .device
                    .allocate_command_buffers(
                        pool,
                        &tuff::CommandBufferAllocateInfo::new(pool).command_buffer_count(1),
                    )
                    .expect("allocate while the other thread records");
                drop(more);
            });
        }
    });
    assert_silent(&s.messages);
}

/// Every count field of a safe struct that more than one setter writes (arrays that
/// share it, or the count's own setter beside an array): each of those setters
/// refuses a length that disagrees (returns a `Result`) or clears the arrays that
/// would no longer match. Read from the emitted code, for every struct at once.
#[test]
fn every_count_that_two_setters_write_is_guarded() {
    use quote::ToTokens;
    use std::collections::BTreeMap;
    let dir = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../generated/src/generated/structs"
    );
    let mut items = Vec::new();
    for entry in std::fs::read_dir(dir).expect("generated structs") {
        let text = std::fs::read_to_string(entry.expect("entry").path()).expect("a file");
        items.extend(syn::parse_file(&text).expect("structs parse").items);
    }
    let mut unguarded = Vec::new();
    let mut shared = 0;
    for item in &items {
        let syn::Item::Impl(imp) = item else { continue };
        if imp.trait_.is_some() {
            continue;
        }
        let ty = imp.self_ty.to_token_stream().to_string();
        // count field -> (setter, sets it from an array's length, guarded)
        let mut writers: BTreeMap<String, Vec<(String, bool, bool)>> = BTreeMap::new();
        let mut array_counts = Vec::new();
        for it in &imp.items {
            let syn::ImplItem::Fn(f) = it else { continue };
            let body = f.block.to_token_stream().to_string();
            let output = f.sig.output.to_token_stream().to_string();
            let guarded = output.contains("Result") || body.contains("core :: ptr :: null ()");
            for (at, _) in body.match_indices("self . raw . ") {
                let rest = &body[at + "self . raw . ".len()..];
                let rest = rest.split(';').next().unwrap_or_default();
                let Some((field, value)) = rest.split_once(" = ") else {
                    continue;
                };
                let field = field.trim().to_owned();
                let value = value.trim();
                let from_len = value.contains("len");
                let plain = value == "value";
                if from_len {
                    array_counts.push(field.clone());
                }
                if from_len || plain {
                    writers.entry(field).or_default().push((
                        f.sig.ident.to_string(),
                        from_len,
                        guarded,
                    ));
                }
            }
        }
        for (field, setters) in writers {
            if !array_counts.contains(&field) || setters.len() < 2 {
                continue;
            }
            shared += 1;
            let arrays = setters.iter().filter(|(_, from_len, _)| *from_len).count();
            for (setter, from_len, guarded) in setters {
                // The only array of a count may set it: the count's own setter is
                // the one that must guard.
                let needs_guard = !from_len || arrays > 1;
                if needs_guard && !guarded {
                    unguarded.push(format!("{ty}::{setter} (writes `{field}`)"));
                }
            }
        }
    }
    assert!(
        shared >= 6,
        "only {shared} shared counts found: the scan is broken"
    );
    assert!(
        unguarded.is_empty(),
        "setters that write a shared count without refusing or clearing:\n{}",
        unguarded.join("\n")
    );
}

/// Timeline semaphores are told from binary ones by their create info, and each is
/// used only where its values are given: the driver reads a value per timeline
/// semaphore of a batch, and a counter value of a binary one does not exist.
#[test]
fn timeline_semaphores_are_used_only_with_their_values() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let binary = semaphore(&s);
    let mut timeline_type = tuff::SemaphoreTypeCreateInfo::new()
        .semaphore_type(vk::SemaphoreType::TIMELINE)
        .initial_value(0);
    let timeline = s
        .device
        .create_semaphore(&tuff::SemaphoreCreateInfo::new().push_next(&mut timeline_type))
        .expect("timeline semaphore");

    assert_eq!(
        vuid(s.device.get_semaphore_counter_value(&binary)),
        "VUID-vkGetSemaphoreCounterValue-semaphore-03255"
    );
    assert_eq!(
        s.device
            .get_semaphore_counter_value(&timeline)
            .expect("value"),
        0
    );
    let wait_binary = tuff::SemaphoreWaitInfo::new()
        .semaphores(&binary, &[1])
        .expect("one value per semaphore");
    assert_eq!(
        vuid(s.device.wait_semaphores(&wait_binary, 0)),
        "VUID-VkSemaphoreWaitInfo-pSemaphores-03256"
    );
    assert_eq!(
        vuid(
            s.device
                .signal_semaphore(&tuff::SemaphoreSignalInfo::new(&binary).value(1))
        ),
        "VUID-VkSemaphoreSignalInfo-semaphore-03257"
    );

    let done = fence(&s);
    let no_values = s.queue.submit(
        &[tuff::SubmitInfo::new().signal_semaphores(&timeline)],
        Some(&done),
    );
    assert_eq!(vuid(no_values), "VUID-VkSubmitInfo-pWaitSemaphores-03239");
    // A count without values, and values of another count.
    let mut counted = tuff::TimelineSemaphoreSubmitInfo::new().signal_semaphore_value_count(1);
    let r = s.queue.submit(
        &[tuff::SubmitInfo::new()
            .signal_semaphores(&timeline)
            .push_next(&mut counted)],
        Some(&done),
    );
    assert_eq!(vuid(r), "VUID-VkSubmitInfo-pNext-03241");
    let mut two = tuff::TimelineSemaphoreSubmitInfo::new().signal_semaphore_values(&[1, 2]);
    let r = s.queue.submit(
        &[tuff::SubmitInfo::new()
            .signal_semaphores(&timeline)
            .push_next(&mut two)],
        Some(&done),
    );
    assert_eq!(vuid(r), "VUID-VkSubmitInfo-pNext-03241");
    // Waits on a timeline semaphore with values of another count.
    let stages = [vk::PipelineStageFlags::ALL_COMMANDS];
    let mut two_waits = tuff::TimelineSemaphoreSubmitInfo::new().wait_semaphore_values(&[1, 2]);
    let r = s.queue.submit(
        &[tuff::SubmitInfo::new()
            .wait_semaphores(&timeline, &stages)
            .expect("one stage per semaphore")
            .push_next(&mut two_waits)],
        Some(&done),
    );
    assert_eq!(vuid(r), "VUID-VkSubmitInfo-pNext-03240");
    assert_silent(&s.messages);

    let mut one = tuff::TimelineSemaphoreSubmitInfo::new().signal_semaphore_values(&[1]);
    s.queue
        .submit(
            &[tuff::SubmitInfo::new()
                .signal_semaphores(&timeline)
                .push_next(&mut one)],
            Some(&done),
        )
        .expect("submit with its value");
    let wait_one = tuff::SemaphoreWaitInfo::new()
        .semaphores(&timeline, &[1])
        .expect("one value per semaphore");
    assert_eq!(
        s.device.wait_semaphores(&wait_one, u64::MAX).expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    assert_eq!(
        s.device
            .get_semaphore_counter_value(&timeline)
            .expect("value"),
        1
    );
    wait(&s, &done);
    assert_silent(&s.messages);
}

/// The two submission commands that take command buffers, and the rule each breaks
/// for one wrong state.
#[derive(Clone, Copy)]
enum Submitter {
    Submit,
    Submit2,
}

impl Submitter {
    fn submit(
        self,
        s: &Setup,
        cbs: &[&tuff::CommandBuffer],
        fence: &tuff::Fence,
    ) -> tuff::Result<()> {
        match self {
            Submitter::Submit => submit(s, cbs, fence),
            Submitter::Submit2 => {
                let infos: Vec<tuff::CommandBufferSubmitInfo> = cbs
                    .iter()
                    .map(|cb| tuff::CommandBufferSubmitInfo::new(cb))
                    .collect();
                s.queue.submit2(
                    &[tuff::SubmitInfo2::new().command_buffer_infos(&infos)],
                    Some(fence),
                )
            }
        }
    }

    /// Not executable, a secondary, twice at once, a secondary recorded again. (A
    /// secondary pending through another primary, the fifth state, is reachable
    /// only after the layer's own complaint at recording: a non-simultaneous
    /// secondary belongs to the last primary that recorded it.)
    fn rules(self) -> [&'static str; 4] {
        match self {
            Submitter::Submit => [
                "VUID-vkQueueSubmit-pCommandBuffers-00070",
                "VUID-VkSubmitInfo-pCommandBuffers-00075",
                "VUID-vkQueueSubmit-pCommandBuffers-00071",
                "VUID-vkQueueSubmit-pCommandBuffers-00072",
            ],
            Submitter::Submit2 => [
                "VUID-vkQueueSubmit2-commandBuffer-03874",
                "VUID-VkCommandBufferSubmitInfo-commandBuffer-03890",
                "VUID-vkQueueSubmit2-commandBuffer-03875",
                "VUID-vkQueueSubmit2-commandBuffer-03876",
            ],
        }
    }
}

/// Records `primary` (with `flags`) to execute `secondary`.
fn record_execute(
    primary: &mut tuff::CommandBuffer,
    flags: vk::CommandBufferUsageFlags,
    secondary: &tuff::CommandBuffer,
) {
    let mut rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new().flags(flags))
        .expect("begin primary");
    rec.execute_commands(secondary).expect("execute");
    rec.end().expect("end primary");
}

#[test]
fn every_submission_command_refuses_every_wrong_command_buffer_state() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (buffer, _memory) = transfer_buffer(&s);
    let none = vk::CommandBufferUsageFlags::empty();
    for submitter in [Submitter::Submit, Submitter::Submit2] {
        let [invalid, secondary_rule, twice, rerecorded] = submitter.rules();
        let gate = event(&s);
        let done = fence(&s);
        let (_pool, fresh) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        assert_eq!(vuid(submitter.submit(&s, &[&fresh], &done)), invalid);

        let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
        let inheritance = tuff::CommandBufferInheritanceInfo::new();
        let secondary_begin =
            tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance));
        let mut rec = secondary.begin(&secondary_begin).expect("begin secondary");
        rec.wait_events(
            &gate,
            vk::PipelineStageFlags::HOST,
            vk::PipelineStageFlags::TRANSFER,
            &[],
            &[],
            &[],
        )
        .expect("recorded");
        rec.fill_buffer(&buffer, 0, 256, 1).expect("fill");
        rec.end().expect("end secondary");
        assert_eq!(
            vuid(submitter.submit(&s, &[&secondary], &done)),
            secondary_rule
        );

        let (_ppool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        record_execute(&mut primary, none, &secondary);
        assert_eq!(
            vuid(submitter.submit(&s, &[&primary, &primary], &done)),
            twice
        );

        // Without SIMULTANEOUS_USE a secondary belongs to the last primary that
        // recorded it: the first is invalid once a second records it.
        let (_opool, mut other) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        record_execute(&mut other, none, &secondary);
        assert_eq!(vuid(submitter.submit(&s, &[&primary], &done)), invalid);
        submitter.submit(&s, &[&other], &done).expect("submit");
        // Nor can a third primary take it while it is pending.
        let (_tpool, mut third) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = third
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin third");
        assert_eq!(
            vuid(rec.execute_commands(&secondary)),
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00091"
        );
        rec.end().expect("end third");
        s.device.set_event(&gate).expect("set");
        wait(&s, &done);
        s.device.reset_fences(&done).expect("reset");

        // The secondary recorded again: the primary that executes it is invalid.
        let rec = secondary.begin(&secondary_begin).expect("begin again");
        rec.end().expect("end again");
        assert_eq!(vuid(submitter.submit(&s, &[&other], &done)), rerecorded);
        assert_silent(&s.messages);
    }
}

/// A debug name is written under the named object's lock; with `multi_thread` an
/// object without one the device can hold (the device itself, the instance's
/// objects) is refused rather than named while another thread may use it.
#[cfg(feature = "multi_thread")]
#[test]
fn debug_names_are_given_only_to_objects_the_device_can_lock() {
    use tuff::vk::Handle as _;
    use tuff::Handle as _;
    let _serial = vulkan::serial();
    let s = setup(true);
    let (buffer, _memory) = transfer_buffer(&s);
    let name = |ty: vk::ObjectType, raw: u64| unsafe {
        s.device.set_debug_utils_object_name_ext(
            &tuff::DebugUtilsObjectNameInfoEXT::new()
                .object_type(ty)
                .object_handle(raw)
                .object_name(Some(c"named")),
        )
    };
    name(vk::ObjectType::BUFFER, buffer.raw().as_raw()).expect("a buffer of the device");
    assert!(matches!(
        name(vk::ObjectType::DEVICE, s.device.raw().as_raw()),
        Err(tuff::Error::Misuse(_))
    ));
    assert_silent(&s.messages);
}

/// A timeline value seen on the host tells that the batches signalling it finished:
/// what they used goes then, before their fence is looked at, and the fence still
/// waits for its own signal before it can be reset or dropped.
#[test]
fn a_timeline_value_seen_on_the_host_releases_what_its_batch_used() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let gate = event(&s);
    let done = fence(&s);
    let mut timeline_type = tuff::SemaphoreTypeCreateInfo::new()
        .semaphore_type(vk::SemaphoreType::TIMELINE)
        .initial_value(0);
    let timeline = s
        .device
        .create_semaphore(&tuff::SemaphoreCreateInfo::new().push_next(&mut timeline_type))
        .expect("timeline semaphore");
    let before = s.device.live_object_count();
    {
        let (buffer, _memory) = transfer_buffer(&s);
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        record_gated_fill(
            &mut cb,
            vk::CommandBufferUsageFlags::empty(),
            &gate,
            &buffer,
        );
        let mut values = tuff::TimelineSemaphoreSubmitInfo::new().signal_semaphore_values(&[1]);
        s.queue
            .submit(
                &[tuff::SubmitInfo::new()
                    .command_buffers(&cb)
                    .signal_semaphores(&timeline)
                    .push_next(&mut values)],
                Some(&done),
            )
            .expect("submit");
    }
    assert!(
        s.device.live_object_count() > before,
        "the pending submission keeps its buffer, memory, pool and command buffer"
    );
    s.device.set_event(&gate).expect("set");
    let wait_info = tuff::SemaphoreWaitInfo::new()
        .semaphores(&timeline, &[1])
        .expect("one value per semaphore");
    assert_eq!(
        s.device
            .wait_semaphores(&wait_info, u64::MAX)
            .expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    assert_eq!(
        s.device.live_object_count(),
        before,
        "the value was reached: the batch's objects went"
    );
    wait(&s, &done);
    s.device.reset_fences(&done).expect("reset");
    assert_silent(&s.messages);
}

/// A copy that reaches past either buffer, or reads what it writes, or uses a buffer
/// without memory or without the usage it needs: tuff refuses each with the rule's
/// VUID before Vulkan sees it, and the recorder and buffers stay usable for a correct
/// copy. The same calls through `_unchecked` make the layer name the same rule (its
/// messenger asks it to skip each call, so the driver never runs them).
#[test]
fn buffer_copies_stay_inside_their_buffers() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let usage = vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST;
    let (big, _big_memory) = host_buffer(&s, 64 << 20, usage);
    let (small, _small_memory) = host_buffer(&s, 16, usage);
    let (dst_only, _m1) = host_buffer(&s, 256, vk::BufferUsageFlags::TRANSFER_DST);
    let (src_only, _m2) = host_buffer(&s, 256, vk::BufferUsageFlags::TRANSFER_SRC);
    let unbound = s
        .device
        .create_buffer(&tuff::BufferCreateInfo::new().size(256).usage(usage))
        .expect("buffer");
    let region = |src_offset, dst_offset, size| {
        [vk::BufferCopy {
            src_offset,
            dst_offset,
            size,
        }]
    };
    let cases: [(&str, &tuff::Buffer, &tuff::Buffer, [vk::BufferCopy; 1]); 10] = [
        // The copy of the issue: 64 MiB into 16 bytes.
        (
            "VUID-vkCmdCopyBuffer-size-00116",
            &big,
            &small,
            region(0, 0, 64 << 20),
        ),
        (
            "VUID-vkCmdCopyBuffer-srcOffset-00113",
            &small,
            &big,
            region(16, 0, 4),
        ),
        (
            "VUID-vkCmdCopyBuffer-dstOffset-00114",
            &big,
            &small,
            region(0, 16, 4),
        ),
        (
            "VUID-vkCmdCopyBuffer-size-00115",
            &small,
            &big,
            region(8, 0, 12),
        ),
        (
            "VUID-VkBufferCopy-size-01988",
            &big,
            &small,
            region(0, 0, 0),
        ),
        (
            "VUID-vkCmdCopyBuffer-pRegions-00117",
            &big,
            &big,
            region(0, 64, 128),
        ),
        (
            "VUID-vkCmdCopyBuffer-srcBuffer-00118",
            &dst_only,
            &big,
            region(0, 0, 4),
        ),
        (
            "VUID-vkCmdCopyBuffer-dstBuffer-00120",
            &big,
            &src_only,
            region(0, 0, 4),
        ),
        (
            "VUID-vkCmdCopyBuffer-srcBuffer-00119",
            &unbound,
            &big,
            region(0, 0, 4),
        ),
        (
            "VUID-vkCmdCopyBuffer-dstBuffer-00121",
            &big,
            &unbound,
            region(0, 0, 4),
        ),
    ];
    // Through the safe method: refused, nothing reaches the layer or the driver, and
    // the same recorder records a correct copy afterwards, which runs.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, src, dst, regions) in &cases {
        assert_eq!(
            vuid(rec.copy_buffer(src, dst, regions)),
            *expected,
            "copy {regions:?}"
        );
    }
    rec.copy_buffer(&big, &small, &region(64, 0, 16))
        .expect("a copy inside both buffers");
    rec.end().expect("end");
    assert_silent(&s.messages);
    let done = fence(&s);
    submit(&s, &[&cb], &done).expect("submit");
    wait(&s, &done);
    assert_silent(&s.messages);

    // Through `_unchecked`: the layer names the same rule for each.
    s.messages.abort_on_error(true);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, src, dst, regions) in &cases {
        // SAFETY: the messenger makes the layer skip the call, which breaks only the
        // rule under test; the command buffer is never submitted.
        unsafe { rec.copy_buffer_unchecked(src, dst, regions) }.expect("recorded");
        assert_layer_reports(&s, expected);
    }
    s.messages.abort_on_error(false);
    rec.end().expect("end");

    // `vkCmdCopyBuffer2` by the same rules, under its own VUIDs (the 1.3.239 layer
    // names some by `vkCmdCopyBuffer`'s).
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, src, dst, regions) in &cases {
        let regions2 = regions.map(|r| {
            tuff::BufferCopy2::new()
                .src_offset(r.src_offset)
                .dst_offset(r.dst_offset)
                .size(r.size)
        });
        let info = tuff::CopyBufferInfo2::new(src, dst).regions(&regions2);
        let expected = expected
            .replace("vkCmdCopyBuffer-", "VkCopyBufferInfo2-")
            .replace("VkBufferCopy-", "VkBufferCopy2-");
        assert_eq!(vuid(rec.copy_buffer2(&info)), expected, "copy {regions:?}");
        s.messages.abort_on_error(true);
        // SAFETY: the messenger makes the layer skip the call, which breaks only the
        // rule under test; the command buffer is never submitted.
        unsafe { rec.copy_buffer2_unchecked(&info) }.expect("recorded");
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        let v1 = expected
            .replace("VkCopyBufferInfo2-", "vkCmdCopyBuffer-")
            .replace("VkBufferCopy2-", "VkBufferCopy-");
        assert!(
            said.iter()
                .any(|m| m.contains(&expected) || m.contains(&v1)),
            "{expected}: the layer said {said:?}"
        );
    }
    let region2 = [tuff::BufferCopy2::new().src_offset(64).size(16)];
    rec.copy_buffer2(&tuff::CopyBufferInfo2::new(&big, &small).regions(&region2))
        .expect("a copy inside both buffers");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// Memory bound with `bind_buffer_memory2` or `bind_image_memory2` stays alive while
/// the buffer or image does, as with `bind_buffer_memory`: dropping the memory's
/// wrapper first, then copying through the buffer, frees nothing in use (the layer
/// would report the freed memory), and the memory goes with the buffer.
#[test]
fn memory_bound_by_bind2_lives_as_long_as_its_object() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let usage = vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST;
    let (target, _target_memory) = host_buffer(&s, 256, usage);
    let before = d.live_object_count();
    let buffer = d
        .create_buffer(&tuff::BufferCreateInfo::new().size(256).usage(usage))
        .expect("buffer");
    let reqs = d
        .get_buffer_memory_requirements(&buffer)
        .expect("requirements");
    let memory = d
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(reqs.size)
                .memory_type_index(
                    s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::HOST_VISIBLE),
                ),
        )
        .expect("memory");
    d.bind_buffer_memory2(&[tuff::BindBufferMemoryInfo::new(&buffer, &memory)])
        .expect("bind");
    drop(memory);
    assert_eq!(
        d.live_object_count(),
        before + 2,
        "the buffer keeps its memory"
    );
    let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.copy_buffer(
        &buffer,
        &target,
        &[vk::BufferCopy {
            src_offset: 0,
            dst_offset: 0,
            size: 256,
        }],
    )
    .expect("copy");
    rec.end().expect("end");
    let done = fence(&s);
    submit(&s, &[&cb], &done).expect("submit");
    wait(&s, &done);
    drop((cb, pool, done, buffer));
    assert_eq!(
        d.live_object_count(),
        before,
        "the memory goes with the buffer"
    );
    assert_silent(&s.messages);
}

/// Slices that share one count in C (`bindingCount` of the buffers and their
/// offsets, `eventCount` of the events and their dependency infos) must be as long as
/// the one that sets it, or Vulkan reads past the end of the shorter one on the host.
/// tuff refuses the call with the slice's `-parameter` rule; an empty optional slice
/// (`pSizes`, `pStrides`) is NULL, so the call runs and the layer says nothing. The
/// layer cannot judge these rules (the unchecked call would read past the slice), so
/// the error alone proves them; the suite's memcheck run shows no read happens.
#[test]
fn slices_sharing_a_count_have_its_length() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let usage = vk::BufferUsageFlags::VERTEX_BUFFER;
    let (a, _ma) = host_buffer(&s, 256, usage);
    let (b, _mb) = host_buffer(&s, 256, usage);
    let gate = event(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    assert_eq!(
        vuid(rec.bind_vertex_buffers(0, &tuff::HandleSlice::new(&[&a, &b]), &[0])),
        "VUID-vkCmdBindVertexBuffers-pOffsets-parameter"
    );
    assert_eq!(
        vuid(rec.bind_vertex_buffers2(0, &tuff::HandleSlice::new(&[&a, &b]), &[0, 0], &[256], &[])),
        "VUID-vkCmdBindVertexBuffers2-pSizes-parameter"
    );
    assert_eq!(
        vuid(rec.bind_vertex_buffers2(0, &a, &[0], &[], &[16, 16])),
        "VUID-vkCmdBindVertexBuffers2-pStrides-parameter"
    );
    assert_eq!(
        vuid(rec.wait_events2(&gate, &[])),
        "VUID-vkCmdWaitEvents2-pDependencyInfos-parameter"
    );
    // The same recorder goes on: equal lengths, and empty optional slices as NULL.
    rec.bind_vertex_buffers(0, &tuff::HandleSlice::new(&[&a, &b]), &[0, 16])
        .expect("one offset per buffer");
    rec.bind_vertex_buffers2(0, &tuff::HandleSlice::new(&[&a, &b]), &[0, 16], &[], &[])
        .expect("no sizes and no strides");
    rec.bind_vertex_buffers2(0, &a, &[0], &[128], &[])
        .expect("a size per buffer");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// Fills, updates and vertex and index bindings outside their buffer, misaligned, or
/// on a buffer without the usage or memory they need: tuff refuses each with the
/// rule's VUID, the recorder goes on, and the same call through `_unchecked` makes
/// the layer name the same rule (it skips the call, so the driver never runs it).
#[test]
fn buffer_commands_stay_inside_their_buffers() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let all = vk::BufferUsageFlags::TRANSFER_DST
        | vk::BufferUsageFlags::VERTEX_BUFFER
        | vk::BufferUsageFlags::INDEX_BUFFER;
    let (buffer, _m) = host_buffer(&s, 256, all);
    let (src_only, _m2) = host_buffer(&s, 256, vk::BufferUsageFlags::TRANSFER_SRC);
    let unbound = s
        .device
        .create_buffer(&tuff::BufferCreateInfo::new().size(256).usage(all))
        .expect("buffer");
    static BIG: [u8; 65540] = [0; 65540];
    type Rec<'r> = tuff::Recorder<'r, tuff::Outside>;
    type Call<'b> = Box<dyn Fn(&mut Rec<'_>, bool) -> tuff::Result<()> + 'b>;
    // Each case: the rule, and the call (through `_unchecked` when the flag is set).
    let fill =
        |b: &'static str, buf: &tuff::Buffer, offset: u64, size: u64| -> (&'static str, Call<'_>) {
            let buf = buf.clone();
            (
                b,
                Box::new(move |rec: &mut Rec<'_>, unchecked: bool| {
                    if unchecked {
                        // SAFETY: the layer skips the call, which breaks only the rule
                        // under test; the command buffer is never submitted.
                        unsafe { rec.fill_buffer_unchecked(&buf, offset, size, 0) }
                    } else {
                        rec.fill_buffer(&buf, offset, size, 0)
                    }
                }),
            )
        };
    let update = |b: &'static str,
                  buf: &tuff::Buffer,
                  offset: u64,
                  data: &'static [u8]|
     -> (&'static str, Call<'_>) {
        let buf = buf.clone();
        (
            b,
            Box::new(move |rec: &mut Rec<'_>, unchecked: bool| {
                if unchecked {
                    // SAFETY: as for the fills.
                    unsafe { rec.update_buffer_unchecked(&buf, offset, data) }
                } else {
                    rec.update_buffer(&buf, offset, data)
                }
            }),
        )
    };
    let vertex = |b: &'static str, buf: &tuff::Buffer, offset: u64| -> (&'static str, Call<'_>) {
        let buf = buf.clone();
        (
            b,
            Box::new(move |rec: &mut Rec<'_>, unchecked: bool| {
                if unchecked {
                    // SAFETY: as for the fills.
                    unsafe { rec.bind_vertex_buffers_unchecked(0, &buf, &[offset]) }
                } else {
                    rec.bind_vertex_buffers(0, &buf, &[offset])
                }
            }),
        )
    };
    let index = |b: &'static str, buf: &tuff::Buffer, offset: u64| -> (&'static str, Call<'_>) {
        let buf = buf.clone();
        (
            b,
            Box::new(move |rec: &mut Rec<'_>, unchecked: bool| {
                if unchecked {
                    // SAFETY: as for the fills.
                    unsafe { rec.bind_index_buffer_unchecked(&buf, offset, vk::IndexType::UINT32) }
                } else {
                    rec.bind_index_buffer(&buf, offset, vk::IndexType::UINT32)
                }
            }),
        )
    };
    let big: &'static [u8] = &BIG;
    let cases: Vec<(&str, Call<'_>)> = vec![
        fill("VUID-vkCmdFillBuffer-dstOffset-00024", &buffer, 256, 4),
        fill("VUID-vkCmdFillBuffer-dstOffset-00025", &buffer, 2, 4),
        fill("VUID-vkCmdFillBuffer-size-00026", &buffer, 0, 0),
        fill("VUID-vkCmdFillBuffer-size-00027", &buffer, 128, 256),
        fill("VUID-vkCmdFillBuffer-size-00028", &buffer, 0, 6),
        fill("VUID-vkCmdFillBuffer-dstBuffer-00029", &src_only, 0, 4),
        fill("VUID-vkCmdFillBuffer-dstBuffer-00031", &unbound, 0, 4),
        update(
            "VUID-vkCmdUpdateBuffer-dstOffset-00032",
            &buffer,
            256,
            &[0; 4],
        ),
        update(
            "VUID-vkCmdUpdateBuffer-dataSize-00033",
            &buffer,
            128,
            &[0; 256],
        ),
        update(
            "VUID-vkCmdUpdateBuffer-dstBuffer-00034",
            &src_only,
            0,
            &[0; 4],
        ),
        update(
            "VUID-vkCmdUpdateBuffer-dstBuffer-00035",
            &unbound,
            0,
            &[0; 4],
        ),
        update(
            "VUID-vkCmdUpdateBuffer-dstOffset-00036",
            &buffer,
            2,
            &[0; 4],
        ),
        update("VUID-vkCmdUpdateBuffer-dataSize-00038", &buffer, 0, &[0; 6]),
        vertex("VUID-vkCmdBindVertexBuffers-pOffsets-00626", &buffer, 256),
        vertex("VUID-vkCmdBindVertexBuffers-pBuffers-00627", &src_only, 0),
        vertex("VUID-vkCmdBindVertexBuffers-pBuffers-00628", &unbound, 0),
        index("VUID-vkCmdBindIndexBuffer-offset-00431", &buffer, 256),
        index("VUID-vkCmdBindIndexBuffer-buffer-00433", &src_only, 0),
        index("VUID-vkCmdBindIndexBuffer-buffer-00434", &unbound, 0),
    ];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, call) in &cases {
        assert_eq!(vuid(call(&mut rec, false)), *expected);
    }
    // 65,540 bytes: more than one update may carry (and than the buffer holds).
    let (large, _m3) = host_buffer(&s, 1 << 17, vk::BufferUsageFlags::TRANSFER_DST);
    assert_eq!(
        vuid(rec.update_buffer(&large, 0, big)),
        "VUID-vkCmdUpdateBuffer-dataSize-00037"
    );
    // The recorder goes on with correct calls, which run.
    rec.fill_buffer(&buffer, 0, 128, 7).expect("fill");
    rec.update_buffer(&buffer, 252, &[1, 2, 3, 4])
        .expect("update");
    rec.bind_vertex_buffers(0, &buffer, &[252]).expect("vertex");
    rec.bind_index_buffer(&buffer, 4, vk::IndexType::UINT32)
        .expect("index");
    rec.end().expect("end");
    assert_silent(&s.messages);
    let done = fence(&s);
    submit(&s, &[&cb], &done).expect("submit");
    wait(&s, &done);
    assert_silent(&s.messages);

    s.messages.abort_on_error(true);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, call) in &cases {
        call(&mut rec, true).expect("recorded");
        assert_layer_reports(&s, expected);
    }
    // SAFETY: as above.
    unsafe { rec.update_buffer_unchecked(&large, 0, big) }.expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdUpdateBuffer-dataSize-00037");
    s.messages.abort_on_error(false);
    rec.end().expect("end");
}

/// Query results read into a slice too small, or for queries past the pool, would
/// have the driver write past `data` or read past its pool: tuff refuses each with
/// the rule's VUID, and the layer names the same rule for the unchecked call (which it
/// then skips, so the driver never writes).
#[test]
fn query_results_stay_inside_data_and_pool() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let pool = |ty| {
        d.create_query_pool(
            &tuff::QueryPoolCreateInfo::new()
                .query_type(ty)
                .query_count(4),
        )
        .expect("query pool")
    };
    let occlusion = pool(vk::QueryType::OCCLUSION);
    let timestamps = pool(vk::QueryType::TIMESTAMP);
    // Eight-byte aligned storage, so the alignment rules break only where a case
    // breaks them on purpose.
    let mut words = [0u64; 8];
    let data: &mut [u8] = bytemuck::cast_slice_mut(&mut words);
    let wide = vk::QueryResultFlags::TYPE_64;
    type Case = (
        &'static str,
        bool,
        u32,
        u32,
        usize,
        u64,
        vk::QueryResultFlags,
    );
    let cases: [Case; 6] = [
        (
            "VUID-vkGetQueryPoolResults-firstQuery-00813",
            false,
            4,
            1,
            64,
            8,
            wide,
        ),
        (
            "VUID-vkGetQueryPoolResults-firstQuery-00816",
            false,
            2,
            3,
            64,
            8,
            wide,
        ),
        (
            "VUID-vkGetQueryPoolResults-flags-00815",
            false,
            0,
            1,
            64,
            4,
            wide,
        ),
        (
            "VUID-vkGetQueryPoolResults-flags-02827",
            false,
            0,
            1,
            64,
            6,
            vk::QueryResultFlags::empty(),
        ),
        // Four queries of eight bytes at a stride of eight need 32 bytes, not 24.
        (
            "VUID-vkGetQueryPoolResults-dataSize-00817",
            false,
            0,
            4,
            24,
            8,
            wide,
        ),
        (
            "VUID-vkGetQueryPoolResults-queryType-00818",
            true,
            0,
            1,
            64,
            8,
            wide | vk::QueryResultFlags::PARTIAL,
        ),
    ];
    for (expected, ts, first, count, len, stride, flags) in cases {
        let p = if ts { &timestamps } else { &occlusion };
        assert_eq!(
            vuid(d.get_query_pool_results(p, first, count, &mut data[..len], stride, flags)),
            expected
        );
    }
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    for (expected, ts, first, count, len, stride, flags) in cases {
        let p = if ts { &timestamps } else { &occlusion };
        // SAFETY: the messenger makes the layer skip the call, so the driver never
        // writes; the call breaks only the rule under test.
        let r = unsafe {
            d.get_query_pool_results_unchecked(p, first, count, &mut data[..len], stride, flags)
        };
        assert!(r.is_err(), "the layer skipped the call");
        assert_layer_reports(&s, expected);
    }
    s.messages.abort_on_error(false);
}

/// Push constants outside the layout's ranges, misaligned or past
/// `maxPushConstantsSize`, and set bindings past the layout's sets or with too few
/// dynamic offsets, would have the driver copy past its arrays: tuff refuses each, the
/// recorder goes on, and the layer names the same rule for the unchecked call.
#[test]
fn push_constants_and_set_bindings_stay_inside_the_layout() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    // Ranges of one stage each (no stage may be in two ranges): the vertex stage
    // reads 0..16, the fragment stage 0..32.
    let ranges = [
        vk::PushConstantRange {
            stage_flags: vk::ShaderStageFlags::VERTEX,
            offset: 0,
            size: 16,
        },
        vk::PushConstantRange {
            stage_flags: vk::ShaderStageFlags::FRAGMENT,
            offset: 0,
            size: 32,
        },
    ];
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::VERTEX)];
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let layout = d
        .create_pipeline_layout(
            &tuff::PipelineLayoutCreateInfo::new()
                .push_constant_ranges(&ranges)
                .set_layouts(&set_layouts),
        )
        .expect("layout");
    let sizes = [vk::DescriptorPoolSize {
        ty: vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
        descriptor_count: 1,
    }];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes),
        )
        .expect("descriptor pool");
    let set = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&set_layouts),
        )
        .expect("set")
        .pop()
        .expect("one set");
    let (buffer, _memory) = host_buffer(&s, 256, vk::BufferUsageFlags::UNIFORM_BUFFER);
    let info = [tuff::DescriptorBufferInfo::new()
        .buffer(Some(&buffer))
        .range(64)];
    d.update_descriptor_sets(
        &[tuff::WriteDescriptorSet::new(&set)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC)
            .buffer_info(&info)],
        &[],
    )
    .expect("write");
    let vertex = vk::ShaderStageFlags::VERTEX;
    let both = vertex | vk::ShaderStageFlags::FRAGMENT;
    let max = s.physical.get_properties().limits.max_push_constants_size;
    let pushes: [(&str, vk::ShaderStageFlags, u32, usize); 6] = [
        ("VUID-vkCmdPushConstants-offset-01795", both, 16, 8),
        ("VUID-vkCmdPushConstants-offset-01796", vertex, 0, 8),
        ("VUID-vkCmdPushConstants-offset-00368", vertex, 2, 4),
        ("VUID-vkCmdPushConstants-size-00369", vertex, 0, 6),
        ("VUID-vkCmdPushConstants-offset-00370", vertex, max, 4),
        ("VUID-vkCmdPushConstants-size-00371", vertex, max - 4, 8),
    ];
    let bytes = [0u8; 64];
    let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, stages, offset, len) in pushes {
        assert_eq!(
            vuid(rec.push_constants(&layout, stages, offset, &bytes[..len])),
            expected
        );
    }
    let graphics = vk::PipelineBindPoint::GRAPHICS;
    assert_eq!(
        vuid(rec.bind_descriptor_sets(graphics, &layout, 1, &set, &[0])),
        "VUID-vkCmdBindDescriptorSets-firstSet-00360"
    );
    assert_eq!(
        vuid(rec.bind_descriptor_sets(graphics, &layout, 0, &set, &[])),
        "VUID-vkCmdBindDescriptorSets-dynamicOffsetCount-00359"
    );
    // The recorder goes on with correct calls.
    rec.push_constants(&layout, both, 0, &bytes[..16])
        .expect("push");
    rec.push_constants(&layout, vk::ShaderStageFlags::FRAGMENT, 16, &bytes[..16])
        .expect("push");
    rec.bind_descriptor_sets(graphics, &layout, 0, &set, &[0])
        .expect("bind");
    rec.end().expect("end");
    assert_silent(&s.messages);

    s.messages.abort_on_error(true);
    let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, stages, offset, len) in pushes {
        // SAFETY: the layer skips the call, which breaks only the rule under test; the
        // command buffer is never submitted.
        unsafe { rec.push_constants_unchecked(&layout, stages, offset, &bytes[..len]) }
            .expect("recorded");
        assert_layer_reports(&s, expected);
    }
    // SAFETY: as above.
    unsafe { rec.bind_descriptor_sets_unchecked(graphics, &layout, 1, &set, &[0]) }
        .expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdBindDescriptorSets-firstSet-00360");
    // SAFETY: as above; the layer reads no dynamic offset it was not given.
    unsafe { rec.bind_descriptor_sets_unchecked(graphics, &layout, 0, &set, &[]) }
        .expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdBindDescriptorSets-dynamicOffsetCount-00359");
    s.messages.abort_on_error(false);
    rec.end().expect("end");
}

/// A set bound for a layout's set number has that set layout, and each dynamic
/// offset is aligned and keeps its descriptor's range inside the buffer: tuff
/// refuses each break, and the layer names the same rule for the unchecked call.
#[test]
fn bound_sets_match_their_layout_and_dynamic_offsets_stay_in_their_buffers() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let set_layout = |ty| {
        let bindings = [tuff::DescriptorSetLayoutBinding::new()
            .binding(0)
            .descriptor_type(ty)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX)];
        d.create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout")
    };
    let uniform = vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC;
    let storage = vk::DescriptorType::STORAGE_BUFFER_DYNAMIC;
    let (uniform_layout, storage_layout) = (set_layout(uniform), set_layout(storage));
    let pipeline_layout = |set_layout: &tuff::DescriptorSetLayout| {
        let set_layouts = tuff::HandleSlice::new(&[set_layout]);
        d.create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layouts))
            .expect("layout")
    };
    let (uniform_pipeline, storage_pipeline) = (
        pipeline_layout(&uniform_layout),
        pipeline_layout(&storage_layout),
    );
    let sizes = [
        vk::DescriptorPoolSize {
            ty: uniform,
            descriptor_count: 2,
        },
        vk::DescriptorPoolSize {
            ty: storage,
            descriptor_count: 1,
        },
    ];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(3)
                .pool_sizes(&sizes),
        )
        .expect("descriptor pool");
    let allocate = |layout: &tuff::DescriptorSetLayout| {
        d.allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(layout),
        )
        .expect("set")
        .pop()
        .expect("one set")
    };
    let (ranged, whole, stored) = (
        allocate(&uniform_layout),
        allocate(&uniform_layout),
        allocate(&storage_layout),
    );
    let usage = vk::BufferUsageFlags::UNIFORM_BUFFER | vk::BufferUsageFlags::STORAGE_BUFFER;
    let (buffer, _memory) = host_buffer(&s, 1024, usage);
    let write = |set: &tuff::DescriptorSet, ty, range| {
        let info = [tuff::DescriptorBufferInfo::new()
            .buffer(Some(&buffer))
            .range(range)];
        d.update_descriptor_sets(
            &[tuff::WriteDescriptorSet::new(set)
                .descriptor_type(ty)
                .buffer_info(&info)],
            &[],
        )
        .expect("write");
    };
    write(&ranged, uniform, 64);
    write(&whole, uniform, vk::WHOLE_SIZE);
    write(&stored, storage, 64);
    let limits = s.physical.get_properties().limits;
    let (ua, sa) = (
        limits.min_uniform_buffer_offset_alignment as u32,
        limits.min_storage_buffer_offset_alignment as u32,
    );
    assert!(ua > 1 && sa > 1, "lavapipe aligns dynamic offsets");
    let graphics = vk::PipelineBindPoint::GRAPHICS;
    type Case<'a> = (
        &'static str,
        &'a tuff::PipelineLayout,
        &'a tuff::DescriptorSet,
        u32,
    );
    let cases: [Case<'_>; 5] = [
        (
            "VUID-vkCmdBindDescriptorSets-pDescriptorSets-00358",
            &storage_pipeline,
            &ranged,
            0,
        ),
        (
            "VUID-vkCmdBindDescriptorSets-pDynamicOffsets-01971",
            &uniform_pipeline,
            &ranged,
            ua / 2,
        ),
        (
            "VUID-vkCmdBindDescriptorSets-pDynamicOffsets-01972",
            &storage_pipeline,
            &stored,
            sa / 2,
        ),
        (
            "VUID-vkCmdBindDescriptorSets-pDescriptorSets-01979",
            &uniform_pipeline,
            &ranged,
            1024 / ua * ua,
        ),
        (
            "VUID-vkCmdBindDescriptorSets-pDescriptorSets-06715",
            &uniform_pipeline,
            &whole,
            ua,
        ),
    ];
    let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, layout, set, offset) in cases {
        assert_eq!(
            vuid(rec.bind_descriptor_sets(graphics, layout, 0, set, &[offset])),
            expected
        );
    }
    // The recorder goes on with correct binds.
    rec.bind_descriptor_sets(graphics, &uniform_pipeline, 0, &ranged, &[ua])
        .expect("bind");
    rec.bind_descriptor_sets(graphics, &uniform_pipeline, 0, &whole, &[0])
        .expect("bind");
    rec.end().expect("end");
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, layout, set, offset) in cases {
        // SAFETY: the layer skips the call, which breaks only the rule under test; the
        // command buffer is never submitted.
        unsafe { rec.bind_descriptor_sets_unchecked(graphics, layout, 0, set, &[offset]) }
            .expect("recorded");
        assert_layer_reports(&s, expected);
    }
    s.messages.abort_on_error(false);
    rec.end().expect("end");
}

/// A batch's wait stages and device-group indices are checked before the queue sees
/// them: each break is refused, and the layer names the same rule for the unchecked
/// submission (which it skips, so nothing is submitted).
#[test]
fn wait_stages_and_device_indices_are_checked_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    for (s, sync2_off) in [(setup(true), false), (tuff_setup::setup_bare(true), true)] {
        let d = &s.device;
        let signaled = d
            .create_semaphore(&tuff::SemaphoreCreateInfo::new())
            .expect("semaphore");
        let first = fence(&s);
        s.queue
            .submit(
                &[tuff::SubmitInfo::new().signal_semaphores(&signaled)],
                Some(&first),
            )
            .expect("signal");
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        cb.begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin")
            .end()
            .expect("end");
        type S = vk::PipelineStageFlags;
        let mut cases: Vec<(&str, S, Vec<u32>, Vec<u32>)> = vec![];
        if sync2_off {
            cases.push((
                "VUID-VkSubmitInfo-pWaitDstStageMask-03937",
                S::empty(),
                vec![],
                vec![],
            ));
        } else {
            cases.extend([
                (
                    "VUID-VkSubmitInfo-pWaitDstStageMask-00078",
                    S::HOST,
                    vec![],
                    vec![],
                ),
                (
                    "VUID-VkSubmitInfo-pWaitDstStageMask-04090",
                    S::GEOMETRY_SHADER,
                    vec![],
                    vec![],
                ),
                (
                    "VUID-VkSubmitInfo-pWaitDstStageMask-04091",
                    S::TESSELLATION_CONTROL_SHADER,
                    vec![],
                    vec![],
                ),
                (
                    "VUID-VkDeviceGroupSubmitInfo-pCommandBufferDeviceMasks-00086",
                    S::ALL_COMMANDS,
                    vec![0],
                    vec![0b10],
                ),
                // Last: the 1.3.239 layer does not check it, so the unchecked call
                // reaches lavapipe (which has one device and reads no index): proven
                // by the error alone.
                (
                    "VUID-VkDeviceGroupSubmitInfo-pWaitSemaphoreDeviceIndices-00085",
                    S::ALL_COMMANDS,
                    vec![1],
                    vec![1],
                ),
            ]);
        }
        let done = fence(&s);
        for (expected, stage, indices, masks) in cases {
            let stages = [stage];
            let mut group = tuff::DeviceGroupSubmitInfo::new()
                .wait_semaphore_device_indices(&indices)
                .command_buffer_device_masks(&masks);
            let mut batch = tuff::SubmitInfo::new()
                .wait_semaphores(&signaled, &stages)
                .expect("one stage per wait")
                .command_buffers(&cb);
            if !indices.is_empty() {
                batch = batch.push_next(&mut group);
            }
            let batch = [batch];
            assert_eq!(vuid(s.queue.submit(&batch, Some(&done))), expected);
            s.messages.take();
            s.messages.abort_on_error(true);
            // SAFETY: the layer skips the submission, which breaks only the rule under
            // test.
            let _ = unsafe { s.queue.submit_unchecked(&batch, Some(&done)) };
            s.messages.abort_on_error(false);
            if expected.ends_with("-00085") {
                let said = s.messages.take();
                assert!(said.is_empty(), "the layer said: {said:?}");
            } else {
                assert_layer_reports(&s, expected);
            }
        }
        s.queue.wait_idle().expect("idle");
    }
}

/// Private data reaches the object through its handle, as a pointer: a handle of a
/// dropped object, or of another type, or of an object that is not a child of the
/// device, is refused before the driver sees it.
#[test]
fn private_data_names_live_objects_only() {
    use tuff::Handle as _;
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let slot = d
        .create_private_data_slot(&tuff::PrivateDataSlotCreateInfo::new())
        .expect("slot");
    let (buffer, _memory) = host_buffer(&s, 64, vk::BufferUsageFlags::TRANSFER_DST);
    let dropped = {
        let (gone, _m) = host_buffer(&s, 64, vk::BufferUsageFlags::TRANSFER_DST);
        vk::Handle::as_raw(gone.raw())
    };
    let live = vk::Handle::as_raw(buffer.raw());
    let instance = vk::Handle::as_raw(s.instance.raw());
    let cases = [
        (
            "VUID-vkSetPrivateData-objectHandle-04017",
            vk::ObjectType::BUFFER,
            dropped,
        ),
        (
            "VUID-vkSetPrivateData-objectHandle-04017",
            vk::ObjectType::IMAGE,
            live,
        ),
        (
            "VUID-vkSetPrivateData-objectHandle-04016",
            vk::ObjectType::INSTANCE,
            instance,
        ),
    ];
    for (expected, ty, handle) in cases {
        assert_eq!(vuid(d.set_private_data(ty, handle, &slot, 7)), expected);
    }
    assert!(matches!(
        d.get_private_data(vk::ObjectType::BUFFER, dropped, &slot),
        Err(tuff::Error::Misuse(_))
    ));
    d.set_private_data(vk::ObjectType::BUFFER, live, &slot, 7)
        .expect("set");
    assert_eq!(
        d.get_private_data(vk::ObjectType::BUFFER, live, &slot)
            .expect("get"),
        7
    );
    let device = vk::Handle::as_raw(d.raw());
    d.set_private_data(vk::ObjectType::DEVICE, device, &slot, 9)
        .expect("set on the device");
    assert_silent(&s.messages);
    // The layer does not check these rules (it reports nothing for a handle of the
    // wrong type or a non-child), so the error alone proves them: the report says so.
}

/// A debug name or tag reaches the object through its handle: a handle of a dropped
/// object, or named with another type, is refused; a live one is named.
#[test]
fn debug_names_are_given_only_to_live_objects() {
    use tuff::vk::Handle as _;
    use tuff::Handle as _;
    let _serial = vulkan::serial();
    let s = setup(true);
    let (buffer, _memory) = transfer_buffer(&s);
    let dropped = {
        let (gone, _m) = transfer_buffer(&s);
        gone.raw().as_raw()
    };
    let name = |ty: vk::ObjectType, raw: u64| unsafe {
        s.device.set_debug_utils_object_name_ext(
            &tuff::DebugUtilsObjectNameInfoEXT::new()
                .object_type(ty)
                .object_handle(raw)
                .object_name(Some(c"named")),
        )
    };
    let tag = |ty: vk::ObjectType, raw: u64| {
        s.device.set_debug_utils_object_tag_ext(
            &tuff::DebugUtilsObjectTagInfoEXT::new()
                .object_type(ty)
                .object_handle(raw)
                .tag(&[1, 2, 3, 4]),
        )
    };
    let live = buffer.raw().as_raw();
    for (ty, raw) in [
        (vk::ObjectType::BUFFER, dropped),
        (vk::ObjectType::IMAGE, live),
    ] {
        assert_eq!(
            vuid(name(ty, raw)),
            "VUID-VkDebugUtilsObjectNameInfoEXT-objectType-02590"
        );
        assert_eq!(
            vuid(tag(ty, raw)),
            "VUID-VkDebugUtilsObjectTagInfoEXT-objectHandle-01910"
        );
    }
    name(vk::ObjectType::BUFFER, live).expect("a live buffer");
    tag(vk::ObjectType::BUFFER, live).expect("a live buffer");
    assert_silent(&s.messages);
    // `_unchecked` looks the object up too (it is how the call finds the lock it
    // holds), so no call reaches the layer: the error alone proves these rules.
}

/// Descriptor writes and copies name a binding, an array element and a count, which
/// drivers use to index the set's descriptor array on the host: each is checked
/// against the set's layout (consecutive bindings included), and the layer names the
/// same rule for the unchecked call.
#[test]
fn descriptor_updates_stay_inside_their_sets() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let uniform = vk::DescriptorType::UNIFORM_BUFFER;
    let storage = vk::DescriptorType::STORAGE_BUFFER;
    let stages = vk::ShaderStageFlags::COMPUTE;
    let binding = |n, ty, count| {
        tuff::DescriptorSetLayoutBinding::new()
            .binding(n)
            .descriptor_type(ty)
            .descriptor_count(count)
            .stage_flags(stages)
    };
    // Bindings 0 (two uniform buffers), 1 (none), 2 (one, alike: a write may run
    // on from 0 into it, skipping 1) and 3 (a storage buffer).
    let bindings = [
        binding(0, uniform, 2),
        binding(1, uniform, 0),
        binding(2, uniform, 1),
        binding(3, storage, 2),
    ];
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let sizes = [
        vk::DescriptorPoolSize {
            ty: uniform,
            descriptor_count: 6,
        },
        vk::DescriptorPoolSize {
            ty: storage,
            descriptor_count: 4,
        },
    ];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(2)
                .pool_sizes(&sizes),
        )
        .expect("pool");
    let layouts = tuff::HandleSlice::new(&[&set_layout, &set_layout]);
    let mut sets = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layouts),
        )
        .expect("sets");
    let (b, a) = (sets.pop().expect("two"), sets.pop().expect("two"));
    let usage = vk::BufferUsageFlags::UNIFORM_BUFFER | vk::BufferUsageFlags::STORAGE_BUFFER;
    let (buffer, _memory) = host_buffer(&s, 1024, usage);
    let info = |n: usize| {
        vec![
            tuff::DescriptorBufferInfo::new()
                .buffer(Some(&buffer))
                .range(64);
            n
        ]
    };
    let (one, two) = (info(1), info(2));
    fn write<'a>(
        set: &'a tuff::DescriptorSet,
        binding: u32,
        element: u32,
        ty: vk::DescriptorType,
        infos: &'a [tuff::DescriptorBufferInfo<'a>],
    ) -> tuff::WriteDescriptorSet<'a> {
        tuff::WriteDescriptorSet::new(set)
            .dst_binding(binding)
            .dst_array_element(element)
            .descriptor_type(ty)
            .buffer_info(infos)
    }
    let writes = [
        (
            "VUID-VkWriteDescriptorSet-dstBinding-00315",
            write(&a, 5, 0, uniform, &one),
        ),
        (
            "VUID-VkWriteDescriptorSet-dstBinding-00316",
            write(&a, 1, 0, uniform, &one),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00319",
            write(&a, 0, 0, storage, &one),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorCount-00317",
            write(&a, 2, 0, uniform, &two),
        ),
        (
            "VUID-VkWriteDescriptorSet-dstArrayElement-00321",
            write(&a, 3, 1, storage, &two),
        ),
    ];
    let copy =
        |src_binding: u32, src_element: u32, dst_binding: u32, dst_element: u32, count: u32| {
            tuff::CopyDescriptorSet::new(&a, &b)
                .src_binding(src_binding)
                .src_array_element(src_element)
                .dst_binding(dst_binding)
                .dst_array_element(dst_element)
                .descriptor_count(count)
        };
    let copies = [
        (
            "VUID-VkCopyDescriptorSet-srcBinding-00345",
            copy(5, 0, 0, 0, 1),
        ),
        (
            "VUID-VkCopyDescriptorSet-dstBinding-00347",
            copy(0, 0, 7, 0, 1),
        ),
        (
            "VUID-VkCopyDescriptorSet-srcArrayElement-00346",
            copy(3, 1, 3, 0, 2),
        ),
        (
            "VUID-VkCopyDescriptorSet-dstArrayElement-00348",
            copy(3, 0, 3, 1, 2),
        ),
        (
            "VUID-VkCopyDescriptorSet-dstBinding-02632",
            copy(0, 0, 3, 0, 1),
        ),
    ];
    for (expected, w) in &writes {
        assert_eq!(vuid(d.update_descriptor_sets(&[*w], &[])), *expected);
    }
    // The writes that set up the copies' sources, then the copies.
    d.update_descriptor_sets(
        &[
            write(&a, 0, 1, uniform, &two),
            write(&a, 0, 0, uniform, &one),
            write(&a, 3, 0, storage, &two),
        ],
        &[],
    )
    .expect("a write running on from binding 0 into binding 2");
    for (expected, c) in &copies {
        assert_eq!(vuid(d.update_descriptor_sets(&[], &[*c])), *expected);
    }
    d.update_descriptor_sets(&[], &[copy(0, 0, 0, 0, 3), copy(3, 0, 3, 0, 2)])
        .expect("copies inside both sets");
    assert_silent(&s.messages);

    s.messages.abort_on_error(true);
    for (expected, w) in &writes {
        // SAFETY: the layer skips the call, which breaks only the rule under test, so
        // the driver never indexes past the set.
        unsafe { d.update_descriptor_sets_unchecked(&[*w], &[]) };
        assert_layer_reports(&s, expected);
    }
    for (expected, c) in &copies {
        // SAFETY: as above.
        unsafe { d.update_descriptor_sets_unchecked(&[], &[*c]) };
        assert_layer_reports(&s, expected);
    }
    s.messages.abort_on_error(false);
}

/// Viewports and scissors past `maxViewports` would be copied past the driver's
/// arrays; without the multiViewport feature only the first is allowed; negative or
/// overflowing scissors are refused too. The layer names the same rule for each
/// unchecked call.
#[test]
fn viewports_and_scissors_stay_inside_max_viewports() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let viewport = vk::Viewport {
        width: 16.0,
        height: 16.0,
        max_depth: 1.0,
        ..Default::default()
    };
    let rect = |x: i32, y: i32, w: u32, h: u32| vk::Rect2D {
        offset: vk::Offset2D { x, y },
        extent: vk::Extent2D {
            width: w,
            height: h,
        },
    };
    type Rec<'r> = tuff::Recorder<'r, tuff::Outside>;
    type Call = Box<dyn Fn(&mut Rec<'_>, bool) -> tuff::Result<()>>;
    type Case = (&'static str, Call);
    let viewports = move |first: u32, n: usize| -> Call {
        Box::new(move |rec: &mut Rec<'_>, unchecked: bool| {
            let v = vec![viewport; n];
            if unchecked {
                // SAFETY: the layer skips the call, which breaks only the rule under
                // test; the command buffer is never submitted.
                unsafe { rec.set_viewport_unchecked(first, &v) }
            } else {
                rec.set_viewport(first, &v)
            }
        })
    };
    let scissors = move |first: u32, r: Vec<vk::Rect2D>| -> Call {
        Box::new(move |rec: &mut Rec<'_>, unchecked: bool| {
            if unchecked {
                // SAFETY: as above.
                unsafe { rec.set_scissor_unchecked(first, &r) }
            } else {
                rec.set_scissor(first, &r)
            }
        })
    };
    let with_count = move |n: usize| -> Call {
        Box::new(move |rec: &mut Rec<'_>, unchecked: bool| {
            let v = vec![viewport; n];
            if unchecked {
                // SAFETY: as above.
                unsafe { rec.set_viewport_with_count_unchecked(&v) }
            } else {
                rec.set_viewport_with_count(&v)
            }
        })
    };
    // Without the multiViewport feature (this setup): one viewport or scissor, the
    // first; the limit itself is tried on a device with the feature below.
    let cases: Vec<Case> = vec![
        ("VUID-vkCmdSetViewport-firstViewport-01224", viewports(1, 1)),
        ("VUID-vkCmdSetViewport-viewportCount-01225", viewports(0, 2)),
        (
            "VUID-vkCmdSetScissor-firstScissor-00593",
            scissors(1, vec![rect(0, 0, 1, 1)]),
        ),
        (
            "VUID-vkCmdSetScissor-scissorCount-00594",
            scissors(0, vec![rect(0, 0, 1, 1); 2]),
        ),
        (
            "VUID-vkCmdSetScissor-x-00595",
            scissors(0, vec![rect(-1, 0, 1, 1)]),
        ),
        (
            "VUID-vkCmdSetScissor-offset-00596",
            scissors(0, vec![rect(i32::MAX, 0, 2, 1)]),
        ),
        (
            "VUID-vkCmdSetScissor-offset-00597",
            scissors(0, vec![rect(0, i32::MAX, 1, 2)]),
        ),
        (
            "VUID-vkCmdSetViewportWithCount-viewportCount-03395",
            with_count(2),
        ),
    ];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, call) in &cases {
        assert_eq!(vuid(call(&mut rec, false)), *expected);
    }
    rec.set_viewport(0, &[viewport]).expect("one viewport");
    rec.set_scissor(0, &[rect(0, 0, 16, 16)])
        .expect("one scissor");
    rec.end().expect("end");
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    for (expected, call) in &cases {
        call(&mut rec, true).expect("recorded");
        assert_layer_reports(&s, expected);
    }
    s.messages.abort_on_error(false);
    rec.end().expect("end");
}

/// The same, on a device with the multiViewport feature: more than one viewport or
/// scissor is allowed, up to `maxViewports`, and one past it is refused.
#[test]
fn viewports_past_max_viewports_are_refused_with_multi_viewport() {
    let _serial = vulkan::serial();
    let features = vk::PhysicalDeviceFeatures {
        multi_viewport: vk::TRUE,
        ..Default::default()
    };
    let s = tuff_setup::setup_with_features(true, features);
    let max = s.physical.get_properties().limits.max_viewports;
    let viewport = vk::Viewport {
        width: 16.0,
        height: 16.0,
        max_depth: 1.0,
        ..Default::default()
    };
    let scissor = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 16,
            height: 16,
        },
    };
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let over = max as usize + 1;
    assert_eq!(
        vuid(rec.set_viewport(1, &vec![viewport; max as usize])),
        "VUID-vkCmdSetViewport-firstViewport-01223"
    );
    assert_eq!(
        vuid(rec.set_scissor(1, &vec![scissor; max as usize])),
        "VUID-vkCmdSetScissor-firstScissor-00592"
    );
    assert_eq!(
        vuid(rec.set_viewport_with_count(&vec![viewport; over])),
        "VUID-vkCmdSetViewportWithCount-viewportCount-03394"
    );
    assert_eq!(
        vuid(rec.set_scissor_with_count(&vec![scissor; over])),
        "VUID-vkCmdSetScissorWithCount-scissorCount-03397"
    );
    rec.set_viewport(0, &vec![viewport; max as usize])
        .expect("every viewport");
    rec.set_scissor(1, &vec![scissor; max as usize - 1])
        .expect("every scissor but the first");
    rec.end().expect("end");
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    // SAFETY: the layer skips each call, which breaks only the rule under test; the
    // command buffer is never submitted.
    unsafe { rec.set_viewport_unchecked(1, &vec![viewport; max as usize]) }.expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdSetViewport-firstViewport-01223");
    // SAFETY: as above.
    unsafe { rec.set_scissor_unchecked(1, &vec![scissor; max as usize]) }.expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdSetScissor-firstScissor-00592");
    // SAFETY: as above.
    unsafe { rec.set_viewport_with_count_unchecked(&vec![viewport; over]) }.expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdSetViewportWithCount-viewportCount-03394");
    // SAFETY: as above.
    unsafe { rec.set_scissor_with_count_unchecked(&vec![scissor; over]) }.expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdSetScissorWithCount-scissorCount-03397");
    s.messages.abort_on_error(false);
    rec.end().expect("end");
}

/// Pipeline creation reads each specialization constant from the data at its map
/// entry, and reads the stages, viewports and scissors through their arrays: an entry
/// outside the data, or a count whose array is NULL (and not dynamic), is refused, and
/// the layer names the same rule for the unchecked call.
#[test]
fn pipeline_creation_reads_inside_its_arrays() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let target = s.color_target(16, vk::ImageUsageFlags::empty());
    // The test pipelines' shaders and the layouts that match their interfaces.
    let p = pipelines::pipelines(&s, &target);
    let (vert, frag, comp) = (&p.vert, &p.frag, &p.comp);
    let (layout, compute_layout) = (&p.graphics_layout, &p.compute_layout);
    let entry = |offset, size| vk::SpecializationMapEntry {
        constant_id: 0,
        offset,
        size,
    };
    let data = [0u8; 4];
    let (past, long) = ([entry(8, 4)], [entry(0, 8)]);
    let specs = [
        (
            "VUID-VkSpecializationInfo-offset-00773",
            tuff::SpecializationInfo::new()
                .map_entries(&past)
                .data(&data),
        ),
        (
            "VUID-VkSpecializationInfo-pMapEntries-00774",
            tuff::SpecializationInfo::new()
                .map_entries(&long)
                .data(&data),
        ),
    ];
    let compute = |spec: &tuff::SpecializationInfo<'_>, unchecked: bool| {
        let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
            .stage(vk::ShaderStageFlags::COMPUTE)
            .module(Some(comp))
            .specialization_info(Some(spec));
        let info = [tuff::ComputePipelineCreateInfo::new(stage, compute_layout)];
        if unchecked {
            // SAFETY: the layer skips the call, which breaks only the rule under test.
            unsafe { d.create_compute_pipelines_unchecked(None, &info) }.map(|_| ())
        } else {
            d.create_compute_pipelines(None, &info).map(|_| ())
        }
    };
    let stages = [
        tuff::PipelineShaderStageCreateInfo::new(c"main")
            .stage(vk::ShaderStageFlags::VERTEX)
            .module(Some(vert)),
        tuff::PipelineShaderStageCreateInfo::new(c"main")
            .stage(vk::ShaderStageFlags::FRAGMENT)
            .module(Some(frag)),
    ];
    let vertex_input = tuff::PipelineVertexInputStateCreateInfo::new();
    let assembly = tuff::PipelineInputAssemblyStateCreateInfo::new()
        .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
    let viewport = tuff::PipelineViewportStateCreateInfo::new()
        .viewport_count(1)
        .scissor_count(1);
    let raster = tuff::PipelineRasterizationStateCreateInfo::new().line_width(1.0);
    let multisample = tuff::PipelineMultisampleStateCreateInfo::new()
        .rasterization_samples(vk::SampleCountFlags::TYPE_1);
    let blend_attachments = [vk::PipelineColorBlendAttachmentState {
        color_write_mask: vk::ColorComponentFlags::RGBA,
        ..Default::default()
    }];
    let blend = tuff::PipelineColorBlendStateCreateInfo::new().attachments(&blend_attachments);
    let only_viewport = [vk::DynamicState::VIEWPORT];
    let only_scissor = [vk::DynamicState::SCISSOR];
    let both = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    let dynamic = |states| tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(states);
    let (dyn_viewport, dyn_scissor, dyn_both) = (
        dynamic(&only_viewport),
        dynamic(&only_scissor),
        dynamic(&both),
    );
    let dynamics = [&dyn_viewport, &dyn_scissor, &dyn_both];
    let graphics = |which: usize, no_stages: bool| {
        let dynamic_state = dynamics[which];
        let info = tuff::GraphicsPipelineCreateInfo::new()
            .stages(&stages)
            .vertex_input_state(Some(&vertex_input))
            .input_assembly_state(Some(&assembly))
            .viewport_state(Some(&viewport))
            .rasterization_state(Some(&raster))
            .multisample_state(Some(&multisample))
            .color_blend_state(Some(&blend))
            .dynamic_state(Some(dynamic_state))
            .layout(Some(layout))
            .render_pass(Some(&target.render_pass))
            .subpass(0);
        if no_stages {
            info.stage_count(1)
        } else {
            info
        }
    };
    let graphics_cases = [
        (
            "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04130",
            graphics(1, false),
        ),
        (
            "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04131",
            graphics(0, false),
        ),
        (
            "VUID-VkGraphicsPipelineCreateInfo-pStages-06600",
            graphics(2, true),
        ),
    ];
    for (expected, spec) in &specs {
        assert_eq!(vuid(compute(spec, false)), *expected);
    }
    for (expected, info) in &graphics_cases {
        assert_eq!(vuid(d.create_graphics_pipelines(None, &[*info])), *expected);
    }
    let inside = [entry(0, 4)];
    let good = tuff::SpecializationInfo::new()
        .map_entries(&inside)
        .data(&data);
    compute(&good, false).expect("a constant inside the data");
    let (_pipelines, r) = d
        .create_graphics_pipelines(None, &[graphics(2, false)])
        .expect("viewports and scissors both dynamic");
    assert_eq!(r, tuff::SuccessOrPipelineCompileRequired::Success);
    assert_silent(&s.messages);

    s.messages.abort_on_error(true);
    for (expected, spec) in &specs {
        assert!(compute(spec, true).is_err(), "the layer skipped the call");
        assert_layer_reports(&s, expected);
    }
    // The layer names these two rules by the VUIDs they had before 1.3 (the same
    // text, renumbered when VIEWPORT_WITH_COUNT joined it).
    let layer_names = [
        "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00747",
        "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00748",
    ];
    for ((_, info), name) in graphics_cases.iter().zip(layer_names) {
        // SAFETY: the layer skips the call, which breaks only the rule under test; the
        // NULL arrays are never read by the driver.
        let r = unsafe { d.create_graphics_pipelines_unchecked(None, &[*info]) };
        assert!(r.is_err(), "the layer skipped the call");
        assert_layer_reports(&s, name);
    }
    s.messages.abort_on_error(false);
}

/// A render pass whose subpasses, dependencies or chained infos name attachments,
/// subpasses or input attachments it does not have, and chained structs whose counts
/// disagree with the struct they extend, would have the driver index past its arrays:
/// each is refused, and the layer names the same rule for the unchecked call.
#[test]
fn indices_and_chained_counts_match_what_they_index() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let attachment = [vk::AttachmentDescription {
        format: vk::Format::R8G8B8A8_UNORM,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::CLEAR,
        final_layout: vk::ImageLayout::GENERAL,
        ..Default::default()
    }];
    let color = |attachment| {
        [vk::AttachmentReference {
            attachment,
            layout: vk::ImageLayout::GENERAL,
        }]
    };
    let (good_ref, bad_ref) = (color(0), color(1));
    let good = [tuff::SubpassDescription::new().color_attachments(&good_ref)];
    let bad = [tuff::SubpassDescription::new().color_attachments(&bad_ref)];
    let dependency = |src, dst| {
        [vk::SubpassDependency {
            src_subpass: src,
            dst_subpass: dst,
            ..Default::default()
        }]
    };
    let (src_past, dst_past) = (dependency(1, 0), dependency(vk::SUBPASS_EXTERNAL, 1));
    let masks = [1u32, 1];
    let aspect = |subpass, input_attachment_index| {
        [vk::InputAttachmentAspectReference {
            subpass,
            input_attachment_index,
            aspect_mask: vk::ImageAspectFlags::COLOR,
        }]
    };
    let (subpass_past, input_past) = (aspect(3, 0), aspect(0, 1));
    let base = || tuff::RenderPassCreateInfo::new().attachments(&attachment);
    let mut multiview = tuff::RenderPassMultiviewCreateInfo::new().view_masks(&masks);
    let mut aspects =
        tuff::RenderPassInputAttachmentAspectCreateInfo::new().aspect_references(&subpass_past);
    let mut inputs =
        tuff::RenderPassInputAttachmentAspectCreateInfo::new().aspect_references(&input_past);
    let cases = [
        (
            "VUID-VkRenderPassCreateInfo-attachment-00834",
            base().subpasses(&bad),
        ),
        (
            "VUID-VkRenderPassCreateInfo-pDependencies-06866",
            base().subpasses(&good).dependencies(&src_past),
        ),
        (
            "VUID-VkRenderPassCreateInfo-pDependencies-06867",
            base().subpasses(&good).dependencies(&dst_past),
        ),
        (
            "VUID-VkRenderPassCreateInfo-pNext-01928",
            base().subpasses(&good).push_next(&mut multiview),
        ),
        (
            "VUID-VkRenderPassCreateInfo-pNext-01926",
            base().subpasses(&good).push_next(&mut aspects),
        ),
        (
            "VUID-VkRenderPassCreateInfo-pNext-01927",
            base().subpasses(&good).push_next(&mut inputs),
        ),
    ];
    for (expected, info) in &cases {
        assert_eq!(vuid(d.create_render_pass(info)), *expected);
    }
    d.create_render_pass(&base().subpasses(&good))
        .expect("a render pass inside its arrays");
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    for (expected, info) in &cases {
        // SAFETY: the layer skips the call, which breaks only the rule under test, so
        // the driver never indexes past the arrays.
        let r = unsafe { d.create_render_pass_unchecked(info) };
        assert!(r.is_err(), "the layer skipped the call");
        assert_layer_reports(&s, expected);
    }
    s.messages.abort_on_error(false);

    // Chained counts: a device-group info with masks for command buffers the batch
    // does not have, a variable-count info with counts for sets not allocated.
    let masks = [1u32];
    let mut group = tuff::DeviceGroupSubmitInfo::new().command_buffer_device_masks(&masks);
    let batch = [tuff::SubmitInfo::new().push_next(&mut group)];
    let done = fence(&s);
    assert_eq!(
        vuid(s.queue.submit(&batch, Some(&done))),
        "VUID-VkDeviceGroupSubmitInfo-commandBufferCount-00083"
    );
    let set_layout = d
        .create_descriptor_set_layout(&tuff::DescriptorSetLayoutCreateInfo::new())
        .expect("set layout");
    let pool = d
        .create_descriptor_pool(&tuff::DescriptorPoolCreateInfo::new().max_sets(1))
        .expect("pool");
    let counts = [1u32, 1];
    let mut variable =
        tuff::DescriptorSetVariableDescriptorCountAllocateInfo::new().descriptor_counts(&counts);
    let allocate = tuff::DescriptorSetAllocateInfo::new(&pool)
        .set_layouts(&set_layout)
        .push_next(&mut variable);
    assert_eq!(
        vuid(d.allocate_descriptor_sets(&pool, &allocate)),
        "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-descriptorSetCount-03045"
    );
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    // SAFETY: the layer skips the call, which breaks only the rule under test.
    let r = unsafe { s.queue.submit_unchecked(&batch, Some(&done)) };
    assert!(r.is_err(), "the layer skipped the call");
    assert_layer_reports(&s, "VUID-VkDeviceGroupSubmitInfo-commandBufferCount-00083");
    // SAFETY: as above.
    let r = unsafe { d.allocate_descriptor_sets_unchecked(&pool, &allocate) };
    assert!(r.is_err(), "the layer skipped the call");
    assert_layer_reports(
        &s,
        "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-descriptorSetCount-03045",
    );
    s.messages.abort_on_error(false);
}

/// A dispatch with no compute pipeline bound (the safe call that crashed lavapipe),
/// or with no set bound where the pipeline's layout has one, and a pipeline bound at
/// a bind point of the other kind, are refused; the recorder goes on and a correct
/// dispatch runs. The layer names the same rules for the unchecked calls, which it
/// then skips.
#[test]
fn draws_and_dispatches_need_their_pipeline_and_sets() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(16, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let compute = vk::PipelineBindPoint::COMPUTE;
    let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    assert_eq!(vuid(rec.dispatch(1, 1, 1)), "VUID-vkCmdDispatch-None-02700");
    assert_eq!(
        vuid(rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &p.compute)),
        "VUID-vkCmdBindPipeline-pipelineBindPoint-00780"
    );
    assert_eq!(
        vuid(rec.bind_pipeline(compute, &p.graphics)),
        "VUID-vkCmdBindPipeline-pipelineBindPoint-00779"
    );
    rec.bind_pipeline(compute, &p.compute).expect("bind");
    assert_eq!(vuid(rec.dispatch(1, 1, 1)), "VUID-vkCmdDispatch-None-02697");
    rec.bind_descriptor_sets(compute, &p.compute_layout, 0, &p.set, &[])
        .expect("sets");
    rec.dispatch(1, 1, 1)
        .expect("a dispatch with its pipeline and set");
    rec.end().expect("end");
    let done = fence(&s);
    submit(&s, &[&cb], &done).expect("submit");
    wait(&s, &done);
    assert_silent(&s.messages);

    s.messages.abort_on_error(true);
    let mut cb = s
        .device
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1),
        )
        .expect("command buffer")
        .pop()
        .expect("one");
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    // SAFETY: the layer skips each call, which breaks only the rule under test; the
    // command buffer is never submitted.
    unsafe { rec.dispatch_unchecked(1, 1, 1) }.expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdDispatch-None-02700");
    // SAFETY: as above.
    unsafe { rec.bind_pipeline_unchecked(vk::PipelineBindPoint::GRAPHICS, &p.compute) }
        .expect("recorded");
    // The layer labels these two rules by the pipeline's kind rather than the bind
    // point, so each call is reported under the other's VUID.
    assert_layer_reports(&s, "VUID-vkCmdBindPipeline-pipelineBindPoint-00779");
    // SAFETY: as above.
    unsafe { rec.bind_pipeline_unchecked(compute, &p.graphics) }.expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdBindPipeline-pipelineBindPoint-00780");
    rec.bind_pipeline(compute, &p.compute).expect("bind");
    // SAFETY: as above.
    unsafe { rec.dispatch_unchecked(1, 1, 1) }.expect("recorded");
    assert_layer_reports(&s, "VUID-vkCmdDispatch-None-02697");
    s.messages.abort_on_error(false);
    rec.end().expect("end");
}

/// Every draw and dispatch command refuses to record with no pipeline bound, and the
/// dispatches with no set bound where the layout has one; the layer names the same
/// rules for the unchecked calls.
#[test]
fn every_draw_and_dispatch_needs_a_bound_pipeline() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(16, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _memory) = host_buffer(&s, 256, usage);
    type Inside<'r> = tuff::Recorder<'r, tuff::InRenderPass>;
    type Outside<'r> = tuff::Recorder<'r, tuff::Outside>;
    type DrawCall<'a> = Box<dyn Fn(&mut Inside<'_>, bool) -> tuff::Result<()> + 'a>;
    type DispatchCall<'a> = Box<dyn Fn(&mut Outside<'_>, bool) -> tuff::Result<()> + 'a>;
    macro_rules! call {
        ($rec:ident, $unchecked:ident, $f:ident, $g:ident ($($a:expr),*)) => {
            if $unchecked {
                // SAFETY: the layer skips the call, which breaks only the rule under
                // test; the command buffer is never submitted.
                unsafe { $rec.$g($($a),*) }
            } else {
                #[allow(unused_unsafe)]
                unsafe { $rec.$f($($a),*) }
            }
        };
    }
    let a = &args;
    let draws: Vec<(&str, DrawCall<'_>)> = vec![
        (
            "VUID-vkCmdDraw-None-02700",
            Box::new(|r, u| call!(r, u, draw, draw_unchecked(3, 1, 0, 0))),
        ),
        (
            "VUID-vkCmdDrawIndexed-None-02700",
            Box::new(|r, u| call!(r, u, draw_indexed, draw_indexed_unchecked(3, 1, 0, 0, 0))),
        ),
        (
            "VUID-vkCmdDrawIndirect-None-02700",
            Box::new(move |r, u| call!(r, u, draw_indirect, draw_indirect_unchecked(a, 0, 1, 16))),
        ),
        (
            "VUID-vkCmdDrawIndexedIndirect-None-02700",
            Box::new(move |r, u| {
                call!(
                    r,
                    u,
                    draw_indexed_indirect,
                    draw_indexed_indirect_unchecked(a, 0, 1, 20)
                )
            }),
        ),
        (
            "VUID-vkCmdDrawIndirectCount-None-02700",
            Box::new(move |r, u| {
                call!(
                    r,
                    u,
                    draw_indirect_count,
                    draw_indirect_count_unchecked(a, 0, a, 64, 1, 16)
                )
            }),
        ),
        (
            "VUID-vkCmdDrawIndexedIndirectCount-None-02700",
            Box::new(move |r, u| {
                call!(
                    r,
                    u,
                    draw_indexed_indirect_count,
                    draw_indexed_indirect_count_unchecked(a, 0, a, 64, 1, 20)
                )
            }),
        ),
    ];
    let dispatches: Vec<(&str, DispatchCall<'_>)> = vec![
        (
            "Dispatch",
            Box::new(|r, u| call!(r, u, dispatch, dispatch_unchecked(1, 1, 1))),
        ),
        (
            "DispatchIndirect",
            Box::new(move |r, u| call!(r, u, dispatch_indirect, dispatch_indirect_unchecked(a, 0))),
        ),
        (
            "DispatchBase",
            Box::new(|r, u| {
                call!(
                    r,
                    u,
                    dispatch_base,
                    dispatch_base_unchecked(0, 0, 0, 1, 1, 1)
                )
            }),
        ),
    ];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: 16,
                height: 16,
            },
        });
    let clear = [vk::ClearValue::default()];
    let begin = begin.clear_values(&clear);
    let viewport = vk::Viewport {
        width: 16.0,
        height: 16.0,
        max_depth: 1.0,
        ..Default::default()
    };
    let scissor = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 16,
            height: 16,
        },
    };
    let empty = s
        .device
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new())
        .expect("layout");
    // A pipeline whose vertex shader reads two attributes from binding 0.
    let vertex_pipeline = pipelines::vertex_pipeline(&s, &empty, &target.render_pass);
    let (vertices, _vertex_memory) = host_buffer(&s, 60, vk::BufferUsageFlags::VERTEX_BUFFER);
    // A pipeline whose vertex shader reads a storage buffer of set 0.
    let set_vert = tuff_setup::shader(&s, include_bytes!("../shaders/spv/bezier.vert.spv"));
    let set_stages = pipelines::test_stages(&set_vert, &p.frag);
    let set_binding = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::VERTEX)];
    let set_layout = s
        .device
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&set_binding),
        )
        .expect("set layout");
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let push = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::FRAGMENT,
        offset: 0,
        size: 16,
    }];
    let set_pipeline_layout = s
        .device
        .create_pipeline_layout(
            &tuff::PipelineLayoutCreateInfo::new()
                .set_layouts(&set_layouts)
                .push_constant_ranges(&push),
        )
        .expect("layout");
    let (mut set_pipeline, _) = pipelines::with_graphics_info(
        &set_stages,
        &set_pipeline_layout,
        &target.render_pass,
        |info| s.device.create_graphics_pipelines(None, &[info]),
    )
    .expect("pipeline with a set");
    let set_pipeline = set_pipeline.pop().expect("one pipeline");
    for unchecked in [false, true] {
        s.messages.abort_on_error(unchecked);
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        for (name, dispatch) in &dispatches {
            let no_pipeline = format!("VUID-vkCmd{name}-None-02700");
            if unchecked {
                dispatch(&mut rec, true).expect("recorded");
                assert_layer_reports(&s, &no_pipeline);
            } else {
                assert_eq!(vuid(dispatch(&mut rec, false)), no_pipeline);
            }
        }
        rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &p.compute)
            .expect("bind");
        for (name, dispatch) in &dispatches {
            let no_set = format!("VUID-vkCmd{name}-None-02697");
            if unchecked {
                dispatch(&mut rec, true).expect("recorded");
                assert_layer_reports(&s, &no_set);
            } else {
                assert_eq!(vuid(dispatch(&mut rec, false)), no_set);
            }
        }
        let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
        for (expected, draw) in &draws {
            if unchecked {
                draw(&mut rec, true).expect("recorded");
                assert_layer_reports(&s, expected);
            } else {
                assert_eq!(vuid(draw(&mut rec, false)), *expected);
            }
        }
        // With the graphics pipeline bound: indexed draws need an index buffer, and a
        // direct one reads only indices inside it.
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &p.graphics)
            .expect("bind");
        rec.set_viewport(0, &[viewport]).expect("viewport");
        rec.set_scissor(0, &[scissor]).expect("scissor");
        pipelines::push_color(&mut rec, &p);
        let no_index: [(&str, &DrawCall<'_>); 3] = [
            ("VUID-vkCmdDrawIndexed-None-07312", &draws[1].1),
            ("VUID-vkCmdDrawIndexedIndirect-None-07312", &draws[3].1),
            ("VUID-vkCmdDrawIndexedIndirectCount-None-07312", &draws[5].1),
        ];
        for (expected, draw) in no_index {
            if unchecked {
                draw(&mut rec, true).expect("recorded");
                assert_layer_reports(&s, expected);
            } else {
                assert_eq!(vuid(draw(&mut rec, false)), expected);
            }
        }
        rec.bind_index_buffer(&args, 0, vk::IndexType::UINT32)
            .expect("index buffer");
        // 65 indices of 4 bytes from a buffer of 256.
        let past = "VUID-vkCmdDrawIndexed-robustBufferAccess2-07825";
        if unchecked {
            // SAFETY: as above.
            unsafe { rec.draw_indexed_unchecked(65, 1, 0, 0, 0) }.expect("recorded");
            assert_layer_reports(&s, past);
        } else {
            assert_eq!(vuid(rec.draw_indexed(65, 1, 0, 0, 0)), past);
        }
        // A pipeline whose vertex shader reads set 0, with no set bound: every draw
        // is refused.
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &set_pipeline)
            .expect("bind");
        for (no_pipeline, draw) in &draws {
            let expected = no_pipeline.replace("02700", "02697");
            if unchecked {
                draw(&mut rec, true).expect("recorded");
                assert_layer_reports(&s, &expected);
            } else {
                assert_eq!(vuid(draw(&mut rec, false)), expected);
            }
        }
        // A pipeline whose vertex shader reads binding 0, with no vertex buffer
        // bound: every draw is refused, and accepted once one is.
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &vertex_pipeline)
            .expect("bind");
        for (no_pipeline, draw) in &draws {
            let expected = no_pipeline.replace("02700", "04007");
            if unchecked {
                draw(&mut rec, true).expect("recorded");
                assert_layer_reports(&s, &expected);
            } else {
                assert_eq!(vuid(draw(&mut rec, false)), expected);
            }
        }
        s.messages.abort_on_error(false);
        if !unchecked {
            rec.bind_vertex_buffers(0, &vertices, &[0])
                .expect("vertex buffer");
            rec.draw(3, 1, 0, 0)
                .expect("a draw with its vertex buffer bound");
            // The same state with more vertices than the buffer holds: the draw's
            // ranges are checked again, not taken from the draw before.
            assert_eq!(vuid(rec.draw(1000, 1, 0, 0)), "VUID-vkCmdDraw-None-02721");
            rec.draw(3, 1, 0, 0).expect("the first draw again");
        }
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &p.graphics)
            .expect("bind");
        if !unchecked {
            let color = [0u8; 16];
            rec.push_constants(
                &p.graphics_layout,
                vk::ShaderStageFlags::FRAGMENT,
                0,
                &color,
            )
            .expect("push");
            rec.draw_indexed(64, 1, 0, 0, 0)
                .expect("64 indices inside the buffer");
            // One index more on the same state: checked again.
            assert_eq!(vuid(rec.draw_indexed(65, 1, 0, 0, 0)), past);
            rec.draw_indexed(64, 1, 0, 0, 0)
                .expect("the draw inside the buffer again");
        }
        rec.end_render_pass().end().expect("end");
        if !unchecked {
            assert_silent(&s.messages);
        }
    }
}

/// A pipeline whose layout lacks what its shader reads would have the driver index
/// past its descriptor tables (lavapipe crashes on a dispatch of one): tuff refuses
/// the compute pipeline whose layout has no set for the shader's bindings, a binding
/// visible to another stage only, or one of the wrong descriptor type, and the
/// graphics pipeline whose layout has no push-constant range for its fragment shader
/// or one too short, and the layer names the same rule for each unchecked call (which
/// it then skips).
#[test]
fn a_pipeline_layout_must_have_what_its_shaders_read() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let comp = tuff_setup::shader(&s, include_bytes!("../shaders/spv/test.comp.spv"));
    let empty = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new())
        .expect("empty layout");
    let stage = || {
        tuff::PipelineShaderStageCreateInfo::new(c"main")
            .stage(vk::ShaderStageFlags::COMPUTE)
            .module(Some(&comp))
    };
    let compute = [tuff::ComputePipelineCreateInfo::new(stage(), &empty)];
    assert_eq!(
        vuid(d.create_compute_pipelines(None, &compute)),
        "VUID-VkComputePipelineCreateInfo-layout-00703"
    );
    // A stage without a module: no code that had the shader promise.
    let no_module = [tuff::ComputePipelineCreateInfo::new(
        stage().module(None),
        &empty,
    )];
    assert_eq!(
        vuid(d.create_compute_pipelines(None, &no_module)),
        "VUID-VkPipelineShaderStageCreateInfo-module-06716"
    );
    // A one-set layout whose bindings 0 and 1 have these types and stages.
    let layout_of = |types: [vk::DescriptorType; 2], stages: vk::ShaderStageFlags| {
        let bindings = [0, 1].map(|binding| {
            tuff::DescriptorSetLayoutBinding::new()
                .binding(binding)
                .descriptor_type(types[binding as usize])
                .descriptor_count(1)
                .stage_flags(stages)
        });
        let set_layout = d
            .create_descriptor_set_layout(
                &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
            )
            .expect("set layout");
        d.create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layout))
            .expect("layout")
    };
    let (uniform, storage) = (
        vk::DescriptorType::UNIFORM_BUFFER,
        vk::DescriptorType::STORAGE_BUFFER,
    );
    // Bindings of the right types but visible to another stage only.
    let vertex_only = layout_of([uniform, storage], vk::ShaderStageFlags::VERTEX);
    let hidden = [tuff::ComputePipelineCreateInfo::new(stage(), &vertex_only)];
    assert_eq!(
        vuid(d.create_compute_pipelines(None, &hidden)),
        "VUID-VkComputePipelineCreateInfo-layout-00703"
    );
    // Visible to the compute stage, but the uniform block's binding holds storage
    // buffers.
    let wrong_type = layout_of([storage, storage], vk::ShaderStageFlags::COMPUTE);
    let mistyped = [tuff::ComputePipelineCreateInfo::new(stage(), &wrong_type)];
    assert_eq!(
        vuid(d.create_compute_pipelines(None, &mistyped)),
        "VUID-VkComputePipelineCreateInfo-layout-00703"
    );
    assert_silent(&s.messages);

    // The graphics pipeline: the test fragment shader pushes 16 bytes.
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let vert = tuff_setup::shader(&s, include_bytes!("../shaders/spv/test.vert.spv"));
    let frag = tuff_setup::shader(&s, include_bytes!("../shaders/spv/test.frag.spv"));
    let stages = pipelines::test_stages(&vert, &frag);
    // A range for the fragment stage, but of 8 of the block's 16 bytes.
    let short = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::FRAGMENT,
        offset: 0,
        size: 8,
    }];
    let short_layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().push_constant_ranges(&short))
        .expect("layout");
    let rp = &target.render_pass;
    for layout in [&empty, &short_layout] {
        pipelines::with_graphics_info(&stages, layout, rp, |info| {
            assert_eq!(
                vuid(d.create_graphics_pipelines(None, &[info])),
                "VUID-VkGraphicsPipelineCreateInfo-layout-00756"
            );
        });
    }
    assert_silent(&s.messages);

    s.messages.abort_on_error(true);
    // SAFETY: the messenger makes the layer skip each call, which breaks only the
    // rule under test.
    drop(unsafe { d.create_compute_pipelines_unchecked(None, &compute) });
    assert_layer_reports(&s, "VUID-VkComputePipelineCreateInfo-layout-00703");
    // SAFETY: as above.
    drop(unsafe { d.create_compute_pipelines_unchecked(None, &mistyped) });
    assert_layer_reports(&s, "VUID-VkComputePipelineCreateInfo-layout-00703");
    for layout in [&empty, &short_layout] {
        pipelines::with_graphics_info(&stages, layout, rp, |info| {
            // SAFETY: as above.
            drop(unsafe { d.create_graphics_pipelines_unchecked(None, &[info]) });
        });
        assert_layer_reports(&s, "VUID-VkGraphicsPipelineCreateInfo-layout-00756");
    }
    s.messages.abort_on_error(false);
}

/// Memory for `reqs` of `size` bytes, of the first type the object allows.
fn memory_for(s: &Setup, reqs: &vk::MemoryRequirements, size: u64) -> tuff::DeviceMemory {
    s.device
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(size)
                .memory_type_index(
                    s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                ),
        )
        .expect("memory")
}

/// Runs `unchecked` with the layer told to skip the erroring call, so the driver
/// never sees it, and fails unless the layer named `vuid`.
fn layer_names(s: &Setup, vuid: &str, unchecked: impl FnOnce()) {
    s.messages.take();
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    assert_layer_reports(s, vuid);
}

/// The ways a safe bind could give a buffer or image memory it does not fit in (an
/// offset past the end, a misaligned offset, too few bytes past the offset) or bind
/// it twice: each is refused with its rule, through `bind_*_memory` and through
/// `bind_*_memory2`, and the layer names the same rule for the unchecked call.
#[test]
fn memory_a_resource_does_not_fit_in_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let buffer = || {
        d.create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(4096)
                .usage(vk::BufferUsageFlags::STORAGE_BUFFER),
        )
        .expect("buffer")
    };
    let image = || {
        d.create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(vk::Format::R8G8B8A8_UNORM)
                .extent(vk::Extent3D {
                    width: 64,
                    height: 64,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(vk::ImageUsageFlags::SAMPLED),
        )
        .expect("image")
    };
    let b = buffer();
    let b_reqs = d.get_buffer_memory_requirements(&b).expect("requirements");
    let i = image();
    let i_reqs = d.get_image_memory_requirements(&i).expect("requirements");
    // (offset, memory size, the rule it breaks), for buffers then images.
    let buffer_cases = [
        (b_reqs.size * 2, b_reqs.size * 2, "memoryOffset-01031"),
        (1, b_reqs.size * 4, "memoryOffset-01036"),
        (0, b_reqs.size / 2, "size-01037"),
    ];
    assert!(
        b_reqs.alignment > 1,
        "the buffer's alignment lets any offset through"
    );
    for (offset, size, rule) in buffer_cases {
        let memory = memory_for(&s, &b_reqs, size);
        let one = format!("VUID-vkBindBufferMemory-{rule}");
        assert_eq!(vuid(d.bind_buffer_memory(&b, &memory, offset)), one);
        let two = format!("VUID-VkBindBufferMemoryInfo-{rule}");
        let infos = [tuff::BindBufferMemoryInfo::new(&b, &memory).memory_offset(offset)];
        assert_eq!(vuid(d.bind_buffer_memory2(&infos)), two);
        assert_silent(&s.messages);
        // SAFETY: the layer skips the call it reports (its messenger says so), so the
        // driver never binds the memory.
        layer_names(&s, &one, || {
            let _ = unsafe { d.bind_buffer_memory_unchecked(&b, &memory, offset) };
        });
        // SAFETY: as above.
        layer_names(&s, &two, || {
            let _ = unsafe { d.bind_buffer_memory2_unchecked(&infos) };
        });
    }
    assert!(
        i_reqs.alignment > 1,
        "the image's alignment lets any offset through"
    );
    let image_cases = [
        (
            i_reqs.size * 2,
            i_reqs.size * 2,
            "memoryOffset-01046",
            "memoryOffset-01046",
        ),
        (1, i_reqs.size * 4, "memoryOffset-01048", "pNext-01616"),
        (0, i_reqs.size / 2, "size-01049", "pNext-01617"),
    ];
    for (offset, size, rule, rule2) in image_cases {
        let memory = memory_for(&s, &i_reqs, size);
        let one = format!("VUID-vkBindImageMemory-{rule}");
        assert_eq!(vuid(d.bind_image_memory(&i, &memory, offset)), one);
        let two = format!("VUID-VkBindImageMemoryInfo-{rule2}");
        let infos = [tuff::BindImageMemoryInfo::new(&i, &memory).memory_offset(offset)];
        assert_eq!(vuid(d.bind_image_memory2(&infos)), two);
        assert_silent(&s.messages);
        // SAFETY: as for the buffer.
        layer_names(&s, &one, || {
            let _ = unsafe { d.bind_image_memory_unchecked(&i, &memory, offset) };
        });
        // SAFETY: as above.
        layer_names(&s, &two, || {
            let _ = unsafe { d.bind_image_memory2_unchecked(&infos) };
        });
    }
    // Bound once, correctly; a second bind of either is refused.
    let b_memory = memory_for(&s, &b_reqs, b_reqs.size);
    d.bind_buffer_memory(&b, &b_memory, 0).expect("bind");
    let i_memory = memory_for(&s, &i_reqs, i_reqs.size);
    d.bind_image_memory(&i, &i_memory, 0).expect("bind");
    assert_silent(&s.messages);
    let again = memory_for(&s, &b_reqs, b_reqs.size);
    assert_eq!(
        vuid(d.bind_buffer_memory(&b, &again, 0)),
        "VUID-vkBindBufferMemory-buffer-07459"
    );
    let infos = [tuff::BindBufferMemoryInfo::new(&b, &again)];
    assert_eq!(
        vuid(d.bind_buffer_memory2(&infos)),
        "VUID-VkBindBufferMemoryInfo-buffer-07459"
    );
    let again_i = memory_for(&s, &i_reqs, i_reqs.size);
    assert_eq!(
        vuid(d.bind_image_memory(&i, &again_i, 0)),
        "VUID-vkBindImageMemory-image-07460"
    );
    let infos_i = [tuff::BindImageMemoryInfo::new(&i, &again_i)];
    assert_eq!(
        vuid(d.bind_image_memory2(&infos_i)),
        "VUID-VkBindImageMemoryInfo-image-07460"
    );
    assert_silent(&s.messages);
    // SAFETY: as above.
    layer_names(&s, "VUID-vkBindBufferMemory-buffer-07459", || {
        let _ = unsafe { d.bind_buffer_memory_unchecked(&b, &again, 0) };
    });
    // SAFETY: as above.
    layer_names(&s, "VUID-VkBindBufferMemoryInfo-buffer-07459", || {
        let _ = unsafe { d.bind_buffer_memory2_unchecked(&infos) };
    });
    // SAFETY: as above.
    layer_names(&s, "VUID-vkBindImageMemory-image-07460", || {
        let _ = unsafe { d.bind_image_memory_unchecked(&i, &again_i, 0) };
    });
    // SAFETY: as above.
    layer_names(&s, "VUID-VkBindImageMemoryInfo-image-07460", || {
        let _ = unsafe { d.bind_image_memory2_unchecked(&infos_i) };
    });
    // One call that binds a fresh buffer twice is refused too (the layer sees the
    // buffer unbound at the first info, so only tuff names it).
    let fresh = buffer();
    let m1 = memory_for(&s, &b_reqs, b_reqs.size);
    let m2 = memory_for(&s, &b_reqs, b_reqs.size);
    let twice = [
        tuff::BindBufferMemoryInfo::new(&fresh, &m1),
        tuff::BindBufferMemoryInfo::new(&fresh, &m2),
    ];
    assert_eq!(
        vuid(d.bind_buffer_memory2(&twice)),
        "VUID-VkBindBufferMemoryInfo-buffer-07459"
    );
    assert_silent(&s.messages);
}

/// An image past what its format allows (its Image Creation Limits, queried from
/// the device, or more levels than its extent has) is refused before the driver
/// sees it, and the layer names the same rule for the unchecked call.
#[test]
fn an_image_past_its_format_limits_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let sampled = vk::ImageUsageFlags::SAMPLED;
    let limits = |ty, tiling| {
        s.physical
            .get_image_format_properties(rgba, ty, tiling, sampled, vk::ImageCreateFlags::empty())
            .expect("image format properties")
    };
    let optimal2d = limits(vk::ImageType::TYPE_2D, vk::ImageTiling::OPTIMAL);
    let optimal3d = limits(vk::ImageType::TYPE_3D, vk::ImageTiling::OPTIMAL);
    let base = || {
        tuff::ImageCreateInfo::new()
            .image_type(vk::ImageType::TYPE_2D)
            .format(rgba)
            .extent(vk::Extent3D {
                width: 4,
                height: 4,
                depth: 1,
            })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .usage(sampled)
    };
    let past = |n: u32| n.checked_add(1).expect("a limit below u32::MAX");
    let mut cases = vec![
        // A 4x4 image has 3 levels.
        (
            base().mip_levels(4),
            "VUID-VkImageCreateInfo-mipLevels-00958",
        ),
        (
            base().extent(vk::Extent3D {
                width: past(optimal2d.max_extent.width),
                height: 1,
                depth: 1,
            }),
            "VUID-VkImageCreateInfo-extent-02252",
        ),
        (
            base().extent(vk::Extent3D {
                width: 1,
                height: past(optimal2d.max_extent.height),
                depth: 1,
            }),
            "VUID-VkImageCreateInfo-extent-02253",
        ),
        (
            base()
                .image_type(vk::ImageType::TYPE_3D)
                .extent(vk::Extent3D {
                    width: 1,
                    height: 1,
                    depth: past(optimal3d.max_extent.depth),
                }),
            "VUID-VkImageCreateInfo-extent-02254",
        ),
        (
            base().array_layers(past(optimal2d.max_array_layers)),
            "VUID-VkImageCreateInfo-arrayLayers-02256",
        ),
        (
            // A color format cannot be a depth attachment.
            base().usage(vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT),
            "VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251",
        ),
    ];
    let unsupported = [
        vk::SampleCountFlags::TYPE_64,
        vk::SampleCountFlags::TYPE_32,
        vk::SampleCountFlags::TYPE_16,
        vk::SampleCountFlags::TYPE_8,
    ]
    .into_iter()
    .find(|c| !optimal2d.sample_counts.contains(*c))
    .expect("a sample count the format does not support");
    cases.push((
        base().samples(unsupported),
        "VUID-VkImageCreateInfo-samples-02258",
    ));
    for (info, rule) in &cases {
        assert_eq!(vuid(d.create_image(info)), *rule, "{rule}");
        assert_silent(&s.messages);
        // SAFETY: the layer skips the call it reports (its messenger says so), so the
        // driver never creates the image.
        layer_names(&s, rule, || {
            let _ = unsafe { d.create_image_unchecked(info) };
        });
    }
    // The same limits allow what they allow: the largest 2D image the format has
    // is accepted (and not bound, so it costs no memory).
    let largest = base()
        .extent(vk::Extent3D {
            width: optimal2d.max_extent.width,
            height: 1,
            depth: 1,
        })
        .mip_levels(32 - optimal2d.max_extent.width.leading_zeros());
    d.create_image(&largest)
        .expect("the largest image the limits allow");
    assert_silent(&s.messages);
}

/// A recorded call over a recorder outside a render pass.
type RecordCall<'a> = Box<dyn Fn(&mut tuff::Recorder<'_, tuff::Outside>) -> tuff::Result<()> + 'a>;

/// A buffer-image copy whose regions reach past the buffer (an offset, a row length
/// or an image height that moves the last texel past its end) would have the
/// device read or write outside it: each is refused through all four commands, and
/// the layer names the same rule for the unchecked call.
#[test]
fn a_buffer_image_copy_past_the_buffer_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    // 4x4 RGBA8 texels are 64 bytes: exactly the buffer.
    let usage = vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST;
    let (buffer, _memory) = host_buffer(&s, 64, usage);
    let image = d
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(vk::Format::R8G8B8A8_UNORM)
                .extent(vk::Extent3D {
                    width: 4,
                    height: 4,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST),
        )
        .expect("image");
    let _image_memory = s.bind_image(&image);
    let layer = vk::ImageSubresourceLayers {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        mip_level: 0,
        base_array_layer: 0,
        layer_count: 1,
    };
    let extent = vk::Extent3D {
        width: 4,
        height: 4,
        depth: 1,
    };
    let region = |offset, row_length, image_height| vk::BufferImageCopy {
        buffer_offset: offset,
        buffer_row_length: row_length,
        buffer_image_height: image_height,
        image_subresource: layer,
        image_offset: vk::Offset3D::default(),
        image_extent: extent,
    };
    // An offset of one texel, rows of 8 texels; and, as a control, the exact fit
    // with an image height of 8 (it only spaces slices, and there is one).
    let past = [region(4, 0, 0), region(0, 8, 0)];
    let fits = region(0, 0, 8);
    let to_image = "VUID-vkCmdCopyBufferToImage-pRegions-00171";
    let to_buffer = "VUID-vkCmdCopyImageToBuffer-pRegions-00183";
    let to_image2 = "VUID-VkCopyBufferToImageInfo2-pRegions-00171";
    let to_buffer2 = "VUID-VkCopyImageToBufferInfo2-pRegions-00183";
    let dst = vk::ImageLayout::TRANSFER_DST_OPTIMAL;
    let src = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
    let region2 = |r: &vk::BufferImageCopy| {
        tuff::BufferImageCopy2::new()
            .buffer_offset(r.buffer_offset)
            .buffer_row_length(r.buffer_row_length)
            .buffer_image_height(r.buffer_image_height)
            .image_subresource(r.image_subresource)
            .image_extent(r.image_extent)
    };
    for r in &past {
        let regions2 = [region2(r)];
        let into = tuff::CopyBufferToImageInfo2::new(&buffer, &image)
            .dst_image_layout(dst)
            .regions(&regions2);
        let out = tuff::CopyImageToBufferInfo2::new(&image, &buffer)
            .src_image_layout(src)
            .regions(&regions2);
        for unchecked in [false, true] {
            let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            if unchecked {
                // SAFETY: the layer skips each call it reports (its messenger says
                // so); the command buffer is never submitted.
                layer_names(&s, to_image, || {
                    let _ =
                        unsafe { rec.copy_buffer_to_image_unchecked(&buffer, &image, dst, &[*r]) };
                });
                // SAFETY: as above.
                layer_names(&s, to_buffer, || {
                    let _ =
                        unsafe { rec.copy_image_to_buffer_unchecked(&image, src, &buffer, &[*r]) };
                });
                // SAFETY: as above.
                layer_names(&s, to_image2, || {
                    let _ = unsafe { rec.copy_buffer_to_image2_unchecked(&into) };
                });
                // SAFETY: as above.
                layer_names(&s, to_buffer2, || {
                    let _ = unsafe { rec.copy_image_to_buffer2_unchecked(&out) };
                });
                rec.end().expect("end");
            } else {
                // A refused copy is not recorded, and the recording goes on.
                assert_eq!(
                    vuid(rec.copy_buffer_to_image(&buffer, &image, dst, &[*r])),
                    to_image
                );
                rec.end().expect("end");
                let calls: [(&str, RecordCall<'_>); 3] = [
                    (
                        to_buffer,
                        Box::new(|rec| rec.copy_image_to_buffer(&image, src, &buffer, &[*r])),
                    ),
                    (to_image2, Box::new(|rec| rec.copy_buffer_to_image2(&into))),
                    (to_buffer2, Box::new(|rec| rec.copy_image_to_buffer2(&out))),
                ];
                for (expected, call) in calls {
                    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
                    let mut rec = cb
                        .begin(&tuff::CommandBufferBeginInfo::new())
                        .expect("begin");
                    assert_eq!(vuid(call(&mut rec)), expected);
                    rec.end().expect("end");
                }
            }
        }
    }
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.copy_image_to_buffer(&image, src, &buffer, &[fits])
        .expect("a region that fills the buffer exactly");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// A pipeline layout past the device's descriptor limits (per stage, or across all
/// stages of its set layouts), with more set layouts than can be bound, or with two
/// push-constant ranges for one stage is refused, and the layer names the same rule
/// for the unchecked call. Each case is sized from the device's own limits.
#[test]
fn a_pipeline_layout_past_the_descriptor_limits_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let l = s.physical.get_properties().limits;
    let mut p12 = vk::PhysicalDeviceVulkan12Properties::default();
    let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(&mut p12);
    // SAFETY: a live physical device of a Vulkan 1.3 instance; the chain is local.
    unsafe {
        s.instance
            .fns()
            .get_physical_device_properties2(*s.physical, &mut p2)
    };
    let (dyn_ubo, dyn_ssbo) = (
        p12.max_descriptor_set_update_after_bind_uniform_buffers_dynamic,
        p12.max_descriptor_set_update_after_bind_storage_buffers_dynamic,
    );
    use vk::DescriptorType as T;
    let compute = vk::ShaderStageFlags::COMPUTE;
    let fragment = vk::ShaderStageFlags::FRAGMENT;
    // (descriptor type, count, stage, the rule): one binding of `count` descriptors.
    let mut cases = vec![
        (
            T::SAMPLER,
            l.max_per_stage_descriptor_samplers + 1,
            compute,
            "descriptorType-03016",
        ),
        (
            T::UNIFORM_BUFFER,
            l.max_per_stage_descriptor_uniform_buffers + 1,
            compute,
            "descriptorType-03017",
        ),
        (
            T::STORAGE_BUFFER,
            l.max_per_stage_descriptor_storage_buffers + 1,
            compute,
            "descriptorType-03018",
        ),
        (
            T::SAMPLED_IMAGE,
            l.max_per_stage_descriptor_sampled_images + 1,
            compute,
            "descriptorType-03019",
        ),
        (
            T::STORAGE_IMAGE,
            l.max_per_stage_descriptor_storage_images + 1,
            compute,
            "descriptorType-03020",
        ),
        (
            T::INPUT_ATTACHMENT,
            l.max_per_stage_descriptor_input_attachments + 1,
            fragment,
            "descriptorType-03021",
        ),
        (
            T::SAMPLER,
            l.max_descriptor_set_samplers + 1,
            compute,
            "descriptorType-03028",
        ),
        (
            T::UNIFORM_BUFFER,
            l.max_descriptor_set_uniform_buffers + 1,
            compute,
            "descriptorType-03029",
        ),
        (
            T::UNIFORM_BUFFER_DYNAMIC,
            l.max_descriptor_set_uniform_buffers_dynamic + 1,
            compute,
            "descriptorType-03030",
        ),
        (
            T::STORAGE_BUFFER,
            l.max_descriptor_set_storage_buffers + 1,
            compute,
            "descriptorType-03031",
        ),
        (
            T::STORAGE_BUFFER_DYNAMIC,
            l.max_descriptor_set_storage_buffers_dynamic + 1,
            compute,
            "descriptorType-03032",
        ),
        (
            T::SAMPLED_IMAGE,
            l.max_descriptor_set_sampled_images + 1,
            compute,
            "descriptorType-03033",
        ),
        (
            T::STORAGE_IMAGE,
            l.max_descriptor_set_storage_images + 1,
            compute,
            "descriptorType-03034",
        ),
        (
            T::INPUT_ATTACHMENT,
            l.max_descriptor_set_input_attachments + 1,
            fragment,
            "descriptorType-03035",
        ),
    ];
    // Where the update-after-bind limit on dynamic buffers is the smaller one (as on
    // lavapipe), a layout past it is within the others' set-wide limits.
    if dyn_ubo < l.max_descriptor_set_uniform_buffers_dynamic {
        cases.push((
            T::UNIFORM_BUFFER_DYNAMIC,
            dyn_ubo + 1,
            compute,
            "pSetLayouts-03038",
        ));
    }
    if dyn_ssbo < l.max_descriptor_set_storage_buffers_dynamic {
        cases.push((
            T::STORAGE_BUFFER_DYNAMIC,
            dyn_ssbo + 1,
            compute,
            "pSetLayouts-03040",
        ));
    }
    assert_eq!(
        cases.len(),
        16,
        "the device's update-after-bind limits on dynamic buffers are not the smaller ones"
    );
    for (ty, count, stage, rule) in cases {
        let rule = format!("VUID-VkPipelineLayoutCreateInfo-{rule}");
        let bindings = [tuff::DescriptorSetLayoutBinding::new()
            .binding(0)
            .descriptor_type(ty)
            .descriptor_count(count)
            .stage_flags(stage)];
        let set_layout = d
            .create_descriptor_set_layout(
                &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
            )
            .expect("set layout");
        let info = tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layout);
        assert_eq!(vuid(d.create_pipeline_layout(&info)), rule, "{rule}");
        assert_silent(&s.messages);
        // SAFETY: the layer skips the call it reports, so the driver never sees it.
        layer_names(&s, &rule, || {
            let _ = unsafe { d.create_pipeline_layout_unchecked(&info) };
        });
    }
    // More set layouts than can be bound at once.
    let empty = d
        .create_descriptor_set_layout(&tuff::DescriptorSetLayoutCreateInfo::new())
        .expect("set layout");
    let many: Vec<&tuff::DescriptorSetLayout> =
        (0..=l.max_bound_descriptor_sets).map(|_| &empty).collect();
    let layouts = tuff::HandleSlice::new(&many);
    let info = tuff::PipelineLayoutCreateInfo::new().set_layouts(&layouts);
    let rule = "VUID-VkPipelineLayoutCreateInfo-setLayoutCount-00286";
    assert_eq!(vuid(d.create_pipeline_layout(&info)), rule);
    // SAFETY: as above.
    layer_names(&s, rule, || {
        let _ = unsafe { d.create_pipeline_layout_unchecked(&info) };
    });
    // Two push-constant ranges for one stage.
    let ranges = [
        vk::PushConstantRange {
            stage_flags: compute,
            offset: 0,
            size: 4,
        },
        vk::PushConstantRange {
            stage_flags: compute | fragment,
            offset: 4,
            size: 4,
        },
    ];
    let info = tuff::PipelineLayoutCreateInfo::new().push_constant_ranges(&ranges);
    let rule = "VUID-VkPipelineLayoutCreateInfo-pPushConstantRanges-00292";
    assert_eq!(vuid(d.create_pipeline_layout(&info)), rule);
    // SAFETY: as above.
    layer_names(&s, rule, || {
        let _ = unsafe { d.create_pipeline_layout_unchecked(&info) };
    });
    // At the limits, a layout is accepted.
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(T::UNIFORM_BUFFER)
        .descriptor_count(l.max_per_stage_descriptor_uniform_buffers)
        .stage_flags(compute)];
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    d.create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layout))
        .expect("a layout at the per-stage limit");
    assert_silent(&s.messages);
}

/// A command pool for a queue family the device has no queue of, or a protected pool
/// without the protectedMemory feature, is refused before Vulkan sees it (the driver
/// would hand out command buffers no queue can run), and the layer names the same
/// rules for the `_unchecked` call.
#[test]
fn a_command_pool_the_device_cannot_use_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let families = s
        .physical
        .get_queue_family_properties()
        .expect("queue families")
        .len();
    let other = u32::try_from(families).expect("few families");
    let cases = [
        (
            tuff::CommandPoolCreateInfo::new().queue_family_index(other),
            "VUID-vkCreateCommandPool-queueFamilyIndex-01937",
        ),
        (
            tuff::CommandPoolCreateInfo::new()
                .queue_family_index(s.family)
                .flags(vk::CommandPoolCreateFlags::PROTECTED),
            "VUID-VkCommandPoolCreateInfo-flags-02860",
        ),
    ];
    for (info, expected) in &cases {
        match s.device.create_command_pool(info) {
            Err(tuff::Error::Validation { vuid, .. }) => assert_eq!(vuid, *expected),
            Err(other) => panic!("expected {expected}, got {other}"),
            Ok(_) => panic!("a pool breaking {expected} was made"),
        }
    }
    let pool = s
        .device
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
        .expect("a pool of the device's queue family");
    drop(pool);
    assert_silent(&s.messages);

    s.messages.abort_on_error(true);
    for (info, expected) in &cases {
        // SAFETY: the messenger makes the layer skip the call, which breaks only the
        // rule under test.
        let made = unsafe { s.device.create_command_pool_unchecked(info) };
        assert!(
            made.is_err(),
            "the layer let a pool breaking {expected} through"
        );
        assert_layer_reports(&s, expected);
    }
    s.messages.abort_on_error(false);
}
