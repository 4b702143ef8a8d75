// The CPU and GPU copies of the SDF maths agree formula by formula: every catalogue primitive
// (the fractals too), every SDF operation (with its material weight), every point and distance
// modifier and every 2D profile solid is evaluated at a few thousand seeded random inputs by a
// compute shader that calls the renderer's own GLSL functions (shaders/common/sdf_functions.glsl,
// sdf_primitives.glsl and the generated catalogue dispatch), and by the C++ functions the CPU
// evaluator uses (sdf/primitives.hpp, sdf/sdf_functions.hpp). A formula changed on one side only
// fails here, naming the formula and the inputs.
#include "gpu_test_support.hpp"

#include "gl/program.hpp"
#include "render/gpu_layout.hpp"
#include "render/shader_library.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"
#include "sdf/sdf_functions.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace rmsc;
using namespace rmsc::test;

namespace {

// Cases per formula (per primitive, per operation and blend curve, per modifier, per profile
// and solid).
constexpr int kCasesPerFormula = 2048;

// Agreement: |gpu - cpu| <= kTolerance * max(|cpu|, scale), per component. `scale` is the
// largest magnitude among the case's length inputs (the point's coordinates, the parameters
// that are lengths), so the tolerance is relative in the formula's own units: a distance near
// zero of a shape 1000 units across is as exact as float arithmetic on 1000s allows, and a
// small shape is held as tightly as a large one. Material weights (in [0, 1]) use scale 1.
// Measured on llvmpipe (LLVM 15): every formula but the Mandelbulb agrees within 4e-6 at these
// cases (most within a few float ulps, many exactly), and within 3.3e-5 at 65536 cases each.
constexpr float kTolerance = 1e-4f;

// How close the GLSL must come for one test's formulas: every case within `relative` (as
// kTolerance explains), but for at most `outlierShare` of a formula's cases, which may reach
// `outlierRelative`.
struct Tolerance {
    float relative = kTolerance;
    double outlierShare = 0.0;
    float outlierRelative = kTolerance;
};

// The Mandelbulb iterates acos and atan, which llvmpipe computes less exactly than the C++
// library: measured against double precision, 2.3e-4 and 2e-5 relative (glibc's: 1.2e-7; sin,
// cos, pow, sqrt and exp2 are within a few ulps on both), and each iteration multiplies the
// angles by the power. Inside the set the estimate is sensitive to that: in double precision,
// acos and atan perturbed by up to those errors spread the result of each case that differs
// over a range that holds the GLSL result, while the C++ float result mostly stays within 1e-5
// of double precision. So the difference is the GPU's acos and atan, not a different formula.
// Measured: of these 2048 cases 12 (0.6%) differ by more than 1e-4, the worst by 2.1e-3; of
// 65536 cases, 0.35%, the worst by 1.8e-2.
constexpr Tolerance kMandelbulbTolerance{kTolerance, 0.02, 5e-2f};

// Which GLSL function a case calls (FORMULA_* in the probe).
enum Family : std::uint32_t { kPrimitive, kCombine, kPointModifier, kDistanceModifier, kProfile };

// One probe input; mirrors struct FormulaCase of the probe (std430, 80 bytes).
struct FormulaCase {
    glm::uvec4 formula{0u}; // x = Family, y = kind (PrimitiveId, SdfOp, the modifier or profile)
    glm::vec4 point{0.0f};  // xyz = the point; combine: x = a, y = b; distance modifier: w = d
    glm::vec4 params[3]{};  // as the program's instructions pack them (sdf/program.hpp)
};
static_assert(sizeof(FormulaCase) == 80);

// What the C++ side computed for a case, and the scale of its tolerance per component.
struct Expectation {
    int formula = 0; // index into CaseSet::formulas
    int components = 1;
    glm::vec4 value{0.0f};
    glm::vec4 scale{1.0f};
};

struct CaseSet {
    std::vector<std::string> formulas; // names, for messages
    std::vector<FormulaCase> cases;
    std::vector<Expectation> expected;
    std::vector<glm::vec4> data; // polygon points (the SDF data buffer)
};

bool isFractal(PrimitiveId id) {
    return id >= PrimitiveId::Mandelbulb;
}

// Seeded draws. std::mt19937 with a fixed seed per family: the same cases on every run.
struct Draw {
    std::mt19937 rng;

    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
    // lo * (hi / lo)^u: every order of magnitude between lo and hi equally often.
    float logUniform(float lo, float hi) {
        return lo * std::pow(hi / lo, std::uniform_real_distribution<float>(0.0f, 1.0f)(rng));
    }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    bool chance(double p) { return std::bernoulli_distribution(p)(rng); }
    glm::vec3 inCube(float halfSide) {
        return glm::vec3(uniform(-halfSide, halfSide), uniform(-halfSide, halfSide),
                         uniform(-halfSide, halfSide));
    }
    // A unit vector, every direction equally likely.
    glm::vec3 onSphere() {
        for (;;) {
            const glm::vec3 v = inCube(1.0f);
            const float length = glm::length(v);
            if (length > 0.1f && length <= 1.0f) return v / length;
        }
    }
};

float largestMagnitude(glm::vec3 v) {
    return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
}

int addFormula(CaseSet& set, std::string name) {
    set.formulas.push_back(std::move(name));
    return int(set.formulas.size()) - 1;
}

void addCase(CaseSet& set, const FormulaCase& c, const Expectation& e) {
    set.cases.push_back(c);
    set.expected.push_back(e);
}

// The catalogue rows `include` accepts, their parameters drawn over their whole [minValue,
// maxValue] range. A parameter whose range reaches 1000 or more is a length: those of one case
// share a size s drawn from 0.01 to 10000 (evenly per decade) and are drawn within [-s, s] of
// their range, so the shape has one size, and the points (in a cube 1.5 times the largest
// length) lie in, on and around it. The other parameters (angles, the fractals' powers,
// iteration counts and constants) span their whole ranges.
CaseSet primitiveCases(const std::function<bool(PrimitiveId)>& include, std::uint32_t seed) {
    CaseSet set;
    Draw draw{std::mt19937(seed)};
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        if (!include(spec.id)) continue;
        const bool fractal = isFractal(spec.id);
        const int formula = addFormula(set, "primitive " + std::string(spec.name));
        for (int n = 0; n < kCasesPerFormula; ++n) {
            const float s = draw.logUniform(0.01f, 1.0e4f);
            PrimitiveParams params{};
            float lengths = 0.0f; // largest length parameter
            for (std::size_t i = 0; i < spec.params.size(); ++i) {
                const ParamSpec& param = spec.params[i];
                const bool length = param.maxValue >= 1000.0f;
                const float lo = length ? std::max(param.minValue, -s) : param.minValue;
                const float hi = length ? std::min(param.maxValue, s) : param.maxValue;
                for (int c = 0; c < param.components; ++c) {
                    const float v = draw.uniform(lo, hi);
                    params[std::size_t(paramOffset(spec, int(i)) + c)] = v;
                    if (length) lengths = std::max(lengths, std::abs(v));
                }
            }
            // The fractals without length parameters lie within a radius of 1 to 2.6 (the
            // Mandelbulb's 2^(1 / (power - 1)), the Julia set's (1 + sqrt(1 + 4 |c|)) / 2):
            // their points lie at a distance from the origin drawn from 0 to 2.5, most of them
            // within the bounding sphere, where the estimator iterates.
            const glm::vec3 p = lengths == 0.0f && fractal
                                    ? draw.onSphere() * draw.uniform(0.0f, 2.5f)
                                    : draw.inCube(lengths > 0.0f ? 1.5f * lengths : 1.5f * s);
            FormulaCase c;
            c.formula = glm::uvec4(kPrimitive, std::uint32_t(spec.id), 0u, 0u);
            c.point = glm::vec4(p, 0.0f);
            for (int k = 0; k < kMaxPrimitiveFloats; ++k)
                c.params[k / 4][k % 4] = params[std::size_t(k)];
            Expectation e;
            e.formula = formula;
            e.value.x = spec.distance(p, params.data());
            e.scale.x = std::max(largestMagnitude(p), lengths);
            addCase(set, c, e);
        }
    }
    return set;
}

// Every operation, the smooth ones with both blend curves. The distances a and b are of a size
// s (0.01 to 1000); the smoothness k from s / 1000 to s; half the cases put b within 1.5 k of a,
// in the blend region of the smooth, chamfer and round operations.
CaseSet combineCases() {
    CaseSet set;
    Draw draw{std::mt19937(1702u)};
    for (const OperationSpec& spec : operationCatalogue()) {
        const std::uint32_t op = std::uint32_t(spec.op);
        for (int blend = 0; blend < (takesBlend(spec.op) ? 2 : 1); ++blend) {
            const int formula = addFormula(
                set, "operation " + std::string(spec.name) +
                         (takesBlend(spec.op) ? blend ? " (circular)" : " (polynomial)" : ""));
            for (int n = 0; n < kCasesPerFormula; ++n) {
                const float s = draw.logUniform(0.01f, 1000.0f);
                const float k = s * draw.logUniform(1e-3f, 1.0f);
                const float a = draw.uniform(-s, s);
                const float b =
                    draw.chance(0.5) ? a + draw.uniform(-1.5f * k, 1.5f * k) : draw.uniform(-s, s);
                FormulaCase c;
                c.formula = glm::uvec4(kCombine, op, 0u, 0u);
                c.point = glm::vec4(a, b, 0.0f, 0.0f);
                c.params[0] = glm::vec4(k, float(blend), 0.0f, 0.0f);
                Expectation e;
                e.formula = formula;
                e.components = 2;
                float weightA = 0.0f;
                e.value.x = sdfCombine(SdfOp(op), a, b, c.params[0], weightA);
                e.value.y = weightA;
                e.scale =
                    glm::vec4(std::max(std::max(std::abs(a), std::abs(b)), k), 1.0f, 1.0f, 1.0f);
                addCase(set, c, e);
            }
        }
    }
    return set;
}

// Whether p lies within 1e-4 radians of a seam between two sectors of a polar repetition of
// `count` copies about `axis`. There the formula jumps from one sector's copy to the next, and
// llvmpipe's atan (2e-5 relative) may pick the other sector than the C++ atan2: both answers
// are right, mirror images across the seam (measured: 2 of 65536 cases, none of the test's).
bool nearPolarSeam(glm::vec3 p, float count, int axis) {
    const int u = axis == 0 ? 1 : 0; // the plane of the angle, as sdfPointModifier takes it
    const int v = axis == 2 ? 1 : 2;
    const double sector = 2.0 * std::numbers::pi / double(count);
    const double x = std::atan2(double(p[v]), double(p[u])) / sector + 0.5;
    return std::abs(x - std::round(x)) * sector < 1e-4;
}

// The modifier catalogue's rows of one stage, in the order of their instruction kinds.
std::vector<const ModifierSpec*> modifierRows(ModifierStage stage) {
    std::vector<const ModifierSpec*> rows;
    for (const ModifierSpec& spec : modifierCatalogue())
        if (spec.stage == stage) rows.push_back(&spec);
    for (std::size_t kind = 0; kind < rows.size(); ++kind)
        EXPECT_EQ(modifierKind(rows[kind]->type), kind) << rows[kind]->name;
    return rows;
}

// Every point modifier, parameters packed as the compiler packs them (the catalogue rows,
// engine/sdf/modifiers.cpp) over the ranges the scene format allows: repeat periods up to the
// size s of the case (0: the axis is not repeated) and counts 0 (infinite), 1 to 8 or up to
// 2^20, with and without the neighbour-cell selector; polar counts 1 to 1024 about each axis,
// points off the seams (nearPolarSeam); twist and bend -3600 to 3600 degrees per unit; taper
// reaches R up to 2 s with |k| R up to 0.99.
CaseSet pointModifierCases() {
    CaseSet set;
    Draw draw{std::mt19937(1703u)};
    const std::vector<const ModifierSpec*> rows = modifierRows(ModifierStage::Point);
    EXPECT_EQ(rows.size(), std::size_t(SdfPointModifierKind::Taper) + 1);
    for (std::uint32_t kind = 0; kind < rows.size(); ++kind) {
        const int formula = addFormula(set, "point modifier " + std::string(rows[kind]->name));
        for (int n = 0; n < kCasesPerFormula; ++n) {
            const float s = draw.logUniform(0.01f, 1000.0f);
            FormulaCase c;
            c.formula = glm::uvec4(kPointModifier, kind, 0u, 0u);
            float extent = 1.5f * s; // of the point's cube
            switch (SdfPointModifierKind(kind)) {
            case SdfPointModifierKind::Repeat: {
                const bool neighbours = draw.chance(0.5);
                for (int axis = 0; axis < 3; ++axis) {
                    c.params[0][axis] = draw.chance(0.25) ? 0.0f : draw.uniform(0.0f, s);
                    const int choice = draw.integer(0, 2);
                    c.params[1][axis] = choice == 0 ? 0.0f
                                        : choice == 1
                                            ? float(draw.integer(1, 8))
                                            : std::floor(draw.logUniform(1.0f, float(1 << 20)));
                    if (neighbours) c.params[2][axis] = float(draw.integer(0, 1));
                }
                c.params[2].w = neighbours ? 1.0f : 0.0f;
                extent = 6.0f * s;
                break;
            }
            case SdfPointModifierKind::Mirror:
                for (int axis = 0; axis < 3; ++axis)
                    c.params[0][axis] = float(draw.integer(0, 1));
                break;
            case SdfPointModifierKind::Polar:
                c.params[0] = glm::vec4(std::floor(draw.logUniform(1.0f, 1024.99f)),
                                        float(draw.integer(0, 2)), 0.0f, 0.0f);
                break;
            case SdfPointModifierKind::Elongate:
                c.params[0] = glm::vec4(draw.uniform(0.0f, s), draw.uniform(0.0f, s),
                                        draw.uniform(0.0f, s), 0.0f);
                break;
            case SdfPointModifierKind::Twist:
            case SdfPointModifierKind::Bend:
                c.params[0].x = draw.uniform(-3600.0f, 3600.0f) * (glm::pi<float>() / 180.0f);
                break;
            case SdfPointModifierKind::Taper: {
                const float reach = draw.uniform(1e-3f, 2.0f) * s;
                c.params[0] = glm::vec4(draw.uniform(-0.99f, 0.99f) / reach, reach, 0.0f, 0.0f);
                break;
            }
            }
            glm::vec3 p = draw.inCube(extent);
            while (SdfPointModifierKind(kind) == SdfPointModifierKind::Polar &&
                   nearPolarSeam(p, c.params[0].x, int(c.params[0].y)))
                p = draw.inCube(extent);
            c.point = glm::vec4(p, 0.0f);
            Expectation e;
            e.formula = formula;
            e.components = 3;
            e.value = glm::vec4(sdfPointModifier(SdfPointModifierKind(kind), p, c.params), 0.0f);
            const float lengths = kind == std::uint32_t(SdfPointModifierKind::Repeat) ||
                                          kind == std::uint32_t(SdfPointModifierKind::Elongate)
                                      ? largestMagnitude(glm::vec3(c.params[0]))
                                      : 0.0f;
            e.scale = glm::vec4(std::max(largestMagnitude(p), lengths));
            addCase(set, c, e);
        }
    }
    return set;
}

// Every distance modifier: distances d and lengths of a size s (0.01 to 1000), the displacement
// noise's frequency from 0.001 to 1000 (the scene format's range).
CaseSet distanceModifierCases() {
    CaseSet set;
    Draw draw{std::mt19937(1704u)};
    const std::vector<const ModifierSpec*> rows = modifierRows(ModifierStage::Distance);
    EXPECT_EQ(rows.size(), std::size_t(SdfDistanceModifierKind::Displace) + 1);
    for (std::uint32_t kind = 0; kind < rows.size(); ++kind) {
        const int formula = addFormula(set, "distance modifier " + std::string(rows[kind]->name));
        for (int n = 0; n < kCasesPerFormula; ++n) {
            const float s = draw.logUniform(0.01f, 1000.0f);
            const glm::vec3 p = draw.inCube(1.5f * s);
            const float d = draw.uniform(-s, s);
            FormulaCase c;
            c.formula = glm::uvec4(kDistanceModifier, kind, 0u, 0u);
            c.point = glm::vec4(p, d);
            c.params[0].x = draw.uniform(0.0f, s);
            if (kind == std::uint32_t(SdfDistanceModifierKind::Displace))
                c.params[0].y = draw.logUniform(1e-3f, 1e3f);
            Expectation e;
            e.formula = formula;
            e.value.x = sdfDistanceModifier(SdfDistanceModifierKind(kind), d, p, c.params[0]);
            e.scale.x = std::max(std::abs(d), c.params[0].x);
            addCase(set, c, e);
        }
    }
    return set;
}

// A polygon of `count` points within [-s, s]^2: star-shaped (points around the centre in
// order, at random radii) or, one time in four, in random order (self-intersecting, which the
// even-odd rule handles).
std::vector<glm::vec2> randomPolygon(Draw& draw, int count, float s) {
    std::vector<glm::vec2> points;
    const bool starShaped = draw.chance(0.75);
    for (int i = 0; i < count; ++i) {
        const float angle =
            starShaped ? (float(i) + draw.uniform(0.0f, 0.9f)) * glm::two_pi<float>() / float(count)
                       : draw.uniform(0.0f, glm::two_pi<float>());
        const float radius = draw.uniform(0.1f * s, s);
        points.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    return points;
}

// Every 2D profile, extruded and revolved: sizes s from 0.01 to 1000, the rounded rectangle's
// radius up to its smaller half size, polygons of 3 to 256 points.
CaseSet profileCases() {
    CaseSet set;
    Draw draw{std::mt19937(1705u)};
    // Polygons shared by the polygon cases: (first point, count, size).
    struct Polygon {
        int first;
        int count;
        float size;
    };
    std::vector<Polygon> polygons;
    for (int i = 0; i < 64; ++i) {
        const int count = i < 8 ? 3 + i : draw.chance(0.1) ? 256 : draw.integer(3, 64);
        const float s = draw.logUniform(0.01f, 1000.0f);
        polygons.push_back({int(set.data.size()), count, s});
        for (glm::vec2 point : randomPolygon(draw, count, s))
            set.data.emplace_back(point, 0.0f, 0.0f);
    }
    for (int solid = 0; solid < 2; ++solid) {
        for (const ProfileSpec& profile : profileCatalogue()) {
            const std::uint32_t kind = std::uint32_t(profile.type);
            const int formula = addFormula(set, std::string(solid ? "revolution" : "extrusion") +
                                                    " of " + std::string(profile.name));
            for (int n = 0; n < kCasesPerFormula; ++n) {
                FormulaCase c;
                c.formula = glm::uvec4(kProfile, kind, 0u, 0u);
                float s = draw.logUniform(0.01f, 1000.0f);
                if (SdfProfileType(kind) == SdfProfileType::Polygon) {
                    const Polygon& polygon =
                        polygons[std::size_t(draw.integer(0, int(polygons.size()) - 1))];
                    s = polygon.size;
                    c.params[2] = glm::vec4(float(polygon.first), float(polygon.count), 0, 0);
                }
                const glm::vec2 half(draw.uniform(0.0f, s), draw.uniform(0.0f, s));
                c.params[0] = glm::vec4(SdfProfileType(kind) == SdfProfileType::Circle
                                            ? draw.uniform(0.0f, s)
                                            : draw.uniform(0.0f, std::min(half.x, half.y)),
                                        half, 0.0f);
                // Extrusion: half the depth; revolution: the profile's distance from the axis.
                c.params[1] = glm::vec4(float(solid), draw.uniform(0.0f, s), 0.0f, 0.0f);
                const glm::vec3 p = draw.inCube(1.5f * (s + c.params[1].y));
                c.point = glm::vec4(p, 0.0f);
                Expectation e;
                e.formula = formula;
                e.value.x = sdfProfile(SdfProfileType(kind), p, c.params, set.data);
                e.scale.x = std::max(largestMagnitude(p), std::max(s, c.params[1].y));
                addCase(set, c, e);
            }
        }
    }
    return set;
}

// The probe: one case per invocation, each calling the renderer's GLSL function for its family.
constexpr const char* kProbeSource = R"(#version 450 core
// Evaluates FormulaCase i into results[i] (tests/gpu/test_formula_parity.cpp).
layout(local_size_x = 64) in;
#include "common/sdf_functions.glsl"
#include "generated/primitives.glsl"

#define FORMULA_PRIMITIVE 0u
#define FORMULA_COMBINE 1u
#define FORMULA_POINT_MODIFIER 2u
#define FORMULA_DISTANCE_MODIFIER 3u
#define FORMULA_PROFILE 4u

struct FormulaCase {
    uvec4 formula; // x = FORMULA_*, y = kind
    vec4 point;    // xyz = the point; combine: x = a, y = b; distance modifier: w = d
    vec4 params[3];
};
layout(std430, binding = 6) readonly buffer FormulaCases { FormulaCase cases[]; };
layout(std430, binding = 7) writeonly buffer FormulaResults { vec4 results[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(cases.length())) return;
    uint family = cases[i].formula.x;
    uint kind = cases[i].formula.y;
    vec4 point = cases[i].point;
    vec4 a = cases[i].params[0];
    vec4 b = cases[i].params[1];
    vec4 c = cases[i].params[2];
    vec4 result = vec4(0.0);
    if (family == FORMULA_PRIMITIVE) {
        result.x = sdfPrimitive(kind, point.xyz, a, b, c);
    } else if (family == FORMULA_COMBINE) {
        float weightA;
        result.x = sdfCombine(kind, point.x, point.y, a, weightA);
        result.y = weightA;
    } else if (family == FORMULA_POINT_MODIFIER) {
        result.xyz = sdfPointModifier(kind, point.xyz, a, b, c);
    } else if (family == FORMULA_DISTANCE_MODIFIER) {
        result.x = sdfDistanceModifier(kind, point.w, point.xyz, a);
    } else {
        result.x = sdfProfile(kind, point.xyz, a, b, c);
    }
    results[i] = result;
}
)";

const gl::Program& probeProgram() {
    static const gl::Program program = [] {
        sharedRenderer(); // makes the context current
        ShaderFiles files = embeddedShaderFiles();
        files.files["test/formula_probe.comp"] = kProbeSource;
        std::string error;
        std::optional<gl::Program> built =
            buildComputeProgram(files, "test/formula_probe.comp", "", error);
        EXPECT_TRUE(built) << error;
        return built ? std::move(*built) : gl::Program();
    }();
    return program;
}

// The probe's results for every case of `set`.
std::vector<glm::vec4> runProbe(const CaseSet& set) {
    const gl::Program& program = probeProgram();
    std::vector<glm::vec4> results(set.cases.size(), glm::vec4(0.0f));
    if (!program) return results;
    const gl::Buffer cases = gl::createBufferWithData(
        GLsizeiptr(set.cases.size() * sizeof(FormulaCase)), set.cases.data());
    const gl::Buffer output =
        gl::createBufferWithData(GLsizeiptr(results.size() * sizeof(glm::vec4)), nullptr);
    const gl::Buffer data =
        gl::createBufferWithData(GLsizeiptr(set.data.size() * sizeof(glm::vec4)), set.data.data());
    glUseProgram(program.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, cases.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, output.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSdfDataBinding, data.id());
    glDispatchCompute(GLuint((set.cases.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(output.id(), 0, GLsizeiptr(results.size() * sizeof(glm::vec4)),
                            results.data());
    for (GLuint binding : {6u, 7u, GLuint(kSdfDataBinding)})
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
    glUseProgram(0);
    expectNoGlErrors();
    return results;
}

std::string format(float v) {
    std::ostringstream out;
    out.precision(9);
    out << v;
    return out.str();
}

std::string format(glm::vec4 v, int components = 4) {
    std::string text = "(";
    for (int i = 0; i < components; ++i)
        text += (i ? ", " : "") + format(v[i]);
    return text + ")";
}

// The inputs of case c, named as its formula takes them.
std::string describeInputs(const FormulaCase& c) {
    const glm::vec3 p(c.point);
    const std::string point = "p " + format(glm::vec4(p, 0.0f), 3);
    const std::string packed =
        "params " + format(c.params[0]) + " " + format(c.params[1]) + " " + format(c.params[2]);
    switch (Family(c.formula.x)) {
    case kPrimitive: {
        const PrimitiveSpec& spec = primitiveSpec(PrimitiveId(c.formula.y));
        std::string text = point;
        for (std::size_t i = 0; i < spec.params.size(); ++i) {
            const int offset = paramOffset(spec, int(i));
            glm::vec4 v(0.0f);
            for (int k = 0; k < spec.params[i].components; ++k)
                v[k] = c.params[(offset + k) / 4][(offset + k) % 4];
            text += ", " + std::string(spec.params[i].name) + " " +
                    (spec.params[i].components == 1 ? format(v.x) : format(v, 3));
        }
        return text;
    }
    case kCombine:
        return "a " + format(c.point.x) + ", b " + format(c.point.y) + ", smoothness " +
               format(c.params[0].x) + ", blend " + format(c.params[0].y);
    case kDistanceModifier:
        return "d " + format(c.point.w) + ", " + point + ", " + packed;
    case kPointModifier:
    case kProfile:
        break;
    }
    return point + ", " + packed;
}

// A result of case c, named.
std::string describeResult(const FormulaCase& c, glm::vec4 v) {
    if (Family(c.formula.x) == kCombine)
        return "distance " + format(v.x) + ", weight of a " + format(v.y);
    if (Family(c.formula.x) == kPointModifier) return "point " + format(v, 3);
    return "distance " + format(v.x);
}

// Two results agree when both are the same non-finite value or differ by at most `tolerance`.
bool agree(float gpu, float cpu, float tolerance) {
    if (std::isnan(gpu) || std::isnan(cpu)) return std::isnan(gpu) && std::isnan(cpu);
    if (std::isinf(gpu) || std::isinf(cpu)) return gpu == cpu;
    return std::abs(gpu - cpu) <= tolerance;
}

// Whether every compared component of a case is within `relative` of the C++ value.
bool caseAgrees(const Expectation& e, glm::vec4 gpu, float relative) {
    for (int k = 0; k < e.components; ++k)
        if (!agree(gpu[k], e.value[k], relative * std::max(std::abs(e.value[k]), e.scale[k])))
            return false;
    return true;
}

// Runs `set` through the probe and checks every case against the C++ value within
// `tolerance`. Fails naming, per formula, how many cases disagree and the inputs and results
// of the first few (those beyond the outliers' tolerance first).
void expectParity(const CaseSet& set, Tolerance tolerance = {}) {
    ASSERT_EQ(set.cases.size(), set.expected.size());
    const std::vector<glm::vec4> gpu = runProbe(set);
    struct Count {
        int cases = 0;
        std::vector<std::string> beyondOutliers; // beyond tolerance.outlierRelative
        std::vector<std::string> outliers;       // beyond tolerance.relative only
    };
    std::vector<Count> counts(set.formulas.size());
    for (std::size_t i = 0; i < set.cases.size(); ++i) {
        const Expectation& e = set.expected[i];
        Count& count = counts[std::size_t(e.formula)];
        ++count.cases;
        if (caseAgrees(e, gpu[i], tolerance.relative)) continue;
        const FormulaCase& c = set.cases[i];
        const std::string line = "\n    " + describeInputs(c) + ": C++ " +
                                 describeResult(c, e.value) + ", GLSL " + describeResult(c, gpu[i]);
        (caseAgrees(e, gpu[i], tolerance.outlierRelative) ? count.outliers : count.beyondOutliers)
            .push_back(line);
    }
    constexpr std::size_t kShown = 4;
    for (std::size_t f = 0; f < set.formulas.size(); ++f) {
        const Count& count = counts[f];
        const std::size_t allowed = std::size_t(tolerance.outlierShare * double(count.cases));
        const std::size_t differing = count.beyondOutliers.size() + count.outliers.size();
        std::string shown;
        for (std::size_t k = 0; k < std::min(differing, kShown); ++k)
            shown += k < count.beyondOutliers.size()
                         ? count.beyondOutliers[k]
                         : count.outliers[k - count.beyondOutliers.size()];
        std::string what = set.formulas[f] + ": " + std::to_string(differing) + " of " +
                           std::to_string(count.cases) + " cases differ by more than " +
                           format(tolerance.relative) + " relative";
        if (tolerance.outlierShare > 0.0)
            what += " (" + std::to_string(allowed) + " may, by up to " +
                    format(tolerance.outlierRelative) + "), " +
                    std::to_string(count.beyondOutliers.size()) + " by more than " +
                    format(tolerance.outlierRelative);
        EXPECT_TRUE(count.cases > 0 && count.beyondOutliers.empty() && differing <= allowed)
            << what << "; the first ones:" << shown;
    }
}

} // namespace

TEST(FormulaParity, Primitives) {
    expectParity(primitiveCases([](PrimitiveId id) { return !isFractal(id); }, 1700u));
}

TEST(FormulaParity, Fractals) {
    expectParity(primitiveCases(
        [](PrimitiveId id) { return isFractal(id) && id != PrimitiveId::Mandelbulb; }, 1701u));
}

TEST(FormulaParity, Mandelbulb) {
    expectParity(
        primitiveCases([](PrimitiveId id) { return id == PrimitiveId::Mandelbulb; }, 1701u),
        kMandelbulbTolerance);
}

TEST(FormulaParity, Operations) {
    expectParity(combineCases());
}

TEST(FormulaParity, PointModifiers) {
    expectParity(pointModifierCases());
}

TEST(FormulaParity, DistanceModifiers) {
    expectParity(distanceModifierCases());
}

TEST(FormulaParity, Profiles) {
    expectParity(profileCases());
}
