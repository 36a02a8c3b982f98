//! The teapots' frame loop through vulkano, the stage benchmark's peer: written as
//! vulkano's guide and examples teach it (its memory and descriptor set allocators,
//! `Subbuffer`s, the automatic command buffer builder, futures with a fence per frame
//! in flight), drawing what [`super::ash_frames`] and [`super::tuff_frames`] draw:
//! the same grid, render pass, pipeline state, uniform writes and push constants,
//! read back the same way. Headless only.

use super::{Run, Samples, Stage, Timer};
use crate::headless::COLOR_FORMAT;
use crate::render::{View, DEPTH_CLEAR, DEPTH_FORMAT, FRAMES_IN_FLIGHT};
use crate::scenes::teapot_grid::{mesh_data, vertex_input, CameraBlock, Layout, TeapotBlock};
use anyhow::{anyhow, Context as _, Result};
use ash::vk;
use std::sync::Arc;
use vulkano::buffer::{Buffer, BufferCreateInfo, BufferUsage, Subbuffer};
use vulkano::command_buffer::allocator::StandardCommandBufferAllocator;
use vulkano::command_buffer::{
    AutoCommandBufferBuilder, CommandBufferExecFuture, CommandBufferUsage, CopyImageToBufferInfo,
    RenderPassBeginInfo, SubpassBeginInfo, SubpassContents, SubpassEndInfo,
};
use vulkano::descriptor_set::allocator::StandardDescriptorSetAllocator;
use vulkano::descriptor_set::{DescriptorSet, WriteDescriptorSet};
use vulkano::device::physical::PhysicalDeviceType;
use vulkano::device::{
    Device, DeviceCreateInfo, DeviceFeatures, Queue, QueueCreateInfo, QueueFlags,
};
use vulkano::format::Format;
use vulkano::image::view::ImageView;
use vulkano::image::{Image, ImageCreateInfo, ImageLayout, ImageType, ImageUsage, SampleCount};
use vulkano::instance::{Instance, InstanceCreateInfo};
use vulkano::memory::allocator::{AllocationCreateInfo, MemoryTypeFilter, StandardMemoryAllocator};
use vulkano::pipeline::graphics::color_blend::{ColorBlendAttachmentState, ColorBlendState};
use vulkano::pipeline::graphics::depth_stencil::{CompareOp, DepthState, DepthStencilState};
use vulkano::pipeline::graphics::input_assembly::InputAssemblyState;
use vulkano::pipeline::graphics::multisample::MultisampleState;
use vulkano::pipeline::graphics::rasterization::{CullMode, FrontFace, RasterizationState};
use vulkano::pipeline::graphics::vertex_input::{
    VertexInputAttributeDescription, VertexInputBindingDescription, VertexInputRate,
    VertexInputState,
};
use vulkano::pipeline::graphics::viewport::{Scissor, Viewport, ViewportState};
use vulkano::pipeline::graphics::GraphicsPipelineCreateInfo;
use vulkano::pipeline::layout::PipelineDescriptorSetLayoutCreateInfo;
use vulkano::pipeline::{
    DynamicState, GraphicsPipeline, Pipeline as _, PipelineBindPoint, PipelineLayout,
    PipelineShaderStageCreateInfo,
};
use vulkano::render_pass::{
    AttachmentDescription, AttachmentLoadOp, AttachmentReference, AttachmentStoreOp, Framebuffer,
    FramebufferCreateInfo, RenderPass, RenderPassCreateInfo, Subpass, SubpassDependency,
    SubpassDescription,
};
use vulkano::shader::{spirv::bytes_to_words, ShaderModule, ShaderModuleCreateInfo};
use vulkano::sync::future::FenceSignalFuture;
use vulkano::sync::{self, AccessFlags, GpuFuture, PipelineStages};
use vulkano::VulkanLibrary;

/// The clear color of the teapots scene (as `scenes::teapots` and `teapots_ash`).
const CLEAR_COLOR: [f32; 4] = [0.02, 0.02, 0.04, 1.0];

/// A slot's last submission: its frame, then its copy, then the fence.
type Submitted = FenceSignalFuture<
    CommandBufferExecFuture<CommandBufferExecFuture<Box<dyn GpuFuture + Send + Sync>>>,
>;

/// A vulkano device and its queue, for the teapots.
pub struct Vulkano {
    device: Arc<Device>,
    queue: Arc<Queue>,
}

impl Vulkano {
    /// The device `TUFF_DEVICE` names (by a part of its name), or else a discrete GPU,
    /// an integrated one, anything, in that order, as the tuff scenes and the raw-ash
    /// baseline pick it; with one queue of the first graphics family and robust buffer
    /// access (the teapots' requirements).
    pub fn open() -> Result<Vulkano> {
        let (device, queue) = open()?;
        Ok(Vulkano { device, queue })
    }

    /// The physical device's name.
    pub fn name(&self) -> String {
        self.device
            .physical_device()
            .properties()
            .device_name
            .clone()
    }
}

fn open() -> Result<(Arc<Device>, Arc<Queue>)> {
    let library = VulkanLibrary::new().context("cannot load the Vulkan loader (libvulkan1)")?;
    let instance = Instance::new(library, InstanceCreateInfo::default())
        .map_err(|e| anyhow!("cannot create a Vulkan instance: {e}"))?;
    let physicals: Vec<_> = instance
        .enumerate_physical_devices()
        .context("vkEnumeratePhysicalDevices")?
        .collect();
    let rank =
        |p: &&Arc<vulkano::device::physical::PhysicalDevice>| match p.properties().device_type {
            PhysicalDeviceType::DiscreteGpu => 0,
            PhysicalDeviceType::IntegratedGpu => 1,
            _ => 2,
        };
    let physical = match std::env::var("TUFF_DEVICE") {
        Ok(wanted) if !wanted.is_empty() => physicals
            .iter()
            .find(|p| p.properties().device_name.contains(&wanted))
            .with_context(|| format!("no Vulkan device's name contains TUFF_DEVICE={wanted:?}"))?,
        _ => physicals.iter().min_by_key(rank).context(
            "no Vulkan device found (for lavapipe: apt-get install mesa-vulkan-drivers)",
        )?,
    }
    .clone();
    let name = physical.properties().device_name.clone();
    let family = physical
        .queue_family_properties()
        .iter()
        .position(|f| f.queue_flags.intersects(QueueFlags::GRAPHICS))
        .with_context(|| format!("the device \"{name}\" has no graphics queue"))?
        as u32;
    let (device, mut queues) = Device::new(
        physical,
        DeviceCreateInfo {
            queue_create_infos: vec![QueueCreateInfo {
                queue_family_index: family,
                ..Default::default()
            }],
            enabled_features: DeviceFeatures {
                robust_buffer_access: true,
                ..DeviceFeatures::empty()
            },
            ..Default::default()
        },
    )
    .map_err(|e| anyhow!("cannot create a device on \"{name}\" for the teapots: {e}"))?;
    let queue = queues.next().context("the device has no queue")?;
    Ok((device, queue))
}

/// A vulkano format of the same value as `format`.
fn format(format: vk::Format) -> Result<Format> {
    Format::try_from(format).map_err(|()| anyhow!("vulkano has no format {format:?}"))
}

/// The render pass of `raw_ash::render_pass` (and tuff's `render::render_pass`):
/// color cleared, stored and left in TRANSFER_SRC_OPTIMAL for the copy; depth
/// cleared and not stored; the same two external dependencies.
fn render_pass(device: &Arc<Device>) -> Result<Arc<RenderPass>> {
    let fragment_tests = PipelineStages::EARLY_FRAGMENT_TESTS | PipelineStages::LATE_FRAGMENT_TESTS;
    let info = RenderPassCreateInfo {
        attachments: vec![
            AttachmentDescription {
                format: format(COLOR_FORMAT)?,
                samples: SampleCount::Sample1,
                load_op: AttachmentLoadOp::Clear,
                store_op: AttachmentStoreOp::Store,
                initial_layout: ImageLayout::Undefined,
                final_layout: ImageLayout::TransferSrcOptimal,
                ..Default::default()
            },
            AttachmentDescription {
                format: format(DEPTH_FORMAT)?,
                samples: SampleCount::Sample1,
                load_op: AttachmentLoadOp::Clear,
                store_op: AttachmentStoreOp::DontCare,
                initial_layout: ImageLayout::Undefined,
                final_layout: ImageLayout::DepthStencilAttachmentOptimal,
                ..Default::default()
            },
        ],
        subpasses: vec![SubpassDescription {
            color_attachments: vec![Some(AttachmentReference {
                attachment: 0,
                layout: ImageLayout::ColorAttachmentOptimal,
                ..Default::default()
            })],
            depth_stencil_attachment: Some(AttachmentReference {
                attachment: 1,
                layout: ImageLayout::DepthStencilAttachmentOptimal,
                ..Default::default()
            }),
            ..Default::default()
        }],
        dependencies: vec![
            // The previous frame's color and depth writes and its copy come before
            // this frame's clears.
            SubpassDependency {
                src_subpass: None,
                dst_subpass: Some(0),
                src_stages: PipelineStages::COLOR_ATTACHMENT_OUTPUT
                    | fragment_tests
                    | PipelineStages::ALL_TRANSFER,
                dst_stages: PipelineStages::COLOR_ATTACHMENT_OUTPUT | fragment_tests,
                src_access: AccessFlags::COLOR_ATTACHMENT_WRITE
                    | AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
                dst_access: AccessFlags::COLOR_ATTACHMENT_WRITE
                    | AccessFlags::COLOR_ATTACHMENT_READ
                    | AccessFlags::DEPTH_STENCIL_ATTACHMENT_READ
                    | AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
                ..Default::default()
            },
            // This frame's color writes come before the copy.
            SubpassDependency {
                src_subpass: Some(0),
                dst_subpass: None,
                src_stages: PipelineStages::COLOR_ATTACHMENT_OUTPUT,
                dst_stages: PipelineStages::ALL_TRANSFER,
                src_access: AccessFlags::COLOR_ATTACHMENT_WRITE,
                dst_access: AccessFlags::TRANSFER_READ,
                ..Default::default()
            },
        ],
        ..Default::default()
    };
    RenderPass::new(device.clone(), info).map_err(|e| anyhow!("cannot create the render pass: {e}"))
}

/// A shader module of committed SPIR-V.
fn shader(device: &Arc<Device>, spirv: &[u8]) -> Result<Arc<ShaderModule>> {
    let words = bytes_to_words(spirv).map_err(|e| anyhow!("bad SPIR-V: {e}"))?;
    // SAFETY: the words are the SPIR-V that `scripts/shaders.sh` compiled from
    // `shaders/src` with glslang, which the raw-ash and tuff scenes load as well.
    unsafe { ShaderModule::new(device.clone(), ShaderModuleCreateInfo::new(&words)) }
        .map_err(|e| anyhow!("cannot create a shader module: {e}"))
}

/// The teapots' pipeline, as `teapots_ash` makes it: the mesh's vertex layout,
/// triangles, no culling, reversed-Z depth test and write, one color attachment
/// written whole, dynamic viewport and scissor. The layout is the one vulkano derives
/// from the shaders (a uniform block in set 0, the `Teapot` push constants).
fn pipeline(device: &Arc<Device>, pass: &Arc<RenderPass>) -> Result<Arc<GraphicsPipeline>> {
    let entry = |module: Arc<ShaderModule>| {
        module
            .entry_point("main")
            .context("the shader has no entry point `main`")
    };
    let vs = entry(shader(device, crate::spirv!("teapot.vert"))?)?;
    let fs = entry(shader(device, crate::spirv!("teapot.frag"))?)?;
    let stages = [
        PipelineShaderStageCreateInfo::new(vs),
        PipelineShaderStageCreateInfo::new(fs),
    ];
    let layout_info = PipelineDescriptorSetLayoutCreateInfo::from_stages(&stages)
        .into_pipeline_layout_create_info(device.clone())
        .map_err(|e| anyhow!("cannot derive the pipeline layout: {e:?}"))?;
    let layout = PipelineLayout::new(device.clone(), layout_info)
        .map_err(|e| anyhow!("cannot create the pipeline layout: {e}"))?;
    let (bindings, attributes) = vertex_input();
    let mut vertex_input_state = VertexInputState::new();
    for b in bindings {
        vertex_input_state = vertex_input_state.binding(
            b.binding,
            VertexInputBindingDescription {
                stride: b.stride,
                input_rate: VertexInputRate::Vertex,
                ..Default::default()
            },
        );
    }
    for a in attributes {
        vertex_input_state = vertex_input_state.attribute(
            a.location,
            VertexInputAttributeDescription {
                binding: a.binding,
                format: format(a.format)?,
                offset: a.offset,
                ..Default::default()
            },
        );
    }
    let subpass = Subpass::from(pass.clone(), 0).context("the render pass has no subpass 0")?;
    GraphicsPipeline::new(
        device.clone(),
        None,
        GraphicsPipelineCreateInfo {
            stages: stages.into_iter().collect(),
            vertex_input_state: Some(vertex_input_state),
            input_assembly_state: Some(InputAssemblyState::default()),
            viewport_state: Some(ViewportState::default()),
            rasterization_state: Some(RasterizationState {
                cull_mode: CullMode::None,
                front_face: FrontFace::CounterClockwise,
                ..Default::default()
            }),
            multisample_state: Some(MultisampleState::default()),
            depth_stencil_state: Some(DepthStencilState {
                // Reversed Z: nearer is greater.
                depth: Some(DepthState {
                    write_enable: true,
                    compare_op: CompareOp::Greater,
                }),
                ..Default::default()
            }),
            color_blend_state: Some(ColorBlendState::with_attachment_states(
                subpass.num_color_attachments(),
                ColorBlendAttachmentState::default(),
            )),
            dynamic_state: [DynamicState::Viewport, DynamicState::Scissor]
                .into_iter()
                .collect(),
            subpass: Some(subpass.into()),
            ..GraphicsPipelineCreateInfo::layout(layout)
        },
    )
    .map_err(|e| anyhow!("cannot create the pipeline: {e}"))
}

/// A 2D image of `extent` with memory of its own (the allocator's choice).
fn image(
    allocator: &Arc<StandardMemoryAllocator>,
    extent: [u32; 2],
    format: Format,
    usage: ImageUsage,
) -> Result<Arc<Image>> {
    Image::new(
        allocator.clone(),
        ImageCreateInfo {
            image_type: ImageType::Dim2d,
            format,
            extent: [extent[0], extent[1], 1],
            usage,
            ..Default::default()
        },
        AllocationCreateInfo::default(),
    )
    .map_err(|e| anyhow!("cannot create an image: {e}"))
}

/// Vulkano's errors (validation or Vulkan), with what failed.
fn vulkan<T, E: std::fmt::Display>(what: &str, result: Result<T, E>) -> Result<T> {
    result.map_err(|e| anyhow!("{what}: {e}"))
}

/// A primary command buffer builder for one submission: the frame's and the copy's.
fn one_time(
    commands: &Arc<StandardCommandBufferAllocator>,
    family: u32,
) -> Result<AutoCommandBufferBuilder<vulkano::command_buffer::PrimaryAutoCommandBuffer>> {
    vulkan(
        "AutoCommandBufferBuilder::primary",
        AutoCommandBufferBuilder::primary(
            commands.clone(),
            family,
            CommandBufferUsage::OneTimeSubmit,
        ),
    )
}

/// Renders `run.warmup + run.frames` frames of the teapots headless through vulkano,
/// as [`super::tuff_frames::headless`] does through tuff, and returns the timed
/// frames' stages (and the last frame's pixels). Each frame is recorded by an
/// `AutoCommandBufferBuilder` and submitted, then copied into a readback buffer of its
/// slot by a second command buffer and submission, chained after the frame's as
/// vulkano's futures chain them. The two submissions of a slot end in one fence,
/// waited before the slot is used again (vulkano's guide for frames in flight: wait
/// for the slot's fence, chain the new frame after the previous frame's future).
pub fn headless(vulkano: &Vulkano, run: &Run) -> Result<Samples> {
    let Vulkano { device, queue } = vulkano;
    let extent = [run.size, run.size];
    let memory = Arc::new(StandardMemoryAllocator::new_default(device.clone()));
    let sets = Arc::new(StandardDescriptorSetAllocator::new(
        device.clone(),
        Default::default(),
    ));
    let commands = Arc::new(StandardCommandBufferAllocator::new(
        device.clone(),
        Default::default(),
    ));
    let pass = render_pass(device)?;
    let pipeline = pipeline(device, &pass)?;
    let layout = Layout::grid(run.count, 1)?;
    let writes = run.writes.max(1) as usize;

    // What the device reads, in memory the host writes once (vertices, indices) or
    // every frame (the camera blocks): device-local where the device has such
    // host-visible memory, as the guide places them.
    let upload = AllocationCreateInfo {
        memory_type_filter: MemoryTypeFilter::PREFER_DEVICE
            | MemoryTypeFilter::HOST_SEQUENTIAL_WRITE,
        ..Default::default()
    };
    let (flat, index_data) = mesh_data();
    let buffer_info = |usage| BufferCreateInfo {
        usage,
        ..Default::default()
    };
    let vertices = vulkan(
        "vertex buffer",
        Buffer::from_iter(
            memory.clone(),
            buffer_info(BufferUsage::VERTEX_BUFFER),
            upload.clone(),
            flat,
        ),
    )?;
    let index_count = index_data.len() as u32;
    let indices = vulkan(
        "index buffer",
        Buffer::from_iter(
            memory.clone(),
            buffer_info(BufferUsage::INDEX_BUFFER),
            upload.clone(),
            index_data,
        ),
    )?;
    let set_layout = pipeline
        .layout()
        .set_layouts()
        .first()
        .context("the pipeline layout has no set 0")?
        .clone();
    // Per slot: `writes` camera blocks, the descriptor set of the first, the color
    // and depth images and their framebuffer, the readback buffer. The depth image is
    // the slot's own, where the raw-ash and tuff loops share one: a frame's future
    // chains after the previous slot's frame and copy, and vulkano 0.35 looks for an
    // image in a chain only up to the first command buffer that does not use it (the
    // copy), so a shared depth image reads as still held by the previous frame and
    // the submission is refused (`CommandBufferExecFuture::check_image_access`).
    let bytes = u64::from(run.size) * u64::from(run.size) * 4;
    let mut slots = Vec::new();
    for _ in 0..FRAMES_IN_FLIGHT {
        let uniform: Subbuffer<[CameraBlock]> = vulkan(
            "uniform buffer",
            Buffer::from_iter(
                memory.clone(),
                buffer_info(BufferUsage::UNIFORM_BUFFER),
                upload.clone(),
                // Written every frame before the frame is recorded.
                std::iter::repeat_n(bytemuck::Zeroable::zeroed(), writes),
            ),
        )?;
        let set = vulkan(
            "descriptor set",
            DescriptorSet::new(
                sets.clone(),
                set_layout.clone(),
                [WriteDescriptorSet::buffer(0, uniform.clone().index(0))],
                [],
            ),
        )?;
        let color = image(
            &memory,
            extent,
            format(COLOR_FORMAT)?,
            ImageUsage::COLOR_ATTACHMENT | ImageUsage::TRANSFER_SRC,
        )?;
        let view = ImageView::new_default(color.clone()).map_err(|e| anyhow!("view: {e}"))?;
        let depth = ImageView::new_default(image(
            &memory,
            extent,
            format(DEPTH_FORMAT)?,
            ImageUsage::DEPTH_STENCIL_ATTACHMENT,
        )?)
        .map_err(|e| anyhow!("depth view: {e}"))?;
        let framebuffer = vulkan(
            "framebuffer",
            Framebuffer::new(
                pass.clone(),
                FramebufferCreateInfo {
                    attachments: vec![view, depth],
                    ..Default::default()
                },
            ),
        )?;
        let readback: Subbuffer<[u8]> = vulkan(
            "readback buffer",
            Buffer::new_slice(
                memory.clone(),
                buffer_info(BufferUsage::TRANSFER_DST),
                AllocationCreateInfo {
                    memory_type_filter: MemoryTypeFilter::PREFER_HOST
                        | MemoryTypeFilter::HOST_RANDOM_ACCESS,
                    ..Default::default()
                },
                bytes,
            ),
        )?;
        slots.push(Slot {
            uniform,
            set,
            color,
            framebuffer,
            readback,
        });
    }
    let viewport = crate::render::viewport(vk::Extent2D {
        width: run.size,
        height: run.size,
    });
    let viewport = Viewport {
        offset: [viewport.x, viewport.y],
        extent: [viewport.width, viewport.height],
        depth_range: viewport.min_depth..=viewport.max_depth,
    };
    let scissor = Scissor {
        offset: [0, 0],
        extent,
    };
    let family = queue.queue_family_index();
    let mut fences: Vec<Option<Arc<Submitted>>> = vec![None; FRAMES_IN_FLIGHT];
    let mut previous = 0;
    let mut samples = Samples::new(run.warmup);
    let mut timer = Timer::default();
    for n in 0..run.warmup + run.frames {
        let slot = n as usize % FRAMES_IN_FLIGHT;
        let s = &slots[slot];
        timer.start();
        if let Some(fence) = &fences[slot] {
            vulkan("waiting for the slot's fence", fence.wait(None))?;
        }
        timer.lap(Stage::Wait);
        let view = View {
            extent: vk::Extent2D {
                width: run.size,
                height: run.size,
            },
            time: n as f32 / 60.0,
            slot,
        };
        {
            let block = layout.camera(view.extent);
            let mut blocks = s
                .uniform
                .write()
                .map_err(|e| anyhow!("the slot's uniforms: {e}"))?;
            for b in blocks.iter_mut() {
                *b = block;
            }
        }
        timer.lap(Stage::Uniform);
        let mut builder = one_time(&commands, family)?;
        vulkan(
            "begin_render_pass",
            builder.begin_render_pass(
                RenderPassBeginInfo {
                    clear_values: vec![Some(CLEAR_COLOR.into()), Some(DEPTH_CLEAR.into())],
                    ..RenderPassBeginInfo::framebuffer(s.framebuffer.clone())
                },
                SubpassBeginInfo {
                    contents: SubpassContents::Inline,
                    ..Default::default()
                },
            ),
        )?;
        vulkan(
            "set_viewport",
            builder.set_viewport(0, [viewport.clone()].into_iter().collect()),
        )?;
        vulkan(
            "set_scissor",
            builder.set_scissor(0, [scissor].into_iter().collect()),
        )?;
        vulkan(
            "bind_pipeline_graphics",
            builder.bind_pipeline_graphics(pipeline.clone()),
        )?;
        vulkan(
            "bind_descriptor_sets",
            builder.bind_descriptor_sets(
                PipelineBindPoint::Graphics,
                pipeline.layout().clone(),
                0,
                s.set.clone(),
            ),
        )?;
        vulkan(
            "bind_vertex_buffers",
            builder.bind_vertex_buffers(0, vertices.clone()),
        )?;
        vulkan(
            "bind_index_buffer",
            builder.bind_index_buffer(indices.clone()),
        )?;
        for teapot in &layout.teapots {
            let block: TeapotBlock = teapot.block(view.time);
            vulkan(
                "push_constants",
                builder.push_constants(pipeline.layout().clone(), 0, block),
            )?;
            // SAFETY: the shaders index only the bound uniform block and the vertex
            // attributes; every index of the mesh is below its vertex count (the
            // mesh is built so, and the raw-ash and tuff loops draw the same).
            vulkan("draw_indexed", unsafe {
                builder.draw_indexed(index_count, 1, 0, 0, 0)
            })?;
        }
        vulkan(
            "end_render_pass",
            builder.end_render_pass(SubpassEndInfo::default()),
        )?;
        let frame = vulkan("build", builder.build())?;
        timer.lap(Stage::Command);
        // After the previous frame's future (the guide's chain), or now for the first.
        let after = match fences[previous].clone() {
            Some(fence) => fence.boxed_send_sync(),
            None => {
                let mut now = sync::now(device.clone());
                now.cleanup_finished();
                now.boxed_send_sync()
            }
        };
        let submitted = after
            .then_execute(queue.clone(), frame)
            .map_err(|e| anyhow!("then_execute: {e}"))?;
        vulkan("flush", submitted.flush())?;
        timer.lap(Stage::Submit);
        // The slot's copy follows its frame in the same chain; one fence covers both,
        // and the slot's last one was waited above.
        timer.lap(Stage::Wait);
        let mut copy = one_time(&commands, family)?;
        vulkan(
            "copy_image_to_buffer",
            copy.copy_image_to_buffer(CopyImageToBufferInfo::image_buffer(
                s.color.clone(),
                s.readback.clone(),
            )),
        )?;
        let copy = vulkan("build", copy.build())?;
        let fence = submitted
            .then_execute(queue.clone(), copy)
            .map_err(|e| anyhow!("then_execute: {e}"))?
            .then_signal_fence_and_flush();
        fences[slot] = Some(Arc::new(vulkan("then_signal_fence_and_flush", fence)?));
        previous = slot;
        timer.lap(Stage::Present);
        samples.push(&timer);
    }
    for fence in fences.iter().flatten() {
        vulkan("waiting for the last frames", fence.wait(None))?;
    }
    let last = (run.warmup + run.frames).saturating_sub(1) as usize % FRAMES_IN_FLIGHT;
    samples.last_frame = slots[last]
        .readback
        .read()
        .map_err(|e| anyhow!("the readback: {e}"))?
        .to_vec();
    Ok(samples)
}

/// A frame slot's own objects.
struct Slot {
    uniform: Subbuffer<[CameraBlock]>,
    set: Arc<DescriptorSet>,
    color: Arc<Image>,
    framebuffer: Arc<Framebuffer>,
    readback: Subbuffer<[u8]>,
}
