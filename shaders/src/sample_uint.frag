#version 450
// Colors with an unsigned integer texture sampled with an implicit LOD: a draw whose
// sampler filters linearly breaks the linear filter rules, and one whose sampler has
// unnormalized coordinates the implicit-LOD rule.
layout(set = 0, binding = 0) uniform usampler2D tex;
layout(location = 0) out vec4 out_color;
void main() {
    out_color = vec4(texture(tex, vec2(0.5, 0.5)));
}
