// What the readers of a scene file's sections share (scene_json.cpp), and the reader of its
// "sdf" tree (sdf_json.cpp): nodes, shapes and their parameters, groups and their operations,
// modifiers, profiles, "cut" and "shell". Internal to the scene layer.
#pragma once

#include "json_reader.hpp"
#include "sdf/sdf_tree.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rmsc {

// Everything the section readers share.
struct SceneReader {
    JsonReader json;
    std::filesystem::path sceneFolder;
    std::vector<std::string> materialNames; // Scene::materials order
    int sdfNodes = 0;                       // nodes read so far, pre-order
    bool sdfNodeLimitReported = false;
};

// Resolves a "material" reference to an index into Scene::materials; absent leaves *out.
bool readMaterialRef(const SceneReader& r, const Json& object, const std::string& pointer,
                     int* out);

// A mesh file named in the scene: relative to the scene's folder.
std::filesystem::path resolveMeshPath(const std::filesystem::path& sceneFolder,
                                      const std::string& file);

// Reads the SDF node at `pointer` and its subtree into `node`; `groupDepth` groups hold it.
void readSdfNode(SceneReader& r, const Json& object, const std::string& pointer, int groupDepth,
                 SdfNode& node);

} // namespace rmsc
