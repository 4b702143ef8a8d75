#version 450 core
// Host pass, first half: turns a host program's depth texture into the raster G-buffer the
// march pass reads, so SDF objects march only up to the host's surfaces. The view depth is the
// host's window depth unprojected through the inverse of its view-projection matrix; where the
// host drew nothing (its far value) it is kNoDepth. Colour, normal and id are zero.
#include "common/frame.glsl"

layout(binding = 0) uniform sampler2D uHostDepth;
uniform mat4 uInverseViewProjection;
uniform ivec2 uOffset;   // the host viewport's lower-left corner in the host's texture
uniform float uFarDepth; // the window depth of nothing drawn: 1, or 0 for reversed-Z

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out float outViewDepth;
layout(location = 3) out uint outObjectId;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(uHostDepth, pixel + uOffset, 0).r;
    outColor = vec4(0.0);
    outNormal = vec4(0.0);
    outObjectId = 0u;
    gl_FragDepth = depth;
    if (depth == uFarDepth) {
        outViewDepth = 1.0e30; // kNoDepth
        return;
    }
    vec2 ndcXy = (vec2(pixel) + 0.5) / frame.viewport.xy * 2.0 - 1.0;
    float ndcZ = frame.viewport.w > 0.5 ? depth : depth * 2.0 - 1.0;
    vec4 world = uInverseViewProjection * vec4(ndcXy, ndcZ, 1.0);
    outViewDepth = dot(world.xyz / world.w - frame.cameraPosition.xyz, frame.cameraForward.xyz);
}
