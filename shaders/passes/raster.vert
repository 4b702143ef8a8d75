#version 450 core
// Raster pass vertex shader: glTF mesh vertices to clip space, with world position, normal,
// texture coordinates, tangent and vertex colour.
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec2 inUv1;
layout(location = 4) in vec4 inTangent; // xyz tangent, w bitangent sign
layout(location = 5) in vec4 inColor;   // COLOR_0, linear RGBA (1 when the file has none)

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vWorldPosition;
out vec3 vWorldNormal;
out vec2 vUv;
out vec2 vUv1;
out vec4 vWorldTangent;
out vec4 vColor;

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = uNormalMatrix * inNormal;
    vUv = inUv;
    vUv1 = inUv1;
    vColor = inColor;
    // Tangents transform like positions; a mirroring model matrix flips the handedness.
    float handedness = determinant(mat3(uModel)) < 0.0 ? -1.0 : 1.0;
    vWorldTangent = vec4(mat3(uModel) * inTangent.xyz, inTangent.w * handedness);
    gl_Position = frame.viewProjection * world;
}
