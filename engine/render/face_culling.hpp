// Which faces of a mesh primitive are drawn, one rule for the raster and the shadow pass (and
// the same as picking's, editor/mesh_coverage.hpp): a single-sided glTF material (and the glTF
// default material) culls its back faces; a double-sided one and a scene material override
// draw both.
#pragma once

#include "render/gpu_scene.hpp"

namespace rmsc {

// Whether both faces of `primitive`, drawn for `instance`, are drawn.
bool drawsBothFaces(const GpuScene& scene, const GpuMeshInstance& instance,
                    const GpuMeshPrimitive& primitive);

// Sets the winding of front faces for `instance`: a mirroring transform turns the glTF's
// counter-clockwise triangles clockwise.
void setFrontFace(const GpuMeshInstance& instance);

// Enables back-face culling, or disables culling when `bothFaces`.
void setFaceCulling(bool bothFaces);

} // namespace rmsc
