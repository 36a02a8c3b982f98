//! Recording on threads. Without the `multi_thread` feature the wrappers share their
//! state through `Rc` and no wrapper crosses a thread (`compile_fail/
//! handle_across_threads.rs`); with it, every wrapper is `Send` and `Sync`, and a
//! recorder stays on the thread that began it (it holds its pool's lock, which that
//! thread took: `compile_fail/recorder_across_threads.rs`). This file runs in the
//! test command's `multi_thread` pass: workers record secondaries from their own
//! pools at once, one primary executes them, and the frame runs with the layer (and
//! its synchronization validation) silent.

#[cfg(feature = "multi_thread")]
#[path = "common/pipelines.rs"]
mod pipelines;
#[cfg(feature = "multi_thread")]
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[cfg(feature = "multi_thread")]
#[path = "common/vulkan.rs"]
mod vulkan;

#[cfg(feature = "multi_thread")]
mod threaded {
    use super::{pipelines, tuff_setup, vulkan};
    use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
    use std::time::{Duration, Instant};
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

    /// One frame of the ring: its workers record their secondaries on threads of their
    /// own, the primary executes them into the frame's target, and the frame is
    /// submitted.
    fn worker_frame(
        frames: &mut tuff::FramesInFlight,
        targets: &[tuff_setup::ColorTarget; 2],
        queue: &tuff::Queue,
    ) {
        let mut frame = frames.next_frame().expect("frame");
        let target = &targets[frame.index];
        record_workers(target, frame.workers().iter_mut());
        let (primary, workers) = frame.parts();
        let secondaries: Vec<&tuff::CommandBuffer> = workers.iter().collect();
        execute_workers(primary, target, &secondaries);
        frame.submit(queue, &[], &[]).expect("submit");
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
            worker_frame(&mut frames, &targets, &s.queue);
        }
        frames.wait_all().expect("wait");
        vulkan::assert_silent(&s.messages);
    }

    /// This process's resident memory in bytes (`VmRSS`).
    fn resident() -> u64 {
        let status = std::fs::read_to_string("/proc/self/status").unwrap();
        let line = status.lines().find(|l| l.starts_with("VmRSS:")).unwrap();
        line.split_whitespace()
            .nth(1)
            .unwrap()
            .parse::<u64>()
            .unwrap()
            * 1024
    }

    /// Eight threads at once for `TUFF_STRESS_SECONDS` (3 by default; the README's
    /// figure is of 60): frames in flight whose four workers record secondaries that
    /// one primary per frame executes, submitted to the queue, while three threads
    /// make and drop pipelines, shader modules, descriptor pools and sets (updated
    /// through a template), buffers and images, over and over. The layer, with
    /// synchronization validation, stays silent; a watchdog fails the run when no
    /// frame completes for 30 s (a deadlock); from a twelfth of the run to its end,
    /// resident memory grows by at most 10 % (checked for runs of 20 s or more).
    #[test]
    fn eight_threads_record_and_churn_objects_at_once() {
        let _serial = vulkan::serial();
        let seconds: u64 = std::env::var("TUFF_STRESS_SECONDS")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(3);
        let s = tuff_setup::setup(true);
        let targets = [
            s.color_target(8, vk::ImageUsageFlags::empty()),
            s.color_target(8, vk::ImageUsageFlags::empty()),
        ];
        let churn_target = s.color_target(8, vk::ImageUsageFlags::empty());
        let mut frames = s
            .device
            .frames_in_flight_with_workers(s.family, 2, 4)
            .expect("frames");
        let done = AtomicBool::new(false);
        let progress = AtomicU64::new(0);
        let churned = AtomicU64::new(0);
        let start = Instant::now();
        let deadline = start + Duration::from_secs(seconds);
        let mut early = None;
        std::thread::scope(|scope| {
            // The watchdog: a deadlock fails the run instead of hanging it.
            scope.spawn(|| {
                let mut last = (progress.load(Ordering::SeqCst), Instant::now());
                while !done.load(Ordering::SeqCst) {
                    std::thread::sleep(Duration::from_millis(100));
                    let now = progress.load(Ordering::SeqCst);
                    if now != last.0 {
                        last = (now, Instant::now());
                    } else if last.1.elapsed() > Duration::from_secs(30) {
                        eprintln!("no frame completed for 30 s after frame {now}: a deadlock");
                        std::process::abort();
                    }
                }
            });
            for _ in 0..3 {
                scope.spawn(|| {
                    // At least once, however slow the machine (valgrind's tools).
                    loop {
                        let made = pipelines::pipelines(&s, &churn_target);
                        let set = pipelines::uniform_set(&s);
                        let image = s.color_image(16, vk::ImageUsageFlags::SAMPLED);
                        drop((made, set, image));
                        churned.fetch_add(1, Ordering::SeqCst);
                        if Instant::now() >= deadline {
                            break;
                        }
                    }
                });
            }
            loop {
                worker_frame(&mut frames, &targets, &s.queue);
                progress.fetch_add(1, Ordering::SeqCst);
                if early.is_none() && start.elapsed() * 12 >= Duration::from_secs(seconds) {
                    early = Some(resident());
                }
                if Instant::now() >= deadline {
                    break;
                }
            }
            frames.wait_all().expect("wait");
            done.store(true, Ordering::SeqCst);
        });
        let (early, last) = (early.unwrap_or_else(resident), resident());
        let mib = |b: u64| b as f64 / (1024.0 * 1024.0);
        println!(
            "{seconds} s: {} frames, {} rounds of objects made and dropped; resident memory {:.1} MiB after a twelfth of the run, {:.1} MiB at its end",
            progress.load(Ordering::SeqCst),
            churned.load(Ordering::SeqCst),
            mib(early),
            mib(last)
        );
        assert!(progress.load(Ordering::SeqCst) > 0 && churned.load(Ordering::SeqCst) > 0);
        if seconds >= 20 {
            assert!(
                last <= early + early / 10,
                "resident memory grew by more than 10 %"
            );
        }
        vulkan::assert_silent(&s.messages);
    }
}
