// Writing an exported mesh: glTF 2.0 (.gltf with the buffer embedded as a data URI, or binary
// .glb), Wavefront OBJ (with its .mtl beside it) and binary STL. Every file is written
// atomically (core/atomic_file.hpp): on failure, or when `cancel` is set while writing, the
// output is left as it was.
#pragma once

#include "core/material.hpp"
#include "export/export_mesh.hpp"

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

namespace rmsc {

enum class MeshFormat { Gltf, Glb, Obj, Stl };

// The format named by the file's extension (case-insensitive); false for any other.
bool meshFormatOf(const std::filesystem::path& path, MeshFormat& format);

struct MeshFile {
    const ExportMesh& mesh;
    const std::vector<Material>& materials; // indexed by the mesh's material indices
    std::string name;                       // the glTF node's and mesh's name
};

// The glTF document: one node, one mesh with one primitive per material, one material per rmsc
// material. Each primitive has vertices of its own (POSITION, NORMAL), so a vertex where two
// materials meet is in both. A primitive where smooth operations blended the base colour away
// from its material's also has COLOR_0, the blended linear base colour itself, and its
// material's baseColorFactor is white: glTF multiplies the two (glTF 2.0, "Meshes" and
// "Metallic-Roughness Material"), so the base colour it shows is the blended one, whatever the
// material's own colour (a channel that is 0 in the material's colour stays blendable). A
// primitive without blending keeps the material's colour as its factor and has no COLOR_0.
std::string gltfBytes(const MeshFile& file, bool binary);
std::string objText(const MeshFile& file, const std::string& mtlFileName);
std::string mtlText(const MeshFile& file);
std::string stlBytes(const MeshFile& file);

// Writes `file` to `path` in `format`; false with `error` saying why (the path named).
bool writeMeshFile(const std::filesystem::path& path, MeshFormat format, const MeshFile& file,
                   const std::atomic<bool>* cancel, std::string& error);

} // namespace rmsc
