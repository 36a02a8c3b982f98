#version 450
#extension GL_EXT_shader_image_load_formatted : require
// Colors with the first texel of a storage image of Unknown format: a draw reads the
// view in its own format, which must support reads without a format.
layout(set = 0, binding = 0) uniform readonly image2D img;
layout(location = 0) out vec4 out_color;
void main() {
    out_color = imageLoad(img, ivec2(0, 0));
}
