#version 450 core
// Raster pass vertex shader: glTF mesh vertices to clip space, with world position, normal,
// texture coordinates, tangent and vertex colour; skinned primitives skinned first.
#include "common/frame.glsl"
#include "common/skinning.glsl"

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
    vec3 position = inPosition;
    vec3 normal = inNormal;
    vec3 tangent = inTangent.xyz;
    if (skinned()) {
        mat4 skin = skinMatrix();
        position = (skin * vec4(position, 1.0)).xyz;
        // Unit length at each vertex, and the tangent made perpendicular to the normal, as the
        // CPU-posed vertices are: the same values to interpolate.
        normal = skinNormalMatrix(skin) * normal;
        normal = dot(normal, normal) > 1e-24 ? normalize(normal) : vec3(0.0);
        vec3 t = mat3(skin) * tangent;
        t -= normal * dot(normal, t);
        if (dot(t, t) > 1e-24) tangent = normalize(t);
    }
    vec4 world = uModel * vec4(position, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = uNormalMatrix * normal;
    vUv = inUv;
    vUv1 = inUv1;
    vColor = inColor;
    // Tangents transform like positions; a mirroring model matrix flips the handedness.
    float handedness = determinant(mat3(uModel)) < 0.0 ? -1.0 : 1.0;
    vWorldTangent = vec4(mat3(uModel) * tangent, inTangent.w * handedness);
    gl_Position = frame.viewProjection * world;
}
