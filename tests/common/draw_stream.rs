//! The draw stream the recording benchmarks time: inside a render pass on a 64x64
//! color target with the test pipeline bound (its viewport and scissor set), `n`
//! draws, each after a 16-byte push constant to the fragment stage, recorded through
//! raw ash and through tuff's `Recorder` into command buffers of one pool, which each
//! recording resets. Each recording returns the time its draws took (the begin and
//! end outside it). Nothing is submitted.
//!
//! SAFETY of the `unsafe` blocks: the raw ash calls record into a command buffer reset
//! with its pool before each recording, with handles that live as long as the stream.
#![allow(dead_code)]

use crate::pipelines::{self, Pipelines};
use crate::tuff_setup::{ColorTarget, Setup};
use std::hint::black_box;
use std::time::{Duration, Instant};
use tuff::vk;

/// What the stream records with.
pub struct DrawStream {
    pub s: Setup,
    target: ColorTarget,
    p: Pipelines,
    pool: tuff::CommandPool,
    raw_cb: tuff::CommandBuffer,
    tuff_cb: tuff::CommandBuffer,
    ash: ash::Device,
}

const SIDE: u32 = 64;
const PUSH: [u8; 16] = [7; 16];

impl DrawStream {
    /// The stream on the setup's device (without the layer: this is for timing).
    pub fn new() -> DrawStream {
        let s = crate::tuff_setup::setup(false);
        let target = s.color_target(SIDE, vk::ImageUsageFlags::empty());
        let p = pipelines::pipelines(&s, &target);
        let d = &s.device;
        let pool = d
            .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
            .expect("pool");
        let mut cbs = d
            .allocate_command_buffers(
                &pool,
                &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(2),
            )
            .expect("command buffers");
        let tuff_cb = cbs.pop().expect("two");
        let raw_cb = cbs.pop().expect("two");
        let ash = d.fns().clone();
        DrawStream {
            target,
            p,
            pool,
            raw_cb,
            tuff_cb,
            ash,
            s,
        }
    }

    fn area() -> vk::Rect2D {
        vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: SIDE,
                height: SIDE,
            },
        }
    }

    fn viewport() -> vk::Viewport {
        vk::Viewport {
            width: SIDE as f32,
            height: SIDE as f32,
            max_depth: 1.0,
            ..Default::default()
        }
    }

    /// Records `n` draws through raw ash, draw `i` with first instance `i` when
    /// `vary` (0 otherwise).
    pub fn ash(&mut self, n: u32, vary: bool) -> Duration {
        self.s
            .device
            .reset_command_pool(&self.pool, vk::CommandPoolResetFlags::empty())
            .expect("reset");
        let (ash, cb, area) = (&self.ash, *self.raw_cb, Self::area());
        let clear = [vk::ClearValue::default()];
        // SAFETY: see the module's documentation.
        unsafe {
            ash.begin_command_buffer(cb, &vk::CommandBufferBeginInfo::default())
                .expect("begin");
            let begin = vk::RenderPassBeginInfo::default()
                .render_pass(*self.target.render_pass)
                .framebuffer(*self.target.framebuffer)
                .render_area(area)
                .clear_values(&clear);
            ash.cmd_begin_render_pass(cb, &begin, vk::SubpassContents::INLINE);
            ash.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, *self.p.graphics);
            ash.cmd_set_viewport(cb, 0, &[Self::viewport()]);
            ash.cmd_set_scissor(cb, 0, &[area]);
            let t = Instant::now();
            for i in 0..n {
                let stages = vk::ShaderStageFlags::FRAGMENT;
                let layout = *self.p.graphics_layout;
                ash.cmd_push_constants(cb, layout, stages, 0, black_box(&PUSH));
                ash.cmd_draw(cb, 36, 1, black_box(if vary { i } else { 0 }), 0);
            }
            let took = t.elapsed();
            ash.cmd_end_render_pass(cb);
            ash.end_command_buffer(cb).expect("end");
            took
        }
    }

    /// The same draws through tuff's checked methods.
    pub fn tuff(&mut self, n: u32, vary: bool) -> Duration {
        self.s
            .device
            .reset_command_pool(&self.pool, vk::CommandPoolResetFlags::empty())
            .expect("reset");
        let clear = [vk::ClearValue::default()];
        let rec = self
            .tuff_cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let begin =
            tuff::RenderPassBeginInfo::new(&self.target.render_pass, &self.target.framebuffer)
                .render_area(Self::area())
                .clear_values(&clear);
        let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.p.graphics)
            .expect("bind");
        rec.set_viewport(0, &[Self::viewport()]).expect("viewport");
        rec.set_scissor(0, &[Self::area()]).expect("scissor");
        let layout = &self.p.graphics_layout;
        let t = Instant::now();
        for i in 0..n {
            rec.push_constants(layout, vk::ShaderStageFlags::FRAGMENT, 0, black_box(&PUSH))
                .expect("recorded");
            rec.draw(36, 1, black_box(if vary { i } else { 0 }), 0)
                .expect("recorded");
        }
        let took = t.elapsed();
        rec.end_render_pass().end().expect("end");
        took
    }
}
