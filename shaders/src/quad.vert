#version 450
// A quad covering the middle of the image, from the vertex index alone (a triangle
// strip of four vertices), with texture coordinates 0 to 1 across it.
layout(location = 0) out vec2 uv;

void main() {
    vec2 corner = vec2(gl_VertexIndex & 1, gl_VertexIndex >> 1);
    uv = corner;
    gl_Position = vec4(corner * 1.5 - 0.75, 0.0, 1.0);
}
