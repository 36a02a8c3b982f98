#version 450
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_position;

layout(push_constant) uniform Params {
    mat4 model_view_projection;
    vec4 eye;
    vec4 light;
    vec4 level;
} params;

layout(location = 0) out vec4 color;

const vec3 BASE = vec3(0.85, 0.75, 0.45);

void main() {
    // The teapot is not closed (the lid leaves a gap), so whichever side faces the
    // eye is lit.
    vec3 n = normalize(v_normal);
    if (dot(n, params.eye.xyz - v_position) < 0.0) {
        n = -n;
    }
    float diffuse = max(dot(n, params.light.xyz), 0.0);
    color = vec4(BASE * (0.2 + 0.8 * diffuse), 1.0);
}
