#version 450 core
// Viewer display pass: shows a rendered frame (possibly rendered at a lower resolution) in the
// window's viewport, as colour, normals, depth or object ids, and outlines the selected
// objects (each an id range; kOutlinedRanges in engine/viewer/display_pass.hpp): a pixel is on the outline when it and a neighbour two window pixels away disagree on
// whether they show a selected id (a screen-space edge of the id buffer).
layout(binding = 0) uniform sampler2D uColor;      // display colour, RGBA8 holding sRGB values
layout(binding = 1) uniform sampler2D uNormal;     // world normal (0 where nothing was hit)
layout(binding = 2) uniform sampler2D uViewDepth;  // linear view depth, 1e30 where nothing was hit
layout(binding = 3) uniform usampler2D uObjectId;  // 0 = background

uniform int uMode;           // 0 colour, 1 normals, 2 depth, 3 object id, 4 march steps
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

// Bilinear filtering by hand (the render targets have no sampler state of their own).
vec3 bilinearColor(vec2 uv) {
    ivec2 size = textureSize(uColor, 0);
    vec2 p = uv * vec2(size) - 0.5;
    ivec2 i = ivec2(floor(p));
    vec2 f = p - vec2(i);
    ivec2 hi = size - 1;
    vec3 a = texelFetch(uColor, clamp(i, ivec2(0), hi), 0).rgb;
    vec3 b = texelFetch(uColor, clamp(i + ivec2(1, 0), ivec2(0), hi), 0).rgb;
    vec3 c = texelFetch(uColor, clamp(i + ivec2(0, 1), ivec2(0), hi), 0).rgb;
    vec3 d = texelFetch(uColor, clamp(i + ivec2(1, 1), ivec2(0), hi), 0).rgb;
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
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
    if (uMode == 1) {
        vec3 n = texelFetch(uNormal, sourceTexel(vUv), 0).xyz;
        color = dot(n, n) > 0.0 ? n * 0.5 + 0.5 : vec3(0.0);
    } else if (uMode == 2) {
        float z = texelFetch(uViewDepth, sourceTexel(vUv), 0).r;
        float v = z >= 1.0e29 ? 1.0 : clamp((z - uDepthRange.x) / (uDepthRange.y - uDepthRange.x), 0.0, 1.0);
        color = vec3(1.0 - pow(v, 0.25)); // near = bright; the fourth root spreads nearby depths
    } else if (uMode == 3) {
        color = idColor(texelFetch(uObjectId, sourceTexel(vUv), 0).r);
    } else if (uMode == 4) {
        // The march pass keeps the step count in the normal target's w. The ramp of
        // encodeStepsHeatmap (engine/core/image_io.cpp): black, blue, cyan, green, yellow, red.
        float x = clamp(texelFetch(uNormal, sourceTexel(vUv), 0).w / max(uMaxSteps, 1.0), 0.0, 1.0) * 5.0;
        const vec3 ramp[6] = vec3[6](vec3(0, 0, 0), vec3(0, 0, 1), vec3(0, 1, 1), vec3(0, 1, 0),
                                     vec3(1, 1, 0), vec3(1, 0, 0));
        int k = min(int(x), 4);
        color = mix(ramp[k], ramp[k + 1], x - float(k));
    } else {
        color = bilinearColor(vUv);
    }
    if (uSelectedCount > 0) {
        vec2 px = 2.0 / uViewportSize;
        bool inside = selectedAt(vUv);
        bool edge = inside != selectedAt(vUv + vec2(px.x, 0.0)) ||
                    inside != selectedAt(vUv - vec2(px.x, 0.0)) ||
                    inside != selectedAt(vUv + vec2(0.0, px.y)) ||
                    inside != selectedAt(vUv - vec2(0.0, px.y));
        if (edge) color = vec3(1.0, 0.55, 0.1);
    }
    outColor = vec4(color, 1.0);
}
