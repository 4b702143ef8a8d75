// rmsc public API: the triangles of a glTF file, as rmsc reads them, for hosts that draw a model
// themselves and want it to meet SDF objects the way `rmsc render` places it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rmsc::api {

// Every triangle primitive of the file's default scene (points and lines are left out), node
// transforms applied, in one indexed list.
struct Triangles {
    std::vector<float> positions;       // x, y, z per vertex
    std::vector<float> normals;         // x, y, z per vertex, unit length
    std::vector<std::uint32_t> indices; // three per triangle
};

// Throws Error (BadInput) with the file and glTF element of every problem.
Triangles loadTriangles(const std::string& gltfPath);

} // namespace rmsc::api
