#version 450 core
// Shell shadow pass: the depth-only variant of the shell pass for the shadow maps. The ray of
// each back-face fragment of the proxy comes from the shadow view (unprojected through its
// inverse, so orthographic and perspective views alike); a hit writes its depth in the view,
// pushed away from the light by a few shadow-map texels (a polygon offset does not apply to
// gl_FragDepth), a miss discards.
#include "common/shell_scene.glsl"

in vec3 vWorldPosition;

uniform mat4 uViewProjection;
uniform mat4 uInverseViewProjection;
uniform float uDepthBias;   // world units: orthographic views in all, perspective at distance 1
uniform float uPerspective; // 1 for perspective views (spot, point), 0 for orthographic

void main() {
    vec4 clip = uViewProjection * vec4(vWorldPosition, 1.0);
    vec2 ndc = clip.xy / clip.w;
    vec4 near = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 far = uInverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 ro = near.xyz / near.w;
    vec3 rd = normalize(far.xyz / far.w - ro);
    float tEnter, tExit;
    if (!shellClipRange(ro, rd, tEnter, tExit)) discard;
    float t;
    int steps;
    if (!shellMarch(ro, rd, max(tEnter, 0.0), tExit, int(frame.march.x), frame.march.z,
                    frame.march.w, t, steps))
        discard;
    // The march stops within epsilon * t of the surface, which from a light far away is more
    // than a shadow-map texel: a few more (safe) sphere-tracing steps close the gap, so the
    // surface does not shadow itself.
    vec3 o = shellObjectPoint(ro);
    vec3 d = mat3(uWorldToObject) * rd;
    for (int i = 0; i < 8; ++i) t += shellObjectDistance(o + d * t);
    vec3 p = ro + rd * (t + uDepthBias * (uPerspective > 0.5 ? t : 1.0));
    vec4 hit = uViewProjection * vec4(p, 1.0);
    gl_FragDepth = clamp(hit.z / hit.w * 0.5 + 0.5, 0.0, 1.0);
}
