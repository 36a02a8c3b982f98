//! What every scene shares: the render pass, the attachments of a set of color
//! images, the frames in flight, and the recording of one frame.

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
    /// Which frame-in-flight slot records it, `0..FRAMES_IN_FLIGHT`.
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

    /// Records the frame's draws; viewport and scissor are set already.
    fn draw(&self, rec: &mut tuff::Recorder<'_, tuff::InRenderPass>, view: &View);
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
    let (after_stage, after_access) = if final_layout == vk::ImageLayout::TRANSFER_SRC_OPTIMAL {
        (
            vk::PipelineStageFlags::TRANSFER,
            vk::AccessFlags::TRANSFER_READ,
        )
    } else {
        (
            vk::PipelineStageFlags::BOTTOM_OF_PIPE,
            vk::AccessFlags::empty(),
        )
    };
    let dependencies = [
        // The previous frame's color writes (and reads of the copy or the presentation
        // engine, which the acquire semaphore waits for at this stage) and depth writes
        // come before this frame's clears.
        vk::SubpassDependency {
            src_subpass: vk::SUBPASS_EXTERNAL,
            dst_subpass: 0,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT
                | fragment_tests
                | after_stage,
            dst_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT | fragment_tests,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dst_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE
                | vk::AccessFlags::COLOR_ATTACHMENT_READ
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_READ
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dependency_flags: vk::DependencyFlags::empty(),
        },
        // This frame's color writes come before the copy or the presentation.
        vk::SubpassDependency {
            src_subpass: 0,
            dst_subpass: vk::SUBPASS_EXTERNAL,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            dst_stage_mask: after_stage,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
            dst_access_mask: after_access,
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
/// sharing one depth buffer.
pub struct Framebuffers {
    /// One per color image, in its order.
    pub framebuffers: Vec<tuff::Framebuffer>,
    /// Their size.
    pub extent: vk::Extent2D,
    // The views keep their images, which keep their memory.
    _depth: Option<tuff::ImageView>,
    _views: Vec<tuff::ImageView>,
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
        let views = images
            .iter()
            .map(|i| gpu.view(i, format, vk::ImageAspectFlags::COLOR))
            .collect::<Result<Vec<_>>>()?;
        let framebuffers = views
            .iter()
            .map(|view| {
                let mut attachments = vec![view];
                attachments.extend(depth.as_ref());
                let attachments = tuff::HandleSlice::new(&attachments);
                gpu.device.create_framebuffer(
                    &tuff::FramebufferCreateInfo::new(render_pass)
                        .attachments(&attachments)
                        .width(extent.width)
                        .height(extent.height)
                        .layers(1),
                )
            })
            .collect::<tuff::Result<Vec<_>>>()?;
        Ok(Framebuffers {
            framebuffers,
            extent,
            _depth: depth,
            _views: views,
        })
    }
}

/// One frame-in-flight slot: its command buffer, the fence of its last submission,
/// and the semaphore an acquire signals.
pub struct Slot {
    /// Recorded anew each frame.
    pub commands: tuff::CommandBuffer,
    /// Signalled when the slot's last submission completed (created signalled).
    pub done: tuff::Fence,
    /// Signalled by the acquire of the image this slot draws into (windowed only).
    pub acquired: Option<tuff::Semaphore>,
}

/// The frames in flight.
pub struct Slots {
    /// `FRAMES_IN_FLIGHT` slots.
    pub slots: Vec<Slot>,
    _pool: tuff::CommandPool,
}

impl Slots {
    /// `FRAMES_IN_FLIGHT` slots on the gpu's queue family, with acquire semaphores
    /// when `acquire` (for a swapchain).
    pub fn new(gpu: &Gpu, acquire: bool) -> Result<Slots> {
        let d = &gpu.device;
        let pool = d.create_command_pool(
            &tuff::CommandPoolCreateInfo::new()
                .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                .queue_family_index(gpu.family),
        )?;
        let buffers = d.allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool)
                .level(vk::CommandBufferLevel::PRIMARY)
                .command_buffer_count(FRAMES_IN_FLIGHT as u32),
        )?;
        let slots = buffers
            .into_iter()
            .map(|commands| {
                Ok(Slot {
                    commands,
                    done: d.create_fence(
                        &tuff::FenceCreateInfo::new().flags(vk::FenceCreateFlags::SIGNALED),
                    )?,
                    acquired: if acquire {
                        Some(d.create_semaphore(&tuff::SemaphoreCreateInfo::new())?)
                    } else {
                        None
                    },
                })
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Slots { slots, _pool: pool })
    }

    /// Waits until slot `i`'s last submission completed.
    pub fn wait(&self, gpu: &Gpu, i: usize) -> Result<()> {
        let r = gpu
            .device
            .wait_for_fences(&[&self.slots[i].done], vk::TRUE, u64::MAX)?;
        waited(r)
    }

    /// Waits for every slot's last submission.
    pub fn wait_all(&self, gpu: &Gpu) -> Result<()> {
        let fences: Vec<&tuff::Fence> = self.slots.iter().map(|s| &s.done).collect();
        let r = gpu.device.wait_for_fences(&fences, vk::TRUE, u64::MAX)?;
        waited(r)
    }
}

/// A wait without timeout ends in SUCCESS; anything else is an error.
fn waited(r: vk::Result) -> Result<()> {
    if r != vk::Result::SUCCESS {
        anyhow::bail!("waiting for a frame's fence returned {r:?}");
    }
    Ok(())
}

/// A copy of a color image into a buffer, recorded after the render pass.
pub struct Readback<'a> {
    /// The image, in TRANSFER_SRC_OPTIMAL after the render pass.
    pub image: &'a tuff::Image,
    /// Receives the tightly packed pixels.
    pub buffer: &'a tuff::Buffer,
}

/// Records a frame of `scene` into `commands`: the render pass on `framebuffer`,
/// the scene's draws and, when asked, the copy of the image into a buffer.
pub fn record_frame<S: Scene>(
    commands: &mut tuff::CommandBuffer,
    render_pass: &tuff::RenderPass,
    framebuffer: &tuff::Framebuffer,
    scene: &S,
    view: &View,
    readback: Option<Readback<'_>>,
) -> Result<()> {
    let mut clear = vec![vk::ClearValue {
        color: vk::ClearColorValue {
            float32: scene.clear_color(),
        },
    }];
    if S::DEPTH {
        clear.push(vk::ClearValue {
            depth_stencil: vk::ClearDepthStencilValue {
                depth: DEPTH_CLEAR,
                stencil: 0,
            },
        });
    }
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: view.extent,
    };
    let rec = commands.begin(
        &tuff::CommandBufferBeginInfo::new().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
    )?;
    let mut rec = rec.cmd_begin_render_pass(
        &tuff::RenderPassBeginInfo::new(render_pass, framebuffer)
            .render_area(area)
            .clear_values(&clear),
        vk::SubpassContents::INLINE,
    );
    rec.cmd_set_viewport(
        0,
        &[vk::Viewport {
            x: 0.0,
            y: 0.0,
            width: view.extent.width as f32,
            height: view.extent.height as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        }],
    );
    rec.cmd_set_scissor(0, &[area]);
    scene.draw(&mut rec, view);
    let mut rec = rec.cmd_end_render_pass();
    if let Some(readback) = readback {
        rec.cmd_copy_image_to_buffer(
            readback.image,
            vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            readback.buffer,
            &[vk::BufferImageCopy {
                image_subresource: vk::ImageSubresourceLayers {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    mip_level: 0,
                    base_array_layer: 0,
                    layer_count: 1,
                },
                image_extent: view.extent.into(),
                ..Default::default()
            }],
        );
        // A fence wait does not make device writes visible to the host; this does.
        let to_host = [tuff::BufferMemoryBarrier::new(readback.buffer)
            .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(vk::AccessFlags::HOST_READ)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .offset(0)
            .size(vk::WHOLE_SIZE)];
        rec.cmd_pipeline_barrier(
            vk::PipelineStageFlags::TRANSFER,
            vk::PipelineStageFlags::HOST,
            vk::DependencyFlags::empty(),
            &[],
            &to_host,
            &[],
        );
    }
    rec.end()?;
    Ok(())
}
