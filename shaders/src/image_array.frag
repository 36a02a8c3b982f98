#version 450
// Colors with the first texel of a 2D array storage image: a draw with a 2D view
// bound breaks the view type rule.
layout(set = 0, binding = 0, rgba8) uniform readonly image2DArray img;
layout(location = 0) out vec4 out_color;
void main() {
    out_color = imageLoad(img, ivec3(0, 0, 0));
}
