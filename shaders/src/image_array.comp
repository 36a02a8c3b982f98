#version 450
// image.comp reading a 2D array image: a dispatch with a 2D view bound breaks the
// view type rule.
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, rgba8) uniform readonly image2DArray img;
layout(set = 0, binding = 1) buffer Out { vec4 value; } out_buf;
void main() {
    out_buf.value = imageLoad(img, ivec3(0, 0, 0));
}
