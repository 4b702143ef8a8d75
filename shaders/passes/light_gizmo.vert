#version 450 core
// The viewer's light gizmos (engine/render/include/render/light_gizmo_pass.hpp): each vertex is
// a world point moved on screen by a fixed number of pixels, so markers keep their size at any
// distance.
layout(location = 0) in vec3 inAnchor;
layout(location = 1) in vec2 inOffsetPixels;
layout(location = 2) in vec3 inColor;

uniform mat4 uViewProjection;
uniform vec2 uViewportSize; // pixels

out vec3 vColor;

void main() {
    vec4 clip = uViewProjection * vec4(inAnchor, 1.0);
    // Pixels to normalized device units (2 / size), times w to stay fixed after the divide.
    clip.xy += inOffsetPixels * 2.0 / uViewportSize * clip.w;
    gl_Position = clip;
    vColor = inColor;
}
