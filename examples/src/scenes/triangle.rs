//! The smallest complete program: one colored triangle from a vertex buffer.

use crate::gpu::{Gpu, Requirements};
use crate::pipeline::{self, PipelineDesc};
use crate::render::{Scene, View};
use anyhow::Result;
use tuff::vk;

/// What the triangle asks of the device: nothing beyond core Vulkan.
pub const REQUIREMENTS: Requirements = Requirements {
    scene: "triangle",
    tessellation_shader: false,
    fill_mode_non_solid: false,
    window: false,
};

/// A vertex: position in clip space and color.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Vertex {
    position: [f32; 2],
    color: [f32; 3],
}

const VERTICES: [Vertex; 3] = [
    Vertex {
        position: [0.0, -0.7],
        color: [1.0, 0.2, 0.2],
    },
    Vertex {
        position: [0.7, 0.6],
        color: [0.2, 1.0, 0.2],
    },
    Vertex {
        position: [-0.7, 0.6],
        color: [0.2, 0.3, 1.0],
    },
];

/// The triangle's pipeline (which keeps its layout) and vertex buffer.
pub struct Triangle {
    pipeline: tuff::Pipeline,
    vertices: tuff::Bound<tuff::Buffer>,
}

impl Triangle {
    /// Builds the pipeline for `render_pass` and uploads the vertices.
    pub fn new(gpu: &Gpu, render_pass: &tuff::RenderPass) -> Result<Triangle> {
        let vert = gpu
            .device
            .create_shader_module_from_spirv(crate::spirv!("triangle.vert"))?;
        let frag = gpu
            .device
            .create_shader_module_from_spirv(crate::spirv!("triangle.frag"))?;
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
            },
        )?;
        let vertices = gpu.device.create_buffer_with(
            vk::BufferUsageFlags::VERTEX_BUFFER,
            &VERTICES,
            &gpu.allocator,
        )?;
        Ok(Triangle { pipeline, vertices })
    }
}

impl Scene for Triangle {
    const DEPTH: bool = false;

    fn clear_color(&self) -> [f32; 4] {
        [0.05, 0.05, 0.08, 1.0]
    }

    fn draw(&self, rec: &mut tuff::Recorder<'_, tuff::InRenderPass>, _view: &View) {
        rec.cmd_bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.pipeline);
        rec.cmd_bind_vertex_buffers(0, &[&self.vertices], &[0]);
        rec.cmd_draw(3, 1, 0, 0);
    }
}
