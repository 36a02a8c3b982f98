#version 450
// image.comp reading unsigned integer texels: a dispatch with a UNORM view bound
// breaks the numeric format rule.
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, rgba8ui) uniform readonly uimage2D img;
layout(set = 0, binding = 1) buffer Out { vec4 value; } out_buf;
void main() {
    out_buf.value = vec4(imageLoad(img, ivec2(0, 0)));
}
