// Distance functions of the SDF primitives, one per row of the primitive catalogue
// (engine/sdf/primitives.cpp), named as the row's glslFunction, parameters in catalogue order.
// The math is identical to the C++ functions there. Formulas: Inigo Quilez, "Distance functions",
// https://iquilezles.org/articles/distfunctions/ (ellipsoid: the bound k0 * (k0 - 1) / k1).

float sdSphere(vec3 p, float radius) { return length(p) - radius; }

float sdBox(vec3 p, vec3 halfExtents) {
    vec3 q = abs(p) - halfExtents;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

// `r` rounds the edges, taken from inside the box.
float sdRoundBox(vec3 p, vec3 halfExtents, float r) {
    vec3 q = abs(p) - halfExtents + r;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

// A ring of radius `major` in the xz plane, tube radius `minor`.
float sdTorus(vec3 p, float major, float minor) {
    vec2 q = vec2(length(p.xz) - major, p.y);
    return length(q) - minor;
}

// A cylinder along y with flat caps at y = +-halfHeight.
float sdCappedCylinder(vec3 p, float radius, float halfHeight) {
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(radius, halfHeight);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

// The half-space below the plane dot(p, normalize(normal)) = offset.
float sdPlane(vec3 p, vec3 normal, float offset) {
    return dot(p, normal) / max(length(normal), 1e-6) - offset;
}

// The segment from (0, -halfHeight, 0) to (0, halfHeight, 0) swept by a sphere.
float sdVerticalCapsule(vec3 p, float halfHeight, float radius) {
    p.y -= clamp(p.y, -halfHeight, halfHeight);
    return length(p) - radius;
}

// A lower bound of the distance to an ellipsoid with semi-axes `radii`.
float sdEllipsoid(vec3 p, vec3 radii) {
    float k0 = length(p / radii);
    float k1 = length(p / (radii * radii));
    return k1 > 0.0 ? k0 * (k0 - 1.0) / k1 : -min(radii.x, min(radii.y, radii.z));
}
