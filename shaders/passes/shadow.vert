#version 450 core
// Shadow pass vertex shader: mesh vertices into one shadow view's clip space (depth only).
layout(location = 0) in vec3 inPosition;

uniform mat4 uModel;
uniform mat4 uLightViewProjection;

void main() { gl_Position = uLightViewProjection * (uModel * vec4(inPosition, 1.0)); }
