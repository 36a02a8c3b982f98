#version 450
// Writes the first texel of a storage image: a draw whose storage image is its own
// color attachment breaks the rule that attachments are written only as attachments.
layout(set = 0, binding = 0, rgba8) uniform writeonly image2D img;
layout(location = 0) out vec4 out_color;
void main() {
    imageStore(img, ivec2(0, 0), vec4(1.0));
    out_color = vec4(0.0);
}
