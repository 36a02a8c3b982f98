#version 450
// Copies the first texel of a storage image into a buffer, so a dispatch reads the
// image through its descriptor, in the layout the descriptor states.
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, rgba8) uniform readonly image2D img;
layout(set = 0, binding = 1) buffer Out { vec4 value; } out_buf;
void main() {
    out_buf.value = imageLoad(img, ivec2(0, 0));
}
