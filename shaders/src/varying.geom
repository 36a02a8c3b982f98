#version 450
// Passes each point on, reading the color the vertex stage writes at location 0.
layout(points) in;
layout(points, max_vertices = 1) out;
layout(location = 0) in vec4 v_color[];
layout(location = 0) out vec4 g_color;
void main() {
    gl_Position = gl_in[0].gl_Position;
    gl_PointSize = 1.0;
    g_color = v_color[0];
    EmitVertex();
    EndPrimitive();
}
