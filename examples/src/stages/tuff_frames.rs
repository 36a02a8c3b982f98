//! The teapots' frame loop through tuff, with each stage timed: headless here, in a
//! window through [`crate::window::run_timed`] (the scenes' own window loop).

use super::{Run, Samples, Stage, Timer};
use crate::gpu::Gpu;
use crate::headless::COLOR_FORMAT;
use crate::render::{self, Framebuffers, Scene as _, View, FRAMES_IN_FLIGHT};
use crate::scenes::teapot_grid::Layout;
use crate::scenes::teapots::Teapots;
use anyhow::Result;
use tuff::vk;

/// Renders `run.warmup + run.frames` frames of the teapots headless and returns the
/// timed frames' stages. Each frame is recorded and submitted as in the scenes, and
/// then copied into a readback buffer of its slot by a second submission: the
/// headless counterpart of presenting. The render pass's dependency on later transfers
/// orders the copy after the frame on the one queue, so no semaphore is needed (a wait
/// on one made lavapipe's submission block until the frame was drawn).
pub fn headless(gpu: &Gpu, run: &Run) -> Result<Samples> {
    let extent = vk::Extent2D {
        width: run.size,
        height: run.size,
    };
    let render_pass = render::render_pass(
        gpu,
        COLOR_FORMAT,
        true,
        vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
    )?;
    let layout = Layout::grid(run.count, 1)?;
    let mut scene = Teapots::with_writes(gpu, &render_pass, layout, u64::from(run.writes))?;
    let usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
    let images = (0..FRAMES_IN_FLIGHT)
        .map(|_| gpu.image(extent, COLOR_FORMAT, usage))
        .collect::<Result<Vec<_>>>()?;
    let targets = Framebuffers::new(gpu, &render_pass, &images, COLOR_FORMAT, extent, true)?;
    let bytes = u64::from(run.size) * u64::from(run.size) * 4;
    let readbacks = (0..FRAMES_IN_FLIGHT)
        .map(|_| {
            gpu.buffer(
                bytes,
                vk::BufferUsageFlags::TRANSFER_DST,
                tuff::MemoryLocation::Readback,
            )
        })
        .collect::<Result<Vec<_>>>()?;
    let mut frames = gpu.device.frames_in_flight(gpu.family, FRAMES_IN_FLIGHT)?;
    let mut copies = gpu.device.frames_in_flight(gpu.family, FRAMES_IN_FLIGHT)?;
    let mut samples = Samples::new(run.warmup);
    let mut timer = Timer::default();
    for n in 0..run.warmup + run.frames {
        timer.start();
        let mut frame = frames.next_frame()?;
        let slot = frame.index;
        timer.lap(Stage::Wait);
        let view = View {
            extent,
            time: n as f32 / 60.0,
            slot,
        };
        scene.update(&view)?;
        timer.lap(Stage::Uniform);
        let framebuffer = &targets.framebuffers[slot];
        render::record_frame(&mut frame, &render_pass, framebuffer, &scene, &view, None)?;
        timer.lap(Stage::Command);
        frame.submit(&gpu.queue, &[], &[])?;
        timer.lap(Stage::Submit);
        let mut copy = copies.next_frame()?;
        timer.lap(Stage::Wait);
        let mut rec = copy.record()?;
        render::record_readback(&mut rec, &images[slot], &readbacks[slot], extent)?;
        rec.end()?;
        copy.submit(&gpu.queue, &[], &[])?;
        timer.lap(Stage::Present);
        samples.push(&timer);
    }
    frames.wait_all()?;
    copies.wait_all()?;
    let last = (run.warmup + run.frames).saturating_sub(1) as usize % FRAMES_IN_FLIGHT;
    samples.last_frame = readbacks[last].memory().read(0, bytes as usize)?;
    Ok(samples)
}
