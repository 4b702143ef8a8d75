// Per-frame camera and settings (std140, binding 0). Mirrors GpuFrame in engine/render/frame.hpp.
layout(std140, binding = 0) uniform FrameBlock {
    mat4 view;
    mat4 viewProjection;
    mat4 frustumCorners; // world directions to the BL, BR, TL, TR corners, forward component 1
    vec4 cameraPosition; // xyz, w = near plane
    vec4 cameraForward;  // xyz, w = far plane
    vec4 background;     // rgb = background, a = exposure
    vec4 ambient;        // rgb = ambient light
    vec4 march;          // x = max steps, y = max distance, z = surface epsilon
    vec4 viewport;       // x = width, y = height
} frame;

// Window-space depth [0, 1] of a world position, as the rasterizer would write it.
float windowDepth(vec3 worldPosition) {
    vec4 clip = frame.viewProjection * vec4(worldPosition, 1.0);
    return clip.z / clip.w * 0.5 + 0.5;
}
