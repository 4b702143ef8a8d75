// Hand-written SDF map of samples/bench/grid_10.json, written the way one would on Shadertoy:
// every shape's formula inline at its literal position, one min() chain, no transforms where
// none are needed. It is the yardstick for the generated code: `rmsc bench
// samples/bench/grid_10.json --sdf-map bench/grid_10.glsl` times it next to the strategies.
// Formulas: Inigo Quilez, "Distance functions", https://iquilezles.org/articles/distfunctions/.
// Materials m0..m4 are indices 0..4; the shapes are the root's children 1..10 (object ids
// 65537..65546), as the compiler numbers them.

bool sdfSceneEmpty() { return false; }

float handBox(vec3 p, float b) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}
float handRoundBox(vec3 p) { return handBox(p, 0.40477 - 0.10119) - 0.10119; }
// The torus turned 90 degrees about x: its ring lies in the xy plane.
float handTorus(vec3 p) { return length(vec2(length(p.xy) - 0.37947, p.z)) - 0.15179; }
float handCapsule(vec3 p) {
    p.y -= clamp(p.y, -0.25298, 0.25298);
    return length(p) - 0.27828;
}

// The ten distances in file order: rows of four cells 1.26491 across (4 / sqrt(10)).
void handShapes(vec3 p, out float d[10]) {
    d[0] = length(p - vec3(-1.89737, 1.26491, 0.0)) - 0.53126;
    d[1] = handBox(p - vec3(-0.63246, 1.26491, 0.0), 0.43007);
    d[2] = handTorus(p - vec3(0.63246, 1.26491, 0.0));
    d[3] = handRoundBox(p - vec3(1.89737, 1.26491, 0.0));
    d[4] = handCapsule(p - vec3(-1.89737, 0.0, 0.0));
    d[5] = length(p - vec3(-0.63246, 0.0, 0.0)) - 0.53126;
    d[6] = handBox(p - vec3(0.63246, 0.0, 0.0), 0.43007);
    d[7] = handTorus(p - vec3(1.89737, 0.0, 0.0));
    d[8] = handRoundBox(p - vec3(-1.89737, -1.26491, 0.0));
    d[9] = handCapsule(p - vec3(-0.63246, -1.26491, 0.0));
}

float sdfDistance(vec3 p) {
    float d[10];
    handShapes(p, d);
    float m = d[0];
    for (int i = 1; i < 10; ++i) m = min(m, d[i]);
    return m;
}

SdfSurface sdfSurface(vec3 p) {
    float d[10];
    handShapes(p, d);
    int best = 0;
    for (int i = 1; i < 10; ++i)
        if (d[i] < d[best]) best = i;
    return sdfMaterialSurface(d[best], 65537u + uint(best), uint(best % 5), p);
}
