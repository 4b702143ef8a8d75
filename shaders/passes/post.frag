#version 450 core
// Post pass: exposure, the ACES filmic tone curve (Krzysztof Narkowicz's fit, "ACES Filmic Tone
// Mapping Curve", 2016) and the sRGB transfer function, to an 8-bit display image.
#include "common/frame.glsl"

layout(binding = 0) uniform sampler2D uHdrColor;

layout(location = 0) out vec4 outColor;

vec3 acesFitted(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// sRGB OETF (IEC 61966-2-1).
vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec3 hdr = texelFetch(uHdrColor, ivec2(gl_FragCoord.xy), 0).rgb * frame.background.a;
    outColor = vec4(linearToSrgb(acesFitted(hdr)), 1.0);
}
