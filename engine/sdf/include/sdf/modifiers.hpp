// The modifier catalogue: one row per SdfModifierType (its JSON name, its parameters with their
// defaults and valid ranges, whether it moves the point or changes the distance, how the
// compiler packs it, its step correction and its bounds rule). The scene reader, the writer, the
// schema, the docs table, the compiler, the bounds and the CPU evaluator all read this table;
// the GLSL names of the instruction kinds are generated from it (sdf/glsl_constants.hpp).
#pragma once

#include "sdf/bounds.hpp"
#include "sdf/param_spec.hpp"
#include "sdf/sdf_tree.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rmsc {

// Where a modifier acts: point modifiers move the evaluation point before the node is evaluated
// (SdfOpcode::PointModifier), distance modifiers change the node's distance afterwards
// (SdfOpcode::DistanceModifier); each in list order.
enum class ModifierStage { Point, Distance };

// The SdfModifier member a parameter is read into (by its type: Number float, Integer and Axis
// int, Vec3 vec3, IVec3 ivec3, Bool bool, Axes bvec3).
using ModifierField =
    std::variant<float SdfModifier::*, int SdfModifier::*, glm::vec3 SdfModifier::*,
                 glm::ivec3 SdfModifier::*, bool SdfModifier::*, glm::bvec3 SdfModifier::*>;

struct ModifierParam {
    SdfParamSpec spec;
    ModifierField field;
};

struct ModifierSpec {
    SdfModifierType type;
    std::string_view name; // JSON value of "type"
    ModifierStage stage;
    std::span<const ModifierParam> params;
    std::string_view description; // one line for the docs
    std::string_view source;      // where the formula comes from

    // The C++ formula (the instruction's params, as `pack` wrote them), mirroring the GLSL one
    // in shaders/common/sdf_functions.glsl: the moved point (Point), the changed distance d at
    // the point p (Distance).
    glm::vec3 (*movePoint)(glm::vec3 p, const glm::vec4* params) = nullptr;
    float (*changeDistance)(float d, glm::vec3 p, const glm::vec4* params) = nullptr;
    // The instruction's params[0..2]. `lengthScale` converts the modifier's lengths to the units
    // of the distance it changes (Distance); `cell` selects the neighbour cell (see `cells`),
    // -1 for none.
    void (*pack)(const SdfModifier& m, float lengthScale, int cell, glm::vec4* params) = nullptr;

    // Problems of a modifier beyond each parameter's range; bit i of `readOk` is set when
    // parameter i was read without error (or left at its default). nullptr: none.
    void (*check)(const SdfModifier& m, unsigned readOk,
                  std::vector<ParamProblem>& problems) = nullptr;
    // Distance modifiers only: the formula reads the point, so the node needs its own frame.
    bool readsPoint = false;
    // Point modifiers: how many times the rest of the node's chain is evaluated (a neighbour
    // check: once per cell, united); nullptr: once.
    int (*cells)(const SdfModifier& m) = nullptr;

    // Step correction: a point modifier's Lipschitz constant (the node's field is divided by the
    // product of them); nullptr: 1.
    double (*lipschitz)(const SdfModifier& m) = nullptr;
    // Step correction of a distance modifier: how much it adds to the field's gradient length
    // (the node's field is divided by 1 + the sum of them); nullptr: 0.
    double (*gradientGain)(const SdfModifier& m) = nullptr;

    // Bounds (sdf/bounds.hpp), point modifiers: the box of the points the modifier maps into
    // `box` (box of the content); distance modifiers: how much further out the modified field
    // reaches a level than the unmodified one (`growth`).
    SdfBounds (*preimage)(const SdfModifier& m, const Aabb& box) = nullptr;
    float (*growth)(const SdfModifier& m) = nullptr;
    // Distance modifiers: the same from the instruction's packed params (the field units the
    // instruction works in): the modified value is never more than this below the unmodified
    // one (the per-cell pruning's lower bounds, sdf/cell_pruning.hpp). nullptr: unknown.
    float (*packedGrowth)(const glm::vec4* params) = nullptr;
};

std::span<const ModifierSpec> modifierCatalogue();
const ModifierSpec& modifierSpec(SdfModifierType type);
const ModifierSpec* findModifier(std::string_view name); // nullptr if unknown
// The JSON names, in catalogue order.
std::vector<std::string> modifierNames();

inline bool isPointModifier(SdfModifierType type) {
    return modifierSpec(type).stage == ModifierStage::Point;
}

// The instruction kind (GpuSdfInstruction::kind) of a modifier: its place among the rows of its
// stage, in catalogue order.
std::uint32_t modifierKind(SdfModifierType type);
// The row of the instruction kind `kind` of `stage`; kind must be valid.
const ModifierSpec& modifierOfKind(ModifierStage stage, std::uint32_t kind);

// A modifier of `type` with every parameter at its catalogue default.
SdfModifier defaultModifier(SdfModifierType type);

} // namespace rmsc
