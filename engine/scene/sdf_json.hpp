// What the readers of a scene file's sections share (scene_json.cpp), and the reader of its
// "sdf" tree (sdf_json.cpp): nodes, shapes and their parameters, groups and their operations,
// modifiers, profiles, "cut" and "shell". Internal to the scene layer.
#pragma once

#include "json_reader.hpp"
#include "sdf/sdf_tree.hpp"

#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace rmsc {

// Everything the section readers share.
struct SceneReader {
    JsonReader json;
    std::filesystem::path sceneFolder;
    std::vector<std::string> materialNames;             // Scene::materials order
    std::unordered_map<std::string, int> materialIndex; // name to index into materialNames
    // Unknown material references whose message got a "did you mean" (each compares the name
    // with every material): only as many as the diagnostics keep, so a scene of many nodes
    // naming unknown materials among many materials stays linear.
    int unknownMaterialsExplained = 0;
    int sdfNodes = 0; // nodes read so far, pre-order
    bool sdfNodeLimitReported = false;
};

// Resolves a "material" reference to an index into Scene::materials; absent leaves *out.
bool readMaterialRef(SceneReader& r, const Json& object, const std::string& pointer, int* out);

// A mesh file named in the scene: relative to the scene's folder.
std::filesystem::path resolveMeshPath(const std::filesystem::path& sceneFolder,
                                      const std::string& file);

// Reads the SDF node at `pointer` and its subtree into `node`; `groupDepth` groups hold it.
void readSdfNode(SceneReader& r, const Json& object, const std::string& pointer, int groupDepth,
                 SdfNode& node);

} // namespace rmsc
