// Per-frame camera and settings (std140, binding FRAME_BINDING). Mirrors GpuFrame in
// engine/render/include/render/frame.hpp.
#include "generated/constants.glsl"

layout(std140, binding = FRAME_BINDING) uniform FrameBlock {
    mat4 view;
    mat4 viewProjection;
    mat4 frustumCorners; // world directions to the BL, BR, TL, TR corners, forward component 1
    vec4 cameraPosition; // xyz, w = near plane
    vec4 cameraForward;  // xyz, w = far plane
    vec4 background;     // rgb = background, a = exposure
    vec4 ambient;        // rgb = ambient light
    vec4 march;          // x = max steps, y = max distance, z = surface epsilon,
                         // w = over-relaxation of the march steps
    vec4 viewport;       // x = width, y = height, z = the instruction of the SDF part nearest
                         // the camera (common/sdf_parts_loop.glsl; 2^32 when none), w = 1 when
                         // clip-space depth runs from 0 to 1 (glClipControl), 0 for -1 to 1
    vec4 sky;            // x = sky type (0 none, 1 constant, 2 gradient, 3 image), y = intensity,
                         // z = image sky's highest mip level, w = image rotation (radians)
    vec4 skyZenith;      // rgb = constant sky colour, or the gradient's zenith
    vec4 skyHorizon;     // rgb = gradient horizon
    vec4 skyGround;      // rgb = gradient ground
    vec4 fog;            // rgb = fog colour, a = density per world unit (0 = none)
    vec4 shadow;         // x = SDF shadow steps (0 = off), y = min distance, z = max distance
    vec4 shadowMap;      // x = map size (texels), y = PCF radius, z = normal offset (texels)
    vec4 ao;             // x = AO samples (0 = off), y = farthest sample, z = strength, w = FXAA
    vec4 orthoRight;     // orthographic: xyz = the camera's right axis, half the view's width long
    vec4 orthoUp;        // orthographic: xyz = its up axis, half the view's height long; w = 1
                         // for an orthographic camera, 0 for a perspective one
} frame;

// Whether the camera is orthographic: parallel rays (the frustum corners are all `forward`),
// each starting at its own point of the camera's plane.
bool cameraIsOrthographic() {
    return frame.orthoUp.w > 0.5;
}

// Where the ray through a window position (pixels) starts: the eye for a perspective camera,
// the point of the camera's plane under it for an orthographic one.
vec3 frustumOrigin(vec2 windowPosition) {
    if (!cameraIsOrthographic()) return frame.cameraPosition.xyz;
    vec2 s = windowPosition / frame.viewport.xy * 2.0 - 1.0;
    return frame.cameraPosition.xyz + s.x * frame.orthoRight.xyz + s.y * frame.orthoUp.xyz;
}

// The unit direction from a world point toward the viewer, and the distance a ray travelled to
// reach it (from the eye, or from the camera's plane when orthographic).
vec3 toViewer(vec3 worldPosition) {
    if (cameraIsOrthographic()) return -frame.cameraForward.xyz;
    return normalize(frame.cameraPosition.xyz - worldPosition);
}
float viewerDistance(vec3 worldPosition) {
    if (cameraIsOrthographic())
        return dot(worldPosition - frame.cameraPosition.xyz, frame.cameraForward.xyz);
    return distance(frame.cameraPosition.xyz, worldPosition);
}

// World direction (unnormalized, forward component 1) through a window position in pixels,
// from the frustum-corner matrix: bilinear over the image, so exact anywhere on it.
vec3 frustumRay(vec2 windowPosition) {
    vec2 uv = windowPosition / frame.viewport.xy;
    vec3 bottom = mix(frame.frustumCorners[0].xyz, frame.frustumCorners[1].xyz, uv.x);
    vec3 top = mix(frame.frustumCorners[2].xyz, frame.frustumCorners[3].xyz, uv.x);
    return mix(bottom, top, uv.y);
}

// Window-space depth [0, 1] of a world position, as the rasterizer would write it with
// glDepthRange(0, 1): z/w mapped from [-1, 1] (OpenGL's default clip space), or z/w itself
// under glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) (OpenGL 4.5 spec, section 13.8).
float windowDepth(vec3 worldPosition) {
    vec4 clip = frame.viewProjection * vec4(worldPosition, 1.0);
    float ndcZ = clip.z / clip.w;
    return frame.viewport.w > 0.5 ? ndcZ : ndcZ * 0.5 + 0.5;
}

// A zero the shader compiler cannot see through (the frame's step budget is at least 1). Loops
// that start at SDF_ZERO are neither unrolled nor is their body inlined once per iteration, so
// the scene's map is compiled once per loop instead of once per tap: the "ZERO" idiom from
// Inigo Quilez's Shadertoy work, see "Normals for an SDF",
// https://iquilezles.org/articles/normalsSDF/ (section "Non-inlining the normal").
#define SDF_ZERO min(int(frame.march.x), 0)
