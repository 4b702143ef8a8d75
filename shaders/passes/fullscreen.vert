#version 450 core
// One triangle covering the screen; passes the world-space ray direction through the pixel,
// interpolated from the frustum-corner matrix (linear in screen space, so exact per pixel).
#include "common/frame.glsl"

out vec3 vRayDirection;
out vec2 vUv;

void main() {
    vec2 uv = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2); // (0,0) (2,0) (0,2)
    vUv = uv;
    vec3 bottom = mix(frame.frustumCorners[0].xyz, frame.frustumCorners[1].xyz, uv.x);
    vec3 top = mix(frame.frustumCorners[2].xyz, frame.frustumCorners[3].xyz, uv.x);
    vRayDirection = mix(bottom, top, uv.y);
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
