//! The smallest complete program: one colored triangle from a vertex buffer.

use crate::gpu::{Gpu, Requirements};
use crate::pipeline::{self, PipelineDesc};
use crate::render::{Scene, View};
use crate::scenes::triangle_vertices::{Vertex, VERTICES};
use anyhow::Result;
use tuff::vk;

/// What the triangle asks of the device: nothing beyond core Vulkan.
pub const REQUIREMENTS: Requirements = Requirements::core("triangle");

/// The triangle's pipeline (which keeps its layout) and vertex buffer.
pub struct Triangle {
    pipeline: tuff::Pipeline,
    vertices: tuff::Bound<tuff::Buffer>,
}

impl Triangle {
    /// Builds the pipeline for `render_pass` and uploads the vertices.
    pub fn new(gpu: &Gpu, render_pass: &tuff::RenderPass) -> Result<Triangle> {
        let (d, a) = (&gpu.device, &gpu.allocator);
        let vert = crate::shader(d, crate::spirv!("triangle.vert"))?;
        let frag = crate::shader(d, crate::spirv!("triangle.frag"))?;
        let layout = pipeline::layout(gpu, &[], vk::ShaderStageFlags::empty(), 0)?;
        let pipeline = pipeline::graphics(
            gpu,
            &layout,
            render_pass,
            &PipelineDesc {
                stages: &[
                    (vk::ShaderStageFlags::VERTEX, &vert),
                    (vk::ShaderStageFlags::FRAGMENT, &frag),
                ],
                bindings: &[vk::VertexInputBindingDescription {
                    binding: 0,
                    stride: std::mem::size_of::<Vertex>() as u32,
                    input_rate: vk::VertexInputRate::VERTEX,
                }],
                attributes: &[
                    vk::VertexInputAttributeDescription {
                        location: 0,
                        binding: 0,
                        format: vk::Format::R32G32_SFLOAT,
                        offset: 0,
                    },
                    vk::VertexInputAttributeDescription {
                        location: 1,
                        binding: 0,
                        format: vk::Format::R32G32B32_SFLOAT,
                        offset: 8,
                    },
                ],
                topology: vk::PrimitiveTopology::TRIANGLE_LIST,
                patch_control_points: 0,
                polygon_mode: vk::PolygonMode::FILL,
                depth: false,
                subpass: 0,
                colors: 1,
            },
        )?;
        let vertices = d.create_buffer_with(vk::BufferUsageFlags::VERTEX_BUFFER, &VERTICES, a)?;
        Ok(Triangle { pipeline, vertices })
    }
}

impl Scene for Triangle {
    const DEPTH: bool = false;

    fn clear_color(&self) -> [f32; 4] {
        [0.05, 0.05, 0.08, 1.0]
    }

    fn draw(
        &self,
        rec: &mut tuff::Recorder<'_, tuff::InRenderPass>,
        _view: &View,
    ) -> tuff::Result<()> {
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.pipeline)?;
        rec.bind_vertex_buffers(0, &self.vertices, &[0])?;
        rec.draw(3, 1, 0, 0)?;
        Ok(())
    }
}
