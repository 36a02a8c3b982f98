#version 450
// Colors with a texture sampled at an explicit LOD, with an offset: a draw whose
// sampler has unnormalized coordinates breaks the offset rule.
layout(set = 0, binding = 0) uniform sampler2D tex;
layout(location = 0) out vec4 out_color;
void main() {
    out_color = textureLodOffset(tex, vec2(0.5, 0.5), 0.0, ivec2(1, 0));
}
