#version 450
#extension GL_EXT_shader_image_load_formatted : require
// image.comp reading a storage image of Unknown format: a dispatch reads the view in
// its own format, which must support reads without a format.
layout(local_size_x = 1) in;
layout(set = 0, binding = 0) uniform readonly image2D img;
layout(set = 0, binding = 1) buffer Out { vec4 value; } out_buf;
void main() {
    out_buf.value = imageLoad(img, ivec2(0, 0));
}
