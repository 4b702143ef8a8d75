#version 450 core
// Post pass: exposure, the ACES filmic tone curve and the sRGB transfer function
// (common/tone_map.glsl), to an 8-bit display image; optional FXAA on the display colours
// (frame.ao.w).
#include "common/frame.glsl"
#include "common/tone_map.glsl"

layout(binding = 0) uniform sampler2D uHdrColor;

layout(location = 0) out vec4 outColor;

// The display colour of a pixel (clamped to the image).
vec3 displayColor(ivec2 pixel) {
    pixel = clamp(pixel, ivec2(0), ivec2(frame.viewport.xy) - 1);
    vec3 hdr = texelFetch(uHdrColor, pixel, 0).rgb * frame.background.a;
    return linearToSrgb(acesFitted(hdr));
}

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

// A simplified FXAA after Timothy Lottes' FXAA 3.11 (NVIDIA, 2011) on the display colours:
// skip pixels whose local luma contrast is low; decide whether the edge runs horizontally or
// vertically from second differences over the 3x3 neighbourhood; walk along the edge (up to
// FXAA_SEARCH pixels each way) until the luma across it changes, and blend with the neighbour
// across the edge by how close the pixel is to the nearer end of the edge (long edges blend
// little near their middle, short staircase steps more); a sub-pixel term softens isolated
// pixels. Written from the idea, not from Lottes' code.
#define FXAA_SEARCH 8
vec3 fxaa(ivec2 p) {
    vec3 centre = displayColor(p);
    float m = luma(centre);
    float n = luma(displayColor(p + ivec2(0, 1))), s = luma(displayColor(p + ivec2(0, -1)));
    float e = luma(displayColor(p + ivec2(1, 0))), w = luma(displayColor(p + ivec2(-1, 0)));
    float lo = min(m, min(min(n, s), min(e, w)));
    float hi = max(m, max(max(n, s), max(e, w)));
    float range = hi - lo;
    if (range < max(0.0312, 0.125 * hi)) return centre;
    float ne = luma(displayColor(p + ivec2(1, 1))), nw = luma(displayColor(p + ivec2(-1, 1)));
    float se = luma(displayColor(p + ivec2(1, -1))), sw = luma(displayColor(p + ivec2(-1, -1)));
    float horizontal = abs(nw + sw - 2.0 * w) + 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e);
    float vertical = abs(nw + ne - 2.0 * n) + 2.0 * abs(w + e - 2.0 * m) + abs(sw + se - 2.0 * s);
    bool isHorizontal = horizontal >= vertical; // the edge runs along x
    // The neighbour across the edge: the side with the larger luma step.
    float a = isHorizontal ? s : w, b = isHorizontal ? n : e;
    bool towardsB = abs(b - m) >= abs(a - m);
    ivec2 across = isHorizontal ? ivec2(0, towardsB ? 1 : -1) : ivec2(towardsB ? 1 : -1, 0);
    ivec2 along = isHorizontal ? ivec2(1, 0) : ivec2(0, 1);
    float edgeLuma = 0.5 * (m + (towardsB ? b : a));
    float gradient = 0.25 * abs((towardsB ? b : a) - m);
    int negative = FXAA_SEARCH, positive = FXAA_SEARCH;
    for (int i = 1; i <= FXAA_SEARCH; ++i) {
        float pairLuma = 0.5 * (luma(displayColor(p - along * i)) +
                                luma(displayColor(p - along * i + across)));
        if (abs(pairLuma - edgeLuma) >= gradient) { negative = i; break; }
    }
    for (int i = 1; i <= FXAA_SEARCH; ++i) {
        float pairLuma = 0.5 * (luma(displayColor(p + along * i)) +
                                luma(displayColor(p + along * i + across)));
        if (abs(pairLuma - edgeLuma) >= gradient) { positive = i; break; }
    }
    float edgeBlend = 0.5 - float(min(negative, positive)) / float(negative + positive);
    // Sub-pixel aliasing: how much the centre differs from its neighbourhood's average.
    float average = (2.0 * (n + s + e + w) + ne + nw + se + sw) / 12.0;
    float subpixel = clamp(abs(average - m) / range, 0.0, 1.0);
    subpixel = subpixel * subpixel * (3.0 - 2.0 * subpixel);
    float blend = max(edgeBlend, 0.75 * subpixel * subpixel);
    return mix(centre, displayColor(p + across), clamp(blend, 0.0, 0.5));
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 color = frame.ao.w > 0.5 ? fxaa(pixel) : displayColor(pixel);
    outColor = vec4(color, 1.0);
}
