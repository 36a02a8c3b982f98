#version 450
// The test triangle, mirrored when its boolean specialization constant says so: a
// map entry of another size than a VkBool32 breaks the rule that sizes match.
layout(constant_id = 0) const bool MIRROR = false;
void main() {
    vec2 p = vec2(float((gl_VertexIndex & 1) * 4 - 1), float((gl_VertexIndex & 2) * 2 - 1));
    gl_Position = vec4(MIRROR ? -p.x : p.x, p.y, 0.0, 1.0);
}
