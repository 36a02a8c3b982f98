//! The projection every scene uses: reversed-Z with an infinite far plane, for depth
//! precision from the near plane to thousands of units away, and a field of view that
//! fits the scene in both directions for any aspect ratio.

use glam::{Mat4, Vec3, Vec4};

/// Near plane distance, in scene units.
pub const NEAR: f32 = 0.1;

/// A perspective projection into Vulkan's clip space (y down, depth 0..1) for an
/// image of `width` x `height` pixels (each clamped to at least 1). `fov` is the field
/// of view, in radians, of the image's *shorter* side, so very wide and very tall
/// images show the same scene height or width rather than a sliver.
///
/// Depth is reversed: the near plane maps to 1 and infinity to 0 (clear depth to 0,
/// test with GREATER). A 32-bit float depth then keeps about the same relative
/// precision at every distance, which is what keeps far surfaces apart.
///
/// ```
/// let p = tuff_examples::camera::projection(1.0, 4096, 1);
/// let near = p * glam::Vec4::new(0.0, 0.0, -tuff_examples::camera::NEAR, 1.0);
/// assert!((near.z / near.w - 1.0).abs() < 1e-6);
/// assert!(p.is_finite());
/// ```
pub fn projection(fov: f32, width: u32, height: u32) -> Mat4 {
    let (w, h) = (width.max(1) as f32, height.max(1) as f32);
    let focal = 1.0 / (fov * 0.5).tan();
    // Scale the shorter side to `focal` and the longer one by the aspect ratio.
    let (fx, fy) = if w >= h {
        (focal * h / w, focal)
    } else {
        (focal, focal * w / h)
    };
    Mat4::from_cols(
        Vec4::new(fx, 0.0, 0.0, 0.0),
        // Vulkan's clip space has y pointing down.
        Vec4::new(0.0, -fy, 0.0, 0.0),
        Vec4::new(0.0, 0.0, 0.0, -1.0),
        Vec4::new(0.0, 0.0, NEAR, 0.0),
    )
}

/// A right-handed view from `eye` towards `target` with z up (the teapot data's up).
pub fn look_at(eye: Vec3, target: Vec3) -> Mat4 {
    Mat4::look_at_rh(eye, target, Vec3::Z)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn depth(p: &Mat4, distance: f32) -> f32 {
        let c = *p * Vec4::new(0.0, 0.0, -distance, 1.0);
        c.z / c.w
    }

    #[test]
    fn extreme_aspect_ratios_and_tiny_images_stay_finite() {
        for (w, h) in [(1, 4096), (4096, 1), (1, 1), (0, 0), (0, 7), (1920, 1080)] {
            let p = projection(1.0, w, h);
            assert!(p.is_finite(), "{w}x{h}");
            // A point straight ahead projects to the centre, inside the image.
            let c = p * Vec4::new(0.0, 0.0, -5.0, 1.0);
            assert_eq!((c.x / c.w, c.y / c.w), (0.0, 0.0));
            // The shorter side keeps the field of view: a point at the edge of the
            // field along the shorter side lands on the image edge.
            let edge = (0.5f32).tan() * 5.0;
            let (x, y) = if w.max(1) >= h.max(1) {
                (0.0, edge)
            } else {
                (edge, 0.0)
            };
            let c = p * Vec4::new(x, y, -5.0, 1.0);
            let ndc = (c.x / c.w).abs().max((c.y / c.w).abs());
            assert!((ndc - 1.0).abs() < 1e-5, "{w}x{h}: {ndc}");
        }
    }

    #[test]
    fn depth_is_reversed_and_ordered_far_away() {
        let p = projection(1.0, 512, 512);
        assert!((depth(&p, NEAR) - 1.0).abs() < 1e-6);
        assert!(depth(&p, 1e9) < 1e-9);
        // Surfaces 10,000 units away and 0.1 % apart still get distinct f32 depths,
        // nearer greater.
        for d in [1.0f32, 100.0, 1_000.0, 10_000.0] {
            let (a, b) = (depth(&p, d), depth(&p, d * 1.001));
            assert!(a > b, "{d}: {a} <= {b}");
        }
    }
}
