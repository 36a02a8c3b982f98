#version 450
// The deferred scene's lighting subpass: reads the G-buffer written by subpass 0
// (color, normal, depth) as input attachments at this pixel, rebuilds the world
// position from the depth, and sums a dim sun and every point light.
layout(input_attachment_index = 0, set = 0, binding = 0) uniform subpassInput albedo_in;
layout(input_attachment_index = 1, set = 0, binding = 1) uniform subpassInput normal_in;
layout(input_attachment_index = 2, set = 0, binding = 2) uniform subpassInput depth_in;

struct Light {
    vec4 position; // xyz world position, w radius of influence
    vec4 color;    // rgb intensity
};

// Must match MAX_LIGHTS in examples/src/scenes/deferred_data.rs.
const uint MAX_LIGHTS = 64;

layout(set = 0, binding = 3) uniform Lights {
    mat4 inverse_view_projection;
    vec4 sun;        // xyz direction towards the sun, w its strength
    vec4 background; // rgb where nothing was drawn
    vec4 extent;     // x, y framebuffer size in pixels; z the light count
    Light lights[MAX_LIGHTS];
} scene;

layout(location = 0) out vec4 color;

void main() {
    float depth = subpassLoad(depth_in).r;
    // Reversed Z clears to 0: nothing was drawn here.
    if (depth == 0.0) {
        color = vec4(scene.background.rgb, 1.0);
        return;
    }
    vec2 ndc = gl_FragCoord.xy / scene.extent.xy * 2.0 - 1.0;
    vec4 h = scene.inverse_view_projection * vec4(ndc, depth, 1.0);
    vec3 world = h.xyz / h.w;
    vec3 n = normalize(subpassLoad(normal_in).xyz);
    vec3 albedo = subpassLoad(albedo_in).rgb;
    vec3 light = vec3(0.06) + scene.sun.w * max(dot(n, scene.sun.xyz), 0.0);
    uint count = min(uint(scene.extent.z), MAX_LIGHTS);
    for (uint i = 0; i < count; i++) {
        vec3 to_light = scene.lights[i].position.xyz - world;
        float distance = length(to_light);
        float reach = clamp(1.0 - distance / scene.lights[i].position.w, 0.0, 1.0);
        light += scene.lights[i].color.rgb * reach * reach
            * max(dot(n, to_light / max(distance, 1e-4)), 0.0);
    }
    color = vec4(albedo * light, 1.0);
}
