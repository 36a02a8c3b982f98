//! A grid of spinning Utah teapots: a depth buffer, a camera uniform buffer per frame
//! in flight, and one push-constant block (model matrix, color) per teapot. What the
//! scene shows is in [`crate::scenes::teapot_grid`].

use crate::gpu::{Gpu, Requirements};
use crate::pipeline::{self, PipelineDesc};
use crate::render::{Scene, View, FRAMES_IN_FLIGHT};
use crate::scenes::teapot_grid::{mesh_data, vertex_input, CameraBlock, Layout, TeapotBlock};
use anyhow::Result;
use tuff::vk;
use tuff::MemoryLocation::Upload;

/// What the teapots ask of the device: core Vulkan with robust buffer access.
/// Robust buffer access keeps the indexed draws' vertex fetches inside the vertex
/// buffer, which makes them safe (see [`Requirements::robust_buffer_access`]).
pub const REQUIREMENTS: Requirements = Requirements {
    robust_buffer_access: true,
    ..Requirements::core("teapots")
};

/// The teapots' pipeline, mesh, and per-frame uniform buffers. The pipeline layout
/// keeps the set layout, and the sets their pool.
pub struct Teapots {
    layout_data: Layout,
    pipeline: tuff::Pipeline,
    pipeline_layout: tuff::PipelineLayout,
    sets: Vec<tuff::DescriptorSet>,
    uniforms: Vec<tuff::Bound<tuff::Buffer>>,
    /// Camera blocks written per frame (the shaders read the first).
    writes: u64,
    vertices: tuff::Bound<tuff::Buffer>,
    indices: tuff::Bound<tuff::Buffer>,
    index_count: u32,
}

impl Teapots {
    /// Builds the scene for `render_pass`.
    pub fn new(gpu: &Gpu, render_pass: &tuff::RenderPass, layout: Layout) -> Result<Teapots> {
        Teapots::with_writes(gpu, render_pass, layout, 1)
    }

    /// Builds the scene for `render_pass`; each frame writes its camera block `writes`
    /// times (at least once), into consecutive blocks of its uniform buffer, as the
    /// stage benchmark measures.
    pub fn with_writes(
        gpu: &Gpu,
        render_pass: &tuff::RenderPass,
        layout: Layout,
        writes: u64,
    ) -> Result<Teapots> {
        let writes = writes.max(1);
        let (d, a) = (&gpu.device, &gpu.allocator);
        let vert = crate::shader(d, crate::spirv!("teapot.vert"))?;
        let frag = crate::shader(d, crate::spirv!("teapot.frag"))?;
        let bindings = [tuff::DescriptorSetLayoutBinding::new()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT)];
        let set_layout = d.create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )?;
        let pipeline_layout = pipeline::layout(
            gpu,
            &[&set_layout],
            vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT,
            std::mem::size_of::<TeapotBlock>() as u32,
        )?;
        let (bindings, attributes) = vertex_input();
        let pipeline = pipeline::graphics(
            gpu,
            &pipeline_layout,
            render_pass,
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
                colors: 1,
            },
        )?;
        let pool = d.create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(FRAMES_IN_FLIGHT as u32)
                .pool_sizes(&[vk::DescriptorPoolSize {
                    ty: vk::DescriptorType::UNIFORM_BUFFER,
                    descriptor_count: FRAMES_IN_FLIGHT as u32,
                }]),
        )?;
        let layouts = tuff::HandleSlice::new(&[&set_layout; FRAMES_IN_FLIGHT]);
        let sets = d.allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layouts),
        )?;
        let size = std::mem::size_of::<CameraBlock>() as u64;
        let uniforms = (0..FRAMES_IN_FLIGHT)
            .map(|_| gpu.buffer(size * writes, vk::BufferUsageFlags::UNIFORM_BUFFER, Upload))
            .collect::<Result<Vec<_>>>()?;
        for (set, buffer) in sets.iter().zip(&uniforms) {
            let info = [tuff::DescriptorBufferInfo::new()
                .buffer(Some(buffer))
                .range(size)];
            d.update_descriptor_sets(
                &[tuff::WriteDescriptorSet::new(set)
                    .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                    .buffer_info(&info)],
                &[],
            )?;
        }
        let (flat, index_data) = mesh_data();
        let vertices = d.create_buffer_with(vk::BufferUsageFlags::VERTEX_BUFFER, &flat, a)?;
        let indices = d.create_buffer_with(vk::BufferUsageFlags::INDEX_BUFFER, &index_data, a)?;
        Ok(Teapots {
            layout_data: layout,
            pipeline,
            pipeline_layout,
            sets,
            uniforms,
            writes,
            vertices,
            indices,
            index_count: index_data.len() as u32,
        })
    }
}

impl Scene for Teapots {
    fn clear_color(&self) -> [f32; 4] {
        [0.02, 0.02, 0.04, 1.0]
    }

    fn update(&mut self, view: &View) -> Result<()> {
        let block = self.layout_data.camera(view.extent);
        // One lock for the frame's writes (a lock per write would drain the
        // write-combining buffers of host-visible VRAM each time with `multi_thread`).
        let mut memory = self.uniforms[view.slot].memory().lock();
        let size = std::mem::size_of::<CameraBlock>() as u64;
        for i in 0..self.writes {
            memory.write_value(i * size, &block)?;
        }
        Ok(())
    }

    fn draw(
        &self,
        rec: &mut tuff::Recorder<'_, tuff::InRenderPass>,
        view: &View,
    ) -> tuff::Result<()> {
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.pipeline)?;
        rec.bind_descriptor_sets(
            vk::PipelineBindPoint::GRAPHICS,
            &self.pipeline_layout,
            0,
            &self.sets[view.slot],
            &[],
        )?;
        rec.bind_vertex_buffers(0, &self.vertices, &[0])?;
        rec.bind_index_buffer(&self.indices, 0, vk::IndexType::UINT32)?;
        for teapot in &self.layout_data.teapots {
            let block = teapot.block(view.time);
            rec.push_constants(
                &self.pipeline_layout,
                vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT,
                0,
                bytemuck::bytes_of(&block),
            )?;
            rec.draw_indexed(self.index_count, 1, 0, 0, 0)?;
        }
        Ok(())
    }
}
