//! What every scene shares: the render pass, the attachments of a set of color
//! images, and the recording of one frame.

use crate::gpu::Gpu;
use anyhow::Result;
use tuff::vk;

/// Frames the CPU records ahead of the GPU.
pub const FRAMES_IN_FLIGHT: usize = 2;
/// The depth buffer's format, which every implementation supports as an attachment.
pub const DEPTH_FORMAT: vk::Format = vk::Format::D32_SFLOAT;
/// The depth a reversed-Z buffer is cleared to: infinitely far.
pub const DEPTH_CLEAR: f32 = 0.0;

/// Where and when a frame is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// The size of the image drawn into.
    pub extent: vk::Extent2D,
    /// Seconds of scene time: frame index / 60 headless, so images are reproducible.
    pub time: f32,
    /// Which frame in flight records it, `0..FRAMES_IN_FLIGHT`.
    pub slot: usize,
}

/// A scene: pipelines and data made for one render pass, and the draws of a frame.
pub trait Scene {
    /// The background color.
    fn clear_color(&self) -> [f32; 4];

    /// Whether the render pass has a depth attachment.
    const DEPTH: bool = true;

    /// Writes what the frame reads from memory (uniforms). The slot's previous
    /// submission has completed.
    fn update(&mut self, _view: &View) -> Result<()> {
        Ok(())
    }

    /// Records the frame's draws; viewport and scissor are set already. Fails when
    /// tuff refuses a command (a binding outside its buffer, say).
    fn draw(
        &self,
        rec: &mut tuff::Recorder<'_, tuff::InRenderPass>,
        view: &View,
    ) -> tuff::Result<()>;
}

/// The viewport of a whole image of `extent`, depth 0 to 1.
pub fn viewport(extent: vk::Extent2D) -> vk::Viewport {
    vk::Viewport {
        x: 0.0,
        y: 0.0,
        width: extent.width as f32,
        height: extent.height as f32,
        min_depth: 0.0,
        max_depth: 1.0,
    }
}

/// Fails unless both sides of `extent` are at least 1.
pub fn check_nonempty(extent: vk::Extent2D) -> anyhow::Result<()> {
    let vk::Extent2D { width, height } = extent;
    if width == 0 || height == 0 {
        anyhow::bail!("cannot render a {width}x{height} image: both sides must be at least 1");
    }
    Ok(())
}

/// Fails unless the device named `device`, of `limits`, can make an image and a
/// framebuffer of `extent`.
pub fn check_limits(
    extent: vk::Extent2D,
    limits: &vk::PhysicalDeviceLimits,
    device: &str,
) -> anyhow::Result<()> {
    let vk::Extent2D { width, height } = extent;
    let largest = limits
        .max_image_dimension2_d
        .min(limits.max_framebuffer_width)
        .min(limits.max_framebuffer_height);
    if width > largest || height > largest {
        anyhow::bail!(
            "cannot render a {width}x{height} image: \"{device}\" allows at most {largest} pixels a side"
        );
    }
    Ok(())
}

/// A one-subpass render pass that clears a color attachment of `format` (and a
/// depth attachment), stores the color and leaves it in `final_layout`: ready for
/// a copy (headless) or for presentation.
pub fn render_pass(
    gpu: &Gpu,
    format: vk::Format,
    depth: bool,
    final_layout: vk::ImageLayout,
) -> Result<tuff::RenderPass> {
    let mut attachments = vec![vk::AttachmentDescription {
        format,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::CLEAR,
        store_op: vk::AttachmentStoreOp::STORE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: vk::ImageLayout::UNDEFINED,
        final_layout,
        ..Default::default()
    }];
    if depth {
        attachments.push(vk::AttachmentDescription {
            format: DEPTH_FORMAT,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::CLEAR,
            store_op: vk::AttachmentStoreOp::DONT_CARE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            ..Default::default()
        });
    }
    let color = [vk::AttachmentReference {
        attachment: 0,
        layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let depth_ref = vk::AttachmentReference {
        attachment: 1,
        layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    };
    let mut subpass = tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color);
    if depth {
        subpass = subpass.depth_stencil_attachment(Some(&depth_ref));
    }
    let subpasses = [subpass];
    let fragment_tests =
        vk::PipelineStageFlags::EARLY_FRAGMENT_TESTS | vk::PipelineStageFlags::LATE_FRAGMENT_TESTS;
    // The same dependencies serve both final layouts: a presentation is ordered by
    // the semaphores around it, so the transfer stages only add a harmless wait.
    let dependencies = [
        // The previous frame's color and depth writes and its copy (or the
        // presentation engine's read, which the acquire semaphore waits for at the
        // color output stage) come before this frame's clears.
        vk::SubpassDependency {
            src_subpass: vk::SUBPASS_EXTERNAL,
            dst_subpass: 0,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT
                | fragment_tests
                | vk::PipelineStageFlags::TRANSFER,
            dst_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT | fragment_tests,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dst_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE
                | vk::AccessFlags::COLOR_ATTACHMENT_READ
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_READ
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dependency_flags: vk::DependencyFlags::empty(),
        },
        // This frame's color writes come before the copy.
        vk::SubpassDependency {
            src_subpass: 0,
            dst_subpass: vk::SUBPASS_EXTERNAL,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            dst_stage_mask: vk::PipelineStageFlags::TRANSFER,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
            dst_access_mask: vk::AccessFlags::TRANSFER_READ,
            dependency_flags: vk::DependencyFlags::empty(),
        },
    ];
    Ok(gpu.device.create_render_pass(
        &tuff::RenderPassCreateInfo::new()
            .attachments(&attachments)
            .subpasses(&subpasses)
            .dependencies(&dependencies),
    )?)
}

/// Framebuffers over a set of color images (offscreen targets or swapchain images)
/// sharing one depth buffer. Each framebuffer keeps its views, which keep their
/// images, which keep their memory.
pub struct Framebuffers {
    /// One per color image, in its order.
    pub framebuffers: Vec<tuff::Framebuffer>,
    /// Their size.
    pub extent: vk::Extent2D,
}

impl Framebuffers {
    /// Framebuffers of `render_pass` for `images` of `format` and `extent`.
    pub fn new(
        gpu: &Gpu,
        render_pass: &tuff::RenderPass,
        images: &[tuff::Image],
        format: vk::Format,
        extent: vk::Extent2D,
        depth: bool,
    ) -> Result<Framebuffers> {
        let depth = if depth {
            let usage = vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT;
            let image = gpu.image(extent, DEPTH_FORMAT, usage)?;
            Some(gpu.view(&image, DEPTH_FORMAT, vk::ImageAspectFlags::DEPTH)?)
        } else {
            None
        };
        let framebuffers = images
            .iter()
            .map(|image| {
                let view = gpu.view(image, format, vk::ImageAspectFlags::COLOR)?;
                let attachments: Vec<_> = [Some(&view), depth.as_ref()]
                    .into_iter()
                    .flatten()
                    .collect();
                let attachments = tuff::HandleSlice::new(&attachments);
                Ok(gpu.device.create_framebuffer(
                    &tuff::FramebufferCreateInfo::new(render_pass)
                        .attachments(&attachments)
                        .width(extent.width)
                        .height(extent.height)
                        .layers(1),
                )?)
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Framebuffers {
            framebuffers,
            extent,
        })
    }
}

/// Whether [`record_frame`] records with automatic synchronization (the stage
/// benchmark's `tuff-auto` variant).
static AUTO_SYNC: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Makes [`record_frame`] record with `tuff::Recorder::auto_sync(on)`.
pub fn set_auto_sync(on: bool) {
    AUTO_SYNC.store(on, std::sync::atomic::Ordering::Relaxed);
}

/// Whether frames record with automatic synchronization ([`set_auto_sync`]).
pub fn auto_sync() -> bool {
    AUTO_SYNC.load(std::sync::atomic::Ordering::Relaxed)
}

/// Records a frame of `scene` into `frame`: the render pass on `framebuffer`, the
/// scene's draws and, when asked, the copy of an image (in TRANSFER_SRC_OPTIMAL
/// after the render pass) into a buffer, tightly packed, for the host to read.
pub fn record_frame<S: Scene>(
    frame: &mut tuff::Frame<'_>,
    render_pass: &tuff::RenderPass,
    framebuffer: &tuff::Framebuffer,
    scene: &S,
    view: &View,
    readback: Option<(&tuff::Image, &tuff::Buffer)>,
) -> Result<()> {
    let clear = [
        vk::ClearValue {
            color: vk::ClearColorValue {
                float32: scene.clear_color(),
            },
        },
        vk::ClearValue {
            depth_stencil: vk::ClearDepthStencilValue {
                depth: DEPTH_CLEAR,
                stencil: 0,
            },
        },
    ];
    let area: vk::Rect2D = view.extent.into();
    let mut rec = frame.record()?;
    rec.auto_sync(auto_sync());
    let mut rec = rec.begin_render_pass(
        &tuff::RenderPassBeginInfo::new(render_pass, framebuffer)
            .render_area(area)
            // Without a depth attachment, only the color is cleared.
            .clear_values(&clear[..1 + usize::from(S::DEPTH)]),
        vk::SubpassContents::INLINE,
    );
    rec.set_viewport(0, &[viewport(view.extent)])?;
    rec.set_scissor(0, &[area])?;
    scene.draw(&mut rec, view)?;
    let mut rec = rec.end_render_pass();
    if let Some((image, buffer)) = readback {
        record_readback(&mut rec, image, buffer, view.extent)?;
    }
    rec.end()?;
    Ok(())
}

/// Records the copy of the whole color image of `extent` (in TRANSFER_SRC_OPTIMAL) into
/// `buffer`, tightly packed, and the barrier that makes it visible to the host (with
/// automatic synchronization on, the recorder's end records that one).
pub fn record_readback(
    rec: &mut tuff::Recorder<'_, tuff::Outside>,
    image: &tuff::Image,
    buffer: &tuff::Buffer,
    extent: vk::Extent2D,
) -> tuff::Result<()> {
    rec.copy_image_to_buffer(
        image,
        vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
        buffer,
        &[vk::BufferImageCopy {
            image_subresource: vk::ImageSubresourceLayers {
                aspect_mask: vk::ImageAspectFlags::COLOR,
                mip_level: 0,
                base_array_layer: 0,
                layer_count: 1,
            },
            image_extent: extent.into(),
            ..Default::default()
        }],
    )?;
    if rec.is_auto_sync() {
        return Ok(());
    }
    // A fence wait does not make device writes visible to the host; this does.
    let to_host = [tuff::BufferMemoryBarrier::new(buffer)
        .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
        .dst_access_mask(vk::AccessFlags::HOST_READ)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .offset(0)
        .size(vk::WHOLE_SIZE)];
    rec.pipeline_barrier(
        vk::PipelineStageFlags::TRANSFER,
        vk::PipelineStageFlags::HOST,
        vk::DependencyFlags::empty(),
        &[],
        &to_host,
        &[],
    )
}
