#version 450 core
// Shadow pass fragment shader: nothing to write but depth, which the rasterizer writes.
void main() {}
