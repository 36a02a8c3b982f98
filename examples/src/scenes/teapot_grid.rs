//! The teapots scene as data, with no Vulkan calls: where the teapots stand, how they
//! spin, the camera, the uniform and push-constant blocks, and the mesh. The tuff
//! scene (`scenes::teapots`) and the raw-ash baseline (`bin/teapots_ash.rs`) both
//! draw exactly this.

use crate::camera;
use anyhow::{bail, Result};
use glam::{Mat4, Quat, Vec3, Vec4};
use tuff::vk;

/// The most teapots a grid may hold.
pub const MAX_TEAPOTS: u32 = 10_000;
/// Cells per patch side of the CPU tessellation the teapots are drawn from.
pub const SEGMENTS: u32 = 6;
/// Distance between neighbouring teapots.
const SPACING: f32 = 8.0;
/// Field of view of the shorter image side, radians.
pub const FOV: f32 = 0.9;

/// The camera uniform block (`Camera` in `teapot.vert`): std140.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct CameraBlock {
    /// Projection times view.
    pub view_projection: [[f32; 4]; 4],
    /// Camera position, world space.
    pub eye: [f32; 4],
    /// Direction towards the light, world space, unit length.
    pub light: [f32; 4],
}

/// The push-constant block (`Teapot` in `teapot.vert`).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TeapotBlock {
    /// Rotation, uniform scale and translation.
    pub model: [[f32; 4]; 4],
    /// RGB color, alpha unused.
    pub color: [f32; 4],
}

/// One teapot of the scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Instance {
    /// Where it stands.
    pub position: Vec3,
    /// Uniform scale.
    pub scale: f32,
    /// Rotation about z at time 0, radians.
    pub phase: f32,
    /// Turns per second about z.
    pub spin: f32,
    /// RGB.
    pub color: [f32; 3],
}

impl Instance {
    /// The push constants at scene time `time`.
    pub fn block(&self, time: f32) -> TeapotBlock {
        let angle = self.phase + self.spin * time * std::f32::consts::TAU;
        let model = Mat4::from_scale_rotation_translation(
            Vec3::splat(self.scale),
            Quat::from_rotation_z(angle),
            self.position,
        );
        TeapotBlock {
            model: model.to_cols_array_2d(),
            color: [self.color[0], self.color[1], self.color[2], 1.0],
        }
    }
}

/// A small deterministic generator (SplitMix64), so a seed fixes the scene.
pub(crate) struct SplitMix(pub(crate) u64);

impl SplitMix {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub(crate) fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// What the scene shows: where the camera is and the teapots.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// Camera position.
    pub eye: Vec3,
    /// Where it looks.
    pub target: Vec3,
    /// The teapots, in drawing order.
    pub teapots: Vec<Instance>,
}

impl Layout {
    /// `count` teapots (1 to [`MAX_TEAPOTS`]) on a square grid, with colors, phases
    /// and spin speeds drawn from `seed`, and a camera that sees the whole grid.
    pub fn grid(count: u32, seed: u64) -> Result<Layout> {
        if !(1..=MAX_TEAPOTS).contains(&count) {
            bail!("the teapot count must be 1 to {MAX_TEAPOTS}, not {count}");
        }
        let side = (count as f32).sqrt().ceil() as u32;
        let half = (side - 1) as f32 * SPACING / 2.0;
        let mut rng = SplitMix(seed);
        let teapots = (0..count)
            .map(|i| {
                let (col, row) = (i % side, i / side);
                Instance {
                    position: Vec3::new(
                        col as f32 * SPACING - half,
                        row as f32 * SPACING - half,
                        0.0,
                    ),
                    scale: 1.0,
                    phase: rng.unit() * std::f32::consts::TAU,
                    spin: 0.1 + 0.3 * rng.unit(),
                    color: [
                        0.3 + 0.7 * rng.unit(),
                        0.3 + 0.7 * rng.unit(),
                        0.3 + 0.7 * rng.unit(),
                    ],
                }
            })
            .collect();
        // Far enough back to fit the grid's diagonal, looking down at 35 degrees.
        let reach = half * std::f32::consts::SQRT_2 + 4.0;
        let distance = reach / (FOV * 0.5).tan() + 6.0;
        let down = 35f32.to_radians();
        let target = Vec3::new(0.0, 0.0, 1.2);
        let eye = target + distance * Vec3::new(0.0, -down.cos(), down.sin());
        Ok(Layout {
            eye,
            target,
            teapots,
        })
    }

    /// Two identical teapots 10,000 units away, the second scaled by 1.0005 about
    /// the eye: it covers exactly the same pixels, 5 units (0.05 %) behind the first.
    /// The first is green and drawn first, the second red, so any red pixel is depth
    /// precision failing.
    pub fn depth_probe() -> Layout {
        let eye = Vec3::ZERO;
        let target = Vec3::new(0.0, 10_000.0, 0.0);
        let front = Instance {
            position: target - Vec3::new(0.0, 0.0, 2_000.0),
            scale: 1_500.0,
            phase: 0.6,
            spin: 0.0,
            color: [0.1, 0.9, 0.1],
        };
        let s = 1.0005;
        let behind = Instance {
            position: front.position * s,
            scale: front.scale * s,
            color: [1.0, 0.0, 0.0],
            ..front
        };
        Layout {
            eye,
            target,
            teapots: vec![front, behind],
        }
    }

    /// The camera block for an image of `extent`.
    pub fn camera(&self, extent: vk::Extent2D) -> CameraBlock {
        let view_projection = camera::projection(FOV, extent.width, extent.height)
            * camera::look_at(self.eye, self.target);
        let light = Vec3::new(0.4, -0.5, 0.8).normalize();
        CameraBlock {
            view_projection: view_projection.to_cols_array_2d(),
            eye: self.eye.extend(1.0).to_array(),
            light: Vec4::from((light, 0.0)).to_array(),
        }
    }
}

/// The mesh's vertex layout: position then normal, 24 bytes.
pub fn vertex_input() -> (
    [vk::VertexInputBindingDescription; 1],
    [vk::VertexInputAttributeDescription; 2],
) {
    let attribute = |location, offset| vk::VertexInputAttributeDescription {
        location,
        binding: 0,
        format: vk::Format::R32G32B32_SFLOAT,
        offset,
    };
    (
        [vk::VertexInputBindingDescription {
            binding: 0,
            stride: 24,
            input_rate: vk::VertexInputRate::VERTEX,
        }],
        [attribute(0, 0), attribute(1, 12)],
    )
}

/// The mesh as flat floats (position, normal per vertex) and indices.
pub fn mesh_data() -> (Vec<f32>, Vec<u32>) {
    let (vertices, indices) = crate::teapot::mesh(SEGMENTS);
    let flat = vertices
        .iter()
        .flat_map(|v| v.position.into_iter().chain(v.normal))
        .collect();
    (flat, indices)
}
