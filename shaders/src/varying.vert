#version 450
// A triangle from the vertex index alone that passes a color on at location 0, as
// a vec4: the interface-matching tests pair it with inputs that match and that do
// not.
layout(location = 0) out vec4 v_color;
void main() {
    vec2 p = vec2(float((gl_VertexIndex & 1) * 4 - 1), float((gl_VertexIndex & 2) * 2 - 1));
    gl_Position = vec4(p, 0.0, 1.0);
    v_color = vec4(p, 0.5, 1.0);
}
