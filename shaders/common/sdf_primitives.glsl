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

// ---- The rest of Quilez's 3D primitives (C++: engine/sdf/primitive_formulas.cpp). Angles arrive
// in degrees. Guards against division by zero (max(.., 1e-12) and the like) match the C++.

float sdfDot2(vec2 v) { return dot(v, v); }
float sdfDot2(vec3 v) { return dot(v, v); }
float sdfNdot(vec2 a, vec2 b) { return a.x * b.x - a.y * b.y; }

float sdfBoxPart(vec3 q) { return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }

// The edges of a box (half size `halfExtents`) as square bars of half thickness e.
float sdBoxFrame(vec3 p, vec3 halfExtents, float e) {
    p = abs(p) - halfExtents;
    vec3 q = abs(p + e) - e;
    return min(min(sdfBoxPart(vec3(p.x, q.y, q.z)), sdfBoxPart(vec3(q.x, p.y, q.z))),
               sdfBoxPart(vec3(q.x, q.y, p.z)));
}

// An arc of a torus in the xy plane spanning `angleDeg` either side of +y.
float sdCappedTorus(vec3 p, float angleDeg, float ra, float rb) {
    float angle = radians(angleDeg);
    vec2 sc = vec2(sin(angle), cos(angle));
    p.x = abs(p.x);
    float k = sc.y * p.x > sc.x * p.y ? dot(p.xy, sc) : length(p.xy);
    return sqrt(max(dot(p, p) + ra * ra - 2.0 * ra * k, 0.0)) - rb;
}

// A chain link: straight sides of half length le along y, ends of radius r1, tube radius r2.
float sdLink(vec3 p, float le, float r1, float r2) {
    vec3 q = vec3(p.x, max(abs(p.y) - le, 0.0), p.z);
    return length(vec2(length(q.xy) - r1, q.z)) - r2;
}

float sdInfiniteCylinder(vec3 p, float radius) { return length(p.xz) - radius; }

// A cone along y: apex at y = h / 2, base at y = -h / 2, `angleDeg` between axis and side.
float sdCone(vec3 p, float angleDeg, float h) {
    float angle = radians(angleDeg);
    vec2 c = vec2(sin(angle), cos(angle));
    p.y -= 0.5 * h;
    vec2 q = h * vec2(c.x / c.y, -1.0);
    vec2 w = vec2(length(p.xz), p.y);
    vec2 pa = w - q * clamp(dot(w, q) / dot(q, q), 0.0, 1.0);
    vec2 pb = w - q * vec2(clamp(w.x / q.x, 0.0, 1.0), 1.0);
    float k = sign(q.y);
    float d = min(dot(pa, pa), dot(pb, pb));
    float s = max(k * (w.x * q.y - w.y * q.x), k * (w.y - q.y));
    return sqrt(d) * sign(s);
}

// An endless cone, apex at the origin, opening towards -y.
float sdInfiniteCone(vec3 p, float angleDeg) {
    float angle = radians(angleDeg);
    vec2 c = vec2(sin(angle), cos(angle));
    vec2 q = vec2(length(p.xz), -p.y);
    float d = length(q - c * max(dot(q, c), 0.0));
    return d * (q.x * c.y - q.y * c.x < 0.0 ? -1.0 : 1.0);
}

// A hexagonal prism along z: `radius` from the axis to each side, half length along z.
float sdHexPrism(vec3 p, float radius, float halfLength) {
    const vec3 k = vec3(-0.8660254, 0.5, 0.57735);
    vec2 h = vec2(radius, halfLength);
    p = abs(p);
    vec2 pxy = p.xy;
    pxy -= 2.0 * min(dot(k.xy, pxy), 0.0) * k.xy;
    vec2 d = vec2(length(pxy - vec2(clamp(pxy.x, -k.z * h.x, k.z * h.x), h.x)) * sign(pxy.y - h.x),
                  p.z - h.y);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}

// A triangular prism along z (a bound): `radius` from the axis to each side.
float sdTriPrism(vec3 p, float radius, float halfLength) {
    vec3 q = abs(p);
    return max(q.z - halfLength, max(q.x * 0.866025 + p.y * 0.5, -p.y) - radius);
}

// The segment from a to b swept by a sphere of radius r.
float sdCapsuleBetween(vec3 p, vec3 a, vec3 b, float r) {
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-12), 0.0, 1.0);
    return length(pa - ba * h) - r;
}

// A cylinder of radius r from a to b with flat caps.
float sdCappedCylinderBetween(vec3 p, vec3 a, vec3 b, float r) {
    vec3 ba = b - a;
    vec3 pa = p - a;
    float baba = max(dot(ba, ba), 1e-12);
    float paba = dot(pa, ba);
    float x = length(pa * baba - ba * paba) - r * baba;
    float y = abs(paba - baba * 0.5) - baba * 0.5;
    float x2 = x * x;
    float y2 = y * y * baba;
    float d = max(x, y) < 0.0 ? -min(x2, y2) : (x > 0.0 ? x2 : 0.0) + (y > 0.0 ? y2 : 0.0);
    return sign(d) * sqrt(abs(d)) / baba;
}

// A cylinder along y of outer radius and half height, rims rounded by edgeRadius.
float sdRoundedCylinder(vec3 p, float radius, float edgeRadius, float halfHeight) {
    float e = min(edgeRadius, min(radius, halfHeight));
    vec2 d = vec2(length(p.xz) - radius + e, abs(p.y) - halfHeight + e);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0)) - e;
}

// A cone along y cut at y = -h (radius r1) and y = +h (radius r2).
float sdCappedCone(vec3 p, float h, float r1, float r2) {
    vec2 q = vec2(length(p.xz), p.y);
    vec2 k1 = vec2(r2, h);
    vec2 k2 = vec2(r2 - r1, 2.0 * h);
    vec2 ca = vec2(q.x - min(q.x, q.y < 0.0 ? r1 : r2), abs(q.y) - h);
    vec2 cb = q - k1 + k2 * clamp(dot(k1 - q, k2) / sdfDot2(k2), 0.0, 1.0);
    float s = cb.x < 0.0 && ca.y < 0.0 ? -1.0 : 1.0;
    return s * sqrt(min(sdfDot2(ca), sdfDot2(cb)));
}

// A capped cone from a (radius ra) to b (radius rb).
float sdCappedConeBetween(vec3 p, vec3 a, vec3 b, float ra, float rb) {
    float rba = rb - ra;
    float baba = max(sdfDot2(b - a), 1e-12);
    float papa = sdfDot2(p - a);
    float paba = dot(p - a, b - a) / baba;
    float x = sqrt(max(papa - paba * paba * baba, 0.0));
    float cax = max(0.0, x - (paba < 0.5 ? ra : rb));
    float cay = abs(paba - 0.5) - 0.5;
    float k = rba * rba + baba;
    float f = clamp((rba * (x - ra) + paba * baba) / k, 0.0, 1.0);
    float cbx = x - ra - f * rba;
    float cby = paba - f;
    float s = cbx < 0.0 && cay < 0.0 ? -1.0 : 1.0;
    return s * sqrt(min(cax * cax + cay * cay * baba, cbx * cbx + cby * cby * baba));
}

// The part of a sphere of radius ra within `angleDeg` of +y (apex at the origin).
float sdSolidAngle(vec3 p, float angleDeg, float ra) {
    float angle = radians(angleDeg);
    vec2 c = vec2(sin(angle), cos(angle));
    vec2 q = vec2(length(p.xz), p.y);
    float l = length(q) - ra;
    float m = length(q - c * clamp(dot(q, c), 0.0, ra));
    return max(l, m * sign(c.y * q.x - c.x * q.y));
}

// The part of a sphere above the plane y = cutHeight.
float sdCutSphere(vec3 p, float r, float cutHeight) {
    float h = clamp(cutHeight, -r, r);
    float w = sqrt(max(r * r - h * h, 0.0));
    vec2 q = vec2(length(p.xz), p.y);
    float s = max((h - r) * q.x * q.x + w * w * (h + r - 2.0 * q.y), h * q.x - w * q.y);
    return s < 0.0 ? length(q) - r : (q.x < w ? h - q.y : length(q - vec2(w, h)));
}

// A spherical shell (half thickness t) below the plane y = cutHeight.
float sdCutHollowSphere(vec3 p, float r, float cutHeight, float t) {
    float h = clamp(cutHeight, -r, r);
    float w = sqrt(max(r * r - h * h, 0.0));
    vec2 q = vec2(length(p.xz), p.y);
    return (h * q.x < w * q.y ? length(q - vec2(w, h)) : abs(length(q) - r)) - t;
}

// A sphere of radius ra minus a sphere of radius rb centred at (d, 0, 0).
float sdDeathStar(vec3 p, float ra, float rb, float d) {
    float ca = (ra * ra - rb * rb + d * d) / (2.0 * d);
    float cb = sqrt(max(ra * ra - ca * ca, 0.0));
    vec2 q = vec2(p.x, length(p.yz));
    if (q.x * cb - q.y * ca > d * max(cb - q.y, 0.0)) return length(q - vec2(ca, cb));
    return max(length(q) - ra, -(length(q - vec2(d, 0.0)) - rb));
}

// Spheres of radius r1 at y = -h / 2 and r2 at y = +h / 2 and the cone tangent to both.
float sdRoundCone(vec3 p, float r1, float r2, float h) {
    p.y += 0.5 * h;
    float b = (r1 - r2) / h;
    float c = sqrt(max(1.0 - b * b, 0.0));
    vec2 q = vec2(length(p.xz), p.y);
    float k = dot(q, vec2(-b, c));
    if (k < 0.0) return length(q) - r1;
    if (k > c * h) return length(q - vec2(0.0, h)) - r2;
    return dot(q, vec2(c, b)) - r1;
}

// Spheres of radius r1 at a and r2 at b and the cone tangent to both.
float sdRoundConeBetween(vec3 p, vec3 a, vec3 b, float r1, float r2) {
    vec3 ba = b - a;
    float l2 = max(dot(ba, ba), 1e-12);
    float rr = r1 - r2;
    float a2 = l2 - rr * rr;
    float il2 = 1.0 / l2;
    vec3 pa = p - a;
    float y = dot(pa, ba);
    float z = y - l2;
    float x2 = sdfDot2(pa * l2 - ba * y);
    float y2 = y * y * l2;
    float z2 = z * z * l2;
    float k = sign(rr) * rr * rr * x2;
    if (sign(z) * a2 * z2 > k) return sqrt(x2 + z2) * il2 - r2;
    if (sign(y) * a2 * y2 < k) return sqrt(x2 + y2) * il2 - r1;
    return (sqrt(max(x2 * a2 * il2, 0.0)) + y * rr) * il2 - r1;
}

// A vesica (two circular arcs meeting at tips a and b, widest radius `width`) revolved about ab.
float sdRevolvedVesica(vec3 p, vec3 a, vec3 b, float width) {
    vec3 c = (a + b) * 0.5;
    float l = max(length(b - a), 1e-6);
    vec3 v = (b - a) / l;
    float y = dot(p - c, v);
    vec2 q = vec2(length(p - c - y * v), abs(y));
    float r = 0.5 * l;
    float w = min(width, r);
    float d = 0.5 * (r * r - w * w) / w;
    if (r * q.x < d * (q.y - r)) return length(q - vec2(0.0, r));
    // length(q + (d, 0)) - (d + w) as a difference of squares over their roots' sum: d grows
    // as 1 / w, and the plain difference of two numbers near d keeps none of the distance's
    // digits for a thin or a far vesica.
    return (dot(q, q) + 2.0 * d * (q.x - w) - w * w) / (length(q + vec2(d, 0.0)) + d + w);
}

// A rhombus in the xz plane (half diagonals la, lb), half thickness h, sides rounded by ra.
float sdRhombus(vec3 p, float la, float lb, float h, float ra) {
    p = abs(p);
    vec2 b = vec2(la, lb);
    float f = clamp(sdfNdot(b, b - 2.0 * p.xz) / dot(b, b), -1.0, 1.0);
    vec2 q = vec2(length(p.xz - 0.5 * b * vec2(1.0 - f, 1.0 + f)) *
                      sign(p.x * b.y + p.z * b.x - b.x * b.y) - ra,
                  p.y - h);
    return min(max(q.x, q.y), 0.0) + length(max(q, 0.0));
}

// A regular octahedron with vertices at distance s on the axes.
float sdOctahedron(vec3 p, float s) {
    p = abs(p);
    float m = p.x + p.y + p.z - s;
    vec3 q;
    if (3.0 * p.x < m)
        q = p;
    else if (3.0 * p.y < m)
        q = p.yzx;
    else if (3.0 * p.z < m)
        q = p.zxy;
    else
        return m * 0.57735027;
    float k = clamp(0.5 * (q.z - q.y + s), 0.0, s);
    return length(vec3(q.x, q.y - s + k, q.z - k));
}

// A square pyramid: base side `base` at y = -height / 2, apex at y = +height / 2.
float sdPyramid(vec3 p, float base, float height) {
    p.y += 0.5 * height;
    p /= base;
    float h = height / base;
    float m2 = h * h + 0.25;
    vec2 xz = abs(p.xz);
    if (xz.y > xz.x) xz = xz.yx;
    xz -= 0.5;
    vec3 q = vec3(xz.y, h * p.y - 0.5 * xz.x, h * xz.x + 0.5 * p.y);
    float s = max(-q.x, 0.0);
    float t = clamp((q.y - 0.5 * xz.y) / (m2 + 0.25), 0.0, 1.0);
    float da = m2 * (q.x + s) * (q.x + s) + q.y * q.y;
    float db = m2 * (q.x + 0.5 * t) * (q.x + 0.5 * t) + (q.y - m2 * t) * (q.y - m2 * t);
    float d2 = min(q.y, -q.x * m2 - q.y * 0.5) > 0.0 ? 0.0 : min(da, db);
    float d = sqrt((d2 + q.z * q.z) / m2) * sign(max(q.z, -p.y));
    // Below the base plane: the distance to the base square; inside: the base is one more
    // half-space (Quilez's formula measures the slanted faces only).
    if (p.y < 0.0) return base * length(vec3(max(abs(p.x) - 0.5, 0.0), p.y, max(abs(p.z) - 0.5, 0.0)));
    return base * (d < 0.0 ? max(d, -p.y) : d);
}

// The triangle a, b, c thickened by t (t = 0: the unsigned distance to the triangle).
float sdTriangle(vec3 p, vec3 a, vec3 b, vec3 c, float t) {
    vec3 ba = b - a, pa = p - a;
    vec3 cb = c - b, pb = p - b;
    vec3 ac = a - c, pc = p - c;
    vec3 nor = cross(ba, ac);
    bool outsideAnEdge = sign(dot(cross(ba, nor), pa)) + sign(dot(cross(cb, nor), pb)) +
                             sign(dot(cross(ac, nor), pc)) <
                         2.0;
    float d2 = outsideAnEdge
                   ? min(min(sdfDot2(ba * clamp(dot(ba, pa) / sdfDot2(ba), 0.0, 1.0) - pa),
                             sdfDot2(cb * clamp(dot(cb, pb) / sdfDot2(cb), 0.0, 1.0) - pb)),
                         sdfDot2(ac * clamp(dot(ac, pc) / sdfDot2(ac), 0.0, 1.0) - pc))
                   : dot(nor, pa) * dot(nor, pa) / sdfDot2(nor);
    return sqrt(d2) - t;
}

// The unsigned distance to the planar quadrilateral a, b, c, d.
float sdQuad(vec3 p, vec3 a, vec3 b, vec3 c, vec3 d) {
    vec3 ba = b - a, pa = p - a;
    vec3 cb = c - b, pb = p - b;
    vec3 dc = d - c, pc = p - c;
    vec3 ad = a - d, pd = p - d;
    vec3 nor = cross(ba, ad);
    bool outsideAnEdge = sign(dot(cross(ba, nor), pa)) + sign(dot(cross(cb, nor), pb)) +
                             sign(dot(cross(dc, nor), pc)) + sign(dot(cross(ad, nor), pd)) <
                         3.0;
    float d2 = outsideAnEdge
                   ? min(min(sdfDot2(ba * clamp(dot(ba, pa) / sdfDot2(ba), 0.0, 1.0) - pa),
                             sdfDot2(cb * clamp(dot(cb, pb) / sdfDot2(cb), 0.0, 1.0) - pb)),
                         min(sdfDot2(dc * clamp(dot(dc, pc) / sdfDot2(dc), 0.0, 1.0) - pc),
                             sdfDot2(ad * clamp(dot(ad, pd) / sdfDot2(ad), 0.0, 1.0) - pd)))
                   : dot(nor, pa) * dot(nor, pa) / sdfDot2(nor);
    return sqrt(d2);
}

// A gyroid sheet, a bound (C++, source and Lipschitz proof: sdGyroid in engine/sdf/primitives.cpp).
float sdGyroid(vec3 p, float period, float thickness) {
    float s = 6.28318531 / period;
    vec3 q = p * s;
    float g = sin(q.x) * cos(q.y) + sin(q.y) * cos(q.z) + sin(q.z) * cos(q.x);
    return abs(g) / (1.73205081 * s) - thickness;
}

// ---- Fractals (C++ and sources: engine/sdf/fractal_formulas.cpp). Each returns the distance to
// its bounding sphere when p is well outside it. Iteration counts arrive as floats, floored.

float sdfOutsideBound(vec3 p, float radius, float margin) {
    float r = length(p);
    return r > radius + margin ? r - radius : -1.0;
}

// Mandelbulb z -> z^n + p (triplex power, y the polar axis); 0.5 |z| log|z| / |z'|.
float sdMandelbulb(vec3 p, float n, float iterationsF, float bailout) {
    int iterations = int(floor(iterationsF));
    float bound = pow(2.0, 1.0 / (n - 1.0));
    float outside = sdfOutsideBound(p, bound, 0.1);
    if (outside >= 0.0) return outside;
    vec3 z = p;
    float dr = 1.0;
    float r = max(length(z), 1e-10);
    for (int i = 0; i < iterations; ++i) {
        if (r > bailout) break;
        float theta = acos(clamp(z.y / r, -1.0, 1.0)) * n;
        float phi = atan(z.x, z.z) * n;
        dr = pow(r, n - 1.0) * n * dr + 1.0;
        float zr = pow(r, n);
        z = zr * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi)) + p;
        r = max(length(z), 1e-10);
    }
    return 0.5 * log(r) * r / dr;
}

// Menger sponge of half edge `size` (Quilez, "Menger fractal").
float sdMengerSponge(vec3 p, float iterationsF, float size) {
    int iterations = int(floor(iterationsF));
    float outside = sdfOutsideBound(p, size * 1.7320508, 0.1 * size);
    if (outside >= 0.0) return outside;
    p /= size;
    vec3 b = abs(p) - 1.0;
    float d = length(max(b, 0.0)) + min(max(b.x, max(b.y, b.z)), 0.0);
    float s = 1.0;
    for (int m = 0; m < iterations; ++m) {
        vec3 ps = p * s;
        vec3 cell = ps - 2.0 * floor(ps / 2.0) - 1.0;
        s *= 3.0;
        vec3 r = abs(1.0 - 3.0 * abs(cell));
        float da = max(r.x, r.y);
        float db = max(r.y, r.z);
        float dc = max(r.z, r.x);
        float c = (min(da, min(db, dc)) - 1.0) / s;
        d = max(d, c);
    }
    return d * size;
}

// Sierpinski tetrahedron by folding space (Christensen, "Distance Estimated 3D Fractals").
float sdSierpinskiTetrahedron(vec3 p, float iterationsF, float size) {
    int iterations = int(floor(iterationsF));
    float outside = sdfOutsideBound(p, size * 1.7320508, 0.1 * size);
    if (outside >= 0.0) return outside;
    vec3 z = p / size;
    for (int i = 0; i < iterations; ++i) {
        if (z.x + z.y < 0.0) z = vec3(-z.y, -z.x, z.z);
        if (z.x + z.z < 0.0) z = vec3(-z.z, z.y, -z.x);
        if (z.y + z.z < 0.0) z = vec3(z.x, -z.z, -z.y);
        z = z * 2.0 - 1.0;
    }
    float planes = max(max(-z.x - z.y - z.z, z.x + z.y - z.z), max(-z.x + z.y + z.z, z.x - z.y + z.z));
    return (planes - 1.0) * 0.57735027 * exp2(-float(iterations)) * size;
}

// Quaternion Julia set z -> z^2 + c, slice (x, y, z, 0) (Hart, Sandin and Kauffman 1989).
float sdQuaternionJulia(vec3 p, float cr, float ci, float cj, float ck, float iterationsF) {
    vec4 c = vec4(cr, ci, cj, ck);
    int iterations = int(floor(iterationsF));
    float bound = 0.5 * (1.0 + sqrt(1.0 + 4.0 * length(c)));
    float outside = sdfOutsideBound(p, bound, 0.1);
    if (outside >= 0.0) return outside;
    vec4 z = vec4(p, 0.0);
    float dz = 1.0;
    float m2 = dot(z, z);
    for (int i = 0; i < iterations; ++i) {
        if (m2 > 256.0) break;
        dz = 2.0 * sqrt(m2) * dz;
        z = vec4(z.x * z.x - dot(z.yzw, z.yzw), 2.0 * z.x * z.yzw) + c;
        m2 = dot(z, z);
    }
    float m = max(sqrt(m2), 1e-10);
    return 0.5 * m * log(m) / max(dz, 1e-10);
}
