#version 450
// Evaluates a bicubic Bezier patch and its normal at the tessellator's (u, v). The
// algorithm, constants included, is `teapot::normal` in examples/src/teapot.rs, which
// the CPU-side tests check at every level from 1 to 64.
layout(quads, equal_spacing, ccw) in;

layout(push_constant) uniform Params {
    mat4 model_view_projection;
    vec4 eye;
    vec4 light;
    vec4 level;
} params;

layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec3 v_position;

// teapot::DEGENERATE_EPSILON and teapot::NUDGE.
const float DEGENERATE_EPSILON = 1e-6;
const float NUDGE = 1e-3;

vec4 bernstein(float t) {
    float s = 1.0 - t;
    return vec4(s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t);
}

vec4 bernstein_derivative(float t) {
    float s = 1.0 - t;
    return vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t);
}

// sum_c bu[c] * sum_r bv[r] * cp[r * 4 + c]: each column over the rows first, then
// across the columns, the order `teapot::point` sums in.
vec3 combine(vec4 bu, vec4 bv) {
    vec3 p = vec3(0.0);
    for (int c = 0; c < 4; c++) {
        vec3 column = vec3(0.0);
        for (int r = 0; r < 4; r++) {
            column += bv[r] * gl_in[r * 4 + c].gl_Position.xyz;
        }
        p += bu[c] * column;
    }
    return p;
}

vec3 cross_of_tangents(float u, float v) {
    vec3 du = combine(bernstein_derivative(u), bernstein(v));
    vec3 dv = combine(bernstein(u), bernstein_derivative(v));
    return cross(du, dv);
}

void main() {
    float u = gl_TessCoord.x;
    float v = gl_TessCoord.y;
    vec3 position = combine(bernstein(u), bernstein(v));
    vec3 n = cross_of_tangents(u, v);
    // Where a row of control points collapses to one point (the lid's apex, the
    // bottom's centre) one tangent vanishes: take the normal a hair inside the patch.
    if (dot(n, n) < DEGENERATE_EPSILON) {
        n = cross_of_tangents(u < 0.5 ? u + NUDGE : u - NUDGE, v < 0.5 ? v + NUDGE : v - NUDGE);
    }
    v_normal = normalize(n);
    v_position = position;
    gl_Position = params.model_view_projection * vec4(position, 1.0);
}
