//! The tessellated teapot as data, with no Vulkan calls: its options, viewpoints,
//! push-constant block and camera. The tuff scene (`scenes::bezier`), the raw-ash
//! port (`bin/bezier_ash.rs`) and the accuracy measurement all use exactly this.

use crate::camera;
use crate::gpu::Requirements;
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
        robust_buffer_access: false,
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

/// The stages that read the push constants.
pub const PARAM_STAGES: vk::ShaderStageFlags = vk::ShaderStageFlags::from_raw(
    vk::ShaderStageFlags::TESSELLATION_CONTROL.as_raw()
        | vk::ShaderStageFlags::TESSELLATION_EVALUATION.as_raw()
        | vk::ShaderStageFlags::FRAGMENT.as_raw(),
);
