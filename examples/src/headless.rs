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
    /// Resident memory through the run: whether frames leak.
    pub resident: Resident,
}

/// The process's resident memory after the first tenth of a run's frames and after
/// the last one (completed): a run that leaks per frame grows between the two. Read
/// from `/proc/self/status` (`VmRSS`); empty elsewhere, and for runs of fewer than
/// 10 frames.
#[derive(Clone, Copy, Debug, Default)]
pub struct Resident {
    /// The frame after which the first reading was taken, and the bytes.
    pub early: Option<(u32, u64)>,
    /// The bytes after the last frame completed.
    pub last: Option<u64>,
}

impl Resident {
    /// Takes the first reading if `frame` (counted from 1) of `frames` is the last of
    /// the run's first tenth (a frame, or any step a run counts).
    pub fn after_frame(&mut self, frame: u32, frames: u32) {
        if frames >= 10 && frame == frames / 10 {
            self.early = resident_bytes().map(|b| (frame, b));
        }
    }

    /// Takes the last reading, once the last frame completed.
    pub fn finish(&mut self) {
        if self.early.is_some() {
            self.last = resident_bytes();
        }
    }

    /// `"; resident memory 41.2 MiB after frame 1000, 41.3 MiB after frame 10000
    /// (+0.2 %)"` (`unit` is `frame`), or nothing without both readings.
    pub fn describe(&self, unit: &str, frames: u32) -> String {
        let (Some((frame, early)), Some(last)) = (self.early, self.last) else {
            return String::new();
        };
        let mib = |b: u64| b as f64 / (1024.0 * 1024.0);
        format!(
            "; resident memory {:.1} MiB after {unit} {frame}, {:.1} MiB after {unit} {frames} ({:+.1} %)",
            mib(early),
            mib(last),
            (last as f64 / early as f64 - 1.0) * 100.0
        )
    }
}

/// This process's resident memory in bytes (`VmRSS` of `/proc/self/status`).
pub fn resident_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
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
    let mut resident = Resident::default();
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
        resident.after_frame(n + 1, frames);
    }
    ring.wait_all()?;
    let elapsed = start.elapsed();
    resident.finish();
    let rgba = readback.memory().read(0, bytes as usize)?;
    Ok(Rendered {
        width,
        height,
        rgba,
        frames,
        elapsed,
        resident,
    })
}
