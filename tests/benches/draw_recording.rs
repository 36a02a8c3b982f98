//! Criterion benchmark of draw recording, per draw: a 16-byte push constant and a
//! `vkCmdDraw`, inside a render pass with the test pipeline bound, through raw ash and
//! through tuff's `Recorder` (every check and the hazard tracker on), on the device
//! `TUFF_DEVICE` names (lavapipe in the test setup), without the layer.
//! Two runs of draws: the same parameters each time (a scene's instances with their
//! transforms in push constants, as the teapots draw), and a first instance that
//! changes with every draw (the tracker's per-draw shortcut does not apply).
//!
//! `cargo bench -p tuff-tests --bench draw_recording` (well under a minute; criterion
//! prints each case's time per draw). Nothing is submitted: recording is what is
//! measured. Each measured run records into command buffers of at most 10,000 draws,
//! their beginning and end outside the time.
//!
//! SAFETY of the `unsafe` blocks: the raw ash calls record into a command buffer reset
//! with its pool before each recording, with handles that live until the end.

#[path = "../common/pipelines.rs"]
mod pipelines;
#[path = "../common/tuff_setup.rs"]
mod tuff_setup;
#[path = "../common/vulkan.rs"]
mod vulkan;

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::{Duration, Instant};
use tuff::vk;

/// The most draws one recording holds (lavapipe keeps every command in memory).
const CHUNK: u64 = 10_000;

fn draws(c: &mut Criterion) {
    let s = tuff_setup::setup(false);
    let d = &s.device;
    let target = s.color_target(64, vk::ImageUsageFlags::empty());
    let (render_pass, framebuffer) = (&target.render_pass, &target.framebuffer);
    let p = pipelines::pipelines(&s, &target);
    let (layout, pipeline) = (&p.graphics_layout, &p.graphics);
    let pool = d
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
        .expect("pool");
    let mut cbs = d
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(2),
        )
        .expect("command buffers");
    let mut tuff_cb = cbs.pop().expect("two");
    let raw_cb = cbs.pop().expect("two");
    let ash = d.fns().clone();
    let clear = [vk::ClearValue::default()];
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 64,
            height: 64,
        },
    };
    let viewport = vk::Viewport {
        width: 64.0,
        height: 64.0,
        max_depth: 1.0,
        ..Default::default()
    };
    let push: [u8; 16] = [7; 16];

    // Records `n` draws through raw ash (first instance `i` when `vary`), timing the
    // draws only.
    let mut ash_draws = |n: u64, vary: bool| -> Duration {
        d.reset_command_pool(&pool, vk::CommandPoolResetFlags::empty())
            .expect("reset");
        let cb = *raw_cb;
        // SAFETY: see the module's documentation.
        unsafe {
            ash.begin_command_buffer(cb, &vk::CommandBufferBeginInfo::default())
                .expect("begin");
            let begin = vk::RenderPassBeginInfo::default()
                .render_pass(**render_pass)
                .framebuffer(**framebuffer)
                .render_area(area)
                .clear_values(&clear);
            ash.cmd_begin_render_pass(cb, &begin, vk::SubpassContents::INLINE);
            ash.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, **pipeline);
            ash.cmd_set_viewport(cb, 0, &[viewport]);
            ash.cmd_set_scissor(cb, 0, &[area]);
            let t = Instant::now();
            for i in 0..n as u32 {
                let stages = vk::ShaderStageFlags::FRAGMENT;
                ash.cmd_push_constants(cb, **layout, stages, 0, black_box(&push));
                ash.cmd_draw(cb, 36, 1, black_box(if vary { i } else { 0 }), 0);
            }
            let took = t.elapsed();
            ash.cmd_end_render_pass(cb);
            ash.end_command_buffer(cb).expect("end");
            took
        }
    };
    // The same through tuff.
    let mut tuff_draws = |n: u64, vary: bool| -> Duration {
        d.reset_command_pool(&pool, vk::CommandPoolResetFlags::empty())
            .expect("reset");
        let rec = tuff_cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let begin = tuff::RenderPassBeginInfo::new(render_pass, framebuffer)
            .render_area(area)
            .clear_values(&clear);
        let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, pipeline)
            .expect("bind");
        rec.set_viewport(0, &[viewport]).expect("viewport");
        rec.set_scissor(0, &[area]).expect("scissor");
        let t = Instant::now();
        for i in 0..n as u32 {
            rec.push_constants(layout, vk::ShaderStageFlags::FRAGMENT, 0, black_box(&push))
                .expect("recorded");
            rec.draw(36, 1, black_box(if vary { i } else { 0 }), 0)
                .expect("recorded");
        }
        let took = t.elapsed();
        rec.end_render_pass().end().expect("end");
        took
    };

    let mut group = c.benchmark_group("per draw (push constant + vkCmdDraw)");
    for (name, vary) in [("same parameters", false), ("first instance varies", true)] {
        // Criterion asks for `iters` draws; they go in recordings of at most CHUNK.
        let chunked = |record: &mut dyn FnMut(u64, bool) -> Duration, iters: u64| {
            let mut total = Duration::ZERO;
            let mut left = iters;
            while left > 0 {
                let n = left.min(CHUNK);
                total += record(n, vary);
                left -= n;
            }
            total
        };
        group.bench_function(format!("raw ash, {name}"), |b| {
            b.iter_custom(|iters| chunked(&mut ash_draws, iters))
        });
        group.bench_function(format!("tuff, {name}"), |b| {
            b.iter_custom(|iters| chunked(&mut tuff_draws, iters))
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(20);
    targets = draws
}
criterion_main!(benches);
