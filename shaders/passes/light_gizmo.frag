#version 450 core
// The viewer's light gizmos: flat colour (engine/render/include/render/light_gizmo_pass.hpp).
in vec3 vColor;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(vColor, 1.0);
}
