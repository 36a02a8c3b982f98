//! The Utah teapot as bicubic Bezier patches, evaluated on the CPU exactly the way the
//! tessellation evaluation shader evaluates it, so that the two can be checked against
//! each other and the CPU side can stand in for the GPU (a reference mesh, error bounds).
//!
//! The parameterisation is fixed because the shader mirrors it:
//!
//! ```text
//! P(u, v) = sum_r sum_c B_c(u) * B_r(v) * cp[r * 4 + c]
//! B_0(t) = (1 - t)^3, B_1(t) = 3t(1 - t)^2, B_2(t) = 3t^2(1 - t), B_3(t) = t^3
//! ```
//!
//! `u` runs along a patch's columns and `v` along its rows; `(u, v)` is `gl_TessCoord.xy`
//! of a `quads, equal_spacing` domain.

pub use crate::teapot_data::{CONTROL_POINTS, PATCHES};

/// One patch's 16 control points in `f64`, row by row: entry `r * 4 + c` is row `r`,
/// column `c`.
pub type Patch = [[f64; 3]; 16];

/// The teapot's height: it stands on `z = 0` and the lid's knob peaks at `z = 3.15`.
pub const TEAPOT_HEIGHT: f64 = 3.15;

/// [`normal`] treats `dot(n, n) < DEGENERATE_EPSILON` (units^4) for `n = cross(du, dv)` as a
/// vanished tangent and re-evaluates at a nudged parameter.
///
/// The value sits between what the two cases produce over every tessellator grid point
/// up to level 64: where a row collapses to one point (`v = 0` on the lid top and the
/// bottom) `dot(n, n)` is at most about 1e-11 in `f32` (rounding only; 2e-29 in `f64`),
/// while everywhere else it is at least 1.5e-3 (the spout's tip). Both are three or
/// more orders of magnitude away, so GPU rounding differences cannot flip the decision.
pub const DEGENERATE_EPSILON: f64 = 1e-6;

/// How far [`normal`] moves `u` and `v` toward the patch interior when the cross product
/// vanishes.
///
/// At a distance of 1e-3 from a collapsed row, `dot(n, n)` is at least 7.7e-5, far above
/// both [`DEGENERATE_EPSILON`] and `f32` rounding noise, so the nudged normal is well
/// conditioned in `f32`; the surface point moves by about a thousandth of a unit, so its
/// normal differs from the limit normal at the collapsed row by about a milliradian.
pub const NUDGE: f64 = 1e-3;

/// The `f64` copy of patch `index`'s control points.
///
/// # Panics
///
/// If `index >= 32` (`PATCHES.len()`): asking for a patch that does not exist is a
/// programming error.
pub fn patch(index: usize) -> Patch {
    patch_f32(index).map(|c| c.map(f64::from))
}

/// Patch `index`'s control points as stored (`f32`), the form the GPU receives them in.
///
/// # Panics
///
/// If `index >= 32` (`PATCHES.len()`).
pub fn patch_f32(index: usize) -> [[f32; 3]; 16] {
    PATCHES[index].map(|i| CONTROL_POINTS[usize::from(i)])
}

/// The surface point `P(u, v)`.
///
/// Sums each column over the rows first and then across the columns; [`crate::accuracy`]
/// evaluates in that same order so its grid vertices equal this function's results bit
/// for bit.
pub fn point(p: &Patch, u: f64, v: f64) -> [f64; 3] {
    eval64::combine(p, eval64::bernstein(u), eval64::bernstein(v))
}

/// The tangents `(dP/du, dP/dv)` at `(u, v)`.
///
/// One of them is zero along a row or column whose four control points coincide (row 0
/// of the lid top and of the bottom patches).
pub fn derivatives(p: &Patch, u: f64, v: f64) -> ([f64; 3], [f64; 3]) {
    eval64::derivatives(p, u, v)
}

/// The unit normal at `(u, v)`, pointing out of the teapot; robust where a tangent
/// vanishes.
///
/// The shader must compute the same thing, step by step (all in `f32` there):
///
/// 1. `du = sum_r sum_c B'_c(u) B_r(v) cp[r*4+c]`, `dv = sum_r sum_c B_c(u) B'_r(v) cp[r*4+c]`
///    with `B'_0(t) = -3(1-t)^2`, `B'_1(t) = 3(1-t)^2 - 6t(1-t)`,
///    `B'_2(t) = 6t(1-t) - 3t^2`, `B'_3(t) = 3t^2`.
/// 2. `n = cross(du, dv)`. For this data set that points out of the teapot on all 32
///    patches, so no per-patch sign is needed. (On the rim and the spout's tip, thin
///    sheets that curl over, "out" continues the outer side over the curl, as a
///    consistently oriented surface must.)
/// 3. If `dot(n, n) < DEGENERATE_EPSILON` (`1e-6`): `u' = u < 0.5 ? u + NUDGE : u - NUDGE`,
///    `v' = v < 0.5 ? v + NUDGE : v - NUDGE` with `NUDGE = 1e-3`, recompute `du`, `dv` at
///    `(u', v')` and set `n = cross(du, dv)`. Only the collapsed rows (`v = 0` of patches
///    20..24 and 28..32) take this branch.
/// 4. Return `n / sqrt(dot(n, n))` (GLSL: `normalize(n)`).
///
/// In GLSL:
///
/// ```glsl
/// vec3 n = cross(du, dv);
/// if (dot(n, n) < 1e-6) {
///     vec2 uv2 = vec2(u < 0.5 ? u + 1e-3 : u - 1e-3, v < 0.5 ? v + 1e-3 : v - 1e-3);
///     // recompute du, dv at uv2
///     n = cross(du, dv);
/// }
/// n = normalize(n);
/// ```
///
/// Returns `[0.0, 0.0, 0.0]` only if the nudged cross product is zero too, which needs
/// a patch collapsed to a curve or a point; no teapot patch is.
pub fn normal(p: &Patch, u: f64, v: f64) -> [f64; 3] {
    eval64::normal(p, u, v)
}

/// [`normal`] computed entirely in `f32`, as the shader computes it; same algorithm,
/// same constants.
pub fn normal_f32(p: &[[f32; 3]; 16], u: f32, v: f32) -> [f32; 3] {
    eval32::normal(p, u, v)
}

/// One vertex of [`mesh`]: laid out for a vertex buffer (`R32G32B32_SFLOAT` position at
/// offset 0, normal at offset 12, stride 24).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MeshVertex {
    /// The surface point.
    pub position: [f32; 3],
    /// The outward unit normal, from [`normal`].
    pub normal: [f32; 3],
}

/// The most cells per patch side that [`mesh`] makes; larger requests are clamped.
///
/// 1024 already means 33.6 million vertices (800 MB); the cap keeps every vertex index
/// well inside `u32`.
pub const MAX_MESH_SEGMENTS: u32 = 1024;

/// The whole teapot tessellated on the CPU into an indexed triangle list, `segments` x
/// `segments` cells per patch (clamped to `1..=MAX_MESH_SEGMENTS`).
///
/// Every patch gets its own `(segments + 1)^2` vertices at `u, v` in `{i / segments}`,
/// row after row (`v` outer, `u` inner); patches share no vertices. Each cell
/// `(i, j)`..`(i + 1, j + 1)` becomes the triangles `(i, j), (i+1, j), (i+1, j+1)` and
/// `(i, j), (i+1, j+1), (i, j+1)`: since `cross(du, dv)` points outward, both are
/// counter-clockwise seen from outside the teapot (the right-hand rule on a triangle's
/// vertices gives the outward normal), as are the GPU's own triangles for the same
/// patches.
///
/// Triangles with two vertices at the same position are left out; they come from the
/// cells touching a collapsed row (`v = 0` of the 4 lid-top and 4 bottom patches), one
/// per such cell, so there are `64 * segments^2 - 8 * segments` triangles. The collapsed
/// row's extra vertices stay in the vertex list, unreferenced or referenced only by the
/// triangle that keeps one of them.
pub fn mesh(segments: u32) -> (Vec<MeshVertex>, Vec<u32>) {
    let n = segments.clamp(1, MAX_MESH_SEGMENTS);
    let side = n + 1;
    let patches = PATCHES.len();
    let per_patch = (side * side) as usize;
    let mut vertices = Vec::with_capacity(patches * per_patch);
    let mut positions = Vec::with_capacity(per_patch);
    let mut indices = Vec::with_capacity(patches * 6 * (n * n) as usize);
    for index in 0..patches {
        let p = patch(index);
        // At most 32 * 1025^2 vertices: fits in u32 by the segment cap.
        let base = vertices.len() as u32;
        positions.clear();
        for j in 0..side {
            let v = f64::from(j) / f64::from(n);
            for i in 0..side {
                let u = f64::from(i) / f64::from(n);
                let position = point(&p, u, v);
                positions.push(position);
                vertices.push(MeshVertex {
                    position: to_f32(position),
                    normal: to_f32(normal(&p, u, v)),
                });
            }
        }
        for j in 0..n {
            for i in 0..n {
                let corner = |di: u32, dj: u32| (j + dj) * side + i + di;
                let cell = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
                for triangle in [[cell[0], cell[1], cell[2]], [cell[0], cell[2], cell[3]]] {
                    let at = |k: usize| positions[triangle[k] as usize];
                    if same_position(at(0), at(1))
                        || same_position(at(1), at(2))
                        || same_position(at(2), at(0))
                    {
                        continue;
                    }
                    indices.extend(triangle.map(|k| base + k));
                }
            }
        }
    }
    (vertices, indices)
}

/// A collapsed row's points differ only by rounding (the Bernstein weights sum to 1 only
/// up to an ulp or so), a billionth of a unit at most; distinct grid points of any usable
/// tessellation are far further apart.
fn same_position(a: [f64; 3], b: [f64; 3]) -> bool {
    const TOLERANCE: f64 = 1e-9;
    let d = eval64::sub(a, b);
    eval64::dot(d, d) <= TOLERANCE * TOLERANCE
}

fn to_f32(a: [f64; 3]) -> [f32; 3] {
    a.map(|x| x as f32)
}

/// The evaluation, written once and instantiated for `f64` (the reference) and `f32` (the
/// shader's precision).
///
/// A macro rather than generics over a number trait: unoptimised builds turn generic
/// arithmetic into trait-method calls, which made the exhaustive normal tests several
/// times slower.
macro_rules! evaluation {
    ($real:ty, $epsilon:expr, $nudge:expr) => {
        /// The cubic Bernstein weights `B_0..B_3` at `t`.
        pub(crate) fn bernstein(t: $real) -> [$real; 4] {
            let s = 1.0 - t;
            [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
        }

        /// The derivatives of the cubic Bernstein weights at `t`.
        pub(crate) fn bernstein_derivative(t: $real) -> [$real; 4] {
            let s = 1.0 - t;
            [
                -3.0 * s * s,
                3.0 * s * s - 6.0 * t * s,
                6.0 * t * s - 3.0 * t * t,
                3.0 * t * t,
            ]
        }

        /// `sum_k w[k] * q[k]`, always in this order: every evaluation goes through
        /// here, which is what makes equal inputs give bit-equal points.
        pub(crate) fn blend(w: [$real; 4], q: [[$real; 3]; 4]) -> [$real; 3] {
            [
                w[0] * q[0][0] + w[1] * q[1][0] + w[2] * q[2][0] + w[3] * q[3][0],
                w[0] * q[0][1] + w[1] * q[1][1] + w[2] * q[2][1] + w[3] * q[3][1],
                w[0] * q[0][2] + w[1] * q[1][2] + w[2] * q[2][2] + w[3] * q[3][2],
            ]
        }

        /// The four columns evaluated at the row weights `bv`: the control points of
        /// the cubic in `u` that is the patch's `v = const` curve.
        pub(crate) fn columns(p: &[[$real; 3]; 16], bv: [$real; 4]) -> [[$real; 3]; 4] {
            [
                blend(bv, [p[0], p[4], p[8], p[12]]),
                blend(bv, [p[1], p[5], p[9], p[13]]),
                blend(bv, [p[2], p[6], p[10], p[14]]),
                blend(bv, [p[3], p[7], p[11], p[15]]),
            ]
        }

        /// `sum_c bu[c] * (sum_r bv[r] * p[r * 4 + c])`.
        pub(crate) fn combine(p: &[[$real; 3]; 16], bu: [$real; 4], bv: [$real; 4]) -> [$real; 3] {
            blend(bu, columns(p, bv))
        }

        pub(crate) fn derivatives(
            p: &[[$real; 3]; 16],
            u: $real,
            v: $real,
        ) -> ([$real; 3], [$real; 3]) {
            let du = combine(p, bernstein_derivative(u), bernstein(v));
            let dv = combine(p, bernstein(u), bernstein_derivative(v));
            (du, dv)
        }

        pub(crate) fn normal(p: &[[$real; 3]; 16], u: $real, v: $real) -> [$real; 3] {
            let (du, dv) = derivatives(p, u, v);
            let mut n = cross(du, dv);
            if dot(n, n) < $epsilon {
                let toward_interior = |t: $real| if t < 0.5 { t + $nudge } else { t - $nudge };
                let (du, dv) = derivatives(p, toward_interior(u), toward_interior(v));
                n = cross(du, dv);
            }
            let length_squared = dot(n, n);
            // Written as `> 0` so that a NaN from non-finite input also takes the zero
            // branch.
            if length_squared > 0.0 {
                let inverse = 1.0 / length_squared.sqrt();
                [n[0] * inverse, n[1] * inverse, n[2] * inverse]
            } else {
                [0.0; 3]
            }
        }

        pub(crate) fn cross(a: [$real; 3], b: [$real; 3]) -> [$real; 3] {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        }

        pub(crate) fn dot(a: [$real; 3], b: [$real; 3]) -> $real {
            a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
        }

        pub(crate) fn sub(a: [$real; 3], b: [$real; 3]) -> [$real; 3] {
            [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
        }
    };
}

/// The `f64` reference evaluation.
pub(crate) mod eval64 {
    use super::{DEGENERATE_EPSILON, NUDGE};
    evaluation!(f64, DEGENERATE_EPSILON, NUDGE);
}

/// The `f32` evaluation, as the shader does it.
// The f32 path needs only the normal and what it calls; the rest comes with the macro.
#[allow(dead_code)]
mod eval32 {
    use super::{DEGENERATE_EPSILON, NUDGE};
    evaluation!(f32, DEGENERATE_EPSILON as f32, NUDGE as f32);
}

#[cfg(test)]
mod tests {
    use super::eval64::{cross, dot, sub};
    use super::*;

    /// The patches whose row 0 collapses to one point.
    const LID_TOP: core::ops::Range<usize> = 20..24;
    const BOTTOM: core::ops::Range<usize> = 28..32;

    fn length(a: [f64; 3]) -> f64 {
        dot(a, a).sqrt()
    }

    fn is_unit(n: [f64; 3], tolerance: f64) -> bool {
        n.iter().all(|x| x.is_finite()) && (length(n) - 1.0).abs() < tolerance
    }

    #[test]
    fn normals_are_finite_and_unit_on_every_tessellator_grid() {
        for index in 0..PATCHES.len() {
            let p = patch(index);
            let p32 = patch_f32(index);
            for level in 1..=64u32 {
                for j in 0..=level {
                    for i in 0..=level {
                        let (u, v) = (
                            f64::from(i) / f64::from(level),
                            f64::from(j) / f64::from(level),
                        );
                        let n = normal(&p, u, v);
                        let (u32_, v32) = (i as f32 / level as f32, j as f32 / level as f32);
                        let n32 = normal_f32(&p32, u32_, v32).map(f64::from);
                        let at = (index, level, i, j);
                        assert!(is_unit(n, 1e-12), "patch, level, i, j {at:?}: {n:?}");
                        assert!(is_unit(n32, 1e-5), "f32 patch, level, i, j {at:?}: {n32:?}");
                        // The f32 path is the shader's: it must agree with the reference.
                        // They differ by 0.3 mrad at most (at the nudged collapsed rows),
                        // 0.02 mrad elsewhere; this allows 1.4 mrad.
                        assert!(dot(n, n32) > 1.0 - 1e-6, "{at:?}: f64 {n:?} vs f32 {n32:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn only_the_collapsed_rows_are_degenerate() {
        for index in 0..PATCHES.len() {
            let p = patch(index);
            let p32 = patch_f32(index);
            for j in 0..=64u32 {
                for i in 0..=64u32 {
                    let (u, v) = (f64::from(i) / 64.0, f64::from(j) / 64.0);
                    let (du, dv) = derivatives(&p, u, v);
                    let n = cross(du, dv);
                    let (du, dv) = eval32::derivatives(&p32, u as f32, v as f32);
                    let n32 = eval32::cross(du, dv);
                    let collapsed = j == 0 && (LID_TOP.contains(&index) || BOTTOM.contains(&index));
                    let eps = DEGENERATE_EPSILON;
                    assert_eq!(dot(n, n) < eps, collapsed, "patch {index} ({i}, {j})");
                    assert_eq!(
                        eval32::dot(n32, n32) < eps as f32,
                        collapsed,
                        "f32 patch {index} ({i}, {j})"
                    );
                }
            }
        }
    }

    #[test]
    fn lid_apex_points_up_and_bottom_centre_points_down() {
        for i in 0..=64u32 {
            let u = f64::from(i) / 64.0;
            for index in LID_TOP {
                assert!(
                    normal(&patch(index), u, 0.0)[2] > 0.9,
                    "patch {index} u {u}"
                );
                assert!(normal_f32(&patch_f32(index), u as f32, 0.0)[2] > 0.9);
            }
            for index in BOTTOM {
                assert!(
                    normal(&patch(index), u, 0.0)[2] < -0.9,
                    "patch {index} u {u}"
                );
                assert!(normal_f32(&patch_f32(index), u as f32, 0.0)[2] < -0.9);
            }
        }
    }

    #[test]
    fn body_normals_point_away_from_the_axis() {
        for index in 4..12 {
            let p = patch(index);
            for j in 0..=16u32 {
                for i in 0..=16u32 {
                    let (u, v) = (f64::from(i) / 16.0, f64::from(j) / 16.0);
                    let x = point(&p, u, v);
                    let n = normal(&p, u, v);
                    assert!(x[0] * n[0] + x[1] * n[1] > 0.0, "patch {index} ({u}, {v})");
                }
            }
        }
    }

    #[test]
    fn lid_normals_point_up_and_bottom_normals_down() {
        // The lid's edge turns straight down and the bottom's edge straight up, so at
        // those edges "out" is sideways: check "up (down) or away from the axis".
        let check = |index: usize, z: f64| {
            let p = patch(index);
            for j in 0..=16u32 {
                for i in 0..=16u32 {
                    let (u, v) = (f64::from(i) / 16.0, f64::from(j) / 16.0);
                    let x = point(&p, u, v);
                    let radius = x[0].hypot(x[1]).max(1e-9);
                    let outward = [x[0] / radius, x[1] / radius, z];
                    let n = normal(&p, u, v);
                    assert!(dot(n, outward) > 0.1, "patch {index} ({u}, {v}): {n:?}");
                }
            }
        };
        for index in 24..28 {
            check(index, 1.0);
        }
        for index in BOTTOM {
            check(index, -1.0);
        }
    }

    /// The handle (12..16) and the spout up to its tip (16..18) are tubes: two patches
    /// per cross-section, `u` around it and `v` along it. Outward there means away from
    /// the cross-section's centre.
    #[test]
    fn handle_and_spout_normals_point_away_from_the_tube_centre() {
        for index in 12..18 {
            let p = patch(index);
            let other = patch(index ^ 1);
            for j in 0..=16u32 {
                let v = f64::from(j) / 16.0;
                let mut centre = [0.0; 3];
                for i in 0..64u32 {
                    let u = (f64::from(i) + 0.5) / 64.0;
                    let (a, b) = (point(&p, u, v), point(&other, u, v));
                    for k in 0..3 {
                        centre[k] += (a[k] + b[k]) / 128.0;
                    }
                }
                for i in 0..=16u32 {
                    let u = f64::from(i) / 16.0;
                    let away = sub(point(&p, u, v), centre);
                    let n = normal(&p, u, v);
                    assert!(
                        dot(n, away) > 0.3 * length(away),
                        "patch {index} ({u}, {v})"
                    );
                }
            }
        }
    }

    /// Patches that share a boundary must agree on which side is out; with the checks
    /// above this carries "outward" to the rim (0..4), the knob (20..24) and the spout's
    /// tip (18..20), which curl over and have no simpler test.
    #[test]
    fn normals_agree_across_shared_edges() {
        // Each boundary as (its 4 control-point indices, its (u, v) at t).
        type Edge = ([u16; 4], fn(f64) -> (f64, f64));
        let edges = |k: usize| -> [Edge; 4] {
            let q = PATCHES[k];
            [
                ([q[0], q[1], q[2], q[3]], |t| (t, 0.0)),
                ([q[12], q[13], q[14], q[15]], |t| (t, 1.0)),
                ([q[0], q[4], q[8], q[12]], |t| (0.0, t)),
                ([q[3], q[7], q[11], q[15]], |t| (1.0, t)),
            ]
        };
        let mut shared = 0;
        for a in 0..PATCHES.len() {
            for b in a + 1..PATCHES.len() {
                for (ea, at_a) in edges(a) {
                    for (eb, at_b) in edges(b) {
                        let reversed = [eb[3], eb[2], eb[1], eb[0]];
                        let flip = if ea == eb {
                            false
                        } else if ea == reversed {
                            true
                        } else {
                            continue;
                        };
                        if ea.iter().all(|&i| i == ea[0]) {
                            continue;
                        }
                        shared += 1;
                        for i in 0..=16u32 {
                            let t = f64::from(i) / 16.0;
                            let (ua, va) = at_a(t);
                            let (ub, vb) = at_b(if flip { 1.0 - t } else { t });
                            let (pa, pb) = (patch(a), patch(b));
                            assert!(length(sub(point(&pa, ua, va), point(&pb, ub, vb))) < 1e-12);
                            let (na, nb) = (normal(&pa, ua, va), normal(&pb, ub, vb));
                            assert!(dot(na, nb) > 0.5, "patches {a} and {b} at t = {t}");
                        }
                    }
                }
            }
        }
        // Rim, upper body, lower body and bottom: 4 seams around each ring and 4 between
        // consecutive rings (28). Knob and lid: 4 + 4 + 4 (12). Handle and spout: two
        // seams along each of their two tube sections and two between the sections (6
        // each).
        assert_eq!(shared, 52);
    }

    #[test]
    fn mesh_has_the_expected_triangles_and_valid_indices() {
        for segments in [0u32, 1, 2, 3, 5, 8, 13, 32] {
            let s = segments.max(1) as usize;
            let (vertices, indices) = mesh(segments);
            assert_eq!(vertices.len(), 32 * (s + 1) * (s + 1));
            assert_eq!(
                indices.len(),
                3 * (64 * s * s - 8 * s),
                "segments {segments}"
            );
            assert!(indices.iter().all(|&i| (i as usize) < vertices.len()));
            for t in indices.chunks_exact(3) {
                let [a, b, c] = [0, 1, 2].map(|k| vertices[t[k] as usize]);
                let p = |v: MeshVertex| v.position.map(f64::from);
                let (pa, pb, pc) = (p(a), p(b), p(c));
                assert!(pa != pb && pb != pc && pc != pa, "collapsed triangle {t:?}");
                // Below 8 segments a triangle can span the whole curl of the rim, the
                // knob or the spout's tip (at 1 segment the tip's corners are even
                // collinear), and its vertex normals say nothing about its face.
                if segments >= 8 {
                    let face = cross(sub(pb, pa), sub(pc, pa));
                    let n = [0, 1, 2].map(|k| a.normal[k] + b.normal[k] + c.normal[k]);
                    // Counter-clockwise seen from the side the normals point to.
                    assert!(
                        dot(face, n.map(f64::from)) > 0.0,
                        "segments {segments} {t:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn mesh_bounding_box_is_the_teapot() {
        let (vertices, _) = mesh(32);
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for v in &vertices {
            for k in 0..3 {
                lo[k] = lo[k].min(f64::from(v.position[k]));
                hi[k] = hi[k].max(f64::from(v.position[k]));
            }
        }
        let close = |a: f64, b: f64| (a - b).abs() < 0.02;
        assert!(
            close(lo[0], -3.0) && close(hi[0], 3.44),
            "x {} .. {}",
            lo[0],
            hi[0]
        );
        assert!(
            close(lo[1], -2.0) && close(hi[1], 2.0),
            "y {} .. {}",
            lo[1],
            hi[1]
        );
        assert!(
            close(lo[2], 0.0) && close(hi[2], TEAPOT_HEIGHT),
            "z {} .. {}",
            lo[2],
            hi[2]
        );
    }
}
