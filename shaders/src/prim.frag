#version 450
// Colors with the primitive's index: after a geometry stage that does not write it,
// that breaks the rule that the geometry stage writes what the fragment stage reads.
layout(location = 0) out vec4 out_color;
void main() {
    out_color = vec4(float(gl_PrimitiveID));
}
