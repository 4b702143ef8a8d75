#version 450 core
// The viewer's ground grid on the plane y = 0 (engine/render/include/render/grid_pass.hpp):
// each pixel's ray meets the plane at view depth t (the ray's forward component is 1), the
// fragment takes that point's window depth, so the depth test against the frame keeps only
// the grid in front of everything else. Lines are antialiased by their width in pixels
// (fwidth of the plane coordinates) and fade out where they get denser than about a pixel.
#include "common/frame.glsl"

in vec3 vRayDirection;
layout(location = 0) out vec4 outColor;

// Coverage of lines at every integer of `coordinate` (in units of one line spacing), about
// one pixel wide, and how much of that survives where lines crowd closer than a few pixels.
float gridLines(vec2 coordinate, out float visibility) {
    vec2 width = fwidth(coordinate);
    vec2 distanceInPixels = abs(fract(coordinate - 0.5) - 0.5) / max(width, vec2(1e-6));
    visibility = 1.0 - smoothstep(0.15, 0.4, max(width.x, width.y));
    return 1.0 - min(min(distanceInPixels.x, distanceInPixels.y), 1.0);
}

void main() {
    // Everything that takes derivatives runs before anything is discarded.
    vec3 origin = frustumOrigin(gl_FragCoord.xy);
    vec3 direction = vRayDirection;
    float t = -origin.y / (abs(direction.y) > 1e-7 ? direction.y : 1e-7); // the plane's view depth
    t = clamp(t, -frame.cameraForward.w, 2.0 * frame.cameraForward.w);
    vec3 p = origin + t * direction;

    float minorVisibility, majorVisibility;
    float minor = gridLines(p.xz, minorVisibility) * minorVisibility;
    float major = gridLines(p.xz / 10.0, majorVisibility) * majorVisibility;
    vec2 axisWidth = max(fwidth(p.xz), vec2(1e-6));
    float xAxis = 1.0 - min(abs(p.z) / axisWidth.y, 1.0); // the line z = 0
    float zAxis = 1.0 - min(abs(p.x) / axisWidth.x, 1.0); // the line x = 0

    vec3 color = vec3(0.35);
    float alpha = max(0.25 * minor, 0.5 * major);
    color = mix(color, vec3(0.8, 0.12, 0.1), xAxis);
    alpha = max(alpha, 0.8 * xAxis);
    color = mix(color, vec3(0.1, 0.25, 0.85), zAxis);
    alpha = max(alpha, 0.8 * zAxis);
    if (t < frame.cameraPosition.w || t > frame.cameraForward.w || alpha <= 0.0) discard;
    outColor = vec4(color, alpha);
    // A little behind the plane, so a floor that lies on it (a mesh or an SDF plane) hides the
    // grid instead of fighting it for the depth test.
    gl_FragDepth = windowDepth(origin + t * 1.001 * direction);
}
