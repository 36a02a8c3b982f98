#version 450
// Passes the 16 control points through and sets every level to the one asked for.
layout(vertices = 16) out;

layout(push_constant) uniform Params {
    mat4 model_view_projection;
    vec4 eye;   // camera position, model space
    vec4 light; // direction towards the light, model space
    vec4 level; // x: tessellation level
} params;

void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    if (gl_InvocationID == 0) {
        float level = params.level.x;
        gl_TessLevelOuter[0] = level;
        gl_TessLevelOuter[1] = level;
        gl_TessLevelOuter[2] = level;
        gl_TessLevelOuter[3] = level;
        gl_TessLevelInner[0] = level;
        gl_TessLevelInner[1] = level;
    }
}
