#version 450 core
// Host pass, second half: writes the SDF hits of the march into the host's colour and depth
// (drawn into the host's framebuffer over its viewport). Pixels where the march hit nothing
// nearer than the host's surface are discarded, so the host's colour and depth stay.
#include "common/frame.glsl"
#include "common/tone_map.glsl"

layout(binding = 0) uniform sampler2D uColor;     // combined G-buffer: linear HDR
layout(binding = 1) uniform usampler2D uObjectId; // 0 where the march passed the host through
layout(binding = 2) uniform sampler2D uDepth;     // window depth in the host's convention
uniform ivec2 uOffset;                            // the host viewport's lower-left corner
uniform int uDisplayEncoded; // 1: exposure, tone curve and sRGB (as `rmsc render`); 0: linear

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy) - uOffset;
    if (texelFetch(uObjectId, pixel, 0).r == 0u) discard;
    vec3 hdr = texelFetch(uColor, pixel, 0).rgb * frame.background.a;
    outColor = vec4(uDisplayEncoded != 0 ? linearToSrgb(acesFitted(hdr)) : hdr, 1.0);
    gl_FragDepth = texelFetch(uDepth, pixel, 0).r;
}
