//! The Utah teapot as its 32 bicubic Bezier patches, tessellated on the GPU: control
//! points in a storage buffer, patches listed by an index buffer, levels from the
//! command line, and normals computed in the evaluation shader. What it shows is in
//! [`crate::scenes::bezier_view`].

use crate::gpu::Gpu;
use crate::pipeline::{self, PipelineDesc};
use crate::render::{Scene, View};
use crate::scenes::bezier_view::{params, Options, Params, MAX_LEVEL, PARAM_STAGES};
use crate::teapot::{CONTROL_POINTS, PATCHES};
use anyhow::{bail, Result};
use tuff::vk;

/// The tessellated teapot's pipeline and buffers. The set keeps the control points
/// written into it and its pool; the pipeline layout keeps the set layout.
pub struct Bezier {
    options: Options,
    pipeline: tuff::Pipeline,
    layout: tuff::PipelineLayout,
    set: tuff::DescriptorSet,
    indices: tuff::Bound<tuff::Buffer>,
}

impl Bezier {
    /// Builds the scene for `render_pass`.
    pub fn new(gpu: &Gpu, render_pass: &tuff::RenderPass, options: Options) -> Result<Bezier> {
        if !(1..=MAX_LEVEL).contains(&options.level) {
            bail!(
                "the tessellation level must be 1 to {MAX_LEVEL}, not {}",
                options.level
            );
        }
        let (d, a) = (&gpu.device, &gpu.allocator);
        let vert = crate::shader(d, crate::spirv!("bezier.vert"))?;
        let tesc = crate::shader(d, crate::spirv!("bezier.tesc"))?;
        let tese = crate::shader(d, crate::spirv!("bezier.tese"))?;
        let frag = crate::shader(d, crate::spirv!("bezier.frag"))?;
        let bindings = [tuff::DescriptorSetLayoutBinding::new()
            .binding(0)
            .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX)];
        let set_layout = d.create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )?;
        let layout = pipeline::layout(
            gpu,
            &[&set_layout],
            PARAM_STAGES,
            std::mem::size_of::<Params>() as u32,
        )?;
        let pipeline = pipeline::graphics(
            gpu,
            &layout,
            render_pass,
            &PipelineDesc {
                stages: &[
                    (vk::ShaderStageFlags::VERTEX, &vert),
                    (vk::ShaderStageFlags::TESSELLATION_CONTROL, &tesc),
                    (vk::ShaderStageFlags::TESSELLATION_EVALUATION, &tese),
                    (vk::ShaderStageFlags::FRAGMENT, &frag),
                ],
                bindings: &[],
                attributes: &[],
                topology: vk::PrimitiveTopology::PATCH_LIST,
                patch_control_points: 16,
                polygon_mode: if options.wireframe {
                    vk::PolygonMode::LINE
                } else {
                    vk::PolygonMode::FILL
                },
                depth: true,
                subpass: 0,
                colors: 1,
            },
        )?;
        let pool = d.create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&[vk::DescriptorPoolSize {
                    ty: vk::DescriptorType::STORAGE_BUFFER,
                    descriptor_count: 1,
                }]),
        )?;
        let set = d
            .allocate_descriptor_sets(
                &pool,
                &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&set_layout),
            )?
            .pop()
            .ok_or_else(|| anyhow::anyhow!("no descriptor set was allocated"))?;
        // vec4 per point: std430 pads a vec3 array to 16 bytes anyway.
        let points: Vec<[f32; 4]> = CONTROL_POINTS
            .iter()
            .map(|p| [p[0], p[1], p[2], 1.0])
            .collect();
        let points = d.create_buffer_with(vk::BufferUsageFlags::STORAGE_BUFFER, &points, a)?;
        let index_data: Vec<u32> = PATCHES.iter().flatten().map(|&i| u32::from(i)).collect();
        let indices = d.create_buffer_with(vk::BufferUsageFlags::INDEX_BUFFER, &index_data, a)?;
        let info = [tuff::DescriptorBufferInfo::new()
            .buffer(Some(&points))
            .range(vk::WHOLE_SIZE)];
        d.update_descriptor_sets(
            &[tuff::WriteDescriptorSet::new(&set)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .buffer_info(&info)],
            &[],
        )?;
        Ok(Bezier {
            options,
            pipeline,
            layout,
            set,
            indices,
        })
    }
}

impl Scene for Bezier {
    fn clear_color(&self) -> [f32; 4] {
        [0.02, 0.02, 0.04, 1.0]
    }

    fn draw(
        &self,
        rec: &mut tuff::Recorder<'_, tuff::InRenderPass>,
        view: &View,
    ) -> tuff::Result<()> {
        let params = params(
            self.options.view,
            self.options.level,
            view.time,
            view.extent,
        );
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.pipeline)?;
        rec.bind_descriptor_sets(
            vk::PipelineBindPoint::GRAPHICS,
            &self.layout,
            0,
            &self.set,
            &[],
        )?;
        rec.bind_index_buffer(&self.indices, 0, vk::IndexType::UINT32)?;
        rec.push_constants(&self.layout, PARAM_STAGES, 0, bytemuck::bytes_of(&params))?;
        // One draw per patch: lavapipe (Mesa 22.3) drops primitives when a single
        // draw tessellates all 32 patches at level 48 or more (the lid, spout and
        // handle went missing; the speckle test caught it).
        for patch in 0..PATCHES.len() as u32 {
            rec.draw_indexed(16, 1, patch * 16, 0, 0)?;
        }
        Ok(())
    }
}
