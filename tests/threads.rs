//! Recording on threads. Without the `multi_thread` feature the wrappers share their
//! state through `Rc` and no wrapper crosses a thread (`compile_fail/
//! handle_across_threads.rs`); with it, every wrapper is `Send` and `Sync`, and a
//! recorder stays on the thread that began it (it holds its pool's lock, which that
//! thread took: `compile_fail/recorder_across_threads.rs`). This file runs in the
//! test command's `multi_thread` pass: workers record secondaries from their own
//! pools at once, one primary executes them, and the frame runs with the layer (and
//! its synchronization validation) silent.

#[cfg(feature = "multi_thread")]
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[cfg(feature = "multi_thread")]
#[path = "common/vulkan.rs"]
mod vulkan;

#[cfg(feature = "multi_thread")]
mod threaded {
    use super::{tuff_setup, vulkan};
    use tuff::vk;

    fn send_sync<T: Send + Sync>() {}

    /// What a worker needs crosses threads: the device and queue, pools and their
    /// buffers, resources and what retains them, the frame ring and the message log.
    #[test]
    fn wrappers_are_send_and_sync_with_multi_thread() {
        send_sync::<tuff::Instance>();
        send_sync::<tuff::Device>();
        send_sync::<tuff::Queue>();
        send_sync::<tuff::CommandPool>();
        send_sync::<tuff::CommandBuffer>();
        send_sync::<tuff::Buffer>();
        send_sync::<tuff::Image>();
        send_sync::<tuff::Pipeline>();
        send_sync::<tuff::DescriptorSet>();
        send_sync::<tuff::RenderPass>();
        send_sync::<tuff::Framebuffer>();
        send_sync::<tuff::Bound<tuff::Buffer>>();
        send_sync::<tuff::IndirectBuffer<vk::DrawIndirectCommand>>();
        send_sync::<tuff::MessageLog>();
    }

    /// Records each of `secondaries` on a thread of its own, all at once: a
    /// secondary that continues `target`'s render pass instance and sets a viewport.
    fn record_workers<'a>(
        target: &tuff_setup::ColorTarget,
        secondaries: impl Iterator<Item = &'a mut tuff::CommandBuffer>,
    ) {
        std::thread::scope(|scope| {
            for secondary in secondaries {
                scope.spawn(move || {
                    let inheritance = tuff::CommandBufferInheritanceInfo::new()
                        .render_pass(Some(&target.render_pass))
                        .framebuffer(Some(&target.framebuffer));
                    let info = tuff::CommandBufferBeginInfo::new()
                        .flags(vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE)
                        .inheritance_info(Some(&inheritance));
                    let mut rec = secondary.begin_continuing(&info).expect("begin");
                    rec.set_viewport(
                        0,
                        &[vk::Viewport {
                            width: 8.0,
                            height: 8.0,
                            max_depth: 1.0,
                            ..Default::default()
                        }],
                    )
                    .expect("viewport");
                    rec.end().expect("end");
                });
            }
        });
    }

    /// Records `primary`: `target`'s render pass instance executing `secondaries`.
    fn execute_workers(
        primary: &mut tuff::CommandBuffer,
        target: &tuff_setup::ColorTarget,
        secondaries: &[&tuff::CommandBuffer],
    ) {
        let area = vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: 8,
                height: 8,
            },
        };
        let clear = [vk::ClearValue::default()];
        let rec = primary
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let mut rec = rec.begin_render_pass(
            &tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
                .render_area(area)
                .clear_values(&clear),
            vk::SubpassContents::SECONDARY_COMMAND_BUFFERS,
        );
        rec.execute_commands(&tuff::HandleSlice::new(secondaries))
            .expect("the workers' secondaries");
        rec.end_render_pass().end().expect("end");
    }

    /// Four workers, each with its own pool, record a secondary that continues the
    /// primary's render pass instance, all at once; the primary executes the four,
    /// and the frame runs twice (the second after recording every buffer again).
    #[test]
    fn workers_record_secondaries_a_primary_executes() {
        let _serial = vulkan::serial();
        let s = tuff_setup::setup(true);
        let target = s.color_target(8, vk::ImageUsageFlags::empty());
        let mut workers: Vec<(tuff::CommandPool, tuff::CommandBuffer)> = (0..4)
            .map(|_| s.command_buffer(vk::CommandBufferLevel::SECONDARY))
            .collect();
        let (_pool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        for _frame in 0..2 {
            record_workers(&target, workers.iter_mut().map(|(_, cb)| cb));
            let secondaries: Vec<&tuff::CommandBuffer> = workers.iter().map(|(_, cb)| cb).collect();
            execute_workers(&mut primary, &target, &secondaries);
            s.submit_wait(&primary);
        }
        vulkan::assert_silent(&s.messages);
    }

    /// The frame ring with worker secondaries: two frames in flight, four workers
    /// each recording their frame's secondary on a thread of their own, the
    /// primary executing them; six frames, the layer silent. Each frame in flight
    /// renders to its own target: one target would be written by two frames at once
    /// (its render pass's implicit dependency waits for nothing).
    #[test]
    fn frames_in_flight_hand_each_worker_its_secondary() {
        let _serial = vulkan::serial();
        let s = tuff_setup::setup(true);
        let targets = [
            s.color_target(8, vk::ImageUsageFlags::empty()),
            s.color_target(8, vk::ImageUsageFlags::empty()),
        ];
        let mut frames = s
            .device
            .frames_in_flight_with_workers(s.family, 2, 4)
            .expect("frames");
        for _ in 0..6 {
            let mut frame = frames.next_frame().expect("frame");
            let target = &targets[frame.index];
            record_workers(target, frame.workers().iter_mut());
            let (primary, workers) = frame.parts();
            let secondaries: Vec<&tuff::CommandBuffer> = workers.iter().collect();
            execute_workers(primary, target, &secondaries);
            frame.submit(&s.queue, &[], &[]).expect("submit");
        }
        frames.wait_all().expect("wait");
        vulkan::assert_silent(&s.messages);
    }
}
