//! The triangle of `triangle`, written against raw ash: the same instance, device,
//! objects and commands as `triangle` makes headless, into `triangle_ash.png`.
//! Headless only: there is no `--window`.

use anyhow::Result;
use ash::vk;
use clap::Parser;
use tuff_examples::gpu::Requirements;
use tuff_examples::raw_ash::{self, Objects, PipelineDesc, Scene};
use tuff_examples::render::View;
use tuff_examples::scenes::triangle_vertices::{Vertex, VERTICES};
use tuff_examples::spirv;

/// Renders a triangle through raw ash, headless.
#[derive(Parser)]
struct Args {
    #[command(flatten)]
    common: raw_ash::Common,
}

/// The triangle's pipeline and vertex buffer, owned by the [`Objects`] they were
/// made into.
struct Triangle {
    pipeline: vk::Pipeline,
    vertices: vk::Buffer,
}

impl Triangle {
    /// Builds the pipeline for `render_pass` and uploads the vertices, into `o`.
    fn new(device: &ash::Device, o: &mut Objects, render_pass: vk::RenderPass) -> Result<Self> {
        let vert = o.shader(device, spirv!("triangle.vert"))?;
        let frag = o.shader(device, spirv!("triangle.frag"))?;
        let layout = o.pipeline_layout(device, &[], vk::ShaderStageFlags::empty(), 0)?;
        let pipeline = o.pipeline(
            device,
            layout,
            render_pass,
            &PipelineDesc {
                stages: &[
                    (vk::ShaderStageFlags::VERTEX, vert),
                    (vk::ShaderStageFlags::FRAGMENT, frag),
                ],
                bindings: &[vk::VertexInputBindingDescription {
                    binding: 0,
                    stride: size_of::<Vertex>() as u32,
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
        let vertices = o.buffer_with(device, vk::BufferUsageFlags::VERTEX_BUFFER, &VERTICES)?;
        Ok(Triangle { pipeline, vertices })
    }
}

impl Scene for Triangle {
    const DEPTH: bool = false;

    fn clear_color(&self) -> [f32; 4] {
        [0.05, 0.05, 0.08, 1.0]
    }

    unsafe fn draw(&self, device: &ash::Device, cb: vk::CommandBuffer, _view: &View) {
        // SAFETY: `cb` is recording inside the render pass the pipeline was made for
        // (the caller promises); the pipeline and buffer live until the device is idle.
        unsafe {
            device.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, self.pipeline);
            device.cmd_bind_vertex_buffers(cb, 0, &[self.vertices], &[0]);
            device.cmd_draw(cb, 3, 1, 0, 0);
        }
    }
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    let req = Requirements::core("triangle_ash");
    tuff_examples::exit(|| raw_ash::run(&args.common, req, Triangle::new))
}
