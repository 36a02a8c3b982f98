//! The per-draw path does no work beyond the draw's own: a frame of the teapots
//! scene, recorded through tuff with every check and the hazard tracker on, allocates,
//! takes locks and computes hashes exactly as often with 300 teapots as with 3
//! (counted on the recording thread by a counting global allocator and the runtime's
//! `work_counts` counters of locks and of tuff's table hashes, after warm-up frames). A count is work, not time: noise on a loaded machine cannot
//! fool it, and a lock or allocation that comes back on the draw path fails it.

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
}

fn count() {
    // `try_with`: a thread's last frees run after its locals are gone.
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
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

/// What recording one frame cost this thread: allocations and locks.
#[derive(Debug, PartialEq, Eq)]
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

/// Renders warm-up frames of `count` teapots headless, then returns what recording
/// the last frame took (the command stage of the stage benchmark: the render pass,
/// its state, the draws), with the validation layer on and silent.
fn frame_work(count: u32, auto_sync: bool) -> Work {
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
    let mut frames = gpu
        .device
        .frames_in_flight(gpu.family, FRAMES_IN_FLIGHT)
        .expect("frames");
    let mut last = None;
    for n in 0..FRAMES {
        let mut frame = frames.next_frame().expect("frame");
        let slot = frame.index;
        let view = View {
            extent,
            time: n as f32 / 60.0,
            slot,
        };
        scene.update(&view).expect("update");
        let framebuffer = &targets.framebuffers[slot];
        let before = now();
        render::record_frame(&mut frame, &render_pass, framebuffer, &scene, &view, None)
            .expect("recorded");
        let after = now();
        frame.submit(&gpu.queue, &[], &[]).expect("submit");
        last = Some(Work {
            allocations: after.allocations - before.allocations,
            locks: after.locks - before.locks,
            hashes: after.hashes - before.hashes,
        });
    }
    frames.wait_all().expect("wait");
    drop((targets, images, scene, render_pass, frames));
    let messages = gpu.finish();
    assert!(messages.is_empty(), "the layer reported: {messages:#?}");
    last.expect("frames")
}

/// The most allocations recording one teapots frame may make, whatever its draws.
const FRAME_ALLOCATIONS: u64 = 12;

#[test]
fn a_draw_allocates_nothing_and_takes_no_lock_or_hash() {
    for auto_sync in [false, true] {
        let few = frame_work(3, auto_sync);
        let many = frame_work(300, auto_sync);
        println!("a frame's recording (auto_sync {auto_sync}): {few:?}");
        // The frame's own allocations (its recorder's tables and what the recording
        // hands its command buffer), counted: a bound pipeline's record, the
        // framebuffer's views, the retained list and the bound sets' and vertex
        // buffers' lists are shared or reused, not copied per frame (it was 29).
        assert!(
            few.allocations <= FRAME_ALLOCATIONS,
            "a frame's recording (auto_sync {auto_sync}) allocated {} times, more than {FRAME_ALLOCATIONS}",
            few.allocations
        );
        assert_eq!(
            few, many,
            "recording 297 more draws (auto_sync {auto_sync}) did more work than the draws"
        );
    }
}
