// Display encoding of linear HDR colour: the ACES filmic tone curve (Krzysztof Narkowicz's fit,
// "ACES Filmic Tone Mapping Curve", 2016) and the sRGB transfer function (IEC 61966-2-1). Used
// by the post pass and by the host pass that writes into a host's colour texture.

vec3 acesFitted(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// sRGB OETF (IEC 61966-2-1).
vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
