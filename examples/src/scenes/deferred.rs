//! Deferred shading in one render pass of two subpasses, its objects recorded by
//! worker threads: subpass 0 draws every object of the grid into a G-buffer (color,
//! normal, depth), from secondary command buffers that `threads` workers record at
//! once, each its share of the objects with their own push constants; subpass 1
//! reads the G-buffer as input attachments and lights every pixel with the point
//! lights. Two frames in flight, each with one secondary per worker from a pool of
//! its own ([`tuff::Device::frames_in_flight_with_workers`]). What the scene shows
//! is in [`crate::scenes::deferred_data`].
//!
//! The workers run on threads of their own when the crate is built with its
//! `multi_thread` feature (see [`crate::workers`]); the image does not depend on it.

use crate::gpu::{Gpu, Requirements};
use crate::headless::{Rendered, COLOR_FORMAT};
use crate::pipeline::{self, PipelineDesc};
use crate::render::{View, DEPTH_FORMAT, FRAMES_IN_FLIGHT};
use crate::scenes::deferred_data::{
    self as data, Layout, LightsBlock, MeshRange, Meshes, GBUFFER_COLORS, GBUFFER_DEPTH,
    LIGHTING_COLOR, LIGHTING_INPUTS,
};
use crate::scenes::teapot_grid::{vertex_input, CameraBlock, TeapotBlock};
use anyhow::{bail, Result};
use std::time::{Duration, Instant};
use tuff::vk;
use tuff::MemoryLocation::Upload;

/// What the scene asks of the device: robust buffer access, which makes the indexed
/// draws safe (see [`Requirements::robust_buffer_access`]).
pub const REQUIREMENTS: Requirements = Requirements {
    robust_buffer_access: true,
    ..Requirements::core("deferred")
};

/// The stages that read the camera block and the push constants.
const OBJECT_STAGES: vk::ShaderStageFlags = vk::ShaderStageFlags::from_raw(
    vk::ShaderStageFlags::VERTEX.as_raw() | vk::ShaderStageFlags::FRAGMENT.as_raw(),
);

/// A run of the scene: its last frame, and how long recording took.
pub struct Run {
    /// The last frame's pixels and the frame rate.
    pub rendered: Rendered,
    /// Recording per frame, on average over every frame but the first (zero for a
    /// single frame): from the workers' start to the end of the primary's recording.
    pub recording: Duration,
}

/// The scene's device objects: the render pass and its framebuffers (one output
/// image per frame in flight, one G-buffer they share, ordered by the render pass's
/// dependencies), the two pipelines, the per-frame uniform buffers and sets, and
/// the meshes.
pub struct Deferred {
    layout: Layout,
    ranges: Vec<MeshRange>,
    render_pass: tuff::RenderPass,
    framebuffers: Vec<tuff::Framebuffer>,
    outputs: Vec<tuff::Image>,
    gbuffer: tuff::Pipeline,
    gbuffer_layout: tuff::PipelineLayout,
    lighting: tuff::Pipeline,
    lighting_layout: tuff::PipelineLayout,
    camera_sets: Vec<tuff::DescriptorSet>,
    lighting_sets: Vec<tuff::DescriptorSet>,
    cameras: Vec<tuff::Bound<tuff::Buffer>>,
    lights: Vec<tuff::Bound<tuff::Buffer>>,
    vertices: tuff::Bound<tuff::Buffer>,
    indices: tuff::Bound<tuff::Buffer>,
}

impl Deferred {
    /// Builds the scene for images of `extent`.
    pub fn new(gpu: &Gpu, layout: Layout, extent: vk::Extent2D) -> Result<Deferred> {
        let (d, a) = (&gpu.device, &gpu.allocator);
        let render_pass = render_pass(gpu)?;
        // The G-buffer: attachments read as input attachments in subpass 1.
        let input = vk::ImageUsageFlags::INPUT_ATTACHMENT;
        let albedo = gpu.image(
            extent,
            data::ALBEDO_FORMAT,
            vk::ImageUsageFlags::COLOR_ATTACHMENT | input,
        )?;
        let normal = gpu.image(
            extent,
            data::NORMAL_FORMAT,
            vk::ImageUsageFlags::COLOR_ATTACHMENT | input,
        )?;
        let depth = gpu.image(
            extent,
            DEPTH_FORMAT,
            vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT | input,
        )?;
        let color = vk::ImageAspectFlags::COLOR;
        let gbuffer_views = [
            gpu.view(&albedo, data::ALBEDO_FORMAT, color)?,
            gpu.view(&normal, data::NORMAL_FORMAT, color)?,
            gpu.view(&depth, DEPTH_FORMAT, vk::ImageAspectFlags::DEPTH)?,
        ];
        let usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
        let outputs = (0..FRAMES_IN_FLIGHT)
            .map(|_| gpu.image(extent, COLOR_FORMAT, usage))
            .collect::<Result<Vec<_>>>()?;
        let framebuffers = outputs
            .iter()
            .map(|output| {
                let view = gpu.view(output, COLOR_FORMAT, color)?;
                let [albedo, normal, depth] = &gbuffer_views;
                let views = [&view, albedo, normal, depth];
                Ok(d.create_framebuffer(
                    &tuff::FramebufferCreateInfo::new(&render_pass)
                        .attachments(&tuff::HandleSlice::new(&views))
                        .width(extent.width)
                        .height(extent.height)
                        .layers(1),
                )?)
            })
            .collect::<Result<Vec<_>>>()?;

        // Subpass 0: the objects, with the teapots scene's vertex stage.
        let uniform = |binding, stages| {
            tuff::DescriptorSetLayoutBinding::new()
                .binding(binding)
                .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                .descriptor_count(1)
                .stage_flags(stages)
        };
        let camera_layout = d.create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&[uniform(0, OBJECT_STAGES)]),
        )?;
        let push_size = size_of::<TeapotBlock>() as u32;
        let gbuffer_layout = pipeline::layout(gpu, &[&camera_layout], OBJECT_STAGES, push_size)?;
        let vert = crate::shader(d, crate::spirv!("teapot.vert"))?;
        let frag = crate::shader(d, crate::spirv!("deferred_gbuffer.frag"))?;
        let (bindings, attributes) = vertex_input();
        let gbuffer = pipeline::graphics(
            gpu,
            &gbuffer_layout,
            &render_pass,
            &PipelineDesc {
                stages: &[
                    (vk::ShaderStageFlags::VERTEX, &vert),
                    (vk::ShaderStageFlags::FRAGMENT, &frag),
                ],
                bindings: &bindings,
                attributes: &attributes,
                topology: vk::PrimitiveTopology::TRIANGLE_LIST,
                patch_control_points: 0,
                polygon_mode: vk::PolygonMode::FILL,
                depth: true,
                subpass: 0,
                colors: GBUFFER_COLORS.len() as u32,
            },
        )?;

        // Subpass 1: one triangle over the framebuffer, reading the G-buffer.
        let fragment = vk::ShaderStageFlags::FRAGMENT;
        let inputs = [0, 1, 2].map(|binding| {
            tuff::DescriptorSetLayoutBinding::new()
                .binding(binding)
                .descriptor_type(vk::DescriptorType::INPUT_ATTACHMENT)
                .descriptor_count(1)
                .stage_flags(fragment)
        });
        let [i0, i1, i2] = inputs;
        let lighting_set_layout = d.create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&[
                i0,
                i1,
                i2,
                uniform(3, fragment),
            ]),
        )?;
        let lighting_layout = pipeline::layout(gpu, &[&lighting_set_layout], fragment, 0)?;
        let vert = crate::shader(d, crate::spirv!("deferred_light.vert"))?;
        let frag = crate::shader(d, crate::spirv!("deferred_light.frag"))?;
        let lighting = pipeline::graphics(
            gpu,
            &lighting_layout,
            &render_pass,
            &PipelineDesc {
                stages: &[
                    (vk::ShaderStageFlags::VERTEX, &vert),
                    (vk::ShaderStageFlags::FRAGMENT, &frag),
                ],
                bindings: &[],
                attributes: &[],
                topology: vk::PrimitiveTopology::TRIANGLE_LIST,
                patch_control_points: 0,
                polygon_mode: vk::PolygonMode::FILL,
                depth: false,
                subpass: 1,
                colors: LIGHTING_COLOR.len() as u32,
            },
        )?;

        // Per frame in flight: the camera block and its set, the lights and theirs.
        let frames = FRAMES_IN_FLIGHT as u32;
        let pool = d.create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(2 * frames)
                .pool_sizes(&[
                    vk::DescriptorPoolSize {
                        ty: vk::DescriptorType::UNIFORM_BUFFER,
                        descriptor_count: 2 * frames,
                    },
                    vk::DescriptorPoolSize {
                        ty: vk::DescriptorType::INPUT_ATTACHMENT,
                        descriptor_count: 3 * frames,
                    },
                ]),
        )?;
        let allocate = |set_layout: &tuff::DescriptorSetLayout| {
            let layouts = tuff::HandleSlice::new(&[set_layout; FRAMES_IN_FLIGHT]);
            d.allocate_descriptor_sets(
                &pool,
                &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layouts),
            )
        };
        let camera_sets = allocate(&camera_layout)?;
        let lighting_sets = allocate(&lighting_set_layout)?;
        let uniforms = |size: usize| {
            (0..FRAMES_IN_FLIGHT)
                .map(|_| gpu.buffer(size as u64, vk::BufferUsageFlags::UNIFORM_BUFFER, Upload))
                .collect::<Result<Vec<_>>>()
        };
        let cameras = uniforms(size_of::<CameraBlock>())?;
        let lights = uniforms(size_of::<LightsBlock>())?;
        for slot in 0..FRAMES_IN_FLIGHT {
            let camera = [tuff::DescriptorBufferInfo::new()
                .buffer(Some(&cameras[slot]))
                .range(vk::WHOLE_SIZE)];
            let light = [tuff::DescriptorBufferInfo::new()
                .buffer(Some(&lights[slot]))
                .range(vk::WHOLE_SIZE)];
            let images: Vec<_> = gbuffer_views
                .iter()
                .zip(LIGHTING_INPUTS)
                .map(|(view, reference)| {
                    [tuff::DescriptorImageInfo::new()
                        .image_view(Some(view))
                        .image_layout(reference.layout)]
                })
                .collect();
            let set = &lighting_sets[slot];
            let mut writes = vec![
                tuff::WriteDescriptorSet::new(&camera_sets[slot])
                    .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                    .buffer_info(&camera),
                tuff::WriteDescriptorSet::new(set)
                    .dst_binding(3)
                    .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                    .buffer_info(&light),
            ];
            for (binding, image) in images.iter().enumerate() {
                writes.push(
                    tuff::WriteDescriptorSet::new(set)
                        .dst_binding(binding as u32)
                        .descriptor_type(vk::DescriptorType::INPUT_ATTACHMENT)
                        .image_info(image),
                );
            }
            d.update_descriptor_sets(&writes, &[])?;
        }
        let meshes = Meshes::new();
        let vertices =
            d.create_buffer_with(vk::BufferUsageFlags::VERTEX_BUFFER, &meshes.vertices, a)?;
        let indices =
            d.create_buffer_with(vk::BufferUsageFlags::INDEX_BUFFER, &meshes.indices, a)?;
        Ok(Deferred {
            layout,
            ranges: meshes.ranges,
            render_pass,
            framebuffers,
            outputs,
            gbuffer,
            gbuffer_layout,
            lighting,
            lighting_layout,
            camera_sets,
            lighting_sets,
            cameras,
            lights,
            vertices,
            indices,
        })
    }

    /// Writes the frame's camera and lights: the slot's previous submission completed.
    fn update(&self, view: &View) -> Result<()> {
        let camera = self.layout.camera(view.extent);
        self.cameras[view.slot].memory().write_value(0, &camera)?;
        let lights = self.layout.lights(view.extent, view.time);
        self.lights[view.slot].memory().write_value(0, &lights)?;
        Ok(())
    }

    /// Records worker `worker`'s share of the objects, of `workers`, into
    /// `secondary`: it continues subpass 0 of the frame's render pass instance.
    fn record_objects(
        &self,
        secondary: &mut tuff::CommandBuffer,
        view: &View,
        worker: usize,
        workers: usize,
    ) -> tuff::Result<()> {
        let inheritance = tuff::CommandBufferInheritanceInfo::new()
            .render_pass(Some(&self.render_pass))
            .subpass(0)
            .framebuffer(Some(&self.framebuffers[view.slot]));
        let info = tuff::CommandBufferBeginInfo::new()
            .flags(
                vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE
                    | vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT,
            )
            .inheritance_info(Some(&inheritance));
        let mut rec = secondary.begin_continuing(&info)?;
        // A secondary inherits no dynamic state: it sets its own.
        rec.set_viewport(0, &[crate::render::viewport(view.extent)])?;
        rec.set_scissor(0, &[view.extent.into()])?;
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.gbuffer)?;
        rec.bind_descriptor_sets(
            vk::PipelineBindPoint::GRAPHICS,
            &self.gbuffer_layout,
            0,
            &self.camera_sets[view.slot],
            &[],
        )?;
        rec.bind_vertex_buffers(0, &self.vertices, &[0])?;
        rec.bind_index_buffer(&self.indices, 0, vk::IndexType::UINT32)?;
        let share = data::share(self.layout.objects.len(), workers, worker);
        for object in &self.layout.objects[share] {
            let block = object.instance.block(view.time);
            rec.push_constants(
                &self.gbuffer_layout,
                OBJECT_STAGES,
                0,
                bytemuck::bytes_of(&block),
            )?;
            let mesh = self.ranges[object.mesh];
            rec.draw_indexed(mesh.index_count, 1, mesh.first_index, mesh.vertex_offset, 0)?;
        }
        rec.end()
    }

    /// Records the frame: the workers' secondaries (at once, on threads with the
    /// `multi_thread` feature), then the primary that executes them in subpass 0,
    /// lights in subpass 1 and, when asked, copies the output into `readback`.
    fn record(
        &self,
        frame: &mut tuff::Frame<'_>,
        view: &View,
        readback: Option<&tuff::Buffer>,
    ) -> Result<()> {
        let workers = frame.workers();
        let count = workers.len();
        crate::workers::tuff_workers(workers.iter_mut().collect(), |worker, secondary| {
            self.record_objects(secondary, view, worker, count)
        })?;
        let (primary, workers) = frame.parts();
        let secondaries: Vec<&tuff::CommandBuffer> = workers.iter().collect();
        let mut rec = primary.begin(
            &tuff::CommandBufferBeginInfo::new()
                .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
        )?;
        rec.auto_sync(crate::render::auto_sync());
        let clear = data::clear_values();
        let area: vk::Rect2D = view.extent.into();
        let mut rec = rec.begin_render_pass(
            &tuff::RenderPassBeginInfo::new(&self.render_pass, &self.framebuffers[view.slot])
                .render_area(area)
                .clear_values(&clear),
            vk::SubpassContents::SECONDARY_COMMAND_BUFFERS,
        );
        rec.execute_commands(&tuff::HandleSlice::new(&secondaries))?;
        rec.next_subpass(vk::SubpassContents::INLINE);
        rec.set_viewport(0, &[crate::render::viewport(view.extent)])?;
        rec.set_scissor(0, &[area])?;
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.lighting)?;
        rec.bind_descriptor_sets(
            vk::PipelineBindPoint::GRAPHICS,
            &self.lighting_layout,
            0,
            &self.lighting_sets[view.slot],
            &[],
        )?;
        rec.draw(3, 1, 0, 0)?;
        let mut rec = rec.end_render_pass();
        if let Some(buffer) = readback {
            crate::render::record_readback(
                &mut rec,
                &self.outputs[view.slot],
                buffer,
                view.extent,
            )?;
        }
        rec.end()?;
        Ok(())
    }
}

/// The render pass: four attachments, the G-buffer subpass and the lighting
/// subpass (`deferred_data` describes both), with the dependencies written by hand,
/// or with automatic synchronization those tuff derives.
fn render_pass(gpu: &Gpu) -> Result<tuff::RenderPass> {
    let attachments = data::attachments(COLOR_FORMAT);
    let subpasses = [
        tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&GBUFFER_COLORS)
            .depth_stencil_attachment(Some(&GBUFFER_DEPTH)),
        tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .input_attachments(&LIGHTING_INPUTS)
            .color_attachments(&LIGHTING_COLOR),
    ];
    let info = tuff::RenderPassCreateInfo::new()
        .attachments(&attachments)
        .subpasses(&subpasses);
    // With automatic synchronization, tuff derives the dependencies from how the
    // subpasses use the attachments; otherwise they are written by hand.
    let dependencies = match crate::render::auto_sync() {
        true => info.needed_dependencies(),
        false => data::dependencies().to_vec(),
    };
    Ok(gpu
        .device
        .create_render_pass(&info.dependencies(&dependencies))?)
}

/// Renders `frames` frames (at least one) of `layout` at `extent` with `threads`
/// workers (1 to [`data::MAX_WORKERS`]) and reads the last one back. Frame `i`
/// shows scene time `i / 60` s.
pub fn render(
    gpu: &Gpu,
    layout: Layout,
    extent: vk::Extent2D,
    frames: u32,
    threads: u32,
) -> Result<Run> {
    if !(1..=data::MAX_WORKERS).contains(&threads) {
        bail!(
            "the thread count must be 1 to {}, not {threads}",
            data::MAX_WORKERS
        );
    }
    crate::headless::check_extent(gpu, extent)?;
    let frames = frames.max(1);
    let scene = Deferred::new(gpu, layout, extent)?;
    let bytes = u64::from(extent.width) * u64::from(extent.height) * 4;
    let readback = gpu.buffer(
        bytes,
        vk::BufferUsageFlags::TRANSFER_DST,
        tuff::MemoryLocation::Readback,
    )?;
    let mut ring =
        gpu.device
            .frames_in_flight_with_workers(gpu.family, FRAMES_IN_FLIGHT, threads as usize)?;
    let mut recording = Duration::ZERO;
    let mut resident = crate::headless::Resident::default();
    let start = Instant::now();
    for n in 0..frames {
        let mut frame = ring.next_frame()?;
        let view = View {
            extent,
            time: n as f32 / 60.0,
            slot: frame.index,
        };
        scene.update(&view)?;
        let last = n + 1 == frames;
        let began = Instant::now();
        scene.record(&mut frame, &view, last.then_some(&*readback))?;
        // The first frame's recording runs on cold caches: left out of the mean.
        if n > 0 {
            recording += began.elapsed();
        }
        frame.submit(&gpu.queue, &[], &[])?;
        resident.after_frame(n + 1, frames);
    }
    ring.wait_all()?;
    let elapsed = start.elapsed();
    resident.finish();
    let rgba = readback.memory().read(0, bytes as usize)?;
    Ok(Run {
        rendered: Rendered {
            width: extent.width,
            height: extent.height,
            rgba,
            frames,
            elapsed,
            resident,
        },
        recording: recording / (frames - 1).max(1),
    })
}
