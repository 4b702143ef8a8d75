#version 450 core
// Shadow pass fragment shader: depth only (the rasterizer writes it). Fragments of MASK
// materials below their alphaCutoff, and of BLEND materials below 0.5, cast no shadow: the
// alpha is the base colour's, as in passes/raster.frag.
in vec2 vUv;
in vec2 vUv1;
in float vAlpha;

// x: the cutoff (< 0: no test, the material is opaque), y: the base colour factor's alpha,
// z: the TEXCOORD set of the base colour texture (-1: none).
uniform vec3 uAlphaTest;
uniform mat3 uUvTransform; // the base colour texture's KHR_texture_transform
layout(binding = 0) uniform sampler2D uBaseColorTexture;

void main() {
    if (uAlphaTest.x < 0.0) return;
    float alpha = uAlphaTest.y * vAlpha;
    if (uAlphaTest.z >= 0.0) {
        vec2 uv = (uUvTransform * vec3(uAlphaTest.z == 1.0 ? vUv1 : vUv, 1.0)).xy;
        alpha *= texture(uBaseColorTexture, uv).a;
    }
    if (alpha < uAlphaTest.x) discard;
}
