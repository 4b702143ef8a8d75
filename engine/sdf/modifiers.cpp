// The modifier catalogue rows (sdf/modifiers.hpp): parameters, instruction packing, checks,
// step corrections and bounds rules of each modifier. The C++ formulas are in
// sdf_functions.cpp (sdf/sdf_functions.hpp), the GLSL ones in shaders/common/sdf_functions.glsl.
#include "sdf/modifiers.hpp"

#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "sdf/sdf_functions.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <utility>

namespace rmsc {
namespace {

constexpr double kBig = 1.0e4;                         // upper bound of lengths in the scene format
constexpr int kMaxPolarCopies = limits::kPolarCopies;  // polar repetition
constexpr int kMaxRepeatCount = limits::kRepeatCopies; // per axis
constexpr float kRadiansPerDegree = std::numbers::pi_v<float> / 180.0f;

// A row's formula: the one of sdf/sdf_functions.hpp for the row's instruction kind.
template <SdfPointModifierKind Kind> glm::vec3 movePointBy(glm::vec3 p, const glm::vec4* params) {
    return sdfPointModifier(Kind, p, params);
}

template <SdfDistanceModifierKind Kind>
float changeDistanceBy(float d, glm::vec3 p, const glm::vec4* params) {
    return sdfDistanceModifier(Kind, d, p, params[0]);
}

SdfBounds boundedBy(const Aabb& box) {
    return {true, box, ""};
}

// The largest distance of `box` from the axis through the origin whose other two axes are u, v.
float radiusAround(const Aabb& box, int u, int v) {
    const float du = std::max(std::abs(box.min[u]), std::abs(box.max[u]));
    const float dv = std::max(std::abs(box.min[v]), std::abs(box.max[v]));
    return std::sqrt(du * du + dv * dv);
}

// ---- repeat ----

constexpr ModifierParam kRepeat[] = {
    {{.key = "period",
      .type = ParamType::Vec3,
      .required = true,
      .range = closedRange(0.0, kBig, Unit::Metres),
      .description = "the cell size along x, y, z; 0 = not repeated on that axis",
      .noun = "a period"},
     &SdfModifier::vector},
    {{.key = "count",
      .type = ParamType::IVec3,
      .required = false,
      .value = {0.0f, 0.0f, 0.0f},
      .range = closedRange(0.0, kMaxRepeatCount, Unit::Count),
      .description = "copies along x, y, z; 0 = unlimited",
      .writtenAtDefault = false},
     &SdfModifier::counts},
    {{.key = "neighbours",
      .type = ParamType::Bool,
      .required = false,
      .value = {0.0f},
      .description = "also evaluate the nearest neighbouring cell along each repeated axis, for "
                     "content that reaches into the next cell",
      .writtenAtDefault = false},
     &SdfModifier::neighbours},
};

void packRepeat(const SdfModifier& m, float, int cell, glm::vec4* params) {
    params[0] = glm::vec4(glm::max(m.vector, 0.0f), 0.0f);
    params[1] = glm::vec4(glm::vec3(glm::max(m.counts, 0)), 0.0f);
    if (cell < 0) return;
    int bit = 0;
    for (int axis = 0; axis < 3; ++axis)
        if (m.vector[axis] > 0.0f) params[2][axis] = float((cell >> bit++) & 1);
    params[2].w = 1.0f;
}

void checkRepeat(const SdfModifier& m, unsigned readOk, std::vector<ParamProblem>& problems) {
    if (!(readOk & 1u)) return; // the period
    if (m.vector == glm::vec3(0.0f))
        problems.push_back({"period", -1,
                            "the period is 0 on every axis, so nothing repeats; give a period "
                            "> 0 on at least one axis"});
    for (int axis = 0; axis < 3; ++axis)
        if (m.counts[axis] > 1 && !(m.vector[axis] > 0.0f))
            problems.push_back({"count", axis,
                                "count " + std::to_string(m.counts[axis]) + " along " +
                                    "xyz"[axis] + " needs a period > 0 on that axis, got " +
                                    shortestNumberText(m.vector[axis])});
}

// Cells a repetition evaluates per point: 2^(repeated axes) with the neighbour check (the own
// cell and the nearest neighbour along each repeated axis), else 1.
int repeatCells(const SdfModifier& m) {
    if (!m.neighbours) return 1;
    int cells = 1;
    for (int axis = 0; axis < 3; ++axis)
        if (m.vector[axis] > 0.0f) cells *= 2;
    return cells;
}

// Along a repeated axis the point moves by (id - first) period, with id clamped to
// 0 .. count - 1 and first = (count - 1) / 2 (the neighbour check picks another id in the same
// range): the content's copies reach first * period further either way. count 0 is infinite
// repetition.
SdfBounds repeatPreimage(const SdfModifier& m, const Aabb& box) {
    Aabb out = box;
    for (int axis = 0; axis < 3; ++axis) {
        const float period = m.vector[axis];
        if (!(period > 0.0f)) continue;
        const int count = std::max(m.counts[axis], 0);
        if (count == 0) return {false, {}, m.pointer};
        const float reach = 0.5f * float(count - 1) * period;
        out.min[axis] -= reach;
        out.max[axis] += reach;
    }
    return boundedBy(out);
}

// ---- mirror ----

constexpr ModifierParam kMirror[] = {
    {{.key = "axes",
      .type = ParamType::Axes,
      .required = true,
      .description = "the axes to mirror, e.g. \"x\" or \"xz\""},
     &SdfModifier::axes},
};

void packMirror(const SdfModifier& m, float, int, glm::vec4* params) {
    params[0] = glm::vec4(glm::vec3(m.axes), 0.0f);
}

// A folded axis sees |x|: x reaches as far either way as the box does on the + side.
SdfBounds mirrorPreimage(const SdfModifier& m, const Aabb& box) {
    Aabb out = box;
    for (int axis = 0; axis < 3; ++axis) {
        if (!m.axes[axis]) continue;
        if (box.max[axis] < 0.0f) return boundedBy(Aabb{});
        out.min[axis] = -box.max[axis];
        out.max[axis] = box.max[axis];
    }
    return boundedBy(out);
}

// ---- polar ----

constexpr ModifierParam kPolar[] = {
    {{.key = "count",
      .type = ParamType::Integer,
      .required = true,
      .range = closedRange(1.0, kMaxPolarCopies, Unit::Count),
      .description = "the number of copies around the axis"},
     &SdfModifier::count},
    {{.key = "axis",
      .type = ParamType::Axis,
      .required = false,
      .value = {1.0f},
      .description = "the axis the copies turn around"},
     &SdfModifier::axis},
};

void packPolar(const SdfModifier& m, float, int, glm::vec4* params) {
    params[0] = glm::vec4(float(std::max(m.count, 1)), float(m.axis), 0, 0);
}

// A rotation about the axis: the same extent along it, and every point within the box's largest
// distance from it.
SdfBounds polarPreimage(const SdfModifier& m, const Aabb& box) {
    Aabb out = box;
    const int axis = m.axis;
    const int u = axis == 0 ? 1 : 0;
    const int v = axis == 2 ? 1 : 2;
    const float radius = radiusAround(box, u, v);
    out.min[u] = out.min[v] = -radius;
    out.max[u] = out.max[v] = radius;
    return boundedBy(out);
}

// ---- elongate ----

constexpr ModifierParam kElongate[] = {
    {{.key = "half_extents",
      .type = ParamType::Vec3,
      .required = true,
      .range = closedRange(0.0, kBig, Unit::Metres),
      .description = "half the stretch along x, y, z"},
     &SdfModifier::vector},
};

void packElongate(const SdfModifier& m, float, int, glm::vec4* params) {
    params[0] = glm::vec4(glm::max(m.vector, 0.0f), 0.0f);
}

// q = x - clamp(x, -h, h): x = q + h for q > 0, q - h for q < 0, [-h, h] for q = 0.
SdfBounds elongatePreimage(const SdfModifier& m, const Aabb& box) {
    Aabb out = box;
    for (int axis = 0; axis < 3; ++axis) {
        const float h = std::max(m.vector[axis], 0.0f);
        out.min[axis] = box.min[axis] > 0.0f ? box.min[axis] + h : box.min[axis] - h;
        out.max[axis] = box.max[axis] < 0.0f ? box.max[axis] - h : box.max[axis] + h;
    }
    return boundedBy(out);
}

// ---- twist, bend ----

constexpr ModifierParam kTwist[] = {
    {{.key = "amount",
      .type = ParamType::Number,
      .required = true,
      .range = closedRange(-3600.0, 3600.0, Unit::DegreesPerMetre),
      .description = "degrees per unit length"},
     &SdfModifier::amount},
    {{.key = "radius",
      .type = ParamType::Number,
      .required = false,
      .value = {1.0f},
      .range = openClosedRange(0.0, kBig, Unit::Metres),
      .description = "how far from the y axis the content reaches (sets the step correction)"},
     &SdfModifier::radius},
};

constexpr ModifierParam kBend[] = {
    {{.key = "amount",
      .type = ParamType::Number,
      .required = true,
      .range = closedRange(-3600.0, 3600.0, Unit::DegreesPerMetre),
      .description = "degrees per unit length"},
     &SdfModifier::amount},
    {{.key = "radius",
      .type = ParamType::Number,
      .required = false,
      .value = {1.0f},
      .range = openClosedRange(0.0, kBig, Unit::Metres),
      .description = "how far from the z axis the content reaches (sets the step correction)"},
     &SdfModifier::radius},
};

void packAngle(const SdfModifier& m, float, int, glm::vec4* params) {
    params[0].x = m.amount * kRadiansPerDegree;
}

// Twist by k rad/unit about y moves a point of the content (within radius R of the axis) so
// that |T(p) - T(q)| <= |shear(kR)| |p - q|, the largest singular value of [[1, 0], [kR, 1]]:
// kR/2 + sqrt(1 + (kR/2)^2).
double twistLipschitz(const SdfModifier& m) {
    const double k = std::abs(double(m.amount)) * std::numbers::pi / 180.0;
    const double r = std::max(double(m.radius), 0.0);
    return k * r / 2.0 + std::sqrt(1.0 + (k * r / 2.0) * (k * r / 2.0));
}

// Bend by k about z (the angle follows x) gives |T(p) - T(q)| <= (1 + kR) |p - q| with R the
// content's radius in the xy plane.
double bendLipschitz(const SdfModifier& m) {
    const double k = std::abs(double(m.amount)) * std::numbers::pi / 180.0;
    const double r = std::max(double(m.radius), 0.0);
    return 1.0 + k * r;
}

// A rotation about y by an angle that depends on y: y and the distance from y are kept.
SdfBounds twistPreimage(const SdfModifier&, const Aabb& box) {
    Aabb out = box;
    const float radius = radiusAround(box, 0, 2);
    out.min.x = out.min.z = -radius;
    out.max.x = out.max.z = radius;
    return boundedBy(out);
}

// A rotation about z (in the xy plane) by an angle that depends on x: z and the distance from z
// are kept.
SdfBounds bendPreimage(const SdfModifier&, const Aabb& box) {
    Aabb out = box;
    const float radius = radiusAround(box, 0, 1);
    out.min.x = out.min.y = -radius;
    out.max.x = out.max.y = radius;
    return boundedBy(out);
}

// ---- taper ----

constexpr ModifierParam kTaper[] = {
    {{.key = "amount",
      .type = ParamType::Number,
      .required = true,
      .range = closedRange(-100.0, 100.0, Unit::PerMetre),
      .description = "the change of the x and z scale per unit along y (the scale is 1 at y = 0)"},
     &SdfModifier::amount},
    {{.key = "radius",
      .type = ParamType::Number,
      .required = false,
      .value = {1.0f},
      .range = openClosedRange(0.0, kBig, Unit::Metres),
      .description = "how far from the y axis the content reaches, and the height beyond which "
                     "the scale stays constant (sets the step correction)"},
     &SdfModifier::radius},
};

void packTaper(const SdfModifier& m, float, int, glm::vec4* params) {
    params[0].x = m.amount;
    params[0].y = m.radius;
}

// The scale 1 + amount y must stay above 0 up to |y| = radius.
void checkTaper(const SdfModifier& m, unsigned readOk, std::vector<ParamProblem>& problems) {
    if ((readOk & 3u) != 3u || std::abs(m.amount) * m.radius < 1.0f) return;
    problems.push_back({"amount", -1,
                        "the taper " + shortestNumberText(m.amount) + " reaches a scale of 0 " +
                            "within the radius " + shortestNumberText(m.radius) +
                            "; |amount| x radius must be below 1"});
}

// Step correction. The field is f(T(p)), T(p) = (x / s, y, z / s), s = 1 + k clamp(y, -R, R),
// f 1-Lipschitz; so it is at most |T(p) - T(p*)| for p* on the tapered surface, whose content
// point T(p*) lies within R of the y axis (Hart, "Sphere tracing", 1996: a field composed with
// a map is Lipschitz with the product of the constants). With m = 1 / (1 - |k| R), the largest
// 1 / s, and x / s - x* / s* = (x - x*) / s + (x* / s*) (s* - s) / s, |s* - s| <= |k| |y - y*|:
// |T(p) - T(p*)|^2 <= (m a + m |k| R b)^2 + b^2 with a the xz part and b the y part of p - p*,
// so the constant is the largest singular value of [[m, m |k| R], [0, 1]].
double taperLipschitz(const SdfModifier& m) {
    const double kr = std::abs(double(m.amount)) * std::max(double(m.radius), 0.0);
    const double inverse = 1.0 / std::max(1.0 - kr, 1e-6);
    const double trace = inverse * inverse * (1.0 + kr * kr) + 1.0; // of M^T M
    const double det = inverse;                                     // of M
    return std::sqrt(0.5 * (trace + std::sqrt(std::max(trace * trace - 4.0 * det * det, 0.0))));
}

// y is kept; x and z are the content's times s(y) > 0, which is monotonic in y: over the box's
// y range it lies between its values at the two ends.
SdfBounds taperPreimage(const SdfModifier& m, const Aabb& box) {
    const auto scale = [&](float y) {
        return 1.0f + m.amount * std::clamp(y, -m.radius, m.radius);
    };
    const float a = scale(box.min.y);
    const float b = scale(box.max.y);
    const float lo = std::min(a, b);
    const float hi = std::max(a, b);
    Aabb out = box;
    for (const int axis : {0, 2}) {
        out.min[axis] = std::min(box.min[axis] * lo, box.min[axis] * hi);
        out.max[axis] = std::max(box.max[axis] * lo, box.max[axis] * hi);
    }
    return boundedBy(out);
}

// ---- round, onion, displace ----
// Each turns "result <= t" into "distance <= t + growth": round d - r; onion |d| - thickness
// (d <= |d|); displace d + amplitude * noise with the noise in [-1, 1].

constexpr ModifierParam kRound[] = {
    {{.key = "radius",
      .type = ParamType::Number,
      .required = true,
      .range = closedRange(0.0, kBig, Unit::Metres),
      .description = "the rounding radius"},
     &SdfModifier::radius},
};

void packRound(const SdfModifier& m, float lengthScale, int, glm::vec4* params) {
    params[0].x = m.radius * lengthScale;
}

float roundGrowth(const SdfModifier& m) {
    return m.radius;
}

constexpr ModifierParam kOnion[] = {
    {{.key = "thickness",
      .type = ParamType::Number,
      .required = true,
      .range = openClosedRange(0.0, kBig, Unit::Metres),
      .description = "the shell thickness"},
     &SdfModifier::thickness},
};

void packOnion(const SdfModifier& m, float lengthScale, int, glm::vec4* params) {
    params[0].x = m.thickness * lengthScale;
}

float onionGrowth(const SdfModifier& m) {
    return m.thickness;
}

constexpr ModifierParam kDisplace[] = {
    {{.key = "amplitude",
      .type = ParamType::Number,
      .required = true,
      .range = closedRange(0.0, kBig, Unit::Metres),
      .description = "the noise amplitude"},
     &SdfModifier::amount},
    {{.key = "frequency",
      .type = ParamType::Number,
      .required = false,
      .value = {1.0f},
      .range = openClosedRange(0.0, 1.0e3, Unit::PerMetre),
      .description = "noise cells per unit length"},
     &SdfModifier::frequency},
};

void packDisplace(const SdfModifier& m, float lengthScale, int, glm::vec4* params) {
    params[0].x = m.amount * lengthScale;
    params[0].y = m.frequency;
}

// The noise's gradient is at most kNoiseGradientBound per unit of its argument, p * frequency.
double displaceGradientGain(const SdfModifier& m) {
    return std::abs(double(m.amount)) * std::abs(double(m.frequency)) * kNoiseGradientBound;
}

float displaceGrowth(const SdfModifier& m) {
    return std::abs(m.amount);
}

// Round (d - radius), onion (|d| - thickness) and displace (d + amplitude * noise, the noise in
// [-1, 1]) lower a value by at most their first packed parameter.
float firstParamGrowth(const glm::vec4* params) {
    return std::abs(params[0].x);
}

constexpr const char* kIq =
    "Quilez, Distance functions (https://iquilezles.org/articles/distfunctions/)";

// In SdfModifierType order.
constexpr ModifierSpec kCatalogue[] = {
    {.type = SdfModifierType::Repeat,
     .name = "repeat",
     .stage = ModifierStage::Point,
     .params = kRepeat,
     .description = "copies of the node on a grid: without end, or `count` per axis centred on "
                    "the origin",
     .source = "Quilez, Domain repetition (https://iquilezles.org/articles/sdfrepetition/)",
     .movePoint = movePointBy<SdfPointModifierKind::Repeat>,
     .pack = packRepeat,
     .check = checkRepeat,
     .cells = repeatCells,
     .preimage = repeatPreimage},
    {.type = SdfModifierType::Mirror,
     .name = "mirror",
     .stage = ModifierStage::Point,
     .params = kMirror,
     .description = "each named axis folded to its absolute value: the + side reflected onto "
                    "the - side",
     .source = kIq,
     .movePoint = movePointBy<SdfPointModifierKind::Mirror>,
     .pack = packMirror,
     .preimage = mirrorPreimage},
    {.type = SdfModifierType::Polar,
     .name = "polar",
     .stage = ModifierStage::Point,
     .params = kPolar,
     .description = "`count` copies turned evenly around `axis`",
     .source = "hg_sdf, pModPolar (https://mercury.sexy/hg_sdf/)",
     .movePoint = movePointBy<SdfPointModifierKind::Polar>,
     .pack = packPolar,
     .preimage = polarPreimage},
    {.type = SdfModifierType::Elongate,
     .name = "elongate",
     .stage = ModifierStage::Point,
     .params = kElongate,
     .description = "the node cut at its centre planes and its halves moved apart by "
                    "`half_extents` each way, the gap filled",
     .source = kIq,
     .movePoint = movePointBy<SdfPointModifierKind::Elongate>,
     .pack = packElongate,
     .preimage = elongatePreimage},
    {.type = SdfModifierType::Twist,
     .name = "twist",
     .stage = ModifierStage::Point,
     .params = kTwist,
     .description = "turned about y by `amount` degrees per unit along y",
     .source = kIq,
     .movePoint = movePointBy<SdfPointModifierKind::Twist>,
     .pack = packAngle,
     .lipschitz = twistLipschitz,
     .preimage = twistPreimage},
    {.type = SdfModifierType::Bend,
     .name = "bend",
     .stage = ModifierStage::Point,
     .params = kBend,
     .description = "bent in the xy plane: turned about z by `amount` degrees per unit along x",
     .source = kIq,
     .movePoint = movePointBy<SdfPointModifierKind::Bend>,
     .pack = packAngle,
     .lipschitz = bendLipschitz,
     .preimage = bendPreimage},
    {.type = SdfModifierType::Taper,
     .name = "taper",
     .stage = ModifierStage::Point,
     .params = kTaper,
     .description = "x and z scaled by 1 + `amount` y: narrowing or widening along y, constant "
                    "beyond y = ±`radius`",
     .source = "Barr, Global and local deformations of solid primitives (SIGGRAPH 1984)",
     .movePoint = movePointBy<SdfPointModifierKind::Taper>,
     .pack = packTaper,
     .check = checkTaper,
     .lipschitz = taperLipschitz,
     .preimage = taperPreimage},
    {.type = SdfModifierType::Round,
     .name = "round",
     .stage = ModifierStage::Distance,
     .params = kRound,
     .description = "the surface moved out by `radius`, rounding the edges",
     .source = kIq,
     .changeDistance = changeDistanceBy<SdfDistanceModifierKind::Round>,
     .pack = packRound,
     .growth = roundGrowth,
     .packedGrowth = firstParamGrowth},
    {.type = SdfModifierType::Onion,
     .name = "onion",
     .stage = ModifierStage::Distance,
     .params = kOnion,
     .description = "hollowed into a shell reaching `thickness` either side of the surface",
     .source = kIq,
     .changeDistance = changeDistanceBy<SdfDistanceModifierKind::Onion>,
     .pack = packOnion,
     .growth = onionGrowth,
     .packedGrowth = firstParamGrowth},
    {.type = SdfModifierType::Displace,
     .name = "displace",
     .stage = ModifierStage::Distance,
     .params = kDisplace,
     .description = "the surface moved in and out by value noise of `amplitude` and `frequency`",
     .source = "value noise: Perlin, An image synthesizer (1985); Quilez, Value noise "
               "derivatives (https://iquilezles.org/articles/morenoise/)",
     .changeDistance = changeDistanceBy<SdfDistanceModifierKind::Displace>,
     .pack = packDisplace,
     .readsPoint = true,
     .gradientGain = displaceGradientGain,
     .growth = displaceGrowth,
     .packedGrowth = firstParamGrowth},
};

constexpr std::size_t kModifierCount = std::size(kCatalogue);

// The instruction kind of row `i`: its place among the rows of its stage (modifierKind).
constexpr std::uint32_t kindOfRow(std::size_t i) {
    std::uint32_t kind = 0;
    for (std::size_t j = 0; j < i; ++j)
        kind += kCatalogue[j].stage == kCatalogue[i].stage;
    return kind;
}

// Each row's formula is the one of sdf/sdf_functions.hpp whose SdfPointModifierKind or
// SdfDistanceModifierKind is the row's instruction kind, so those enums list each stage's rows
// in catalogue order: a row moved without its enum value (or the other way round) fails here.
template <std::size_t... I>
constexpr bool rowsUseTheFormulasOfTheirKinds(std::index_sequence<I...>) {
    return ((kCatalogue[I].stage == ModifierStage::Point
                 ? kCatalogue[I].movePoint == &movePointBy<SdfPointModifierKind(kindOfRow(I))>
                 : kCatalogue[I].changeDistance ==
                       &changeDistanceBy<SdfDistanceModifierKind(kindOfRow(I))>)&&...);
}
static_assert(rowsUseTheFormulasOfTheirKinds(std::make_index_sequence<kModifierCount>()),
              "SdfPointModifierKind and SdfDistanceModifierKind (sdf/program.hpp) must list each "
              "stage's modifier rows in catalogue order");

// kind -> row index, per stage.
struct KindTables {
    std::array<std::uint32_t, kModifierCount> kindOf{};
    std::vector<std::size_t> rows[2];
};

const KindTables& kindTables() {
    static const KindTables tables = [] {
        KindTables t;
        for (std::size_t i = 0; i < kModifierCount; ++i) {
            std::vector<std::size_t>& rows = t.rows[std::size_t(kCatalogue[i].stage)];
            t.kindOf[i] = std::uint32_t(rows.size());
            rows.push_back(i);
        }
        return t;
    }();
    return tables;
}

} // namespace

std::span<const ModifierSpec> modifierCatalogue() {
    return kCatalogue;
}

const ModifierSpec& modifierSpec(SdfModifierType type) {
    assert(std::size_t(type) < kModifierCount && kCatalogue[std::size_t(type)].type == type);
    return kCatalogue[std::size_t(type)];
}

const ModifierSpec* findModifier(std::string_view name) {
    for (const ModifierSpec& spec : kCatalogue)
        if (spec.name == name) return &spec;
    return nullptr;
}

std::vector<std::string> modifierNames() {
    std::vector<std::string> names;
    for (const ModifierSpec& spec : kCatalogue)
        names.emplace_back(spec.name);
    return names;
}

std::uint32_t modifierKind(SdfModifierType type) {
    return kindTables().kindOf[std::size_t(type)];
}

const ModifierSpec& modifierOfKind(ModifierStage stage, std::uint32_t kind) {
    const std::vector<std::size_t>& rows = kindTables().rows[std::size_t(stage)];
    assert(kind < rows.size());
    return kCatalogue[rows[kind]];
}

SdfModifier defaultModifier(SdfModifierType type) {
    SdfModifier m;
    m.type = type;
    for (const ModifierParam& param : modifierSpec(type).params) {
        const std::array<float, 3>& v = param.spec.value;
        std::visit(
            [&](auto field) {
                auto& out = m.*field;
                using T = std::decay_t<decltype(out)>;
                if constexpr (std::is_same_v<T, float>) {
                    out = v[0];
                } else if constexpr (std::is_same_v<T, int>) {
                    out = int(v[0]);
                } else if constexpr (std::is_same_v<T, bool>) {
                    out = v[0] != 0.0f;
                } else {
                    for (int c = 0; c < 3; ++c)
                        out[c] = typename T::value_type(v[std::size_t(c)]);
                }
            },
            param.field);
    }
    return m;
}

} // namespace rmsc
