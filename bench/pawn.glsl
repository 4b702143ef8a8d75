// Hand-written SDF map of samples/scenes/pawn.json (the smooth-CSG chess pawn), written the way
// one would on Shadertoy: every shape of the pawn is a solid of revolution about the y axis, so
// the map reduces the point once to q = (distance from the axis, height) and evaluates 2D
// formulas at literal positions, combined in the scene's order. The distances are the scene's
// (same shapes, same operations, same order), so the march takes the same steps and only the cost
// of one evaluation is compared. It is the second yardstick for the generated code: `rmsc bench
// samples/scenes/pawn.json --sdf-map bench/pawn.glsl` times it next to the strategies.
// Formulas: Inigo Quilez, "Distance functions" (capped cylinder, torus, sphere, rounding,
// revolution), https://iquilezles.org/articles/distfunctions/, "2D distance functions"
// (polygon), https://iquilezles.org/articles/distfunctions2d/, and "Smooth minimum" (the
// polynomial one; smooth subtraction as -smin(b, -a)), https://iquilezles.org/articles/smin/.
// Materials: ivory is index 0, felt 1. Object ids as the compiler numbers the nodes in pre-order
// (65536 + n): felt pad 65538, foot 65539, foot ring 65540, groove 65541, body 65542, collar disc
// 65544, collar ring 65545, head 65547, neck 65548.

bool sdfSceneEmpty() { return false; }

// Quilez's capped cylinder in the (radius, height) half-plane, centred at height 0.
float handCappedCylinder(vec2 q, float radius, float halfHeight) {
    vec2 d = abs(q) - vec2(radius, halfHeight);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

// A torus in the xz plane is a circle of radius `minor` at (major, 0) in the half-plane.
float handTorus(vec2 q, float major, float minor) {
    return length(vec2(q.x - major, q.y)) - minor;
}

// The body's profile, revolved about the y axis: a closed polygon in the half-plane.
const vec2 kBodyProfile[6] = vec2[6](vec2(0.0, 0.15), vec2(0.23, 0.15), vec2(0.16, 0.3),
                                     vec2(0.11, 0.48), vec2(0.09, 0.62), vec2(0.0, 0.62));

// Signed distance to the body's profile: the nearest edge, negative inside by the even-odd
// crossing rule (W. R. Franklin, PNPOLY).
float handBody(vec2 q) {
    float nearest = 1e30;
    bool inside = false;
    for (int i = 0; i < 6; ++i) {
        vec2 a = kBodyProfile[i];
        vec2 b = kBodyProfile[(i + 5) % 6];
        vec2 edge = b - a;
        vec2 w = q - a;
        vec2 off = w - edge * clamp(dot(w, edge) / dot(edge, edge), 0.0, 1.0);
        nearest = min(nearest, dot(off, off));
        if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * edge.x / edge.y)
            inside = !inside;
    }
    return (inside ? -1.0 : 1.0) * sqrt(nearest);
}

// The shapes at their heights (the scene's positions), in the half-plane.
float handFeltPad(vec2 q) { return handCappedCylinder(q - vec2(0.0, 0.012), 0.33, 0.012); }
float handFoot(vec2 q) { return handCappedCylinder(q - vec2(0.0, 0.065), 0.32, 0.04) - 0.015; }
float handFootRing(vec2 q) { return handTorus(q - vec2(0.0, 0.14), 0.26, 0.06); }
float handGroove(vec2 q) { return handTorus(q - vec2(0.0, 0.1), 0.3, 0.025); }
float handCollarDisc(vec2 q) {
    return handCappedCylinder(q - vec2(0.0, 0.62), 0.17, 0.018) - 0.012;
}
float handCollarRing(vec2 q) { return handTorus(q - vec2(0.0, 0.585), 0.13, 0.028); }
float handHead(vec2 q) { return length(q - vec2(0.0, 0.8)) - 0.16; }
float handNeck(vec2 q) { return handCappedCylinder(q - vec2(0.0, 0.68), 0.07, 0.08); }

// Polynomial smooth minimum of a and b over |a - b| < k, and in h the share of a.
float handSmoothMin(float a, float b, float k, out float h) {
    h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return mix(b, a, h) - k * h * (1.0 - h);
}

// a with b cut away smoothly: -smin(b, -a).
float handSmoothSubtract(float a, float b, float k) {
    float h;
    return -handSmoothMin(b, -a, k, h);
}

float sdfDistance(vec3 p) {
    vec2 q = vec2(length(p.xz), p.y);
    float h;
    float base = handSmoothMin(handFeltPad(q), handFoot(q), 0.03, h);
    base = handSmoothMin(base, handFootRing(q), 0.03, h);
    base = handSmoothSubtract(base, handGroove(q), 0.03);
    float collar = min(handCollarDisc(q), handCollarRing(q));
    float head = handSmoothMin(handHead(q), handNeck(q), 0.03, h);
    float d = handSmoothMin(base, handBody(q), 0.04, h);
    d = handSmoothMin(d, collar, 0.04, h);
    return handSmoothMin(d, head, 0.04, h);
}

// One shape or blend of shapes at the hit: its distance, the dominant shape's id, material and
// height (for its local point), and the felt's share of the material (the rest is ivory).
struct HandPart {
    float d;
    uint id;
    uint material;
    float height;
    float felt;
};

HandPart handIvory(float d, uint id, float height) { return HandPart(d, id, 0u, height, 0.0); }

// The smooth union with the material blended by the same factor (the dominant side keeps its id).
HandPart handSmoothUnion(HandPart a, HandPart b, float k) {
    float h;
    float d = handSmoothMin(a.d, b.d, k, h);
    HandPart r = h >= 0.5 ? a : b;
    r.felt = mix(b.felt, a.felt, h);
    r.d = d;
    return r;
}

SdfSurface sdfSurface(vec3 p) {
    vec2 q = vec2(length(p.xz), p.y);
    HandPart base = handSmoothUnion(HandPart(handFeltPad(q), 65538u, 1u, 0.012, 1.0),
                                    handIvory(handFoot(q), 65539u, 0.065), 0.03);
    base = handSmoothUnion(base, handIvory(handFootRing(q), 65540u, 0.14), 0.03);
    base.d = handSmoothSubtract(base.d, handGroove(q), 0.03); // the cut keeps the base's material
    float disc = handCollarDisc(q);
    float ring = handCollarRing(q);
    HandPart collar =
        disc <= ring ? handIvory(disc, 65544u, 0.62) : handIvory(ring, 65545u, 0.585);
    HandPart head = handSmoothUnion(handIvory(handHead(q), 65547u, 0.8),
                                    handIvory(handNeck(q), 65548u, 0.68), 0.03);
    HandPart pawn = handSmoothUnion(base, handIvory(handBody(q), 65542u, 0.0), 0.04);
    pawn = handSmoothUnion(pawn, collar, 0.04);
    pawn = handSmoothUnion(pawn, head, 0.04);

    vec3 local = p - vec3(0.0, pawn.height, 0.0); // the dominant shape's local point
    SdfSurface s = sdfMaterialSurface(pawn.d, pawn.id, pawn.material, local);
    SdfSurface ivory = sdfMaterialSurface(pawn.d, pawn.id, 0u, p);
    SdfSurface felt = sdfMaterialSurface(pawn.d, pawn.id, 1u, p);
    s.baseColor = mix(ivory.baseColor, felt.baseColor, pawn.felt);
    s.metallic = mix(ivory.metallic, felt.metallic, pawn.felt);
    s.roughness = mix(ivory.roughness, felt.roughness, pawn.felt);
    s.emissive = mix(ivory.emissive, felt.emissive, pawn.felt);
    return s;
}
