//! The teapots' frame loop in raw ash, with each stage timed as in
//! [`super::tuff_frames`]: headless, and in a window (X11 surface, swapchain,
//! recreated when acquire or present says it is out of date or suboptimal).

use super::{Run, Samples, Stage, Timer};
use crate::headless::COLOR_FORMAT;
use crate::raw_ash::{self, Scene as _, Vulkan};
use crate::render::{View, DEPTH_FORMAT, FRAMES_IN_FLIGHT};
use crate::scenes::teapot_grid::Layout;
use crate::teapots_ash::Teapots;
use anyhow::{anyhow, bail, Context as _, Result};
use ash::vk;
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::raw_window_handle::{self, HasDisplayHandle as _, HasWindowHandle as _};
use winit::window::{Window, WindowId};

/// `count` binary semaphores, owned by the objects.
fn semaphores(vulkan: &mut Vulkan, count: usize) -> Result<Vec<vk::Semaphore>> {
    (0..count)
        .map(|_| {
            // SAFETY: a valid create info; the semaphore goes into the objects.
            let s = unsafe {
                vulkan
                    .device
                    .create_semaphore(&vk::SemaphoreCreateInfo::default(), None)
            }
            .context("vkCreateSemaphore")?;
            vulkan.objects.semaphores.push(s);
            Ok(s)
        })
        .collect()
}

/// Renders `run.warmup + run.frames` frames of the teapots headless in raw ash, as
/// [`super::tuff_frames::headless`] does in tuff, and returns the timed frames' stages
/// (and the last frame's pixels).
pub fn headless(vulkan: &mut Vulkan, run: &Run) -> Result<Samples> {
    let extent = vk::Extent2D {
        width: run.size,
        height: run.size,
    };
    let pass = raw_ash::render_pass(
        &vulkan.device,
        COLOR_FORMAT,
        true,
        vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
    )?;
    vulkan.objects.render_pass = pass;
    let layout = Layout::grid(run.count, 1)?;
    let writes = run.writes as usize;
    let mut scene = Teapots::new(&vulkan.device, &mut vulkan.objects, pass, layout, writes)?;
    let device = vulkan.device.clone();
    let o = &mut vulkan.objects;
    let usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
    let color = vk::ImageAspectFlags::COLOR;
    let depth_usage = vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT;
    let (_, depth) = o.image(
        &device,
        extent,
        DEPTH_FORMAT,
        depth_usage,
        vk::ImageAspectFlags::DEPTH,
    )?;
    let bytes = u64::from(run.size) * u64::from(run.size) * 4;
    let mut images = Vec::new();
    let mut readbacks = Vec::new();
    for _ in 0..FRAMES_IN_FLIGHT {
        let (image, view) = o.image(&device, extent, COLOR_FORMAT, usage, color)?;
        let attachments = [view, depth];
        let info = vk::FramebufferCreateInfo::default()
            .render_pass(pass)
            .attachments(&attachments)
            .width(extent.width)
            .height(extent.height)
            .layers(1);
        // SAFETY: a valid create info of live views; the framebuffer goes into `o`.
        let framebuffer =
            unsafe { device.create_framebuffer(&info, None) }.context("vkCreateFramebuffer")?;
        o.framebuffers.push(framebuffer);
        images.push((image, framebuffer));
        let cached = vk::MemoryPropertyFlags::HOST_CACHED;
        let dst = vk::BufferUsageFlags::TRANSFER_DST;
        readbacks.push(o.buffer(&device, bytes, dst, cached)?);
    }
    let frames = raw_ash::frame_slots(vulkan, FRAMES_IN_FLIGHT)?;
    let copies = raw_ash::frame_slots(vulkan, FRAMES_IN_FLIGHT)?;
    let queue = vulkan.queue;
    let mut samples = Samples::new(run.warmup);
    let mut timer = Timer::default();
    // SAFETY: every handle is a live object of `device`; a slot's command buffers are
    // recorded only after their fences say the last submissions of them completed,
    // and each fence is reset right before the submission that signals it; the last
    // frame's readback (host-visible and coherent, never mapped, its copy made visible
    // to the host by the copy's barrier) is read once the device is idle.
    unsafe {
        for n in 0..run.warmup + run.frames {
            let slot = n as usize % FRAMES_IN_FLIGHT;
            timer.start();
            let (cb, fence) = frames[slot];
            device
                .wait_for_fences(&[fence], true, u64::MAX)
                .context("vkWaitForFences")?;
            timer.lap(Stage::Wait);
            let view = View {
                extent,
                time: n as f32 / 60.0,
                slot,
            };
            scene.update(&view);
            timer.lap(Stage::Uniform);
            raw_ash::record_frame(&device, cb, pass, images[slot].1, &scene, &view, None)?;
            timer.lap(Stage::Command);
            let submit = vk::SubmitInfo::default().command_buffers(std::slice::from_ref(&cb));
            device.reset_fences(&[fence]).context("vkResetFences")?;
            device
                .queue_submit(queue, &[submit], fence)
                .context("vkQueueSubmit")?;
            timer.lap(Stage::Submit);
            let (copy, copy_fence) = copies[slot];
            device
                .wait_for_fences(&[copy_fence], true, u64::MAX)
                .context("vkWaitForFences")?;
            timer.lap(Stage::Wait);
            device
                .begin_command_buffer(
                    copy,
                    &vk::CommandBufferBeginInfo::default()
                        .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
                )
                .context("vkBeginCommandBuffer")?;
            raw_ash::record_readback(&device, copy, images[slot].0, readbacks[slot].0, extent);
            device
                .end_command_buffer(copy)
                .context("vkEndCommandBuffer")?;
            // Ordered after the frame by the render pass's dependency on later
            // transfers, as in tuff's loop.
            let submit = vk::SubmitInfo::default().command_buffers(std::slice::from_ref(&copy));
            device
                .reset_fences(&[copy_fence])
                .context("vkResetFences")?;
            device
                .queue_submit(queue, &[submit], copy_fence)
                .context("vkQueueSubmit")?;
            timer.lap(Stage::Present);
            samples.push(&timer);
        }
        device.device_wait_idle().context("vkDeviceWaitIdle")?;
        let last = (run.warmup + run.frames).saturating_sub(1) as usize % FRAMES_IN_FLIGHT;
        samples.last_frame = raw_ash::read_memory(&device, readbacks[last].1, bytes as usize)?;
    }
    Ok(samples)
}

/// Renders `run.warmup + run.frames` frames of the teapots into a window in raw ash,
/// as the tuff scenes' window loop does, and returns the timed frames' stages.
pub fn window(vulkan: &mut Vulkan, run: &Run) -> Result<Samples> {
    let event_loop = EventLoop::new().context(
        "cannot open a window: no X server (set DISPLAY, or run headless without --window)",
    )?;
    event_loop.set_control_flow(ControlFlow::Poll);
    let mut app = App {
        vulkan,
        run: *run,
        live: None,
        window: None,
        error: None,
        samples: Samples::new(run.warmup),
        timer: Timer::default(),
    };
    event_loop.run_app(&mut app)?;
    if let Some(e) = app.error {
        return Err(e);
    }
    Ok(app.samples)
}

struct App<'v> {
    vulkan: &'v mut Vulkan,
    run: Run,
    live: Option<Live>,
    window: Option<Window>,
    error: Option<anyhow::Error>,
    samples: Samples,
    timer: Timer,
}

/// A swapchain's images with their views and framebuffers, and a semaphore per image
/// that its frame's submission signals for the presentation to wait on.
struct Chain {
    swapchain: vk::SwapchainKHR,
    images: Vec<vk::Image>,
    views: Vec<vk::ImageView>,
    framebuffers: Vec<vk::Framebuffer>,
    rendered: Vec<vk::Semaphore>,
    extent: vk::Extent2D,
}

/// The window's surface and swapchain and the frame loop's objects. The surface and
/// the swapchain are destroyed in [`Live::destroy`]; the rest goes with the objects.
struct Live {
    surface_fn: ash::khr::surface::Instance,
    swapchain_fn: ash::khr::swapchain::Device,
    surface: vk::SurfaceKHR,
    format: vk::SurfaceFormatKHR,
    render_pass: vk::RenderPass,
    scene: Teapots,
    chain: Option<Chain>,
    frames: Vec<(vk::CommandBuffer, vk::Fence)>,
    acquired: Vec<vk::Semaphore>,
    stale: bool,
    n: u32,
}

impl Live {
    fn open(vulkan: &mut Vulkan, window: &Window, run: &Run) -> Result<Live> {
        let display = window.display_handle()?.as_raw();
        let handle = window.window_handle()?.as_raw();
        let (
            raw_window_handle::RawDisplayHandle::Xlib(display),
            raw_window_handle::RawWindowHandle::Xlib(handle),
        ) = (display, handle)
        else {
            bail!("the window is not an X11 (Xlib) window");
        };
        let dpy = display
            .display
            .ok_or_else(|| anyhow!("the X11 window has no display"))?;
        let xlib = ash::khr::xlib_surface::Instance::new(&vulkan.entry, &vulkan.instance);
        let info = vk::XlibSurfaceCreateInfoKHR::default()
            .dpy(dpy.as_ptr().cast())
            .window(handle.window);
        // SAFETY: the display and window are the live X11 objects of `window`, which
        // outlives the surface (the app drops the window after `Live::destroy`).
        let surface =
            unsafe { xlib.create_xlib_surface(&info, None) }.context("vkCreateXlibSurfaceKHR")?;
        let surface_fn = ash::khr::surface::Instance::new(&vulkan.entry, &vulkan.instance);
        let swapchain_fn = ash::khr::swapchain::Device::new(&vulkan.instance, &vulkan.device);
        let live = (|| {
            // SAFETY: the surface and physical device are live.
            let (supported, formats) = unsafe {
                (
                    surface_fn.get_physical_device_surface_support(
                        vulkan.physical,
                        vulkan.family,
                        surface,
                    )?,
                    surface_fn.get_physical_device_surface_formats(vulkan.physical, surface)?,
                )
            };
            if !supported {
                bail!("\"{}\" cannot present to this window", vulkan.name);
            }
            let format = formats
                .iter()
                .copied()
                .find(|f| f.format == vk::Format::B8G8R8A8_UNORM)
                .or_else(|| formats.first().copied())
                .ok_or_else(|| anyhow!("the surface offers no formats"))?;
            let pass = raw_ash::render_pass(
                &vulkan.device,
                format.format,
                true,
                vk::ImageLayout::PRESENT_SRC_KHR,
            )?;
            vulkan.objects.render_pass = pass;
            let layout = Layout::grid(run.count, 1)?;
            let writes = run.writes as usize;
            let scene = Teapots::new(&vulkan.device, &mut vulkan.objects, pass, layout, writes)?;
            Ok(Live {
                surface_fn: surface_fn.clone(),
                swapchain_fn,
                surface,
                format,
                render_pass: pass,
                scene,
                chain: None,
                frames: raw_ash::frame_slots(vulkan, FRAMES_IN_FLIGHT)?,
                acquired: semaphores(vulkan, FRAMES_IN_FLIGHT)?,
                stale: true,
                n: 0,
            })
        })();
        if live.is_err() {
            // SAFETY: nothing was made from the surface.
            unsafe { surface_fn.destroy_surface(surface, None) };
        }
        live
    }

    /// Makes a swapchain that matches the window (retiring the old one), with its
    /// views, framebuffers and semaphores; `false` while the window has no area.
    fn refresh(&mut self, vulkan: &mut Vulkan, window: &Window) -> Result<bool> {
        let device = &vulkan.device;
        // SAFETY: the surface and physical device are live; the device is idle before
        // the old swapchain's objects go.
        unsafe {
            let caps = self
                .surface_fn
                .get_physical_device_surface_capabilities(vulkan.physical, self.surface)?;
            let size = window.inner_size();
            let Some(extent) = crate::window::swapchain_extent(&caps, size.width, size.height)
            else {
                return Ok(false);
            };
            device.device_wait_idle().context("vkDeviceWaitIdle")?;
            let count = crate::window::image_count(&caps);
            let old = self.chain.take();
            let info = vk::SwapchainCreateInfoKHR::default()
                .surface(self.surface)
                .min_image_count(count)
                .image_format(self.format.format)
                .image_color_space(self.format.color_space)
                .image_extent(extent)
                .image_array_layers(1)
                .image_usage(vk::ImageUsageFlags::COLOR_ATTACHMENT)
                .image_sharing_mode(vk::SharingMode::EXCLUSIVE)
                .pre_transform(caps.current_transform)
                .composite_alpha(crate::window::composite_alpha(
                    caps.supported_composite_alpha,
                ))
                .present_mode(vk::PresentModeKHR::FIFO)
                .clipped(true)
                .old_swapchain(
                    old.as_ref()
                        .map_or(vk::SwapchainKHR::null(), |c| c.swapchain),
                );
            let made = self.swapchain_fn.create_swapchain(&info, None);
            if let Some(old) = old {
                self.destroy_chain(device, old);
            }
            let swapchain = made.context("vkCreateSwapchainKHR")?;
            let mut chain = Chain {
                swapchain,
                images: Vec::new(),
                views: Vec::new(),
                framebuffers: Vec::new(),
                rendered: Vec::new(),
                extent,
            };
            let made = self.fill_chain(vulkan, &mut chain);
            self.chain = Some(chain);
            made?;
        }
        self.stale = false;
        Ok(true)
    }

    /// The views, framebuffers (with a depth buffer of the chain's extent) and
    /// semaphores of a new swapchain's images.
    fn fill_chain(&self, vulkan: &mut Vulkan, chain: &mut Chain) -> Result<()> {
        let extent = chain.extent;
        let depth_usage = vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT;
        let aspect = vk::ImageAspectFlags::DEPTH;
        // Kept by the objects until the end: a recreation leaves the old one there.
        let (_, depth) =
            vulkan
                .objects
                .image(&vulkan.device, extent, DEPTH_FORMAT, depth_usage, aspect)?;
        let device = &vulkan.device;
        // SAFETY: valid create infos of live objects; each object goes into the chain
        // as soon as it is made, which destroys it before the swapchain.
        unsafe {
            chain.images = self
                .swapchain_fn
                .get_swapchain_images(chain.swapchain)
                .context("vkGetSwapchainImagesKHR")?;
            for &image in &chain.images {
                let view = device
                    .create_image_view(
                        &vk::ImageViewCreateInfo::default()
                            .image(image)
                            .view_type(vk::ImageViewType::TYPE_2D)
                            .format(self.format.format)
                            .subresource_range(vk::ImageSubresourceRange {
                                aspect_mask: vk::ImageAspectFlags::COLOR,
                                base_mip_level: 0,
                                level_count: 1,
                                base_array_layer: 0,
                                layer_count: 1,
                            }),
                        None,
                    )
                    .context("vkCreateImageView")?;
                chain.views.push(view);
                let attachments = [view, depth];
                let framebuffer = device
                    .create_framebuffer(
                        &vk::FramebufferCreateInfo::default()
                            .render_pass(self.render_pass)
                            .attachments(&attachments)
                            .width(extent.width)
                            .height(extent.height)
                            .layers(1),
                        None,
                    )
                    .context("vkCreateFramebuffer")?;
                chain.framebuffers.push(framebuffer);
                let semaphore = device
                    .create_semaphore(&vk::SemaphoreCreateInfo::default(), None)
                    .context("vkCreateSemaphore")?;
                chain.rendered.push(semaphore);
            }
        }
        Ok(())
    }

    /// Destroys a swapchain and what was made for its images.
    ///
    /// # Safety
    ///
    /// The device is idle, or at least nothing pending uses the chain.
    unsafe fn destroy_chain(&self, device: &ash::Device, chain: Chain) {
        // SAFETY: as the caller promises; users go before what they use.
        unsafe {
            for f in chain.framebuffers {
                device.destroy_framebuffer(f, None);
            }
            for v in chain.views {
                device.destroy_image_view(v, None);
            }
            for s in chain.rendered {
                device.destroy_semaphore(s, None);
            }
            self.swapchain_fn.destroy_swapchain(chain.swapchain, None);
        }
    }

    /// Draws and presents one frame, timing its stages; `false` when none was drawn
    /// (the window has no area, or the swapchain went out of date at acquire).
    fn draw(&mut self, vulkan: &mut Vulkan, window: &Window, timer: &mut Timer) -> Result<bool> {
        timer.start();
        if (self.stale || self.chain.is_none()) && !self.refresh(vulkan, window)? {
            return Ok(false);
        }
        timer.lap(Stage::Acquire);
        let slot = self.n as usize % FRAMES_IN_FLIGHT;
        let (cb, fence) = self.frames[slot];
        let device = &vulkan.device;
        let chain = self.chain.as_ref().context("no swapchain")?;
        // SAFETY: every handle is live; the slot's command buffer is recorded only
        // after its fence says its last submission completed; the fence is reset right
        // before the submission that signals it; the image is presented only after the
        // submission that renders it, which signals the semaphore the present waits on.
        unsafe {
            device
                .wait_for_fences(&[fence], true, u64::MAX)
                .context("vkWaitForFences")?;
            timer.lap(Stage::Wait);
            let acquired = self.acquired[slot];
            let index = match self.swapchain_fn.acquire_next_image(
                chain.swapchain,
                u64::MAX,
                acquired,
                vk::Fence::null(),
            ) {
                Ok((index, suboptimal)) => {
                    self.stale |= suboptimal;
                    index as usize
                }
                Err(vk::Result::ERROR_OUT_OF_DATE_KHR) => {
                    self.stale = true;
                    return Ok(false);
                }
                Err(e) => return Err(e).context("vkAcquireNextImageKHR"),
            };
            timer.lap(Stage::Acquire);
            let view = View {
                extent: chain.extent,
                time: self.n as f32 / 60.0,
                slot,
            };
            self.scene.update(&view);
            timer.lap(Stage::Uniform);
            raw_ash::record_frame(
                device,
                cb,
                self.render_pass,
                chain.framebuffers[index],
                &self.scene,
                &view,
                None,
            )?;
            timer.lap(Stage::Command);
            let waits = [acquired];
            let stages = [vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT];
            let signals = [chain.rendered[index]];
            let submit = vk::SubmitInfo::default()
                .command_buffers(std::slice::from_ref(&cb))
                .wait_semaphores(&waits)
                .wait_dst_stage_mask(&stages)
                .signal_semaphores(&signals);
            device.reset_fences(&[fence]).context("vkResetFences")?;
            device
                .queue_submit(vulkan.queue, &[submit], fence)
                .context("vkQueueSubmit")?;
            timer.lap(Stage::Submit);
            let swapchains = [chain.swapchain];
            let indices = [index as u32];
            let present = vk::PresentInfoKHR::default()
                .wait_semaphores(&signals)
                .swapchains(&swapchains)
                .image_indices(&indices);
            match self.swapchain_fn.queue_present(vulkan.queue, &present) {
                Ok(suboptimal) => self.stale |= suboptimal,
                Err(vk::Result::ERROR_OUT_OF_DATE_KHR) => self.stale = true,
                Err(e) => return Err(e).context("vkQueuePresentKHR"),
            }
            timer.lap(Stage::Present);
        }
        self.n += 1;
        Ok(true)
    }

    /// Waits for the device, then destroys the swapchain and the surface.
    fn destroy(mut self, vulkan: &Vulkan) -> Result<()> {
        // SAFETY: after the wait nothing pending uses the chain or the surface; the
        // swapchain goes before its surface.
        unsafe {
            let idle = vulkan.device.device_wait_idle().context("vkDeviceWaitIdle");
            if let Some(chain) = self.chain.take() {
                self.destroy_chain(&vulkan.device, chain);
            }
            self.surface_fn.destroy_surface(self.surface, None);
            idle
        }
    }
}

impl ApplicationHandler for App<'_> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.live.is_some() {
            return;
        }
        let opened = event_loop
            .create_window(
                Window::default_attributes()
                    .with_title("tuff stages (raw ash)")
                    .with_inner_size(PhysicalSize::new(self.run.size, self.run.size)),
            )
            .map_err(anyhow::Error::from)
            .and_then(|window| {
                let live = Live::open(self.vulkan, &window, &self.run)?;
                Ok((window, live))
            });
        match opened {
            Ok((window, live)) => {
                self.window = Some(window);
                self.live = Some(live);
            }
            Err(e) => {
                self.error = Some(e);
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let (Some(live), Some(window)) = (self.live.as_mut(), self.window.as_ref()) else {
            return;
        };
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(_) => live.stale = true,
            WindowEvent::RedrawRequested => match live.draw(self.vulkan, window, &mut self.timer) {
                Ok(drawn) => {
                    if drawn {
                        self.samples.push(&self.timer);
                    }
                    if self.samples.seen() >= self.run.warmup + self.run.frames {
                        event_loop.exit();
                    }
                }
                Err(e) => {
                    self.error = Some(e);
                    event_loop.exit();
                }
            },
            _ => {}
        }
    }

    fn about_to_wait(&mut self, _event_loop: &ActiveEventLoop) {
        if let Some(window) = &self.window {
            window.request_redraw();
        }
    }

    fn exiting(&mut self, _event_loop: &ActiveEventLoop) {
        if let Some(live) = self.live.take() {
            if let Err(e) = live.destroy(self.vulkan) {
                self.error.get_or_insert(e);
            }
        }
        // The surface is gone; the window may go.
        self.window = None;
    }
}
