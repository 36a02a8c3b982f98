//! The tessellated Bezier teapot of `bezier`, written against raw ash: the same
//! instance, device, objects and commands as `bezier` makes headless, into
//! `bezier_ash.png`. Headless only: there is no `--window`.

use anyhow::{bail, Context as _, Result};
use ash::vk;
use clap::Parser;
use tuff_examples::raw_ash::{self, Objects, PipelineDesc, Scene};
use tuff_examples::render::View;
use tuff_examples::scenes::bezier_view::{
    self, Options, Params, Viewpoint, MAX_LEVEL, PARAM_STAGES,
};
use tuff_examples::spirv;
use tuff_examples::teapot::{CONTROL_POINTS, PATCHES};

/// Renders the tessellated Bezier teapot through raw ash, headless.
#[derive(Parser)]
struct Args {
    /// Tessellation level of every patch edge and inside, 1 to 64.
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=64))]
    level: u32,
    /// Draw lines instead of filled triangles (needs fillModeNonSolid).
    #[arg(long)]
    wireframe: bool,
    /// Where the camera looks from.
    #[arg(long, value_enum, default_value_t = Viewpoint::Orbit)]
    view: Viewpoint,
    #[command(flatten)]
    common: raw_ash::Common,
}

/// The tessellated teapot's pipeline, descriptor set and index buffer, owned by the
/// [`Objects`] they were made into.
struct Bezier {
    options: Options,
    pipeline: vk::Pipeline,
    layout: vk::PipelineLayout,
    set: vk::DescriptorSet,
    indices: vk::Buffer,
}

impl Bezier {
    /// Builds the scene for `render_pass` into `o`.
    fn new(
        device: &ash::Device,
        o: &mut Objects,
        render_pass: vk::RenderPass,
        options: Options,
    ) -> Result<Bezier> {
        if !(1..=MAX_LEVEL).contains(&options.level) {
            bail!(
                "the tessellation level must be 1 to {MAX_LEVEL}, not {}",
                options.level
            );
        }
        let vert = o.shader(device, spirv!("bezier.vert"))?;
        let tesc = o.shader(device, spirv!("bezier.tesc"))?;
        let tese = o.shader(device, spirv!("bezier.tese"))?;
        let frag = o.shader(device, spirv!("bezier.frag"))?;
        let bindings = [vk::DescriptorSetLayoutBinding::default()
            .binding(0)
            .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX)];
        // SAFETY: every create info and what it points at lives across its call; each
        // object goes into `o` as soon as it is made; the set is written before any
        // command buffer uses it.
        unsafe {
            let set_layout = device
                .create_descriptor_set_layout(
                    &vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings),
                    None,
                )
                .context("vkCreateDescriptorSetLayout")?;
            o.set_layouts.push(set_layout);
            let push_size = size_of::<Params>() as u32;
            let layout = o.pipeline_layout(device, &[set_layout], PARAM_STAGES, push_size)?;
            let pipeline = o.pipeline(
                device,
                layout,
                render_pass,
                &PipelineDesc {
                    stages: &[
                        (vk::ShaderStageFlags::VERTEX, vert),
                        (vk::ShaderStageFlags::TESSELLATION_CONTROL, tesc),
                        (vk::ShaderStageFlags::TESSELLATION_EVALUATION, tese),
                        (vk::ShaderStageFlags::FRAGMENT, frag),
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
            let pool_sizes = [vk::DescriptorPoolSize {
                ty: vk::DescriptorType::STORAGE_BUFFER,
                descriptor_count: 1,
            }];
            let pool = device
                .create_descriptor_pool(
                    &vk::DescriptorPoolCreateInfo::default()
                        .max_sets(1)
                        .pool_sizes(&pool_sizes),
                    None,
                )
                .context("vkCreateDescriptorPool")?;
            o.descriptor_pools.push(pool);
            let set = device
                .allocate_descriptor_sets(
                    &vk::DescriptorSetAllocateInfo::default()
                        .descriptor_pool(pool)
                        .set_layouts(&[set_layout]),
                )
                .context("vkAllocateDescriptorSets")?
                .pop()
                .context("no descriptor set was allocated")?;
            // vec4 per point: std430 pads a vec3 array to 16 bytes anyway.
            let points: Vec<[f32; 4]> = CONTROL_POINTS
                .iter()
                .map(|p| [p[0], p[1], p[2], 1.0])
                .collect();
            let points = o.buffer_with(device, vk::BufferUsageFlags::STORAGE_BUFFER, &points)?;
            let index_data: Vec<u32> = PATCHES.iter().flatten().map(|&i| u32::from(i)).collect();
            let usage = vk::BufferUsageFlags::INDEX_BUFFER;
            let indices = o.buffer_with(device, usage, &index_data)?;
            let info = [vk::DescriptorBufferInfo {
                buffer: points,
                offset: 0,
                range: vk::WHOLE_SIZE,
            }];
            let write = vk::WriteDescriptorSet::default()
                .dst_set(set)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .buffer_info(&info);
            device.update_descriptor_sets(&[write], &[]);
            Ok(Bezier {
                options,
                pipeline,
                layout,
                set,
                indices,
            })
        }
    }
}

impl Scene for Bezier {
    fn clear_color(&self) -> [f32; 4] {
        [0.02, 0.02, 0.04, 1.0]
    }

    unsafe fn draw(&self, device: &ash::Device, cb: vk::CommandBuffer, view: &View) {
        let o = &self.options;
        let params = bezier_view::params(o.view, o.level, view.time, view.extent);
        // SAFETY: `cb` is recording inside the render pass the pipeline was made for
        // (the caller promises); every object bound is live until the device is idle.
        unsafe {
            device.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, self.pipeline);
            device.cmd_bind_descriptor_sets(
                cb,
                vk::PipelineBindPoint::GRAPHICS,
                self.layout,
                0,
                &[self.set],
                &[],
            );
            device.cmd_bind_index_buffer(cb, self.indices, 0, vk::IndexType::UINT32);
            let bytes = bytemuck::bytes_of(&params);
            device.cmd_push_constants(cb, self.layout, PARAM_STAGES, 0, bytes);
            // One draw per patch, as `bezier` does (lavapipe drops primitives when one
            // draw tessellates all 32 patches at level 48 or more).
            for patch in 0..PATCHES.len() as u32 {
                device.cmd_draw_indexed(cb, 16, 1, patch * 16, 0, 0);
            }
        }
    }
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    let options = Options {
        level: args.level,
        wireframe: args.wireframe,
        view: args.view,
    };
    let mut req = bezier_view::requirements(&options);
    req.scene = "bezier_ash";
    tuff_examples::exit(|| {
        raw_ash::run(&args.common, req, |device, o, render_pass| {
            Bezier::new(device, o, render_pass, options)
        })
    })
}
