//! Rendering into a winit window through a swapchain, recreated (through
//! `SwapchainKHR::recreate`, which retires the old one) on resize and whenever
//! acquire or present says the swapchain is out of date or suboptimal.

use crate::cli::Common;
use crate::gpu::Gpu;
use crate::render::{self, Framebuffers, Scene, View, FRAMES_IN_FLIGHT};
use crate::stages::{Samples, Stage, Timer};
use anyhow::{anyhow, bail, Context as _, Result};
use std::time::Instant;
use tuff::vk;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::window::{Window, WindowId};

/// The sizes `--resizes` cycles through: tiny, extreme aspect ratios, and ordinary.
const RESIZES: [(u32, u32); 10] = [
    (320, 240),
    (1, 1),
    (640, 32),
    (24, 480),
    (2, 300),
    (300, 2),
    (512, 512),
    (97, 61),
    (800, 600),
    (33, 33),
];

/// What scripted resize number `n` does: the sizes of [`RESIZES`] first, then sizes
/// drawn from a fixed sequence (most ordinary, some of one to four pixels a side),
/// every 25th `0x0`, and every 50th a minimise and, at the next step, a restore.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Step {
    Size(u32, u32),
    Minimise,
    Restore,
}

fn step(n: u32) -> Step {
    if let Some(&(w, h)) = RESIZES.get(n as usize) {
        return Step::Size(w, h);
    }
    match n % 50 {
        0 => return Step::Minimise,
        1 => return Step::Restore,
        25 => return Step::Size(0, 0),
        _ => {}
    }
    // splitmix64: the same sizes on every run.
    let mut z = u64::from(n).wrapping_mul(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^= z >> 31;
    let side = |bits: u64| match bits % 8 {
        0 => 1 + (bits >> 3) as u32 % 4,
        _ => 1 + (bits >> 3) as u32 % 1024,
    };
    Step::Size(side(z & 0xffff_ffff), side(z >> 32))
}

/// The instance extensions a window on X11 needs.
pub const INSTANCE_EXTENSIONS: [tuff::CStrPtr<'static>; 2] = [
    tuff::CStrPtr::new(c"VK_KHR_surface"),
    tuff::CStrPtr::new(c"VK_KHR_xlib_surface"),
];
/// The device extensions presenting to a window needs.
pub const DEVICE_EXTENSIONS: [tuff::CStrPtr<'static>; 1] =
    [tuff::CStrPtr::new(c"VK_KHR_swapchain")];

/// Frames drawn between one resize request and the next.
const FRAMES_PER_RESIZE: u32 = 2;

/// Opens a window, renders the scene `make` builds until the window closes (or
/// `--frames` frames are drawn, or `--resizes` resizes are done), and prints what
/// happened.
pub fn run<S: Scene>(
    gpu: &Gpu,
    common: &Common,
    make: impl Fn(&Gpu, &tuff::RenderPass) -> Result<S>,
) -> Result<()> {
    run_with(gpu, common, make, 0, true).map(|_| ())
}

/// [`run`], timing each drawn frame's stages (see [`crate::stages`]); the first
/// `warmup` drawn frames are not kept.
pub fn run_timed<S: Scene>(
    gpu: &Gpu,
    common: &Common,
    make: impl Fn(&Gpu, &tuff::RenderPass) -> Result<S>,
    warmup: u32,
) -> Result<Samples> {
    run_with(gpu, common, make, warmup, false)
}

/// [`run_timed`], printing what happened at the end when `report` is set.
fn run_with<S: Scene>(
    gpu: &Gpu,
    common: &Common,
    make: impl Fn(&Gpu, &tuff::RenderPass) -> Result<S>,
    warmup: u32,
    report: bool,
) -> Result<Samples> {
    let event_loop = EventLoop::new().context(
        "cannot open a window: no X server (set DISPLAY, or run headless without --window)",
    )?;
    event_loop.set_control_flow(ControlFlow::Poll);
    let mut app = App {
        gpu,
        common,
        make,
        live: None,
        error: None,
        samples: Samples::new(warmup),
        timer: Timer::default(),
        report,
    };
    event_loop.run_app(&mut app)?;
    if let Some(e) = app.error {
        return Err(e);
    }
    Ok(app.samples)
}

/// The window's state once it exists. Field order is drop order: everything made
/// from the surface goes before it, and the window goes last.
struct Live<S> {
    scene: S,
    framebuffers: Option<Framebuffers>,
    /// One per swapchain image: signalled when the frame drawn into it is done.
    rendered: Vec<tuff::Semaphore>,
    images: Vec<tuff::Image>,
    swapchain: Option<tuff::SwapchainKHR>,
    frames: tuff::FramesInFlight,
    /// One per frame in flight: signalled by the acquire of the image it draws into.
    acquired: Vec<tuff::Semaphore>,
    render_pass: tuff::RenderPass,
    format: vk::SurfaceFormatKHR,
    surface: tuff::SurfaceKHR,
    window: tuff::runtime::Vrc<Window>,
    /// The swapchain no longer matches the window.
    stale: bool,
    /// The window may have changed size: compare before the next frame.
    resized: bool,
    frame: u64,
    start: Instant,
    recreations: u32,
    resizes_requested: u32,
    frames_since_request: u32,
    paused_frames: u64,
    /// The window has no area: wait for events instead of polling.
    paused: bool,
    /// Each swapchain's extent, in order (repeats of the last one left out).
    extents: Vec<vk::Extent2D>,
    /// Resident memory after the first tenth of the scripted resizes.
    resident: crate::headless::Resident,
}

struct App<'g, S, F> {
    gpu: &'g Gpu,
    common: &'g Common,
    make: F,
    live: Option<Live<S>>,
    error: Option<anyhow::Error>,
    samples: Samples,
    timer: Timer,
    /// Print the frame count, resizes and extents at the end.
    report: bool,
}

impl<S: Scene, F: Fn(&Gpu, &tuff::RenderPass) -> Result<S>> App<'_, S, F> {
    fn open(&self, event_loop: &ActiveEventLoop) -> Result<Live<S>> {
        let gpu = self.gpu;
        let window = event_loop.create_window(
            Window::default_attributes()
                .with_title("tuff")
                .with_inner_size(PhysicalSize::new(
                    self.common.width.max(1),
                    self.common.height.max(1),
                )),
        )?;
        // The surface keeps the window alive, and its swapchains keep the surface.
        let window = tuff::runtime::Vrc::new(window);
        let surface = gpu.instance.create_surface(window.clone())?;
        if !gpu.physical.get_surface_support_khr(gpu.family, &surface)? {
            bail!("\"{}\" cannot present to this window", gpu.name);
        }
        let formats = gpu.physical.get_surface_formats_khr(Some(&surface))?;
        // Unorm, as headless, so a window shows the same colors as the PNG.
        let format = formats
            .iter()
            .copied()
            .find(|f| f.format == vk::Format::B8G8R8A8_UNORM)
            .or_else(|| formats.first().copied())
            .ok_or_else(|| anyhow!("the surface offers no formats"))?;
        let render_pass = render::render_pass(
            gpu,
            format.format,
            S::DEPTH,
            vk::ImageLayout::PRESENT_SRC_KHR,
        )?;
        let scene = (self.make)(gpu, &render_pass)?;
        Ok(Live {
            scene,
            framebuffers: None,
            rendered: Vec::new(),
            images: Vec::new(),
            swapchain: None,
            frames: gpu.device.frames_in_flight(gpu.family, FRAMES_IN_FLIGHT)?,
            acquired: (0..FRAMES_IN_FLIGHT)
                .map(|_| {
                    gpu.device
                        .create_semaphore(&tuff::SemaphoreCreateInfo::new())
                })
                .collect::<tuff::Result<_>>()?,
            render_pass,
            format,
            surface,
            window,
            stale: true,
            resized: false,
            frame: 0,
            start: Instant::now(),
            recreations: 0,
            resizes_requested: 0,
            frames_since_request: 0,
            paused_frames: 0,
            paused: false,
            extents: Vec::new(),
            resident: crate::headless::Resident::default(),
        })
    }
}

/// A composite alpha mode the surface supports, opaque where it can be.
pub fn composite_alpha(supported: vk::CompositeAlphaFlagsKHR) -> vk::CompositeAlphaFlagsKHR {
    [
        vk::CompositeAlphaFlagsKHR::OPAQUE,
        vk::CompositeAlphaFlagsKHR::INHERIT,
        vk::CompositeAlphaFlagsKHR::PRE_MULTIPLIED,
        vk::CompositeAlphaFlagsKHR::POST_MULTIPLIED,
    ]
    .into_iter()
    .find(|mode| supported.contains(*mode))
    // The specification requires at least one bit to be set.
    .unwrap_or(vk::CompositeAlphaFlagsKHR::OPAQUE)
}

/// How many images to ask a swapchain for: two at least (one shown, one drawn), within
/// what the surface allows (a maximum of 0 means no limit).
pub fn image_count(caps: &vk::SurfaceCapabilitiesKHR) -> u32 {
    let count = caps.min_image_count.max(2);
    if caps.max_image_count == 0 {
        count
    } else {
        count.min(caps.max_image_count)
    }
}

/// The swapchain size for a window of `width` x `height` pixels, or `None` while it
/// has no area (minimised), when rendering pauses rather than failing: a swapchain
/// cannot have a zero extent.
pub fn swapchain_extent(
    caps: &vk::SurfaceCapabilitiesKHR,
    width: u32,
    height: u32,
) -> Option<vk::Extent2D> {
    if width == 0 || height == 0 {
        return None;
    }
    // u32::MAX means the surface takes the swapchain's size, within the limits.
    let extent = if caps.current_extent.width == u32::MAX {
        vk::Extent2D {
            width: width.clamp(caps.min_image_extent.width, caps.max_image_extent.width),
            height: height.clamp(caps.min_image_extent.height, caps.max_image_extent.height),
        }
    } else {
        caps.current_extent
    };
    (extent.width > 0 && extent.height > 0).then_some(extent)
}

impl<S: Scene> Live<S> {
    /// Makes the swapchain match the window: `None` while the window has no area
    /// (minimised), when rendering pauses.
    fn refresh(&mut self, gpu: &Gpu) -> Result<Option<vk::Extent2D>> {
        // Until a resize event or an acquire or present result says otherwise, the
        // swapchain still fits: no surface query on the per-frame path.
        if let (false, false, Some(framebuffers)) = (self.stale, self.resized, &self.framebuffers) {
            return Ok(Some(framebuffers.extent));
        }
        self.resized = false;
        let caps = gpu.physical.get_surface_capabilities_khr(&self.surface)?;
        let size = self.window.inner_size();
        let Some(extent) = swapchain_extent(&caps, size.width, size.height) else {
            // Looked at again every frame until the window has an area.
            self.resized = true;
            return Ok(None);
        };
        if let (false, Some(framebuffers)) = (self.stale, &self.framebuffers) {
            if framebuffers.extent == extent {
                return Ok(Some(extent));
            }
        }
        // Every frame that used the old images, and every present waiting on their
        // semaphores, is done before they go.
        gpu.device.wait_idle()?;
        let count = image_count(&caps);
        let info = tuff::SwapchainCreateInfoKHR::new(&self.surface)
            .min_image_count(count)
            .image_format(self.format.format)
            .image_color_space(self.format.color_space)
            .image_extent(extent)
            .image_array_layers(1)
            .image_usage(vk::ImageUsageFlags::COLOR_ATTACHMENT)
            .image_sharing_mode(vk::SharingMode::EXCLUSIVE)
            .pre_transform(caps.current_transform)
            .composite_alpha(composite_alpha(caps.supported_composite_alpha))
            .present_mode(vk::PresentModeKHR::FIFO)
            .clipped(true);
        let swapchain = match &self.swapchain {
            Some(old) => {
                let new = old.recreate(&gpu.device, &self.surface, &info)?;
                self.recreations += 1;
                new
            }
            None => gpu.device.create_swapchain_khr(&self.surface, &info)?,
        };
        self.framebuffers = None;
        self.images = gpu.device.get_swapchain_images_khr(&swapchain)?;
        self.swapchain = Some(swapchain);
        self.rendered = self
            .images
            .iter()
            .map(|_| {
                gpu.device
                    .create_semaphore(&tuff::SemaphoreCreateInfo::new())
            })
            .collect::<tuff::Result<_>>()?;
        self.framebuffers = Some(Framebuffers::new(
            gpu,
            &self.render_pass,
            &self.images,
            self.format.format,
            extent,
            S::DEPTH,
        )?);
        self.stale = false;
        if self.extents.last() != Some(&extent) {
            self.extents.push(extent);
        }
        Ok(Some(extent))
    }

    /// Draws and presents one frame, or nothing while the window has no area.
    fn draw(&mut self, gpu: &Gpu, timer: &mut Timer) -> Result<bool> {
        timer.start();
        let Some(extent) = self.refresh(gpu)? else {
            self.paused_frames += 1;
            self.paused = true;
            return Ok(false);
        };
        // A recreated swapchain counts as acquiring.
        timer.lap(Stage::Acquire);
        let mut frame = self.frames.next_frame()?;
        timer.lap(Stage::Wait);
        let acquired = &self.acquired[frame.index];
        let swapchain = self.swapchain.as_ref().context("no swapchain")?;
        let index =
            match gpu
                .device
                .acquire_next_image_khr(swapchain, u64::MAX, Some(acquired), None)
            {
                Ok((index, tuff::SuccessTimeoutNotReadyOrSuboptimal::Success)) => index as usize,
                Ok((index, tuff::SuccessTimeoutNotReadyOrSuboptimal::Suboptimal)) => {
                    self.stale = true;
                    index as usize
                }
                // No timeout was asked for, so no image is a driver fault.
                Ok((_, status)) => {
                    anyhow::bail!("acquiring an image without a timeout: {status:?}")
                }
                Err(tuff::Error::Vk(vk::Result::ERROR_OUT_OF_DATE_KHR)) => {
                    self.stale = true;
                    return Ok(false);
                }
                Err(e) => return Err(e.into()),
            };
        timer.lap(Stage::Acquire);
        let view = View {
            extent,
            time: self.start.elapsed().as_secs_f32(),
            slot: frame.index,
        };
        self.scene.update(&view)?;
        timer.lap(Stage::Uniform);
        let framebuffers = self.framebuffers.as_ref().context("no framebuffers")?;
        let framebuffer = &framebuffers.framebuffers[index];
        render::record_frame(
            &mut frame,
            &self.render_pass,
            framebuffer,
            &self.scene,
            &view,
            None,
        )?;
        timer.lap(Stage::Command);
        let stage = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        let rendered = &self.rendered[index];
        frame.submit(&gpu.queue, &[(acquired, stage)], &[rendered])?;
        timer.lap(Stage::Submit);
        let swapchains = tuff::HandleSlice::new(&[swapchain]);
        let indices = [index as u32];
        match gpu.queue.present_khr(
            &tuff::PresentInfoKHR::new()
                .wait_semaphores(rendered)
                .swapchains(&swapchains, &indices)?,
        ) {
            Ok(status) => self.stale |= status == tuff::SuccessOrSuboptimal::Suboptimal,
            Err(tuff::Error::Vk(vk::Result::ERROR_OUT_OF_DATE_KHR)) => self.stale = true,
            Err(e) => return Err(e.into()),
        }
        timer.lap(Stage::Present);
        self.frame += 1;
        Ok(true)
    }
}

impl<S: Scene, F: Fn(&Gpu, &tuff::RenderPass) -> Result<S>> ApplicationHandler for App<'_, S, F> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.live.is_some() {
            return;
        }
        match self.open(event_loop) {
            Ok(live) => self.live = Some(live),
            Err(e) => {
                self.error = Some(e);
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(live) = self.live.as_mut() else {
            return;
        };
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(_) => {
                live.resized = true;
                live.paused = false;
            }
            WindowEvent::RedrawRequested => {
                let drawn = match live.draw(self.gpu, &mut self.timer) {
                    Ok(drawn) => drawn,
                    Err(e) => {
                        self.error = Some(e);
                        event_loop.exit();
                        return;
                    }
                };
                let common = self.common;
                if drawn {
                    self.samples.push(&self.timer);
                }
                // While the window has no area, scripted steps go on at the pace of
                // the wake-ups `about_to_wait` asks for.
                if drawn || live.paused {
                    live.frames_since_request += 1;
                }
                // Scripted resizes, for tests: wait a few frames between them.
                if common.resizes > 0 {
                    if live.frames_since_request >= FRAMES_PER_RESIZE {
                        if live.resizes_requested == common.resizes {
                            event_loop.exit();
                            return;
                        }
                        match step(live.resizes_requested) {
                            // The window manager (if any) may refuse; the swapchain
                            // follows whatever size the window ends up with.
                            Step::Size(w, h) => {
                                let _ = live.window.request_inner_size(PhysicalSize::new(w, h));
                            }
                            Step::Minimise => live.window.set_minimized(true),
                            Step::Restore => live.window.set_minimized(false),
                        }
                        live.resident
                            .after_frame(live.resizes_requested + 1, common.resizes);
                        // Look at the surface again next frame rather than wait for
                        // the resize event.
                        live.resized = true;
                        live.resizes_requested += 1;
                        live.frames_since_request = 0;
                    }
                } else if common
                    .frames
                    .is_some_and(|f| f > 0 && live.frame >= u64::from(f))
                {
                    event_loop.exit();
                }
            }
            _ => {}
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if let Some(live) = &self.live {
            // While minimised nothing is drawn; sleep until an event (a resize) comes,
            // or, with scripted resizes, until the next step is due.
            if live.paused && self.common.resizes > 0 {
                let due = Instant::now() + std::time::Duration::from_millis(10);
                event_loop.set_control_flow(ControlFlow::WaitUntil(due));
                live.window.request_redraw();
            } else if live.paused {
                event_loop.set_control_flow(ControlFlow::Wait);
            } else {
                event_loop.set_control_flow(ControlFlow::Poll);
                live.window.request_redraw();
            }
        }
    }

    fn exiting(&mut self, _event_loop: &ActiveEventLoop) {
        let Some(live) = self.live.take() else {
            return;
        };
        // Nothing may go while the GPU or the presentation engine still uses it.
        if let Err(e) = self.gpu.device.wait_idle() {
            self.error.get_or_insert(e.into());
        }
        if !self.report {
            return;
        }
        let seconds = live.start.elapsed().as_secs_f64();
        let mut resident = live.resident;
        resident.finish();
        println!(
            "window: {} frames in {:.2} s ({:.1} frames/s), {} resizes, {} swapchain recreations, {} frames paused{}",
            live.frame,
            seconds,
            live.frame as f64 / seconds.max(1e-9),
            live.resizes_requested,
            live.recreations,
            live.paused_frames,
            resident.describe("resize", live.resizes_requested)
        );
        let extents: Vec<String> = live
            .extents
            .iter()
            .map(|e| format!("{}x{}", e.width, e.height))
            .collect();
        println!("swapchain extents: {}", extents.join(" "));
        drop(live);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_storm_has_every_kind_of_step() {
        let steps: Vec<Step> = (0..500).map(step).collect();
        assert_eq!(
            steps[..RESIZES.len()],
            RESIZES.map(|(w, h)| Step::Size(w, h))
        );
        assert_eq!(
            (steps[50], steps[51], steps[75]),
            (Step::Minimise, Step::Restore, Step::Size(0, 0))
        );
        let sizes: Vec<(u32, u32)> = steps
            .iter()
            .filter_map(|s| match *s {
                Step::Size(w, h) => Some((w, h)),
                _ => None,
            })
            .collect();
        assert!(sizes.iter().filter(|&&(w, h)| w <= 4 || h <= 4).count() > 50);
        assert!(sizes.iter().all(|&(w, h)| w <= 1024 && h <= 1024));
        assert!(sizes.iter().filter(|&&(w, h)| w > 512 && h > 512).count() > 50);
        assert_eq!(steps, (0..500).map(step).collect::<Vec<_>>());
    }

    fn caps(current: (u32, u32)) -> vk::SurfaceCapabilitiesKHR {
        vk::SurfaceCapabilitiesKHR {
            current_extent: vk::Extent2D {
                width: current.0,
                height: current.1,
            },
            min_image_extent: vk::Extent2D {
                width: 1,
                height: 1,
            },
            max_image_extent: vk::Extent2D {
                width: 16384,
                height: 16384,
            },
            ..Default::default()
        }
    }

    #[test]
    fn a_minimised_window_pauses_and_tiny_ones_render() {
        // X11 and most platforms report the window's size as the current extent.
        assert_eq!(swapchain_extent(&caps((0, 0)), 0, 0), None);
        assert_eq!(swapchain_extent(&caps((0, 600)), 0, 600), None);
        assert_eq!(
            swapchain_extent(&caps((1, 1)), 1, 1),
            Some(vk::Extent2D {
                width: 1,
                height: 1
            })
        );
        assert_eq!(
            swapchain_extent(&caps((4096, 1)), 4096, 1),
            Some(vk::Extent2D {
                width: 4096,
                height: 1
            })
        );
        // Where the surface follows the swapchain, the window's size is clamped into
        // the surface's limits.
        let free = caps((u32::MAX, u32::MAX));
        assert_eq!(swapchain_extent(&free, 0, 0), None);
        assert_eq!(
            swapchain_extent(&free, 99_999, 20),
            Some(vk::Extent2D {
                width: 16384,
                height: 20
            })
        );
    }
}
