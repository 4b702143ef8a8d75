#version 450 core
// Shadow pass vertex shader: mesh vertices into one shadow view's clip space, with what the
// alpha test of MASK and BLEND materials needs (texture coordinates, vertex alpha); skinned
// primitives skinned first.
#include "common/skinning.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec2 inUv1;
layout(location = 5) in vec4 inColor;

uniform mat4 uModel;
uniform mat4 uLightViewProjection;

out vec2 vUv;
out vec2 vUv1;
out float vAlpha;

void main() {
    vUv = inUv;
    vUv1 = inUv1;
    vAlpha = inColor.a;
    vec3 position = skinned() ? (skinMatrix() * vec4(inPosition, 1.0)).xyz : inPosition;
    gl_Position = uLightViewProjection * (uModel * vec4(position, 1.0));
}
