//! The triangle as data, with no Vulkan calls: its three corners. The tuff scene
//! (`scenes::triangle`) and the raw-ash port (`bin/triangle_ash.rs`) both draw exactly
//! this.

/// A vertex: position in clip space and color.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    /// Clip-space x and y.
    pub position: [f32; 2],
    /// Linear RGB.
    pub color: [f32; 3],
}

/// The triangle's corners.
pub const VERTICES: [Vertex; 3] = [
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
