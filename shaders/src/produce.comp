#version 450
// Writes a triangle's three vertices (a vec2 position and a vec3 color each, as the
// triangle shaders fetch them) and the parameters of a draw of them
// (VkDrawIndirectCommand): a compute shader whose writes a draw reads.
layout(local_size_x = 1) in;
layout(set = 0, binding = 0) buffer Vertices { float v[15]; };
layout(set = 0, binding = 1) buffer Args { uint args[4]; };
void main() {
    const float data[15] = float[](
        -1.0, -1.0, 1.0, 0.0, 0.0,
        3.0, -1.0, 0.0, 1.0, 0.0,
        -1.0, 3.0, 0.0, 0.0, 1.0);
    for (int i = 0; i < 15; i++) {
        v[i] = data[i];
    }
    args[0] = 3u;
    args[1] = 1u;
    args[2] = 0u;
    args[3] = 0u;
}
