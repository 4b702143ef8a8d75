#version 450 core
// Raster pass fragment shader: shades glTF mesh fragments with the shared lighting module and
// writes the G-buffer (colour, normal, linear view depth, object id).
#include "common/lighting.glsl"

in vec3 vWorldPosition;
in vec3 vWorldNormal;
in vec2 vUv;

uniform vec4 uBaseColorFactor;
uniform vec4 uMetallicRoughness; // x = metallic, y = roughness
uniform vec3 uEmissive;
uniform bool uHasBaseColorTexture;
uniform uint uObjectId;
layout(binding = 0) uniform sampler2D uBaseColorTexture; // sRGB texture, decoded by GL

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out float outViewDepth;
layout(location = 3) out uint outObjectId;

void main() {
    vec4 baseColor = uBaseColorFactor;
    if (uHasBaseColorTexture) baseColor *= texture(uBaseColorTexture, vUv);
    vec3 normal = normalize(vWorldNormal);
    if (!gl_FrontFacing) normal = -normal; // double-sided lighting of back faces

    SurfacePoint s;
    s.position = vWorldPosition;
    s.normal = normal;
    s.baseColor = baseColor.rgb;
    s.metallic = uMetallicRoughness.x;
    s.roughness = uMetallicRoughness.y;
    s.emissive = uEmissive;

    outColor = vec4(shadeSurface(s), 1.0);
    outNormal = vec4(normal, 0.0);
    outViewDepth = -(frame.view * vec4(vWorldPosition, 1.0)).z;
    outObjectId = uObjectId;
}
