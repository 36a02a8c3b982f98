//! The deferred scene as data, with no Vulkan calls: the objects and their meshes,
//! the point lights, the camera and lighting blocks, the render pass's attachments,
//! subpasses and dependencies, and how the objects are shared among worker threads.
//! The tuff scene (`scenes::deferred`) and its raw-ash twin (`deferred_ash`) both
//! draw exactly this.

use crate::camera;
use crate::scenes::teapot_grid::{CameraBlock, Instance, SplitMix, FOV};
use anyhow::{bail, Result};
use glam::{Mat4, Vec3, Vec4};
use std::ops::Range;
use tuff::vk;

/// The most objects a grid may hold.
pub const MAX_OBJECTS: u32 = 100_000;
/// The most point lights (`MAX_LIGHTS` in `deferred_light.frag`).
pub const MAX_LIGHTS: usize = 64;
/// The most worker threads recording a frame.
pub const MAX_WORKERS: u32 = 64;
/// Cells per patch side of the teapot's tessellation: coarser than the teapots
/// scene's, as there are many more of them.
const TEAPOT_SEGMENTS: u32 = 4;
/// Distance between neighbouring objects.
const SPACING: f32 = 6.0;

/// The G-buffer's color attachment: each object's color.
pub const ALBEDO_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;
/// The G-buffer's normal attachment: world-space normals, signed.
pub const NORMAL_FORMAT: vk::Format = vk::Format::R16G16B16A16_SFLOAT;
/// The render pass's attachments, in order.
pub const OUTPUT: u32 = 0;
/// See [`OUTPUT`].
pub const ALBEDO: u32 = 1;
/// See [`OUTPUT`].
pub const NORMAL: u32 = 2;
/// See [`OUTPUT`].
pub const DEPTH: u32 = 3;

/// The scene's own command-line options (beside `cli::Headless`), shared by the tuff
/// scene and its raw-ash twin.
#[derive(clap::Args, Debug, Clone)]
pub struct Options {
    /// How many objects, 1 to 100,000.
    #[arg(long, default_value_t = 2000)]
    pub count: u32,
    /// Seeds the objects' meshes, colors, phases and spins, and the lights.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker threads recording the objects, 1 to 64 (tuff's on threads of their own
    /// only in a build with the `multi_thread` feature).
    #[arg(long, default_value_t = 4)]
    pub threads: u32,
}

/// One point light (`Light` in `deferred_light.frag`): std140.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LightBlock {
    /// World position, and in w the distance at which its light reaches zero.
    pub position: [f32; 4],
    /// RGB intensity.
    pub color: [f32; 4],
}

/// The lighting subpass's uniform block (`Lights` in `deferred_light.frag`): std140.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LightsBlock {
    /// Inverse of the camera's projection times view: rebuilds world positions from
    /// depth.
    pub inverse_view_projection: [[f32; 4]; 4],
    /// Direction towards the sun, and in w its strength.
    pub sun: [f32; 4],
    /// Where nothing was drawn.
    pub background: [f32; 4],
    /// Framebuffer width and height in pixels, the light count, unused.
    pub extent: [f32; 4],
    /// The lights; the first `extent[2]` are lit.
    pub lights: [LightBlock; MAX_LIGHTS],
}

/// Where one of the scene's meshes lies in the shared vertex and index buffers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MeshRange {
    /// Its first index.
    pub first_index: u32,
    /// How many indices.
    pub index_count: u32,
    /// Added to each index.
    pub vertex_offset: i32,
}

/// The scene's meshes (the teapot, a cube, an octahedron) in one vertex buffer
/// (position and normal per vertex, as `teapot_grid::vertex_input` reads them) and
/// one index buffer.
pub struct Meshes {
    /// Position then normal, per vertex.
    pub vertices: Vec<f32>,
    /// Indices of every mesh, each mesh's from 0.
    pub indices: Vec<u32>,
    /// Each mesh's range.
    pub ranges: Vec<MeshRange>,
}

impl Meshes {
    /// The teapot, a cube and an octahedron.
    pub fn new() -> Meshes {
        let mut meshes = Meshes {
            vertices: Vec::new(),
            indices: Vec::new(),
            ranges: Vec::new(),
        };
        let (teapot, indices) = crate::teapot::mesh(TEAPOT_SEGMENTS);
        let teapot: Vec<_> = teapot.iter().map(|v| (v.position, v.normal)).collect();
        meshes.add(&teapot, &indices);
        // Flat-shaded solids: each face has vertices of its own with its normal.
        let (cube, cube_indices) = solid(&CUBE_FACES);
        meshes.add(&cube, &cube_indices);
        let (octahedron, octahedron_indices) = solid(&OCTAHEDRON_FACES);
        meshes.add(&octahedron, &octahedron_indices);
        meshes
    }

    fn add(&mut self, vertices: &[Vertex], indices: &[u32]) {
        self.ranges.push(MeshRange {
            first_index: self.indices.len() as u32,
            index_count: indices.len() as u32,
            vertex_offset: (self.vertices.len() / 6) as i32,
        });
        self.vertices
            .extend(vertices.iter().flat_map(|(p, n)| p.iter().chain(n)));
        self.indices.extend_from_slice(indices);
    }
}

impl Default for Meshes {
    fn default() -> Meshes {
        Meshes::new()
    }
}

/// A cube of side 2.4 standing on z = 0, as quads (corners counter-clockwise seen
/// from outside).
const CUBE_FACES: [[[f32; 3]; 4]; 6] = {
    const L: f32 = -1.2;
    const H: f32 = 1.2;
    const B: f32 = 0.0;
    const T: f32 = 2.4;
    [
        [[L, L, B], [L, H, B], [H, H, B], [H, L, B]],
        [[L, L, T], [H, L, T], [H, H, T], [L, H, T]],
        [[L, L, B], [H, L, B], [H, L, T], [L, L, T]],
        [[H, H, B], [L, H, B], [L, H, T], [H, H, T]],
        [[H, L, B], [H, H, B], [H, H, T], [H, L, T]],
        [[L, H, B], [L, L, B], [L, L, T], [L, H, T]],
    ]
};

/// An octahedron of radius 1.6 centred 1.6 above z = 0, as triangles (each face
/// given twice over as a degenerate quad: its last corner repeats its first).
const OCTAHEDRON_FACES: [[[f32; 3]; 4]; 8] = {
    const R: f32 = 1.6;
    const C: f32 = 1.6;
    const PX: [f32; 3] = [R, 0.0, C];
    const NX: [f32; 3] = [-R, 0.0, C];
    const PY: [f32; 3] = [0.0, R, C];
    const NY: [f32; 3] = [0.0, -R, C];
    const PZ: [f32; 3] = [0.0, 0.0, C + R];
    const NZ: [f32; 3] = [0.0, 0.0, C - R];
    [
        [PX, PY, PZ, PX],
        [PY, NX, PZ, PY],
        [NX, NY, PZ, NX],
        [NY, PX, PZ, NY],
        [PY, PX, NZ, PY],
        [NX, PY, NZ, NX],
        [NY, NX, NZ, NY],
        [PX, NY, NZ, PX],
    ]
};

/// A vertex: position and normal.
type Vertex = ([f32; 3], [f32; 3]);

/// Flat-shaded vertices and indices of `faces`, quads whose last corner may repeat
/// the first (a triangle).
fn solid<const N: usize>(faces: &[[[f32; 3]; 4]; N]) -> (Vec<Vertex>, Vec<u32>) {
    let mut vertices = Vec::new();
    let mut indices = Vec::new();
    for face in faces {
        let [a, b, c, d] = face.map(Vec3::from);
        let normal = (b - a).cross(c - a).normalize().to_array();
        let base = vertices.len() as u32;
        vertices.extend(face.iter().map(|&p| (p, normal)));
        indices.extend([base, base + 1, base + 2]);
        if d != a {
            indices.extend([base, base + 2, base + 3]);
        }
    }
    (vertices, indices)
}

/// One object of the grid: where and how it stands, and which mesh it is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Object {
    /// Position, scale, spin and color (as a teapot of the teapots scene).
    pub instance: Instance,
    /// Index into [`Meshes::ranges`].
    pub mesh: usize,
}

/// A point light circling above the grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointLight {
    /// The centre of its circle.
    pub centre: Vec3,
    /// The circle's radius.
    pub orbit: f32,
    /// Turns per second, and the angle at time 0.
    pub speed: f32,
    /// See `speed`.
    pub phase: f32,
    /// Where its light reaches zero.
    pub reach: f32,
    /// RGB intensity.
    pub color: [f32; 3],
}

/// What the scene shows: the camera, the objects, the lights.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// Camera position.
    pub eye: Vec3,
    /// Where it looks.
    pub target: Vec3,
    /// The objects, in drawing order.
    pub objects: Vec<Object>,
    /// The point lights.
    pub lights: Vec<PointLight>,
}

impl Layout {
    /// `count` objects (1 to [`MAX_OBJECTS`]) on a square grid, meshes, colors,
    /// phases, spins and the lights drawn from `seed`, and a camera that sees the
    /// whole grid.
    pub fn grid(count: u32, seed: u64) -> Result<Layout> {
        if !(1..=MAX_OBJECTS).contains(&count) {
            bail!("the object count must be 1 to {MAX_OBJECTS}, not {count}");
        }
        let side = (count as f32).sqrt().ceil() as u32;
        let half = (side - 1) as f32 * SPACING / 2.0;
        let mut rng = SplitMix(seed);
        let objects = (0..count)
            .map(|i| {
                let (col, row) = (i % side, i / side);
                let mesh = (rng.next() % 3) as usize;
                let instance = Instance {
                    position: Vec3::new(
                        col as f32 * SPACING - half,
                        row as f32 * SPACING - half,
                        0.0,
                    ),
                    scale: 0.8,
                    phase: rng.unit() * std::f32::consts::TAU,
                    spin: 0.1 + 0.3 * rng.unit(),
                    color: [
                        0.5 + 0.5 * rng.unit(),
                        0.5 + 0.5 * rng.unit(),
                        0.5 + 0.5 * rng.unit(),
                    ],
                };
                Object { instance, mesh }
            })
            .collect();
        // The lights spread over the grid, each reaching a few objects around it.
        let lights = (0..MAX_LIGHTS)
            .map(|_| {
                let hue = rng.unit();
                PointLight {
                    centre: Vec3::new(
                        (rng.unit() * 2.0 - 1.0) * (half + SPACING),
                        (rng.unit() * 2.0 - 1.0) * (half + SPACING),
                        3.0 + 2.0 * rng.unit(),
                    ),
                    orbit: SPACING * (0.3 + rng.unit()),
                    speed: 0.05 + 0.2 * rng.unit(),
                    phase: rng.unit() * std::f32::consts::TAU,
                    reach: SPACING * 4.0,
                    color: hue_color(hue).map(|c| 2.0 * c),
                }
            })
            .collect();
        // From above the near edge, looking across the grid: near objects large,
        // far ones small, as in a game.
        let view = half.max(2.0 * SPACING);
        let eye = Vec3::new(0.0, -1.1 * view, 0.75 * view + 4.0);
        let target = Vec3::new(0.0, 0.2 * view, 0.0);
        Ok(Layout {
            eye,
            target,
            objects,
            lights,
        })
    }

    fn view_projection(&self, extent: vk::Extent2D) -> Mat4 {
        camera::projection(FOV, extent.width, extent.height)
            * camera::look_at(self.eye, self.target)
    }

    /// The G-buffer subpass's camera block for an image of `extent`.
    pub fn camera(&self, extent: vk::Extent2D) -> CameraBlock {
        CameraBlock {
            view_projection: self.view_projection(extent).to_cols_array_2d(),
            eye: self.eye.extend(1.0).to_array(),
            light: Vec4::from((sun(), 0.0)).to_array(),
        }
    }

    /// The lighting subpass's block for an image of `extent` at scene time `time`.
    pub fn lights(&self, extent: vk::Extent2D, time: f32) -> LightsBlock {
        let mut lights = [LightBlock {
            position: [0.0; 4],
            color: [0.0; 4],
        }; MAX_LIGHTS];
        for (block, light) in lights.iter_mut().zip(&self.lights) {
            let angle = light.phase + light.speed * time * std::f32::consts::TAU;
            let at = light.centre + light.orbit * Vec3::new(angle.cos(), angle.sin(), 0.0);
            *block = LightBlock {
                position: at.extend(light.reach).to_array(),
                color: [light.color[0], light.color[1], light.color[2], 0.0],
            };
        }
        LightsBlock {
            inverse_view_projection: self.view_projection(extent).inverse().to_cols_array_2d(),
            sun: Vec4::from((sun(), 0.45)).to_array(),
            background: [0.02, 0.02, 0.04, 1.0],
            extent: [
                extent.width as f32,
                extent.height as f32,
                self.lights.len().min(MAX_LIGHTS) as f32,
                0.0,
            ],
            lights,
        }
    }
}

/// Direction towards the sun.
fn sun() -> Vec3 {
    Vec3::new(0.4, -0.5, 0.8).normalize()
}

/// A saturated color of hue `h` in [0, 1).
fn hue_color(h: f32) -> [f32; 3] {
    let channel = |offset: f32| {
        let x = (h + offset).fract() * 6.0;
        (2.0 - (x - 3.0).abs()).clamp(0.0, 1.0) * 0.8 + 0.2
    };
    [channel(0.0), channel(2.0 / 3.0), channel(1.0 / 3.0)]
}

/// The objects worker `worker` of `workers` records: contiguous and in order, so
/// every worker count draws the objects in the same order (and the same image).
pub fn share(objects: usize, workers: usize, worker: usize) -> Range<usize> {
    let workers = workers.max(1);
    objects * worker / workers..objects * (worker + 1) / workers
}

/// The render pass's attachments: the output color (cleared, stored, left ready to
/// be copied out), then the G-buffer (color, normal, depth), cleared and not stored:
/// they live for the render pass instance only.
pub fn attachments(output: vk::Format) -> [vk::AttachmentDescription; 4] {
    let attachment = |format, store_op, final_layout| vk::AttachmentDescription {
        format,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::CLEAR,
        store_op,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: vk::ImageLayout::UNDEFINED,
        final_layout,
        ..Default::default()
    };
    let read = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;
    let dont = vk::AttachmentStoreOp::DONT_CARE;
    [
        attachment(
            output,
            vk::AttachmentStoreOp::STORE,
            vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
        ),
        attachment(ALBEDO_FORMAT, dont, read),
        attachment(NORMAL_FORMAT, dont, read),
        attachment(
            crate::render::DEPTH_FORMAT,
            dont,
            vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
        ),
    ]
}

/// Subpass 0's color attachments: the G-buffer's color and normal.
pub const GBUFFER_COLORS: [vk::AttachmentReference; 2] = [
    vk::AttachmentReference {
        attachment: ALBEDO,
        layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
    },
    vk::AttachmentReference {
        attachment: NORMAL,
        layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
    },
];
/// Subpass 0's depth attachment.
pub const GBUFFER_DEPTH: vk::AttachmentReference = vk::AttachmentReference {
    attachment: DEPTH,
    layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
};
/// Subpass 1's color attachment: the output.
pub const LIGHTING_COLOR: [vk::AttachmentReference; 1] = [vk::AttachmentReference {
    attachment: OUTPUT,
    layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
}];
/// Subpass 1's input attachments, in the order of `deferred_light.frag`'s
/// `input_attachment_index`: color, normal, depth, each in a read-only layout.
pub const LIGHTING_INPUTS: [vk::AttachmentReference; 3] = [
    vk::AttachmentReference {
        attachment: ALBEDO,
        layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
    },
    vk::AttachmentReference {
        attachment: NORMAL,
        layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
    },
    vk::AttachmentReference {
        attachment: DEPTH,
        layout: vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
    },
];

/// The render pass's dependencies.
pub fn dependencies() -> [vk::SubpassDependency; 4] {
    use vk::AccessFlags as A;
    use vk::PipelineStageFlags as S;
    let tests = S::EARLY_FRAGMENT_TESTS | S::LATE_FRAGMENT_TESTS;
    [
        // The previous frame's lighting read the G-buffer (and its copy read the
        // output) before this frame clears and writes them again.
        vk::SubpassDependency {
            src_subpass: vk::SUBPASS_EXTERNAL,
            dst_subpass: 0,
            src_stage_mask: S::FRAGMENT_SHADER | S::COLOR_ATTACHMENT_OUTPUT | tests,
            dst_stage_mask: S::COLOR_ATTACHMENT_OUTPUT | tests,
            src_access_mask: A::COLOR_ATTACHMENT_WRITE | A::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dst_access_mask: A::COLOR_ATTACHMENT_WRITE
                | A::COLOR_ATTACHMENT_READ
                | A::DEPTH_STENCIL_ATTACHMENT_READ
                | A::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dependency_flags: vk::DependencyFlags::empty(),
        },
        // The output is first used in subpass 1: the copy of its previous frame
        // comes before its clear.
        vk::SubpassDependency {
            src_subpass: vk::SUBPASS_EXTERNAL,
            dst_subpass: 1,
            src_stage_mask: S::COLOR_ATTACHMENT_OUTPUT | S::TRANSFER,
            dst_stage_mask: S::COLOR_ATTACHMENT_OUTPUT,
            src_access_mask: A::COLOR_ATTACHMENT_WRITE,
            dst_access_mask: A::COLOR_ATTACHMENT_WRITE | A::COLOR_ATTACHMENT_READ,
            dependency_flags: vk::DependencyFlags::empty(),
        },
        // The G-buffer written in subpass 0 is read, at the same pixel, in subpass 1.
        vk::SubpassDependency {
            src_subpass: 0,
            dst_subpass: 1,
            src_stage_mask: S::COLOR_ATTACHMENT_OUTPUT | tests,
            dst_stage_mask: S::FRAGMENT_SHADER,
            src_access_mask: A::COLOR_ATTACHMENT_WRITE | A::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dst_access_mask: A::INPUT_ATTACHMENT_READ,
            dependency_flags: vk::DependencyFlags::BY_REGION,
        },
        // The output's writes come before the copy.
        vk::SubpassDependency {
            src_subpass: 1,
            dst_subpass: vk::SUBPASS_EXTERNAL,
            src_stage_mask: S::COLOR_ATTACHMENT_OUTPUT,
            dst_stage_mask: S::TRANSFER,
            src_access_mask: A::COLOR_ATTACHMENT_WRITE,
            dst_access_mask: A::TRANSFER_READ,
            dependency_flags: vk::DependencyFlags::empty(),
        },
    ]
}

/// The clear values of the four attachments; the output's is never seen (the
/// lighting subpass writes every pixel).
pub fn clear_values() -> [vk::ClearValue; 4] {
    let color = |float32| vk::ClearValue {
        color: vk::ClearColorValue { float32 },
    };
    [
        color([0.0; 4]),
        color([0.0; 4]),
        color([0.0; 4]),
        vk::ClearValue {
            depth_stencil: vk::ClearDepthStencilValue {
                depth: crate::render::DEPTH_CLEAR,
                stencil: 0,
            },
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_worker_count_shares_all_objects_in_order() {
        for objects in [0, 1, 7, 1000] {
            for workers in 1..=16 {
                let all: Vec<usize> = (0..workers)
                    .flat_map(|w| share(objects, workers, w))
                    .collect();
                assert_eq!(all, (0..objects).collect::<Vec<_>>());
            }
        }
    }

    #[test]
    fn lights_block_matches_the_shader_layout() {
        // mat4 + 3 vec4 + 64 lights of 2 vec4, std140.
        assert_eq!(size_of::<LightsBlock>(), 64 + 48 + MAX_LIGHTS * 32);
    }

    #[test]
    fn grids_hold_one_to_the_most_objects_each_of_a_mesh() {
        assert!(Layout::grid(0, 1).is_err());
        assert!(Layout::grid(MAX_OBJECTS + 1, 1).is_err());
        let layout = Layout::grid(10, 3).expect("grid");
        let meshes = Meshes::new();
        assert!(layout.objects.iter().all(|o| o.mesh < meshes.ranges.len()));
    }
}
