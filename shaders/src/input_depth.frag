#version 450
// Reads input attachment 0 as floats: the depth aspect of a depth/stencil
// attachment.
layout(input_attachment_index = 0, set = 0, binding = 0) uniform subpassInput depth_in;
layout(location = 0) out vec4 out_color;
void main() {
    out_color = vec4(subpassLoad(depth_in).r);
}
