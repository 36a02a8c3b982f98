#version 450
// Writes its push constant into a buffer, so a dispatch reads push constants.
layout(local_size_x = 1) in;
layout(push_constant) uniform Push { vec4 value; } push;
layout(set = 0, binding = 0) buffer Out { vec4 value; } out_buf;
void main() {
    out_buf.value = push.value;
}
