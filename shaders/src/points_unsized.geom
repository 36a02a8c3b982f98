#version 450
// Passes each point through without writing its size: on a device that reads the
// point size from a geometry stage, that breaks the rule that the stage writes it.
layout(points) in;
layout(points, max_vertices = 1) out;
void main() {
    gl_Position = gl_in[0].gl_Position;
    EmitVertex();
    EndPrimitive();
}
