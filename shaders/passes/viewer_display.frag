#version 450 core
// Viewer display pass: shows a rendered frame (possibly rendered at a lower resolution) in the
// window's viewport, as colour, normals, depth or object ids, and outlines the selected
// objects (each an id range; kOutlinedRanges in engine/viewer/display_pass.hpp): a pixel is on
// the outline when it and a neighbour two window pixels away disagree on whether they show a
// selected id (a screen-space edge of the id buffer). Built once per view mode (DISPLAY_MODE)
// and with or without the outline (DISPLAY_OUTLINE): llvmpipe runs untaken branches.
layout(binding = 0) uniform sampler2D uColor;      // display colour, RGBA8 holding sRGB values
layout(binding = 1) uniform sampler2D uNormal;     // world normal (0 where nothing was hit)
layout(binding = 2) uniform sampler2D uViewDepth;  // linear view depth, 1e30 where nothing was hit
layout(binding = 3) uniform usampler2D uObjectId;  // 0 = background

uniform float uMaxSteps;     // march steps at which the heatmap is red
uniform uvec2 uSelected[32]; // selected ids: [x, y) of each selected object
uniform int uSelectedCount;  // how many of uSelected are used
uniform vec2 uDepthRange;    // near, far of the depth view
uniform vec2 uViewportSize;  // window pixels the image covers

in vec2 vUv;
layout(location = 0) out vec4 outColor;

ivec2 sourceTexel(vec2 uv) {
    ivec2 size = textureSize(uObjectId, 0);
    return clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
}

// A stable colour per id (integer hash, "hash without sine"-style bit mixing).
vec3 idColor(uint id) {
    if (id == 0u) return vec3(0.0);
    uint h = id * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return vec3(float(h & 255u), float((h >> 8u) & 255u), float((h >> 16u) & 255u)) / 255.0 * 0.8 + 0.2;
}

bool selectedAt(vec2 uv) {
    uint id = texelFetch(uObjectId, sourceTexel(uv), 0).r;
    for (int i = 0; i < uSelectedCount; ++i)
        if (id >= uSelected[i].x && id < uSelected[i].y) return true;
    return false;
}

void main() {
    vec3 color;
#if DISPLAY_MODE == 1
    vec3 n = texelFetch(uNormal, sourceTexel(vUv), 0).xyz;
    color = dot(n, n) > 0.0 ? n * 0.5 + 0.5 : vec3(0.0);
#elif DISPLAY_MODE == 2
    float z = texelFetch(uViewDepth, sourceTexel(vUv), 0).r;
    float v = z >= 1.0e29 ? 1.0 : clamp((z - uDepthRange.x) / (uDepthRange.y - uDepthRange.x), 0.0, 1.0);
    color = vec3(1.0 - pow(v, 0.25)); // near = bright; the fourth root spreads nearby depths
#elif DISPLAY_MODE == 3
    color = idColor(texelFetch(uObjectId, sourceTexel(vUv), 0).r);
#elif DISPLAY_MODE == 4
    // The march pass keeps the step count in the normal target's w. The ramp of
    // encodeStepsHeatmap (engine/core/image_io.cpp): black, blue, cyan, green, yellow, red.
    float x = clamp(texelFetch(uNormal, sourceTexel(vUv), 0).w / max(uMaxSteps, 1.0), 0.0, 1.0) * 5.0;
    const vec3 ramp[6] = vec3[6](vec3(0, 0, 0), vec3(0, 0, 1), vec3(0, 1, 1), vec3(0, 1, 0),
                                 vec3(1, 1, 0), vec3(1, 0, 0));
    int k = min(int(x), 4);
    color = mix(ramp[k], ramp[k + 1], x - float(k));
#else
    // Bilinear filtering (the display pass binds a linear sampler to the colour's unit).
    color = texture(uColor, vUv).rgb;
#endif
#if DISPLAY_OUTLINE
    vec2 px = 2.0 / uViewportSize;
    bool inside = selectedAt(vUv);
    bool edge = inside != selectedAt(vUv + vec2(px.x, 0.0)) ||
                inside != selectedAt(vUv - vec2(px.x, 0.0)) ||
                inside != selectedAt(vUv + vec2(0.0, px.y)) ||
                inside != selectedAt(vUv - vec2(0.0, px.y));
    if (edge) color = vec3(1.0, 0.55, 0.1);
#endif
    outColor = vec4(color, 1.0);
}
