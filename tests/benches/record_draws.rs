//! Recording 10,000 draws, each with a 16-byte push constant, inside a render pass
//! with the test pipeline bound (its viewport and scissor set):
//! raw ash against tuff's `Recorder`, on the same lavapipe command pool. Each round
//! resets the pool, records one buffer with ash and one with tuff (in an order that
//! alternates), and the table reports the median time per draw and the geometric mean
//! of the per-round ratios. Nothing is submitted; recording is what is measured.
//!
//! Run with `cargo bench -p tuff-tests --bench record_draws`, and with
//! `--features multi_thread` for `Vrc` = `Arc` and real locks.
//!
//! SAFETY of the `unsafe` blocks around checked methods: such a method is `unsafe`
//! because it leaves rules to its caller (its `# Safety` section lists them). The
//! calls here keep every rule so listed and break, on purpose, only rules the method
//! checks; that one argument covers every such block in this file.

#[path = "../common/pipelines.rs"]
mod pipelines;
#[path = "../common/tuff_setup.rs"]
mod tuff_setup;
#[path = "../common/vulkan.rs"]
mod vulkan;

use std::hint::black_box;
use std::time::Instant;
use tuff::vk;

const DRAWS: u32 = 10_000;
const ROUNDS: usize = 41;

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let s = tuff_setup::setup(false);
    let d = &s.device;
    let target = s.color_target(64, vk::ImageUsageFlags::empty());
    let (render_pass, framebuffer) = (&target.render_pass, &target.framebuffer);
    // The test pipeline: a fragment push constant of 16 bytes, dynamic viewport and
    // scissor.
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
    let ash_device = d.fns().clone();
    let clear = [vk::ClearValue::default()];
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 64,
            height: 64,
        },
    };
    let push: [u8; 16] = [7; 16];
    let viewport = vk::Viewport {
        width: 64.0,
        height: 64.0,
        max_depth: 1.0,
        ..Default::default()
    };

    let record_ash = |cb: vk::CommandBuffer| {
        // SAFETY: the command buffer is reset with its pool before each recording, and
        // every handle passed lives until the end of main.
        unsafe {
            ash_device
                .begin_command_buffer(cb, &vk::CommandBufferBeginInfo::default())
                .expect("begin");
            let begin = vk::RenderPassBeginInfo::default()
                .render_pass(**render_pass)
                .framebuffer(**framebuffer)
                .render_area(area)
                .clear_values(&clear);
            ash_device.cmd_begin_render_pass(cb, &begin, vk::SubpassContents::INLINE);
            ash_device.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, **pipeline);
            ash_device.cmd_set_viewport(cb, 0, &[viewport]);
            ash_device.cmd_set_scissor(cb, 0, &[area]);
            for i in 0..DRAWS {
                ash_device.cmd_push_constants(
                    cb,
                    **layout,
                    vk::ShaderStageFlags::FRAGMENT,
                    0,
                    black_box(&push),
                );
                ash_device.cmd_draw(cb, 36, 1, black_box(i), 0);
            }
            ash_device.cmd_end_render_pass(cb);
            ash_device.end_command_buffer(cb).expect("end");
        }
    };
    let record_tuff = |cb: &mut tuff::CommandBuffer| {
        let rec = cb
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
        for i in 0..DRAWS {
            rec.push_constants(layout, vk::ShaderStageFlags::FRAGMENT, 0, black_box(&push))
                .expect("recorded");
            rec.draw(36, 1, black_box(i), 0).expect("recorded");
        }
        rec.end_render_pass().end().expect("end");
    };

    let mut ash_ns = Vec::new();
    let mut tuff_ns = Vec::new();
    let mut ratios = Vec::new();
    for round in 0..ROUNDS {
        d.reset_command_pool(&pool, vk::CommandPoolResetFlags::empty())
            .expect("reset");
        let mut time_ash = 0.0;
        let mut time_tuff = 0.0;
        for step in 0..2 {
            if (round + step) % 2 == 0 {
                let t = Instant::now();
                record_ash(*raw_cb);
                time_ash = t.elapsed().as_nanos() as f64 / f64::from(DRAWS);
            } else {
                let t = Instant::now();
                record_tuff(&mut tuff_cb);
                time_tuff = t.elapsed().as_nanos() as f64 / f64::from(DRAWS);
            }
        }
        if round > 0 {
            ash_ns.push(time_ash);
            tuff_ns.push(time_tuff);
            ratios.push(time_tuff / time_ash);
        }
    }
    let mode = if cfg!(feature = "multi_thread") {
        "multi_thread (Arc, mutex)"
    } else {
        "single-threaded (Rc)"
    };
    println!(
        "recording {DRAWS} draws with push constants, {} rounds, {mode}",
        ROUNDS - 1
    );
    // The order alternates between rounds, and the second recording of a round is
    // often slower than the first, so the per-round ratios come in two groups; their
    // geometric mean weighs both orders equally, where a median picks one group.
    let geo_mean = (ratios.iter().map(|r| r.ln()).sum::<f64>() / ratios.len() as f64).exp();
    println!("| case | median per draw (ns) | tuff / ash (geometric mean of rounds) |");
    println!("|---|---|---|");
    println!("| raw ash | {:.1} | 1.00 |", median(&mut ash_ns));
    println!(
        "| tuff Recorder | {:.1} | {:.3} |",
        median(&mut tuff_ns),
        geo_mean
    );
}
