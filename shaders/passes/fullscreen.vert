#version 450 core
// One triangle covering the screen; passes the world-space ray direction through the pixel,
// interpolated from the frustum-corner matrix (linear in screen space, so exact per pixel).
#include "common/frame.glsl"

out vec3 vRayDirection;
out vec2 vUv;

void main() {
    vec2 uv = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2); // (0,0) (2,0) (0,2)
    vUv = uv;
    vRayDirection = frustumRay(uv * frame.viewport.xy);
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
