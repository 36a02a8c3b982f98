#version 450
// Colors with the first texel of an unsigned integer storage image: a draw with a
// UNORM view bound breaks the numeric format rule.
layout(set = 0, binding = 0, rgba8ui) uniform readonly uimage2D img;
layout(location = 0) out vec4 out_color;
void main() {
    out_color = vec4(imageLoad(img, ivec2(0, 0)));
}
