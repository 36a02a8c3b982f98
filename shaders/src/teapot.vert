#version 450
// One teapot of the grid: the camera from the frame's uniform buffer, the model
// matrix and color from push constants.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(set = 0, binding = 0) uniform Camera {
    mat4 view_projection;
    vec4 eye;   // camera position, world space
    vec4 light; // direction towards the light, world space
} camera;

layout(push_constant) uniform Teapot {
    mat4 model; // rotation, uniform scale and translation
    vec4 color;
} teapot;

layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec3 v_world;

void main() {
    vec4 world = teapot.model * vec4(position, 1.0);
    gl_Position = camera.view_projection * world;
    // The model matrix has a uniform scale, so it turns normals as it turns points.
    v_normal = mat3(teapot.model) * normal;
    v_world = world.xyz;
}
