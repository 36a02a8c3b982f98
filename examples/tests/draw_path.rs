//! The per-draw path does no work beyond the draw's own, and each stage of a frame
//! does a counted amount: a frame of the teapots scene, recorded, submitted and
//! copied out through tuff with every check and the hazard tracker on, allocates,
//! takes locks and computes hashes exactly as often with 300 teapots as with 3, and
//! each stage allocates no more than its budget (counted on the frame's thread by a
//! counting global allocator and the runtime's `work_counts` counters of locks and
//! of tuff's table hashes, after warm-up frames). A count is work, not time: noise
//! on a loaded machine cannot fool it, and a lock or allocation that comes back
//! fails it. `TUFF_ALLOC_SITES=1` prints the call stack of each allocation of the
//! last frame (and checks no budget), to find one that came back.

use std::alloc::{GlobalAlloc, Layout as AllocLayout, System};
use std::cell::Cell;
use tuff::vk;
use tuff_examples::gpu::Gpu;
use tuff_examples::headless::COLOR_FORMAT;
use tuff_examples::render::{self, Framebuffers, Scene as _, View, FRAMES_IN_FLIGHT};
use tuff_examples::scenes::teapot_grid::Layout;
use tuff_examples::scenes::teapots::{Teapots, REQUIREMENTS};

/// Counts the heap allocations (and reallocations) of each thread, then hands them to
/// the system allocator.
struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<u64> = const { Cell::new(0) };
    /// Whether each allocation's call stack is printed (`TUFF_ALLOC_SITES=1`), and
    /// whether one is being printed (its own allocations are not traced).
    static TRACE: Cell<(bool, bool)> = const { Cell::new((false, false)) };
}

fn count() {
    // `try_with`: a thread's last frees run after its locals are gone.
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
    let _ = TRACE.try_with(|t| {
        if t.get() == (true, false) {
            t.set((true, true));
            eprintln!(
                "allocation at:\n{}",
                std::backtrace::Backtrace::force_capture()
            );
            t.set((true, false));
        }
    });
}

// SAFETY: every call is passed on to `System` with its arguments unchanged, which
// keeps the `GlobalAlloc` contract; counting touches a thread-local cell only.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: AllocLayout) -> *mut u8 {
        count();
        // SAFETY: the caller's contract, passed on.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: AllocLayout) -> *mut u8 {
        count();
        // SAFETY: the caller's contract, passed on.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: AllocLayout, new_size: usize) -> *mut u8 {
        count();
        // SAFETY: the caller's contract, passed on.
        unsafe { System.realloc(ptr, layout, new_size) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: AllocLayout) {
        // SAFETY: the caller's contract, passed on.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// What one stage of a frame cost this thread: allocations, locks and hashes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct Work {
    allocations: u64,
    locks: u64,
    hashes: u64,
}

fn now() -> Work {
    Work {
        allocations: ALLOCATIONS.with(Cell::get),
        locks: tuff_runtime::locks_taken(),
        hashes: tuff_runtime::hashes_taken(),
    }
}

impl core::ops::Sub for Work {
    type Output = Work;
    fn sub(self, before: Work) -> Work {
        Work {
            allocations: self.allocations - before.allocations,
            locks: self.locks - before.locks,
            hashes: self.hashes - before.hashes,
        }
    }
}

/// The work of each stage of one frame, as the stage benchmark splits it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct Stages {
    /// The frame's command buffer recorded: the render pass, its state, the draws.
    command: Work,
    /// Its submission.
    submit: Work,
    /// The headless present: the copy into a readback buffer, recorded and
    /// submitted on its own.
    copy_out: Work,
}

/// Renders warm-up frames of `count` teapots headless as the stage benchmark does
/// (a frame, then its copy-out), then returns what each stage of the last frame
/// took, with the validation layer on and silent. With `TUFF_ALLOC_SITES=1`, the
/// last frame's allocations print their call stacks.
fn frame_work(count: u32, auto_sync: bool) -> Stages {
    const FRAMES: u32 = 6;
    render::set_auto_sync(auto_sync);
    let gpu = Gpu::new(REQUIREMENTS, true).expect("device");
    let extent = vk::Extent2D {
        width: 32,
        height: 32,
    };
    let layout = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
    let render_pass = render::render_pass(&gpu, COLOR_FORMAT, true, layout).expect("pass");
    let mut scene =
        Teapots::new(&gpu, &render_pass, Layout::grid(count, 1).expect("grid")).expect("scene");
    let usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
    let images = (0..FRAMES_IN_FLIGHT)
        .map(|_| gpu.image(extent, COLOR_FORMAT, usage))
        .collect::<anyhow::Result<Vec<_>>>()
        .expect("images");
    let targets = Framebuffers::new(&gpu, &render_pass, &images, COLOR_FORMAT, extent, true)
        .expect("framebuffers");
    let readbacks = (0..FRAMES_IN_FLIGHT)
        .map(|_| {
            gpu.buffer(
                u64::from(extent.width * extent.height * 4),
                vk::BufferUsageFlags::TRANSFER_DST,
                tuff::MemoryLocation::Readback,
            )
        })
        .collect::<anyhow::Result<Vec<_>>>()
        .expect("readbacks");
    let mut frames = gpu
        .device
        .frames_in_flight(gpu.family, FRAMES_IN_FLIGHT)
        .expect("frames");
    let mut copies = gpu
        .device
        .frames_in_flight(gpu.family, FRAMES_IN_FLIGHT)
        .expect("copies");
    let trace = std::env::var_os("TUFF_ALLOC_SITES").is_some_and(|v| v == "1");
    let mut last = Stages::default();
    for n in 0..FRAMES {
        if n + 1 == FRAMES && trace {
            TRACE.with(|t| t.set((true, false)));
        }
        let mut frame = frames.next_frame().expect("frame");
        let slot = frame.index;
        let view = View {
            extent,
            time: n as f32 / 60.0,
            slot,
        };
        scene.update(&view).expect("update");
        let framebuffer = &targets.framebuffers[slot];
        let mark = |stage: &str| {
            if trace && n + 1 == FRAMES {
                eprintln!("stage: {stage}");
            }
        };
        mark("command");
        let before = now();
        render::record_frame(&mut frame, &render_pass, framebuffer, &scene, &view, None)
            .expect("recorded");
        let recorded = now();
        mark("submit");
        frame.submit(&gpu.queue, &[], &[]).expect("submit");
        let submitted = now();
        let mut copy = copies.next_frame().expect("copy");
        mark("copy-out");
        let waited = now();
        let mut rec = copy.record().expect("record");
        render::record_readback(&mut rec, &images[slot], &readbacks[slot], extent)
            .expect("readback");
        rec.end().expect("end");
        copy.submit(&gpu.queue, &[], &[]).expect("copy submit");
        let copied = now();
        TRACE.with(|t| t.set((false, false)));
        mark("done");
        last = Stages {
            command: recorded - before,
            submit: submitted - recorded,
            copy_out: copied - waited,
        };
    }
    frames.wait_all().expect("wait");
    copies.wait_all().expect("wait");
    drop((
        targets,
        images,
        readbacks,
        scene,
        render_pass,
        frames,
        copies,
    ));
    let messages = gpu.finish();
    assert!(messages.is_empty(), "the layer reported: {messages:#?}");
    last
}

/// The most allocations recording one teapots frame may make, whatever its draws:
/// the log of what it did to memory, handed to its submissions (it was 29, then 12).
const FRAME_ALLOCATIONS: u64 = 1;

/// The most allocations a frame's submission may make: its record, which the fence
/// holds until the submission is known complete (it was 12).
const SUBMIT_ALLOCATIONS: u64 = 1;

/// The most allocations the headless present (the copy-out recorded and submitted)
/// may make: the recording's log and the submission's record (it was 17).
const COPY_OUT_ALLOCATIONS: u64 = 2;

#[test]
fn a_draw_allocates_nothing_and_takes_no_lock_or_hash() {
    for auto_sync in [false, true] {
        let few = frame_work(3, auto_sync);
        let many = frame_work(300, auto_sync);
        println!("a frame's stages (auto_sync {auto_sync}): {few:#?}");
        if std::env::var_os("TUFF_ALLOC_SITES").is_some() {
            // Traced: the counts include the tracing's own.
            continue;
        }
        // The frame's own allocations (its recorder's tables and what the recording
        // hands its command buffer), counted: a bound pipeline's record, the
        // framebuffer's views, the retained list and the bound sets' and vertex
        // buffers' lists are shared or reused, not copied per frame (it was 29).
        let limits = [
            ("recording", few.command, FRAME_ALLOCATIONS),
            ("submission", few.submit, SUBMIT_ALLOCATIONS),
            ("copy-out", few.copy_out, COPY_OUT_ALLOCATIONS),
        ];
        for (stage, work, limit) in limits {
            assert!(
                work.allocations <= limit,
                "a frame's {stage} (auto_sync {auto_sync}) allocated {} times, more than {limit}",
                work.allocations
            );
        }
        assert_eq!(
            few, many,
            "297 more draws (auto_sync {auto_sync}) did more work than the draws"
        );
    }
}
