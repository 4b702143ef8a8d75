// Which optional parts of the shading code a scene's programs are built with: the text of the
// virtual include "generated/shading.glsl" (common/lighting.glsl, common/sdf_textures.glsl).
//
// Shadows, ambient occlusion and the SDF materials' textures each inline the scene's SDF map
// once more (a shadow ray and the occlusion taps march it, a texture's frame reads the surface
// beside the hit). A frame that has them off paid for them anyway on llvmpipe, which runs the
// code of a branch, and a loop's body once, whether or not a pixel takes it: a sixth of the
// frame of the 4,096-sphere tree and a quarter of the 10-shape grid's (docs/performance.md). So
// each is compiled only where the frame uses it; the uniforms still say how much of it runs.
#pragma once

#include "core/render_settings.hpp"

#include <string>

namespace rmsc {

struct ShadingCode {
    bool shadows = true;          // soft shadows through the SDF and the mesh shadow maps
    bool ambientOcclusion = true; // the SDF's ambient occlusion
    bool sdfTextures = true;      // material textures on SDF surfaces

    bool operator==(const ShadingCode&) const = default;
    // Does this code hold every part `other` has? (Programs built with it draw a frame that
    // needs `other` the same: the frame's uniforms turn off what it holds beyond.)
    bool holds(const ShadingCode& other) const {
        return (shadows || !other.shadows) && (ambientOcclusion || !other.ambientOcclusion) &&
               (sdfTextures || !other.sdfTextures);
    }
};

// What a frame drawn with `settings` needs, where the scene's materials have textures or not.
ShadingCode shadingCode(const RenderSettings& settings, bool sdfTextures);

// The text of "generated/shading.glsl" (SHADING_SHADOWS, SHADING_AMBIENT_OCCLUSION,
// SHADING_SDF_TEXTURES, each defined when on). Two codes give the same text only when equal, so
// it keys the programs built with it.
std::string shadingDefines(const ShadingCode& code);

} // namespace rmsc
