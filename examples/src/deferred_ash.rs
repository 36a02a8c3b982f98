//! The deferred scene of `scenes::deferred`, written against raw ash: the baseline
//! tuff is measured against (`deferred_ash`, and the threads table). The same
//! render pass, pipelines, descriptor sets and per-frame commands, with the same
//! worker threads recording the objects into secondaries from pools of their own
//! (raw handles cross threads in any build), and the same image.

use crate::raw_ash::{frame_slots, record_readback, Objects, PipelineDesc, Vulkan};
use crate::render::{View, DEPTH_FORMAT, FRAMES_IN_FLIGHT};
use crate::scenes::deferred_data::{
    self as data, Layout, LightsBlock, MeshRange, Meshes, GBUFFER_COLORS, GBUFFER_DEPTH,
    LIGHTING_COLOR, LIGHTING_INPUTS,
};
use crate::scenes::teapot_grid::{vertex_input, CameraBlock, TeapotBlock};
use crate::spirv;
use anyhow::{bail, Context as _, Result};
use ash::vk;
use std::time::{Duration, Instant};

/// What the scene asks of the device, as in the tuff scene: robust buffer access.
pub const REQUIREMENTS: crate::gpu::Requirements = crate::gpu::Requirements {
    robust_buffer_access: true,
    ..crate::gpu::Requirements::core("deferred_ash")
};

/// The stages that read the camera block and the push constants.
const OBJECT_STAGES: vk::ShaderStageFlags = vk::ShaderStageFlags::from_raw(
    vk::ShaderStageFlags::VERTEX.as_raw() | vk::ShaderStageFlags::FRAGMENT.as_raw(),
);

/// The scene's objects, all owned by the [`Objects`] they were made into, and the
/// mapped per-frame uniforms.
struct Deferred {
    layout: Layout,
    ranges: Vec<MeshRange>,
    render_pass: vk::RenderPass,
    framebuffers: Vec<vk::Framebuffer>,
    outputs: Vec<vk::Image>,
    gbuffer: vk::Pipeline,
    gbuffer_layout: vk::PipelineLayout,
    lighting: vk::Pipeline,
    lighting_layout: vk::PipelineLayout,
    camera_sets: Vec<vk::DescriptorSet>,
    lighting_sets: Vec<vk::DescriptorSet>,
    cameras: Vec<*mut CameraBlock>,
    lights: Vec<*mut LightsBlock>,
    vertices: vk::Buffer,
    indices: vk::Buffer,
}

// SAFETY: the raw pointers are mappings of coherent memory that only `update`
// writes, on the thread that records the primary, while no worker runs; the
// workers read the handles only.
unsafe impl Sync for Deferred {}

impl Deferred {
    /// Builds the scene for images of `extent` into `o`.
    fn new(
        device: &ash::Device,
        o: &mut Objects,
        layout: Layout,
        extent: vk::Extent2D,
    ) -> Result<Deferred> {
        let render_pass = render_pass(device)?;
        o.render_pass = render_pass;
        let input = vk::ImageUsageFlags::INPUT_ATTACHMENT;
        let color_usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | input;
        let color = vk::ImageAspectFlags::COLOR;
        let (_, albedo) = o.image(device, extent, data::ALBEDO_FORMAT, color_usage, color)?;
        let (_, normal) = o.image(device, extent, data::NORMAL_FORMAT, color_usage, color)?;
        let depth_usage = vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT | input;
        let depth_aspect = vk::ImageAspectFlags::DEPTH;
        let (_, depth) = o.image(device, extent, DEPTH_FORMAT, depth_usage, depth_aspect)?;
        let gbuffer_views = [albedo, normal, depth];
        let mut outputs = Vec::new();
        // SAFETY: every create info and what it points at lives across its call; each
        // object goes into `o` as soon as it is made; the uniform memory stays mapped
        // until `o` frees it, after the device is idle.
        unsafe {
            for _ in 0..FRAMES_IN_FLIGHT {
                let usage =
                    vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
                let format = crate::headless::COLOR_FORMAT;
                let (image, view) = o.image(device, extent, format, usage, color)?;
                outputs.push(image);
                let attachments = [view, albedo, normal, depth];
                let info = vk::FramebufferCreateInfo::default()
                    .render_pass(render_pass)
                    .attachments(&attachments)
                    .width(extent.width)
                    .height(extent.height)
                    .layers(1);
                let framebuffer = device
                    .create_framebuffer(&info, None)
                    .context("vkCreateFramebuffer")?;
                o.framebuffers.push(framebuffer);
            }
            let framebuffers = o.framebuffers.clone();

            let binding = |binding, ty, stages| {
                vk::DescriptorSetLayoutBinding::default()
                    .binding(binding)
                    .descriptor_type(ty)
                    .descriptor_count(1)
                    .stage_flags(stages)
            };
            let uniform = vk::DescriptorType::UNIFORM_BUFFER;
            let camera_bindings = [binding(0, uniform, OBJECT_STAGES)];
            let camera_layout = device
                .create_descriptor_set_layout(
                    &vk::DescriptorSetLayoutCreateInfo::default().bindings(&camera_bindings),
                    None,
                )
                .context("vkCreateDescriptorSetLayout")?;
            o.set_layouts.push(camera_layout);
            let push_size = size_of::<TeapotBlock>() as u32;
            let gbuffer_layout =
                o.pipeline_layout(device, &[camera_layout], OBJECT_STAGES, push_size)?;
            let vert = o.shader(device, spirv!("teapot.vert"))?;
            let frag = o.shader(device, spirv!("deferred_gbuffer.frag"))?;
            let (bindings, attributes) = vertex_input();
            let gbuffer = o.pipeline(
                device,
                gbuffer_layout,
                render_pass,
                &PipelineDesc {
                    stages: &[
                        (vk::ShaderStageFlags::VERTEX, vert),
                        (vk::ShaderStageFlags::FRAGMENT, frag),
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

            let fragment = vk::ShaderStageFlags::FRAGMENT;
            let input = vk::DescriptorType::INPUT_ATTACHMENT;
            let lighting_bindings = [
                binding(0, input, fragment),
                binding(1, input, fragment),
                binding(2, input, fragment),
                binding(3, uniform, fragment),
            ];
            let lighting_set_layout = device
                .create_descriptor_set_layout(
                    &vk::DescriptorSetLayoutCreateInfo::default().bindings(&lighting_bindings),
                    None,
                )
                .context("vkCreateDescriptorSetLayout")?;
            o.set_layouts.push(lighting_set_layout);
            let lighting_layout = o.pipeline_layout(device, &[lighting_set_layout], fragment, 0)?;
            let vert = o.shader(device, spirv!("deferred_light.vert"))?;
            let frag = o.shader(device, spirv!("deferred_light.frag"))?;
            let lighting = o.pipeline(
                device,
                lighting_layout,
                render_pass,
                &PipelineDesc {
                    stages: &[
                        (vk::ShaderStageFlags::VERTEX, vert),
                        (vk::ShaderStageFlags::FRAGMENT, frag),
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

            let frames = FRAMES_IN_FLIGHT as u32;
            let pool_sizes = [
                vk::DescriptorPoolSize {
                    ty: uniform,
                    descriptor_count: 2 * frames,
                },
                vk::DescriptorPoolSize {
                    ty: input,
                    descriptor_count: 3 * frames,
                },
            ];
            let pool = device
                .create_descriptor_pool(
                    &vk::DescriptorPoolCreateInfo::default()
                        .max_sets(2 * frames)
                        .pool_sizes(&pool_sizes),
                    None,
                )
                .context("vkCreateDescriptorPool")?;
            o.descriptor_pools.push(pool);
            let allocate = |layout| {
                let layouts = [layout; FRAMES_IN_FLIGHT];
                device
                    .allocate_descriptor_sets(
                        &vk::DescriptorSetAllocateInfo::default()
                            .descriptor_pool(pool)
                            .set_layouts(&layouts),
                    )
                    .context("vkAllocateDescriptorSets")
            };
            let camera_sets = allocate(camera_layout)?;
            let lighting_sets = allocate(lighting_set_layout)?;
            let local = vk::MemoryPropertyFlags::DEVICE_LOCAL;
            let usage = vk::BufferUsageFlags::UNIFORM_BUFFER;
            let mut cameras = Vec::new();
            let mut lights = Vec::new();
            for slot in 0..FRAMES_IN_FLIGHT {
                let camera_size = size_of::<CameraBlock>() as u64;
                let (camera, camera_memory) = o.buffer(device, camera_size, usage, local)?;
                let lights_size = size_of::<LightsBlock>() as u64;
                let (light, light_memory) = o.buffer(device, lights_size, usage, local)?;
                // Mapped for the whole run, as tuff's allocator keeps it; freeing the
                // memory unmaps it.
                let map = |memory| {
                    device
                        .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                        .context("vkMapMemory")
                };
                cameras.push(map(camera_memory)?.cast::<CameraBlock>());
                lights.push(map(light_memory)?.cast::<LightsBlock>());
                let buffer_info = |buffer| {
                    [vk::DescriptorBufferInfo {
                        buffer,
                        offset: 0,
                        range: vk::WHOLE_SIZE,
                    }]
                };
                let (camera_info, light_info) = (buffer_info(camera), buffer_info(light));
                let images: Vec<_> = gbuffer_views
                    .iter()
                    .zip(LIGHTING_INPUTS)
                    .map(|(&view, reference)| {
                        [vk::DescriptorImageInfo {
                            sampler: vk::Sampler::null(),
                            image_view: view,
                            image_layout: reference.layout,
                        }]
                    })
                    .collect();
                let set = lighting_sets[slot];
                let mut writes = vec![
                    vk::WriteDescriptorSet::default()
                        .dst_set(camera_sets[slot])
                        .descriptor_type(uniform)
                        .buffer_info(&camera_info),
                    vk::WriteDescriptorSet::default()
                        .dst_set(set)
                        .dst_binding(3)
                        .descriptor_type(uniform)
                        .buffer_info(&light_info),
                ];
                for (binding, image) in images.iter().enumerate() {
                    writes.push(
                        vk::WriteDescriptorSet::default()
                            .dst_set(set)
                            .dst_binding(binding as u32)
                            .descriptor_type(input)
                            .image_info(image),
                    );
                }
                device.update_descriptor_sets(&writes, &[]);
            }
            let meshes = Meshes::new();
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
                vertices: o.buffer_with(
                    device,
                    vk::BufferUsageFlags::VERTEX_BUFFER,
                    &meshes.vertices,
                )?,
                indices: o.buffer_with(
                    device,
                    vk::BufferUsageFlags::INDEX_BUFFER,
                    &meshes.indices,
                )?,
            })
        }
    }

    /// Writes the frame's camera and lights.
    ///
    /// # Safety
    ///
    /// The slot's previous submission has completed.
    unsafe fn update(&self, view: &View) {
        let camera = self.layout.camera(view.extent);
        let lights = self.layout.lights(view.extent, view.time);
        // SAFETY: no read of the slot's uniforms is pending (the caller promises);
        // the mappings are of whole buffers of these blocks, aligned to
        // minMemoryMapAlignment (at least 64 bytes) and coherent: no flush needed.
        unsafe {
            self.cameras[view.slot].write(camera);
            self.lights[view.slot].write(lights);
        }
    }

    /// Records worker `worker`'s share of the objects, of `workers`, into
    /// `secondary`: it continues subpass 0 of the frame's render pass instance.
    ///
    /// # Safety
    ///
    /// `secondary` is a secondary command buffer of `device` that no other thread
    /// uses, from a pool no other thread uses, and not pending.
    unsafe fn record_objects(
        &self,
        device: &ash::Device,
        secondary: vk::CommandBuffer,
        view: &View,
        worker: usize,
        workers: usize,
    ) -> Result<()> {
        let inheritance = vk::CommandBufferInheritanceInfo::default()
            .render_pass(self.render_pass)
            .subpass(0)
            .framebuffer(self.framebuffers[view.slot]);
        let info = vk::CommandBufferBeginInfo::default()
            .flags(
                vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE
                    | vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT,
            )
            .inheritance_info(&inheritance);
        let cb = secondary;
        // SAFETY: as the caller promises; every object bound lives until the device
        // is idle; the draws' indices stay inside their meshes.
        unsafe {
            device
                .begin_command_buffer(cb, &info)
                .context("vkBeginCommandBuffer")?;
            device.cmd_set_viewport(cb, 0, &[crate::render::viewport(view.extent)]);
            device.cmd_set_scissor(cb, 0, &[view.extent.into()]);
            device.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, self.gbuffer);
            device.cmd_bind_descriptor_sets(
                cb,
                vk::PipelineBindPoint::GRAPHICS,
                self.gbuffer_layout,
                0,
                &[self.camera_sets[view.slot]],
                &[],
            );
            device.cmd_bind_vertex_buffers(cb, 0, &[self.vertices], &[0]);
            device.cmd_bind_index_buffer(cb, self.indices, 0, vk::IndexType::UINT32);
            let share = data::share(self.layout.objects.len(), workers, worker);
            for object in &self.layout.objects[share] {
                let block = object.instance.block(view.time);
                let bytes = bytemuck::bytes_of(&block);
                device.cmd_push_constants(cb, self.gbuffer_layout, OBJECT_STAGES, 0, bytes);
                let mesh = self.ranges[object.mesh];
                device.cmd_draw_indexed(
                    cb,
                    mesh.index_count,
                    1,
                    mesh.first_index,
                    mesh.vertex_offset,
                    0,
                );
            }
            device.end_command_buffer(cb).context("vkEndCommandBuffer")
        }
    }

    /// Records the frame: the workers' secondaries on threads of their own, then
    /// `primary`, which executes them in subpass 0, lights in subpass 1 and, when
    /// asked, copies the output into `readback`.
    ///
    /// # Safety
    ///
    /// The frame's previous submission completed; `primary` and `secondaries` are the
    /// frame's, each secondary from a pool of its own.
    unsafe fn record(
        &self,
        device: &ash::Device,
        primary: vk::CommandBuffer,
        secondaries: &[vk::CommandBuffer],
        view: &View,
        readback: Option<vk::Buffer>,
    ) -> Result<()> {
        let count = secondaries.len();
        crate::workers::on_threads(secondaries.to_vec(), |worker, secondary| {
            // SAFETY: as the caller promises; each worker has a secondary of its own.
            unsafe { self.record_objects(device, secondary, view, worker, count) }
        })?;
        let cb = primary;
        let area: vk::Rect2D = view.extent.into();
        let clear = data::clear_values();
        // SAFETY: as the caller promises; the secondaries continue this instance's
        // subpass 0 and framebuffer.
        unsafe {
            device
                .begin_command_buffer(
                    cb,
                    &vk::CommandBufferBeginInfo::default()
                        .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
                )
                .context("vkBeginCommandBuffer")?;
            device.cmd_begin_render_pass(
                cb,
                &vk::RenderPassBeginInfo::default()
                    .render_pass(self.render_pass)
                    .framebuffer(self.framebuffers[view.slot])
                    .render_area(area)
                    .clear_values(&clear),
                vk::SubpassContents::SECONDARY_COMMAND_BUFFERS,
            );
            device.cmd_execute_commands(cb, secondaries);
            device.cmd_next_subpass(cb, vk::SubpassContents::INLINE);
            device.cmd_set_viewport(cb, 0, &[crate::render::viewport(view.extent)]);
            device.cmd_set_scissor(cb, 0, &[area]);
            device.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, self.lighting);
            device.cmd_bind_descriptor_sets(
                cb,
                vk::PipelineBindPoint::GRAPHICS,
                self.lighting_layout,
                0,
                &[self.lighting_sets[view.slot]],
                &[],
            );
            device.cmd_draw(cb, 3, 1, 0, 0);
            device.cmd_end_render_pass(cb);
            if let Some(buffer) = readback {
                record_readback(device, cb, self.outputs[view.slot], buffer, view.extent);
            }
            device.end_command_buffer(cb).context("vkEndCommandBuffer")
        }
    }
}

/// The render pass of `deferred_data`.
fn render_pass(device: &ash::Device) -> Result<vk::RenderPass> {
    let attachments = data::attachments(crate::headless::COLOR_FORMAT);
    let subpasses = [
        vk::SubpassDescription::default()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&GBUFFER_COLORS)
            .depth_stencil_attachment(&GBUFFER_DEPTH),
        vk::SubpassDescription::default()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .input_attachments(&LIGHTING_INPUTS)
            .color_attachments(&LIGHTING_COLOR),
    ];
    let dependencies = data::dependencies();
    let info = vk::RenderPassCreateInfo::default()
        .attachments(&attachments)
        .subpasses(&subpasses)
        .dependencies(&dependencies);
    // SAFETY: the create info and the arrays it points at live across the call.
    unsafe { device.create_render_pass(&info, None) }.context("vkCreateRenderPass")
}

/// `workers` secondaries per frame in flight, each from a resettable pool of its
/// own (as tuff's `frames_in_flight_with_workers` makes them), kept by `o`.
fn worker_secondaries(
    device: &ash::Device,
    o: &mut Objects,
    family: u32,
    workers: usize,
) -> Result<Vec<Vec<vk::CommandBuffer>>> {
    (0..FRAMES_IN_FLIGHT)
        .map(|_| {
            (0..workers)
                .map(|_| {
                    // SAFETY: valid create and allocate infos; the pool goes into `o`.
                    unsafe {
                        let pool = device
                            .create_command_pool(
                                &vk::CommandPoolCreateInfo::default()
                                    .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                                    .queue_family_index(family),
                                None,
                            )
                            .context("vkCreateCommandPool")?;
                        o.worker_pools.push(pool);
                        let buffers = device
                            .allocate_command_buffers(
                                &vk::CommandBufferAllocateInfo::default()
                                    .command_pool(pool)
                                    .level(vk::CommandBufferLevel::SECONDARY)
                                    .command_buffer_count(1),
                            )
                            .context("vkAllocateCommandBuffers")?;
                        buffers.first().copied().context("no command buffer")
                    }
                })
                .collect()
        })
        .collect()
}

/// Renders `frames` frames (at least one) of `layout` at `extent` with `threads`
/// workers (1 to [`data::MAX_WORKERS`]) and reads the last one back: its pixels, the
/// time from the first recording to the last completion, and the average
/// recording time per frame over every frame but the first (zero for one frame), and
/// the resident memory through the run.
pub fn render(
    vulkan: &mut Vulkan,
    layout: Layout,
    extent: vk::Extent2D,
    frames: u32,
    threads: u32,
) -> Result<(Vec<u8>, Duration, Duration, crate::headless::Resident)> {
    if !(1..=data::MAX_WORKERS).contains(&threads) {
        bail!(
            "the thread count must be 1 to {}, not {threads}",
            data::MAX_WORKERS
        );
    }
    let frames = frames.max(1);
    let slots = frame_slots(vulkan, FRAMES_IN_FLIGHT)?;
    let family = vulkan.family;
    let Vulkan {
        device,
        queue,
        objects: o,
        ..
    } = vulkan;
    let queue = *queue;
    let scene = Deferred::new(device, o, layout, extent)?;
    let secondaries = worker_secondaries(device, o, family, threads as usize)?;
    let bytes = u64::from(extent.width) * u64::from(extent.height) * 4;
    let cached = vk::MemoryPropertyFlags::HOST_CACHED;
    let (readback, readback_memory) =
        o.buffer(device, bytes, vk::BufferUsageFlags::TRANSFER_DST, cached)?;
    let mut recording = Duration::ZERO;
    let mut resident = crate::headless::Resident::default();
    // SAFETY: a slot is updated and recorded only after its fence says the slot's
    // last submission completed, and the readback is read only after every fence.
    unsafe {
        let start = Instant::now();
        for frame in 0..frames {
            let slot = frame as usize % FRAMES_IN_FLIGHT;
            let (cb, fence) = slots[slot];
            device
                .wait_for_fences(&[fence], true, u64::MAX)
                .context("vkWaitForFences")?;
            device.reset_fences(&[fence]).context("vkResetFences")?;
            let view = View {
                extent,
                time: frame as f32 / 60.0,
                slot,
            };
            scene.update(&view);
            let last = frame + 1 == frames;
            let began = Instant::now();
            scene.record(
                device,
                cb,
                &secondaries[slot],
                &view,
                last.then_some(readback),
            )?;
            // The first frame's recording runs on cold caches: left out of the mean.
            if frame > 0 {
                recording += began.elapsed();
            }
            let submit = vk::SubmitInfo::default().command_buffers(std::slice::from_ref(&cb));
            device
                .queue_submit(queue, &[submit], fence)
                .context("vkQueueSubmit")?;
            resident.after_frame(frame + 1, frames);
        }
        device
            .wait_for_fences(&o.fences, true, u64::MAX)
            .context("vkWaitForFences")?;
        let elapsed = start.elapsed();
        resident.finish();
        let rgba = crate::raw_ash::read_memory(device, readback_memory, bytes as usize)?;
        Ok((rgba, elapsed, recording / (frames - 1).max(1), resident))
    }
}
