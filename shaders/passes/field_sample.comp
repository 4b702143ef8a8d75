#version 450 core
// The SDF's distance on lattices of points (render/gpu_field_sampler.hpp): invocation i of a
// dispatch computes point base + i: lattice start (base + i) / side^3, point (x, y, z) of it
// from the rest, x fastest.
#include "common/sdf_scene.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = FIELD_SAMPLE_START_BINDING) readonly buffer LatticeStarts {
    ivec4 starts[];
};
layout(std430, binding = FIELD_SAMPLE_DISTANCE_BINDING) writeonly buffer LatticeDistances {
    float distances[];
};

uniform vec4 lattice; // xyz = origin, w = spacing
uniform uvec4 info;   // x = points a side, y = points in all, z = the dispatch's first point

void main() {
    uint i = info.z + gl_GlobalInvocationID.x;
    if (i >= info.y) return;
    uint side = info.x;
    uint perStart = side * side * side;
    uint rest = i % perStart;
    ivec3 local = ivec3(rest % side, (rest / side) % side, rest / (side * side));
    vec3 p = lattice.xyz + lattice.w * vec3(starts[i / perStart].xyz + local);
    distances[i] = sdfDistance(p);
}
