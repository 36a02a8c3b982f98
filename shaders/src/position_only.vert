#version 450
// Redeclares the built-in output block with gl_Position alone, so that the block
// does not match the full one a geometry or tessellation stage reads.
out gl_PerVertex {
    vec4 gl_Position;
};
void main() {
    vec2 p = vec2(float((gl_VertexIndex & 1) * 4 - 1), float((gl_VertexIndex & 2) * 2 - 1));
    gl_Position = vec4(p, 0.0, 1.0);
}
