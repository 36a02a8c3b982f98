#version 450
// Adds to the first texel of an unsigned integer storage image atomically, so a
// dispatch uses atomics on the image through its descriptor.
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, r32ui) uniform uimage2D img;
layout(set = 0, binding = 1) buffer Out { vec4 value; } out_buf;
void main() {
    out_buf.value = vec4(imageAtomicAdd(img, ivec2(0, 0), 1u));
}
