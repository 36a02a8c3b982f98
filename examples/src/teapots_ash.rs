//! The spinning teapots of `scenes::teapots`, written against raw ash: the baseline
//! tuff is measured against (`teapots_ash`, and the stage benchmark).

use crate::raw_ash::{Objects, PipelineDesc, Scene};
use crate::render::{View, FRAMES_IN_FLIGHT};
use crate::scenes::teapot_grid::{mesh_data, vertex_input, CameraBlock, Layout, TeapotBlock};
use crate::spirv;
use anyhow::{Context as _, Result};
use ash::vk;

/// What the teapots ask of the device, as in the tuff scene: robust buffer access.
pub const REQUIREMENTS: crate::gpu::Requirements = crate::gpu::Requirements {
    robust_buffer_access: true,
    ..crate::gpu::Requirements::core("teapots_ash")
};

/// The stages that read the uniforms and push constants.
const STAGES: vk::ShaderStageFlags = vk::ShaderStageFlags::from_raw(
    vk::ShaderStageFlags::VERTEX.as_raw() | vk::ShaderStageFlags::FRAGMENT.as_raw(),
);

/// The teapots' pipeline, mesh, descriptor sets and mapped per-frame uniforms, all
/// owned by the [`Objects`] they were made into.
pub struct Teapots {
    layout_data: Layout,
    pipeline: vk::Pipeline,
    pipeline_layout: vk::PipelineLayout,
    sets: Vec<vk::DescriptorSet>,
    uniforms: Vec<*mut CameraBlock>,
    /// Camera blocks written per frame (the shaders read the first).
    writes: usize,
    vertices: vk::Buffer,
    indices: vk::Buffer,
    index_count: u32,
}

impl Teapots {
    /// Builds the scene for `render_pass` into `o`; each frame writes its camera block
    /// `writes` times (at least once), into consecutive blocks of its uniform buffer.
    pub fn new(
        device: &ash::Device,
        o: &mut Objects,
        render_pass: vk::RenderPass,
        layout: Layout,
        writes: usize,
    ) -> Result<Teapots> {
        let writes = writes.max(1);
        let vert = o.shader(device, spirv!("teapot.vert"))?;
        let frag = o.shader(device, spirv!("teapot.frag"))?;
        let bindings = [vk::DescriptorSetLayoutBinding::default()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
            .descriptor_count(1)
            .stage_flags(STAGES)];
        // SAFETY: every create info and what it points at lives across its call; each
        // object goes into `o` as soon as it is made; the uniform memory stays mapped
        // until `o` frees it, after the device is idle.
        unsafe {
            let set_layout = device
                .create_descriptor_set_layout(
                    &vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings),
                    None,
                )
                .context("vkCreateDescriptorSetLayout")?;
            o.set_layouts.push(set_layout);
            let push_size = size_of::<TeapotBlock>() as u32;
            let pipeline_layout = o.pipeline_layout(device, &[set_layout], STAGES, push_size)?;
            let (bindings, attributes) = vertex_input();
            let pipeline = o.pipeline(
                device,
                pipeline_layout,
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
                    colors: 1,
                },
            )?;
            let pool_sizes = [vk::DescriptorPoolSize {
                ty: vk::DescriptorType::UNIFORM_BUFFER,
                descriptor_count: FRAMES_IN_FLIGHT as u32,
            }];
            let pool = device
                .create_descriptor_pool(
                    &vk::DescriptorPoolCreateInfo::default()
                        .max_sets(FRAMES_IN_FLIGHT as u32)
                        .pool_sizes(&pool_sizes),
                    None,
                )
                .context("vkCreateDescriptorPool")?;
            o.descriptor_pools.push(pool);
            let set_layouts = [set_layout; FRAMES_IN_FLIGHT];
            let sets = device
                .allocate_descriptor_sets(
                    &vk::DescriptorSetAllocateInfo::default()
                        .descriptor_pool(pool)
                        .set_layouts(&set_layouts),
                )
                .context("vkAllocateDescriptorSets")?;
            let camera_size = size_of::<CameraBlock>() as u64;
            let mut uniforms = Vec::new();
            for &set in &sets {
                let usage = vk::BufferUsageFlags::UNIFORM_BUFFER;
                let local = vk::MemoryPropertyFlags::DEVICE_LOCAL;
                let whole = camera_size * writes as u64;
                let (buffer, memory) = o.buffer(device, whole, usage, local)?;
                let info = [vk::DescriptorBufferInfo {
                    buffer,
                    offset: 0,
                    range: camera_size,
                }];
                let write = vk::WriteDescriptorSet::default()
                    .dst_set(set)
                    .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                    .buffer_info(&info);
                device.update_descriptor_sets(&[write], &[]);
                // Mapped for the whole run, as tuff's allocator keeps it; freeing the
                // memory unmaps it.
                let ptr = device
                    .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                    .context("vkMapMemory")?;
                uniforms.push(ptr.cast::<CameraBlock>());
            }
            let (flat, index_data) = mesh_data();
            Ok(Teapots {
                layout_data: layout,
                pipeline,
                pipeline_layout,
                sets,
                uniforms,
                writes,
                vertices: o.buffer_with(device, vk::BufferUsageFlags::VERTEX_BUFFER, &flat)?,
                indices: o.buffer_with(device, vk::BufferUsageFlags::INDEX_BUFFER, &index_data)?,
                index_count: index_data.len() as u32,
            })
        }
    }
}

impl Scene for Teapots {
    fn clear_color(&self) -> [f32; 4] {
        [0.02, 0.02, 0.04, 1.0]
    }

    unsafe fn update(&mut self, view: &View) {
        let block = self.layout_data.camera(view.extent);
        let first = self.uniforms[view.slot];
        for i in 0..self.writes {
            // SAFETY: the slot's last submission completed (the caller promises), so
            // no read of its uniforms is pending; the buffer holds `writes` blocks
            // (`new`), and the mapping is aligned to minMemoryMapAlignment (at least
            // 64 bytes, and a block is 96) and coherent, so a plain store needs no flush.
            unsafe { first.add(i).write(block) };
        }
    }

    unsafe fn draw(&self, device: &ash::Device, cb: vk::CommandBuffer, view: &View) {
        // SAFETY: `cb` is recording inside the render pass the pipeline was made for
        // (the caller promises); every object bound is live until the device is idle.
        unsafe {
            device.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, self.pipeline);
            device.cmd_bind_descriptor_sets(
                cb,
                vk::PipelineBindPoint::GRAPHICS,
                self.pipeline_layout,
                0,
                &[self.sets[view.slot]],
                &[],
            );
            device.cmd_bind_vertex_buffers(cb, 0, &[self.vertices], &[0]);
            device.cmd_bind_index_buffer(cb, self.indices, 0, vk::IndexType::UINT32);
            for teapot in &self.layout_data.teapots {
                let block = teapot.block(view.time);
                let bytes = bytemuck::bytes_of(&block);
                device.cmd_push_constants(cb, self.pipeline_layout, STAGES, 0, bytes);
                device.cmd_draw_indexed(cb, self.index_count, 1, 0, 0, 0);
            }
        }
    }
}
