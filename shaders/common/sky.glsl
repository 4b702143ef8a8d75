// The sky (environment): radiance seen along a direction, with a blur from 0 (sharp, for the
// background and mirror reflections) to 1 (the widest, standing in for diffuse irradiance).
// Approximations, chosen to stay cheap and simple:
// - constant sky: the same everywhere, blur changes nothing;
// - gradient sky: ground / horizon / zenith colours blended by the direction's height; blurred
//   versions fade to "hemisphere lighting" (sky and ground averages mixed by 0.5 + 0.5 y);
// - image sky: an equirectangular HDR image with a mip chain; blur picks the mip level
//   (roughness-driven level selection, as in prefiltered environment maps, but with a box
//   filter instead of GGX prefiltering). Diffuse uses the level two below the top (8x4 texels
//   or coarser), a rough irradiance map.
// With no sky (type 0) the frame's constant ambient colour is used (the original behaviour).
#include "common/frame.glsl"

layout(binding = SKY_IMAGE_UNIT) uniform sampler2D uSkyImage; // linear RGB, rows top down

const float SKY_PI = 3.14159265358979;

vec3 skyGradient(vec3 dir, float blur) {
    float y = clamp(dir.y, -1.0, 1.0);
    vec3 sharp = y >= 0.0 ? mix(frame.skyHorizon.rgb, frame.skyZenith.rgb, smoothstep(0.0, 0.6, y))
                          : mix(frame.skyHorizon.rgb, frame.skyGround.rgb, smoothstep(0.0, 0.15, -y));
    vec3 skyAverage = 0.5 * (frame.skyZenith.rgb + frame.skyHorizon.rgb);
    vec3 groundAverage = 0.5 * (frame.skyGround.rgb + frame.skyHorizon.rgb);
    vec3 hemisphere = mix(groundAverage, skyAverage, 0.5 + 0.5 * y);
    return mix(sharp, hemisphere, clamp(blur, 0.0, 1.0));
}

// Equirectangular lookup: u = longitude (turned by the rotation), v = 0 at +Y (top row).
vec3 skyImage(vec3 dir, float lod) {
    float longitude = atan(dir.z, dir.x) + frame.sky.w;
    float u = fract(longitude / (2.0 * SKY_PI) + 0.5);
    float v = acos(clamp(dir.y, -1.0, 1.0)) / SKY_PI;
    return textureLod(uSkyImage, vec2(u, v), lod).rgb;
}

// Radiance of the sky along the normalized dir, blurred by `blur` in [0, 1].
vec3 skyRadiance(vec3 dir, float blur) {
    int type = int(frame.sky.x + 0.5);
    vec3 radiance = frame.skyZenith.rgb; // constant
    if (type == SKY_GRADIENT) radiance = skyGradient(dir, blur);
    if (type == SKY_IMAGE) radiance = skyImage(dir, clamp(blur, 0.0, 1.0) * max(frame.sky.z - 2.0, 0.0));
    return radiance * frame.sky.y;
}

bool hasSky() { return int(frame.sky.x + 0.5) != SKY_NONE; }

// Diffuse ambient: the sky's radiance averaged around the normal (irradiance / pi).
vec3 skyDiffuse(vec3 normal) {
    return hasSky() ? skyRadiance(normal, 1.0) : frame.ambient.rgb;
}

// Specular ambient along the reflected direction, blurred by the roughness.
vec3 skySpecular(vec3 reflected, float roughness) {
    return hasSky() ? skyRadiance(reflected, roughness) : frame.ambient.rgb;
}

// What the camera sees where a ray hits nothing.
vec3 skyBackground(vec3 dir) { return skyRadiance(dir, 0.0); }

// Exponential distance fog: the fraction of the surface's colour that reaches the eye is
// exp(-density * distance); the rest is the fog colour.
vec3 applyFog(vec3 color, float distance) {
    if (frame.fog.a <= 0.0) return color;
    return mix(frame.fog.rgb, color, exp(-frame.fog.a * distance));
}
