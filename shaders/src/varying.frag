#version 450
// Reads the color at location 0 as a vec4, as varying.vert and varying.geom write it.
layout(location = 0) in vec4 v_color;
layout(location = 0) out vec4 out_color;
void main() {
    out_color = v_color;
}
