// The inspector's number fields (editor/param_fields.hpp): units from the catalogue rows, the
// help each field shows (what, unit, range), and the clamping of typed values with the notice
// the field shows and for how long.
#include "editor/param_fields.hpp"

#include "core/units.hpp"
#include "scene/camera_spec.hpp"
#include "scene/environment_spec.hpp"
#include "scene/light_spec.hpp"
#include "scene/material_spec.hpp"
#include "scene/render_spec.hpp"
#include "sdf/modifiers.hpp"
#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"
#include "sdf/profiles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace rmsc;
using namespace rmsc::editor;

TEST(FieldHelp, CatalogueRowsHaveUnits) {
    // Every primitive length is in metres, every angle in degrees, iterations are counts.
    for (const PrimitiveSpec& spec : primitiveCatalogue())
        for (const ParamSpec& p : spec.params) {
            if (p.name == "angle") {
                EXPECT_EQ(p.unit, Unit::Degrees) << spec.name;
            } else if (p.name == "iterations") {
                EXPECT_EQ(p.unit, Unit::Count) << spec.name;
            } else if (p.name.find("radius") != std::string_view::npos ||
                       p.name.find("half") != std::string_view::npos || p.name == "height") {
                EXPECT_EQ(p.unit, Unit::Metres) << spec.name << " " << p.name;
            }
        }
    EXPECT_EQ(smoothnessParam().range.unit, Unit::Metres);
    for (const ModifierSpec& spec : modifierCatalogue())
        for (const ModifierParam& p : spec.params) {
            if (p.spec.type == ParamType::Number || p.spec.type == ParamType::Vec3 ||
                p.spec.type == ParamType::Integer || p.spec.type == ParamType::IVec3) {
                EXPECT_NE(p.spec.range.unit, Unit::None) << spec.name << " " << p.spec.key;
            }
        }
    for (const ProfileSpec& spec : profileCatalogue())
        for (const ProfileParam& p : spec.params)
            EXPECT_EQ(p.spec.range.unit, Unit::Metres) << spec.name << " " << p.spec.key;
    EXPECT_EQ(kCameraFovRange.unit, Unit::Degrees);
    EXPECT_EQ(kCameraNearRange.unit, Unit::Metres);
    EXPECT_EQ(kFogDensityRange.unit, Unit::PerMetre);
    EXPECT_EQ(kSpotOuterAngleRange.unit, Unit::Degrees);
    EXPECT_EQ(kShadowMapSizeRange.unit, Unit::Pixels);
    EXPECT_EQ(kRoughnessRange.unit, Unit::Ratio);
    EXPECT_EQ(lightIntensityUnit(LightType::Directional), Unit::Lux);
    EXPECT_EQ(lightIntensityUnit(LightType::Spot), Unit::Candela);
}

TEST(FieldHelp, RangeTextAndHelp) {
    EXPECT_EQ(rangeText(closedRange(0.001, 10.0)), "[0.001, 10]");
    EXPECT_EQ(rangeText(openClosedRange(0.0, 10000.0)), "(0, 10000]");
    EXPECT_EQ(rangeText(kCameraFovRange), "(0, 180)");
    EXPECT_EQ(rangeText(kCameraNearRange), "> 0");
    EXPECT_EQ(rangeText(kLightIntensityRange), ">= 0");
    EXPECT_EQ(rangeText({-std::numeric_limits<double>::infinity(), 10.0, false, true}), "< 10");
    EXPECT_EQ(rangeText(ParamRange{}), "any");

    EXPECT_EQ(fieldHelp("radius", closedRange(0.0, 10000.0, Unit::Metres)),
              "radius\nUnit: metres\nRange: [0, 10000]");
    EXPECT_EQ(fieldHelp("", kCameraFovRange), "Unit: degrees\nRange: (0, 180)");
    EXPECT_EQ(fieldHelp("exponent", closedRange(2.0, 16.0)), "exponent\nRange: [2, 16]")
        << "no unit line for a plain number";
    const ParamSpec& radius = primitiveSpec(PrimitiveId::Sphere).params[0];
    EXPECT_EQ(fieldHelp(radius.description, primitiveParamRange(radius)),
              "radius\nUnit: metres\nRange: [0, 10000]");
}

TEST(FieldHelp, TypedValuesAreClampedAndSaySo) {
    const ParamRange smoothness = smoothnessParam().range;
    const FloatFieldRange field = floatFieldRange(smoothness);
    EXPECT_EQ(field.min, 0.001f);
    const ClampedValue low = clampToField(0.0f, field);
    EXPECT_TRUE(low.clamped);
    EXPECT_EQ(low.value, 0.001f);
    const ClampedValue inside = clampToField(0.5f, field);
    EXPECT_FALSE(inside.clamped);
    EXPECT_EQ(inside.value, 0.5f);
    EXPECT_EQ(clampNotice(smoothness), "clamped to >= 0.001 m");

    const ParamRange fog = kFogDensityRange;
    const ClampedValue high = clampToField(50.0f, floatFieldRange(fog));
    EXPECT_TRUE(high.clamped);
    EXPECT_EQ(high.value, 10.0f);
    EXPECT_EQ(clampNotice(fog), "clamped to [0, 10] 1/m");
    const ClampedValue nan = clampToField(std::nanf(""), floatFieldRange(fog));
    EXPECT_TRUE(nan.clamped);
    EXPECT_EQ(nan.value, 0.0f);
    const ClampedValue infinite =
        clampToField(std::numeric_limits<float>::infinity(), floatFieldRange(fog));
    EXPECT_TRUE(infinite.clamped);
    EXPECT_EQ(infinite.value, 10.0f);
    // An exclusive end clamps to the nearest value the reader accepts.
    const ClampedValue zero = clampToField(0.0f, floatFieldRange(kCameraNearRange));
    EXPECT_TRUE(zero.clamped);
    EXPECT_GT(zero.value, 0.0f);

    const ClampedInt steps = clampToField(5000, intFieldRange(kMaxStepsRange));
    EXPECT_TRUE(steps.clamped);
    EXPECT_EQ(steps.value, 4096);
    EXPECT_FALSE(clampToField(64, intFieldRange(kMaxStepsRange)).clamped);
    EXPECT_EQ(clampNotice(kMaxStepsRange), "clamped to [1, 4096]") << "a count has no symbol";
    EXPECT_EQ(clampNotice(kSkyRotationRange), "clamped to [-360, 360] \u00b0");
}

TEST(FieldHelp, TheNoticeIsShortLived) {
    EXPECT_FALSE(clampNoticeShown(-1.0, 5.0)) << "never clamped";
    EXPECT_TRUE(clampNoticeShown(5.0, 5.0));
    EXPECT_TRUE(clampNoticeShown(5.0, 5.0 + kClampNoticeSeconds - 0.01));
    EXPECT_FALSE(clampNoticeShown(5.0, 5.0 + kClampNoticeSeconds));
    EXPECT_FALSE(clampNoticeShown(5.0, 4.0)) << "a clock that went back";
}

TEST(FieldHelp, UnitWords) {
    EXPECT_EQ(unitSymbol(Unit::Metres), "m");
    EXPECT_EQ(unitName(Unit::DegreesPerMetre), "degrees per metre");
    EXPECT_EQ(unitPhrase(Unit::Metres), "in metres");
    EXPECT_EQ(unitPhrase(Unit::Count), "a count");
    EXPECT_EQ(unitPhrase(Unit::PerMetre), "per metre");
    EXPECT_EQ(unitPhrase(Unit::None), "");
    for (int u = 1; u <= int(Unit::Lux); ++u) {
        EXPECT_FALSE(unitName(Unit(u)).empty()) << u;
        EXPECT_FALSE(unitPhrase(Unit(u)).empty()) << u;
    }
}
