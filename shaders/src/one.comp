#version 450
// One invocation per workgroup and nothing to read: a pipeline that asks for full
// subgroups breaks the rules that the workgroup's width is a multiple of the
// subgroup size.
layout(local_size_x = 1) in;
void main() {}
