//! The Utah teapot as its 32 bicubic Bezier patches, tessellated on the GPU: control
//! points in a storage buffer, patches listed by an index buffer, levels from the
//! command line, and normals computed in the evaluation shader.

use crate::camera;
use crate::gpu::{Gpu, Requirements};
use crate::pipeline::{self, PipelineDesc};
use crate::render::{Scene, View};
use crate::teapot::{CONTROL_POINTS, PATCHES};
use anyhow::{bail, Result};
use glam::{Mat4, Vec3};
use tuff::vk;

/// The highest tessellation level the scene accepts (every implementation supports
/// 64: `maxTessellationGenerationLevel`'s required minimum).
pub const MAX_LEVEL: u32 = 64;
/// Field of view of the shorter image side, radians.
pub const FOV: f32 = 0.8;

/// How the scene is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Tessellation level, 1 to [`MAX_LEVEL`], for every edge and the inside.
    pub level: u32,
    /// Lines instead of filled triangles (asks for `fillModeNonSolid`).
    pub wireframe: bool,
    /// Where the camera is.
    pub view: Viewpoint,
}

/// Where the camera looks from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Viewpoint {
    /// From the front, a little above, while the teapot turns.
    Orbit,
    /// Straight down onto the lid's apex, where a row of control points collapses.
    Top,
    /// Straight up at the bottom's centre, where another row collapses.
    Bottom,
}

/// What the scene asks of the device: tessellation shaders, and non-solid fill for
/// wireframe.
pub fn requirements(options: &Options) -> Requirements {
    Requirements {
        scene: "bezier",
        tessellation_shader: true,
        fill_mode_non_solid: options.wireframe,
        window: false,
    }
}

/// The push-constant block (`Params` in the tessellation and fragment shaders).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Params {
    /// Projection, view and model.
    pub model_view_projection: [[f32; 4]; 4],
    /// Camera position, model space.
    pub eye: [f32; 4],
    /// Direction towards the light, model space.
    pub light: [f32; 4],
    /// x: the tessellation level.
    pub level: [f32; 4],
}

/// The camera and model transform of `viewpoint` at scene time `time`, for an image
/// of `extent`: (projection * view * model, eye and light in model space).
pub fn params(viewpoint: Viewpoint, level: u32, time: f32, extent: vk::Extent2D) -> Params {
    let target = Vec3::new(0.0, 0.0, 1.5);
    let (eye, up, angle) = match viewpoint {
        Viewpoint::Orbit => (Vec3::new(0.0, -8.0, 5.0), Vec3::Z, 0.6 + 0.5 * time),
        Viewpoint::Top => (Vec3::new(0.0, 0.0, 9.0), Vec3::Y, 0.0),
        Viewpoint::Bottom => (Vec3::new(0.0, 0.0, -6.0), Vec3::Y, 0.0),
    };
    let model = Mat4::from_rotation_z(angle);
    let view = Mat4::look_at_rh(eye, target, up);
    let mvp = camera::projection(FOV, extent.width, extent.height) * view * model;
    let to_model = model.inverse();
    let light = to_model.transform_vector3(Vec3::new(0.3, -0.6, 0.75).normalize());
    let eye_model = to_model.transform_point3(eye);
    Params {
        model_view_projection: mvp.to_cols_array_2d(),
        eye: eye_model.extend(1.0).to_array(),
        light: light.extend(0.0).to_array(),
        level: [level as f32, 0.0, 0.0, 0.0],
    }
}

/// The tessellated teapot's pipeline and buffers. The set keeps the control points
/// written into it and its pool; the pipeline layout keeps the set layout.
pub struct Bezier {
    options: Options,
    pipeline: tuff::Pipeline,
    layout: tuff::PipelineLayout,
    set: tuff::DescriptorSet,
    indices: tuff::Bound<tuff::Buffer>,
}

/// The stages that read the push constants.
const PARAM_STAGES: vk::ShaderStageFlags = vk::ShaderStageFlags::from_raw(
    vk::ShaderStageFlags::TESSELLATION_CONTROL.as_raw()
        | vk::ShaderStageFlags::TESSELLATION_EVALUATION.as_raw()
        | vk::ShaderStageFlags::FRAGMENT.as_raw(),
);

impl Bezier {
    /// Builds the scene for `render_pass`.
    pub fn new(gpu: &Gpu, render_pass: &tuff::RenderPass, options: Options) -> Result<Bezier> {
        if !(1..=MAX_LEVEL).contains(&options.level) {
            bail!(
                "the tessellation level must be 1 to {MAX_LEVEL}, not {}",
                options.level
            );
        }
        let d = &gpu.device;
        let vert = gpu
            .device
            .create_shader_module_from_spirv(crate::spirv!("bezier.vert"))?;
        let tesc = gpu
            .device
            .create_shader_module_from_spirv(crate::spirv!("bezier.tesc"))?;
        let tese = gpu
            .device
            .create_shader_module_from_spirv(crate::spirv!("bezier.tese"))?;
        let frag = gpu
            .device
            .create_shader_module_from_spirv(crate::spirv!("bezier.frag"))?;
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
        let layouts = tuff::HandleSlice::new(&[&set_layout]);
        let set = d
            .allocate_descriptor_sets(
                &pool,
                &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layouts),
            )?
            .pop()
            .ok_or_else(|| anyhow::anyhow!("no descriptor set was allocated"))?;
        // vec4 per point: std430 pads a vec3 array to 16 bytes anyway.
        let points: Vec<[f32; 4]> = CONTROL_POINTS
            .iter()
            .map(|p| [p[0], p[1], p[2], 1.0])
            .collect();
        let points = gpu.device.create_buffer_with(
            vk::BufferUsageFlags::STORAGE_BUFFER,
            &points,
            &gpu.allocator,
        )?;
        let index_data: Vec<u32> = PATCHES.iter().flatten().map(|&i| u32::from(i)).collect();
        let indices = gpu.device.create_buffer_with(
            vk::BufferUsageFlags::INDEX_BUFFER,
            &index_data,
            &gpu.allocator,
        )?;
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

    fn draw(&self, rec: &mut tuff::Recorder<'_, tuff::InRenderPass>, view: &View) {
        let params = params(
            self.options.view,
            self.options.level,
            view.time,
            view.extent,
        );
        rec.cmd_bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.pipeline);
        rec.cmd_bind_descriptor_sets(
            vk::PipelineBindPoint::GRAPHICS,
            &self.layout,
            0,
            &[&self.set],
            &[],
        );
        rec.cmd_bind_index_buffer(&self.indices, 0, vk::IndexType::UINT32);
        rec.cmd_push_constants(&self.layout, PARAM_STAGES, 0, bytemuck::bytes_of(&params));
        // One draw per patch: lavapipe (Mesa 22.3) drops primitives when a single
        // draw tessellates all 32 patches at level 48 or more (the lid, spout and
        // handle went missing; the speckle test caught it).
        for patch in 0..PATCHES.len() as u32 {
            rec.cmd_draw_indexed(16, 1, patch * 16, 0, 0);
        }
    }
}
