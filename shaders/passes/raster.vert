#version 450 core
// Raster pass vertex shader: glTF mesh vertices to clip space, with world position and normal.
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vWorldPosition;
out vec3 vWorldNormal;
out vec2 vUv;

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = uNormalMatrix * inNormal;
    vUv = inUv;
    gl_Position = frame.viewProjection * world;
}
