#version 450
// Writes each invocation's index times the uniform factor, so a read-back proves the
// dispatch ran with the descriptor set it was given.
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform Factor { uint factor; } u;
layout(set = 0, binding = 1) buffer Out { uint values[]; } out_buf;
void main() {
    uint i = gl_GlobalInvocationID.x;
    out_buf.values[i] = i * u.factor;
}
