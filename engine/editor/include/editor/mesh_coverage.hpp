// Whether a point of a mesh triangle is drawn, as the raster pass decides it: the side it is
// seen from (single-sided materials cull back faces) and, for MASK materials, its alpha
// against the cutoff. Picking skips what the image does not show.
#pragma once

#include "scene/mesh_asset.hpp"

namespace rmsc::editor {

// The base colour alpha at barycentric weights (u of b, v of c) of the triangle (a, b, c) of a
// primitive with material `m`: the factor's alpha, the vertex colours' and the base colour
// texture's (nearest texel, with its sampler's wrap modes and its KHR_texture_transform).
float meshAlphaAt(const MeshAsset& asset, const MeshMaterial& m, const MeshVertex& a,
                  const MeshVertex& b, const MeshVertex& c, float u, float v);

// Whether the raster pass draws that point of `primitive` when seen from the front (frontFace)
// or the back.
bool meshPointDrawn(const MeshAsset& asset, const MeshPrimitive& primitive, const MeshVertex& a,
                    const MeshVertex& b, const MeshVertex& c, float u, float v, bool frontFace);

} // namespace rmsc::editor
