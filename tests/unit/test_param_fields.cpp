// The inspector's number fields against the scene reader (editor/param_fields.hpp): for every
// numeric parameter of the modifier, primitive and profile catalogues and for a group's
// smoothness, both ends of the field's range, written by the scene writer, are read back
// without an error, and the nearest value past each end is refused at that value's JSON pointer.
// A range written by hand in the inspector instead of taken from the catalogue fails here.
#include "editor/param_fields.hpp"
#include "scene/scene_json.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// A scene whose tree is `node`, written and read back: "" when it loads without an error,
// otherwise its errors, each as "POINTER: MESSAGE".
std::string errorsOfSaved(const SdfNode& node) {
    Scene scene;
    scene.sdf = node;
    Diagnostics d;
    parseScene(sceneToJson(scene), "fields.json", d);
    std::string errors;
    for (const Diagnostic& item : d.items)
        if (item.severity == Severity::Error) errors += item.location + ": " + item.message + "\n";
    return errors;
}

// The ends of a field and the values just past them.
struct Probe {
    double value;
    bool accepted;
};

std::vector<Probe> floatProbes(const FloatFieldRange& r) {
    std::vector<Probe> probes = {{r.min, true}, {r.max, true}};
    if (r.min > -std::numeric_limits<float>::max())
        probes.push_back({std::nextafter(r.min, -kInfinity), false});
    if (r.max < std::numeric_limits<float>::max())
        probes.push_back({std::nextafter(r.max, kInfinity), false});
    return probes;
}

std::vector<Probe> intProbes(const IntFieldRange& r) {
    return {
        {double(r.min), true}, {double(r.max), true}, {r.min - 1.0, false}, {r.max + 1.0, false}};
}

// Sets one number of `node` to `value`, saves and reads back: accepted must say whether the
// reader took it; refused values must be refused at `pointer`.
void expectReaderAgrees(SdfNode node, const std::function<void(SdfNode&, double)>& set,
                        const Probe& probe, const std::string& pointer, const std::string& what) {
    set(node, probe.value);
    const std::string errors = errorsOfSaved(node);
    if (probe.accepted) {
        EXPECT_EQ(errors, "") << what << " = " << probe.value << " is an end of the field";
    } else {
        EXPECT_NE(errors.find(pointer + ": "), std::string::npos)
            << what << " = " << probe.value << " is past the field's end, so the reader must "
            << "refuse it at " << pointer << "; errors:\n"
            << errors;
    }
}

SdfNode sphere() {
    SdfNode node;
    node.primitive = PrimitiveId::Sphere;
    node.params = defaultParams(primitiveSpec(PrimitiveId::Sphere));
    return node;
}

// A modifier of `type` whose other parameters let each one reach both ends of its range: every
// number at the value of its range nearest 0, and a repetition repeated on every axis (its
// check wants a period > 0 where a count is given).
SdfModifier baseModifier(SdfModifierType type) {
    SdfModifier m = defaultModifier(type);
    for (const ModifierParam& param : modifierSpec(type).params) {
        const FloatFieldRange f = floatFieldRange(param.spec.range);
        const IntFieldRange i = intFieldRange(param.spec.range);
        std::visit(
            [&](auto member) {
                auto& value = m.*member;
                using T = std::decay_t<decltype(value)>;
                if constexpr (std::is_same_v<T, float> || std::is_same_v<T, glm::vec3>)
                    value = T(std::clamp(0.0f, f.min, f.max));
                else if constexpr (std::is_same_v<T, glm::ivec3>)
                    value = T(std::clamp(0, i.min, i.max));
                else if constexpr (std::is_same_v<T, int>)
                    if (param.spec.type == ParamType::Integer) value = std::clamp(0, i.min, i.max);
            },
            param.field);
    }
    if (type == SdfModifierType::Repeat) m.vector = glm::vec3(1.0f);
    return m;
}

int componentsOf(ParamType type) {
    switch (type) {
    case ParamType::Number:
    case ParamType::Integer:
        return 1;
    case ParamType::Vec2:
        return 2;
    case ParamType::Vec3:
    case ParamType::IVec3:
        return 3;
    default:
        return 0; // not a number field
    }
}

} // namespace

TEST(ParamFields, ExclusiveAndUnboundedEndsBecomeTheNearestFloatInside) {
    const FloatFieldRange open = floatFieldRange(openClosedRange(0.0, 10.0));
    EXPECT_EQ(open.min, std::nextafter(0.0f, 1.0f));
    EXPECT_EQ(open.max, 10.0f);
    const FloatFieldRange any = floatFieldRange({});
    EXPECT_EQ(any.min, -std::numeric_limits<float>::max());
    EXPECT_EQ(any.max, std::numeric_limits<float>::max());
    // 0.1 is not a float: the field's end is the float nearest it on the inside.
    const FloatFieldRange tenth = floatFieldRange(closedRange(0.1, 0.3));
    EXPECT_GE(double(tenth.min), 0.1);
    EXPECT_LT(double(std::nextafter(tenth.min, 0.0f)), 0.1);
    EXPECT_LE(double(tenth.max), 0.3);
    EXPECT_GT(double(std::nextafter(tenth.max, 1.0f)), 0.3);
    const IntFieldRange ints = intFieldRange({0.0, 8.0, true, true});
    EXPECT_EQ(ints.min, 1);
    EXPECT_EQ(ints.max, 7);
}

TEST(ParamFields, EveryModifierFieldTakesExactlyWhatTheReaderAccepts) {
    int checked = 0;
    for (const ModifierSpec& spec : modifierCatalogue()) {
        for (const ModifierParam& param : spec.params) {
            const int components = componentsOf(param.spec.type);
            for (int c = 0; c < components; ++c) {
                SdfNode node = sphere();
                node.modifiers = {baseModifier(spec.type)};
                ASSERT_EQ(errorsOfSaved(node), "") << spec.name << ": the base must load";
                const auto set = [&](SdfNode& n, double v) {
                    std::visit(
                        [&](auto member) {
                            auto& value = n.modifiers[0].*member;
                            using T = std::decay_t<decltype(value)>;
                            if constexpr (std::is_same_v<T, float>)
                                value = float(v);
                            else if constexpr (std::is_same_v<T, int>)
                                value = int(v);
                            else if constexpr (std::is_same_v<T, glm::vec3>)
                                value[c] = float(v);
                            else if constexpr (std::is_same_v<T, glm::ivec3>)
                                value[c] = int(v);
                        },
                        param.field);
                };
                std::string pointer = "/sdf/modifiers/0/" + std::string(param.spec.key);
                if (components > 1) pointer += "/" + std::to_string(c);
                const bool integer =
                    param.spec.type == ParamType::Integer || param.spec.type == ParamType::IVec3;
                const std::vector<Probe> probes =
                    integer ? intProbes(intFieldRange(param.spec.range))
                            : floatProbes(floatFieldRange(param.spec.range));
                for (const Probe& probe : probes)
                    expectReaderAgrees(node, set, probe, pointer,
                                       std::string(spec.name) + " " + pointer);
                ++checked;
            }
        }
    }
    EXPECT_GE(checked, 20);
}

TEST(ParamFields, EveryPrimitiveFieldTakesExactlyWhatTheReaderAccepts) {
    int checked = 0;
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        for (int i = 0; i < int(spec.params.size()); ++i) {
            const ParamSpec& param = spec.params[std::size_t(i)];
            for (int c = 0; c < param.components; ++c) {
                SdfNode node;
                node.primitive = spec.id;
                node.params = defaultParams(spec);
                ASSERT_EQ(errorsOfSaved(node), "") << spec.name << ": the defaults must load";
                const int at = paramOffset(spec, i) + c;
                const auto set = [&](SdfNode& n, double v) {
                    n.params[std::size_t(at)] = float(v);
                };
                std::string pointer = "/sdf/" + std::string(param.name);
                if (param.components > 1) pointer += "/" + std::to_string(c);
                for (const Probe& probe : floatProbes(primitiveFieldRange(param)))
                    expectReaderAgrees(node, set, probe, pointer,
                                       std::string(spec.name) + " " + pointer);
                ++checked;
            }
        }
    }
    EXPECT_GE(checked, int(primitiveCatalogue().size()));
}

TEST(ParamFields, EveryProfileFieldTakesExactlyWhatTheReaderAccepts) {
    int checked = 0;
    const auto probeProfile = [&](SdfProfile profile, const ProfileParam& param,
                                  const std::string& pointerBase, const std::string& what) {
        const int components = componentsOf(param.spec.type);
        for (int c = 0; c < components; ++c) {
            SdfNode node;
            node.profile = profile;
            ASSERT_EQ(errorsOfSaved(node), "") << what << ": the base must load";
            const auto set = [&](SdfNode& n, double v) {
                std::visit(
                    [&](auto member) {
                        auto& value = (*n.profile).*member;
                        using T = std::decay_t<decltype(value)>;
                        if constexpr (std::is_same_v<T, float>)
                            value = float(v);
                        else if constexpr (std::is_same_v<T, glm::vec2>)
                            value[c] = float(v);
                    },
                    param.field);
            };
            std::string pointer = pointerBase + std::string(param.spec.key);
            if (components > 1) pointer += "/" + std::to_string(c);
            for (const Probe& probe : floatProbes(floatFieldRange(param.spec.range)))
                expectReaderAgrees(node, set, probe, pointer, what + " " + pointer);
            ++checked;
        }
    };
    for (const ProfileSpec& spec : profileCatalogue()) {
        if (spec.type == SdfProfileType::Polygon) continue; // points: no number field
        SdfProfile profile;
        profile.type = spec.type;
        // Half sizes as large as they go, corners as round as 0: the rounded rectangle's check
        // (radius at most the smaller half size) then holds at every end of the other key.
        profile.halfSize = glm::vec2(floatFieldRange(spec.params[0].spec.range).max);
        if (spec.type == SdfProfileType::RoundedRectangle) profile.radius = 0.0f;
        for (const ProfileParam& param : spec.params) {
            SdfProfile base = profile;
            if (param.spec.key == "half_size") base.radius = 0.0f;
            probeProfile(base, param, "/sdf/profile/", std::string(spec.name));
        }
    }
    for (const ProfileSolidSpec& solid : profileSolidCatalogue()) {
        SdfProfile profile;
        profile.solid = solid.solid;
        probeProfile(profile, solid.param, "/sdf/", std::string(solid.name));
    }
    EXPECT_GE(checked, 6);
}

TEST(ParamFields, SmoothnessFieldTakesExactlyWhatTheReaderAccepts) {
    for (const OperationSpec& op : operationCatalogue()) {
        if (!takesSmoothness(op.op)) continue;
        SdfNode group;
        group.isGroup = true;
        group.op = op.op;
        group.smoothness = 0.1f;
        group.children = {sphere(), sphere()};
        const auto set = [](SdfNode& n, double v) { n.smoothness = float(v); };
        for (const Probe& probe : floatProbes(smoothnessFieldRange()))
            expectReaderAgrees(group, set, probe, "/sdf/smoothness", std::string(op.name));
    }
    // 0, what typing 0 into the field gave before, is below the field.
    EXPECT_GT(smoothnessFieldRange().min, 0.0f);
}
