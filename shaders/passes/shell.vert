#version 450 core
// Shell pass vertex shader: the proxy mesh (object space) into the camera's or a shadow view's
// clip space; the fragment shader builds its ray from the world position.
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;

uniform mat4 uObjectToWorld;
uniform mat4 uViewProjection; // the camera's, or the shadow view's

out vec3 vWorldPosition;

void main() {
    vec4 world = uObjectToWorld * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    gl_Position = uViewProjection * world;
}
