#version 450
// The deferred scene's G-buffer subpass: each object's color and its normal (turned
// to face the eye: the teapot is not closed) into two color attachments; the depth
// attachment keeps the rest. Its vertex stage is teapot.vert.
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_world;

layout(set = 0, binding = 0) uniform Camera {
    mat4 view_projection;
    vec4 eye;
    vec4 light;
} camera;

layout(push_constant) uniform Object {
    mat4 model;
    vec4 color;
} object;

layout(location = 0) out vec4 albedo;
layout(location = 1) out vec4 normal;

void main() {
    vec3 n = normalize(v_normal);
    if (dot(n, camera.eye.xyz - v_world) < 0.0) {
        n = -n;
    }
    albedo = vec4(object.color.rgb, 1.0);
    normal = vec4(n, 0.0);
}
