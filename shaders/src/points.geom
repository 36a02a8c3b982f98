#version 450
// Passes each point through: a pipeline whose topology or tessellation gives it
// lines or triangles breaks the rules that a geometry shader's input primitive
// matches what comes before it.
layout(points) in;
layout(points, max_vertices = 1) out;
void main() {
    gl_Position = gl_in[0].gl_Position;
    // Written, as a device with shaderTessellationAndGeometryPointSize asks.
    gl_PointSize = 1.0;
    EmitVertex();
    EndPrimitive();
}
