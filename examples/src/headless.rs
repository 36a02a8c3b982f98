//! Rendering into offscreen images, one per frame in flight, and reading the last
//! frame back.

use crate::gpu::Gpu;
use crate::render::{self, Framebuffers, Scene, View, FRAMES_IN_FLIGHT};
use anyhow::Result;
use std::time::{Duration, Instant};
use tuff::vk;

/// The offscreen color format: the bytes are RGBA as a PNG wants them.
pub const COLOR_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;

/// The last frame's pixels and how long the frames took.
pub struct Rendered {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Tightly packed RGBA8 rows, top row first.
    pub rgba: Vec<u8>,
    /// Frames rendered.
    pub frames: u32,
    /// From the first frame's recording to the last frame's completion.
    pub elapsed: Duration,
}

impl Rendered {
    /// Frames per second over the run.
    pub fn fps(&self) -> f64 {
        self.frames as f64 / self.elapsed.as_secs_f64().max(1e-9)
    }
}

/// Fails unless `gpu` can render an image of `extent`: at least 1 pixel and at
/// most the largest image and framebuffer side.
pub fn check_extent(gpu: &Gpu, extent: vk::Extent2D) -> Result<()> {
    render::check_nonempty(extent)?;
    render::check_limits(extent, &gpu.physical.get_properties().limits, &gpu.name)
}

/// Renders `frames` frames (at least one) of the scene `make` builds, at
/// `width` x `height`, and reads the last one back. Frame `i` shows scene time
/// `i / 60` s, so the same arguments give the same image.
pub fn render<S: Scene>(
    gpu: &Gpu,
    width: u32,
    height: u32,
    frames: u32,
    make: impl FnOnce(&Gpu, &tuff::RenderPass) -> Result<S>,
) -> Result<Rendered> {
    let extent = vk::Extent2D { width, height };
    check_extent(gpu, extent)?;
    let frames = frames.max(1);
    let render_pass = render::render_pass(
        gpu,
        COLOR_FORMAT,
        S::DEPTH,
        vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
    )?;
    let mut scene = make(gpu, &render_pass)?;
    let usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
    let images = (0..FRAMES_IN_FLIGHT)
        .map(|_| gpu.image(extent, COLOR_FORMAT, usage))
        .collect::<Result<Vec<_>>>()?;
    let targets = Framebuffers::new(gpu, &render_pass, &images, COLOR_FORMAT, extent, S::DEPTH)?;
    let bytes = u64::from(width) * u64::from(height) * 4;
    let readback = gpu.buffer(
        bytes,
        vk::BufferUsageFlags::TRANSFER_DST,
        tuff::MemoryLocation::Readback,
    )?;
    let mut ring = gpu.device.frames_in_flight(gpu.family, FRAMES_IN_FLIGHT)?;
    let start = Instant::now();
    for n in 0..frames {
        let mut frame = ring.next_frame()?;
        let (slot, last) = (frame.index, n + 1 == frames);
        let view = View {
            extent,
            time: n as f32 / 60.0,
            slot,
        };
        scene.update(&view)?;
        let copy = last.then_some((&images[slot], &*readback));
        let framebuffer = &targets.framebuffers[slot];
        render::record_frame(&mut frame, &render_pass, framebuffer, &scene, &view, copy)?;
        frame.submit(&gpu.queue, &[], &[])?;
    }
    ring.wait_all()?;
    let elapsed = start.elapsed();
    let rgba = readback.memory().read(0, bytes as usize)?;
    Ok(Rendered {
        width,
        height,
        rgba,
        frames,
        elapsed,
    })
}
