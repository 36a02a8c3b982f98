//! What tuff's checks cost, side by side in one run: three workloads, each through
//! raw ash, tuff's `_unchecked` methods, tuff's checked methods, and raw ash under
//! the Khronos validation layer (on a second device made with the layer on).
//!
//! - **draws**: 10,000 draws, each with a 16-byte push constant, in a render pass
//!   with the test pipeline, its layout's set and its viewport and scissor bound;
//! - **buffers**: 1,000 buffer creations, each destroyed again;
//! - **submits**: 1,000 submissions of one (empty) command buffer each, with a fence
//!   each; the fences are waited for and reset outside the timing.
//!
//! Rounds run the four variants in an order that rotates, so drift hits all alike;
//! the table gives the median time per operation and its ratio to raw ash. The
//! layer's message log must stay empty: every call here is valid.
//!
//! Run with `cargo bench -p tuff-tests --bench checks_cost`.
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
use tuff_setup::Setup;

const DRAWS: u32 = 10_000;
const BUFFERS: usize = 1_000;
const SUBMITS: usize = 1_000;
const ROUNDS: usize = 31;

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// One device's objects for every workload; the setup goes last.
struct Bench {
    fences: Vec<tuff::Fence>,
    submit_cbs: Vec<tuff::CommandBuffer>,
    cb: tuff::CommandBuffer,
    _pool: tuff::CommandPool,
    p: pipelines::Pipelines,
    target: tuff_setup::ColorTarget,
    s: Setup,
}

fn bench(validation: bool) -> Bench {
    let s = tuff_setup::setup(validation);
    let target = s.color_target(64, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let d = &s.device;
    let pool = d
        .create_command_pool(
            &tuff::CommandPoolCreateInfo::new()
                .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                .queue_family_index(s.family),
        )
        .expect("pool");
    let mut cbs = d
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1 + SUBMITS as u32),
        )
        .expect("command buffers");
    let cb = cbs.pop().expect("one");
    for cb in &mut cbs {
        cb.begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin")
            .end()
            .expect("end");
    }
    let fences = (0..SUBMITS)
        .map(|_| {
            d.create_fence(&tuff::FenceCreateInfo::new())
                .expect("fence")
        })
        .collect();
    Bench {
        s,
        target,
        p,
        _pool: pool,
        cb,
        submit_cbs: cbs,
        fences,
    }
}

const AREA: vk::Rect2D = vk::Rect2D {
    offset: vk::Offset2D { x: 0, y: 0 },
    extent: vk::Extent2D {
        width: 64,
        height: 64,
    },
};
const VIEWPORT: vk::Viewport = vk::Viewport {
    x: 0.0,
    y: 0.0,
    width: 64.0,
    height: 64.0,
    min_depth: 0.0,
    max_depth: 1.0,
};
const PUSH: [u8; 16] = [7; 16];

/// The draws through raw ash (on `b`'s device, with or without the layer).
fn draws_ash(b: &Bench) {
    let d = b.s.device.fns();
    let cb = *b.cb;
    let clear = [vk::ClearValue::default()];
    // SAFETY: beginning the command buffer resets it (its pool allows that), as
    // tuff's `begin` does, and every handle passed lives as long as `b`.
    unsafe {
        d.begin_command_buffer(cb, &vk::CommandBufferBeginInfo::default())
            .expect("begin");
        let begin = vk::RenderPassBeginInfo::default()
            .render_pass(*b.target.render_pass)
            .framebuffer(*b.target.framebuffer)
            .render_area(AREA)
            .clear_values(&clear);
        d.cmd_begin_render_pass(cb, &begin, vk::SubpassContents::INLINE);
        d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, *b.p.graphics);
        d.cmd_set_viewport(cb, 0, &[VIEWPORT]);
        d.cmd_set_scissor(cb, 0, &[AREA]);
        for i in 0..DRAWS {
            d.cmd_push_constants(
                cb,
                *b.p.graphics_layout,
                vk::ShaderStageFlags::FRAGMENT,
                0,
                black_box(&PUSH),
            );
            d.cmd_draw(cb, 36, 1, black_box(i), 0);
        }
        d.cmd_end_render_pass(cb);
        d.end_command_buffer(cb).expect("end");
    }
}

/// The draws through tuff's recorder, checked or not.
fn draws_tuff(b: &mut Bench, checked: bool) {
    let clear = [vk::ClearValue::default()];
    let (render_pass, framebuffer) = (&b.target.render_pass, &b.target.framebuffer);
    let (layout, pipeline) = (&b.p.graphics_layout, &b.p.graphics);
    let rec =
        b.cb.begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
    let begin = tuff::RenderPassBeginInfo::new(render_pass, framebuffer)
        .render_area(AREA)
        .clear_values(&clear);
    let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
    rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, pipeline)
        .expect("bind");
    rec.set_viewport(0, &[VIEWPORT]).expect("viewport");
    rec.set_scissor(0, &[AREA]).expect("scissor");
    let stage = vk::ShaderStageFlags::FRAGMENT;
    for i in 0..DRAWS {
        if checked {
            rec.push_constants(layout, stage, 0, black_box(&PUSH))
                .expect("recorded");
            rec.draw(36, 1, black_box(i), 0).expect("recorded");
        } else {
            // SAFETY: the same valid calls as the checked branch makes.
            unsafe {
                rec.push_constants_unchecked(layout, stage, 0, black_box(&PUSH))
                    .expect("recorded");
                rec.draw_unchecked(36, 1, black_box(i), 0)
                    .expect("recorded");
            }
        }
    }
    rec.end_render_pass().end().expect("end");
}

fn buffer_info() -> vk::BufferCreateInfo<'static> {
    vk::BufferCreateInfo::default()
        .size(256)
        .usage(vk::BufferUsageFlags::UNIFORM_BUFFER)
}

fn buffers_ash(b: &Bench) {
    let d = b.s.device.fns();
    let info = buffer_info();
    for _ in 0..BUFFERS {
        // SAFETY: a valid create info; the buffer is destroyed at once, unused.
        unsafe {
            let buffer = d.create_buffer(black_box(&info), None).expect("buffer");
            d.destroy_buffer(buffer, None);
        }
    }
}

fn buffers_tuff(b: &Bench, checked: bool) {
    let info = tuff::BufferCreateInfo::new()
        .size(256)
        .usage(vk::BufferUsageFlags::UNIFORM_BUFFER);
    for _ in 0..BUFFERS {
        let buffer = if checked {
            b.s.device.create_buffer(black_box(&info))
        } else {
            // SAFETY: the same valid create info as the checked branch passes.
            unsafe { b.s.device.create_buffer_unchecked(black_box(&info)) }
        };
        drop(buffer.expect("buffer"));
    }
}

fn submits_ash(b: &Bench) {
    let d = b.s.device.fns();
    for (cb, fence) in b.submit_cbs.iter().zip(&b.fences) {
        let cbs = [**cb];
        let submit = vk::SubmitInfo::default().command_buffers(&cbs);
        // SAFETY: each command buffer is executable and not pending (the previous
        // round's fences were waited for), each fence unsignaled.
        unsafe { d.queue_submit(*b.s.queue, &[submit], **fence) }.expect("submit");
    }
}

fn submits_tuff(b: &Bench, checked: bool) {
    for (cb, fence) in b.submit_cbs.iter().zip(&b.fences) {
        let one = [cb];
        let cbs = tuff::HandleSlice::new(&one);
        let submit = [tuff::SubmitInfo::new().command_buffers(&cbs)];
        let r = if checked {
            b.s.queue.submit(&submit, Some(fence))
        } else {
            // SAFETY: as in `submits_ash`.
            unsafe { b.s.queue.submit_unchecked(&submit, Some(fence)) }
        };
        r.expect("submit");
    }
}

/// Waits for and resets every fence of the submits, outside the timing.
fn settle(b: &Bench) {
    let fences: Vec<&tuff::Fence> = b.fences.iter().collect();
    let waited =
        b.s.device
            .wait_for_fences(&tuff::HandleSlice::new(&fences), true, u64::MAX)
            .expect("wait");
    assert_eq!(waited, tuff::SuccessOrTimeout::Success);
    b.s.device
        .reset_fences(&tuff::HandleSlice::new(&fences))
        .expect("reset");
}

const VARIANTS: [&str; 4] = [
    "raw ash",
    "tuff _unchecked",
    "tuff checked",
    "raw ash + layer",
];

fn main() {
    let mut plain = bench(false);
    let layered = bench(true);
    let mut times: Vec<[Vec<f64>; 4]> = (0..3).map(|_| Default::default()).collect();
    for round in 0..ROUNDS {
        for k in 0..4 {
            let v = (round + k) % 4;
            let time = |f: &mut dyn FnMut(), n: usize| {
                let t = Instant::now();
                f();
                t.elapsed().as_nanos() as f64 / n as f64
            };
            let (draws, buffers, submits) = match v {
                0 => (
                    time(&mut || draws_ash(&plain), DRAWS as usize),
                    time(&mut || buffers_ash(&plain), BUFFERS),
                    time(&mut || submits_ash(&plain), SUBMITS),
                ),
                1 | 2 => {
                    let checked = v == 2;
                    let d = time(&mut || draws_tuff(&mut plain, checked), DRAWS as usize);
                    (
                        d,
                        time(&mut || buffers_tuff(&plain, checked), BUFFERS),
                        time(&mut || submits_tuff(&plain, checked), SUBMITS),
                    )
                }
                _ => (
                    time(&mut || draws_ash(&layered), DRAWS as usize),
                    time(&mut || buffers_ash(&layered), BUFFERS),
                    time(&mut || submits_ash(&layered), SUBMITS),
                ),
            };
            settle(if v == 3 { &layered } else { &plain });
            if round > 0 {
                times[0][v].push(draws);
                times[1][v].push(buffers);
                times[2][v].push(submits);
            }
        }
    }
    let messages = layered.s.messages.take();
    assert!(
        messages.is_empty(),
        "the layer reported the benchmark's calls:\n{}",
        messages.join("\n")
    );
    println!(
        "{} rounds of each variant, interleaved; median ns per operation (ratio to raw ash)",
        ROUNDS - 1
    );
    println!("| workload | {} |", VARIANTS.join(" | "));
    println!("|---|---|---|---|---|");
    for (name, t) in ["draw + push constant", "buffer create + destroy", "submit"]
        .iter()
        .zip(&mut times)
    {
        let base = median(&mut t[0]);
        let cells: Vec<String> = t
            .iter_mut()
            .map(|v| {
                let m = median(v);
                format!("{m:.0} ({:.2}x)", m / base)
            })
            .collect();
        println!("| {name} | {} |", cells.join(" | "));
    }
}
