#version 450
// Fetches a patch's control point from the storage buffer; the index buffer lists
// each patch's 16 control points.
layout(set = 0, binding = 0) readonly buffer Points {
    vec4 points[];
};

void main() {
    gl_Position = vec4(points[gl_VertexIndex].xyz, 1.0);
}
