#version 450
// Adds to the first texel of an unsigned integer storage image atomically, so a
// draw uses atomics on the image through its descriptor.
layout(set = 0, binding = 0, r32ui) uniform uimage2D img;
layout(location = 0) out vec4 out_color;
void main() {
    out_color = vec4(imageAtomicAdd(img, ivec2(0, 0), 1u));
}
