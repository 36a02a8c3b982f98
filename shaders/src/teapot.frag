#version 450
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_world;

layout(set = 0, binding = 0) uniform Camera {
    mat4 view_projection;
    vec4 eye;
    vec4 light;
} camera;

layout(push_constant) uniform Teapot {
    mat4 model;
    vec4 color;
} teapot;

layout(location = 0) out vec4 color;

void main() {
    // The teapot is not closed (the lid leaves a gap), so whichever side faces the
    // eye is lit.
    vec3 n = normalize(v_normal);
    if (dot(n, camera.eye.xyz - v_world) < 0.0) {
        n = -n;
    }
    float diffuse = max(dot(n, camera.light.xyz), 0.0);
    color = vec4(teapot.color.rgb * (0.2 + 0.8 * diffuse), 1.0);
}
