// What a glTF file keeps after loading so that it can be drawn in another pose: each mesh's
// primitives in their own space with their morph targets and skin weights, the node hierarchy
// at rest, the skins, the animations and the cameras. poseMeshAsset (mesh_pose.hpp) bakes a
// pose of it into MeshAsset::primitives; loading bakes the rest pose.
#pragma once

#include "scene/gltf_animation.hpp"
#include "scene/mesh_asset.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rmsc {

// One morph target of a primitive: per-vertex deltas, each empty when the target lacks it.
struct MorphTarget {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec3> tangents;
};

// One primitive as stored in the file, in its mesh's local space.
struct RigPrimitive {
    bool drawable = false; // false for primitives skipped with a warning
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;     // empty when the file has none
    std::vector<glm::vec2> uvs;         // TEXCOORD_0, zeros when absent
    std::vector<glm::vec2> uvs1;        // TEXCOORD_1, zeros when absent
    std::vector<glm::vec4> tangents;    // empty when the file has none
    std::vector<glm::vec4> colors;      // COLOR_0 as RGBA, empty when the file has none
    std::vector<std::uint32_t> indices; // indicesPerElement(mode) per element
    PrimitiveMode mode = PrimitiveMode::Triangles;
    int material = -1;
    int tangentUvSet = 0; // the TEXCOORD set of the material's normal texture
    std::vector<MorphTarget> targets;
    // JOINTS_0 / WEIGHTS_0 and JOINTS_1 / WEIGHTS_1: four joints (indices into the skin's
    // joints) and their weights per vertex and set; a set is empty when the file lacks it.
    std::array<std::vector<glm::uvec4>, 2> joints;
    std::array<std::vector<glm::vec4>, 2> weights;
};

struct RigMesh {
    std::vector<RigPrimitive> primitives;
    std::vector<float> weights; // mesh.weights: the default morph weights (zeros without)
};

struct RigNode {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    bool hasMatrix = false; // a node with "matrix" (never animated: glTF 2.0 section 3.11)
    glm::dmat4 matrix{1.0};
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0}; // w, x, y, z
    glm::dvec3 scale{1.0};
    int mesh = -1;
    int skin = -1;
    int camera = -1;
    std::vector<float> weights; // node.weights, overriding the mesh's; empty when absent
};

struct RigSkin {
    std::vector<int> joints;             // nodes
    std::vector<glm::dmat4> inverseBind; // per joint; identity when the file gives none
};

// A glTF camera (glTF 2.0 section 3.10), placed by the first node of the drawn scene using it.
struct RigCamera {
    std::string name;
    bool orthographic = false;
    double yfov = 0.8;   // perspective: vertical field of view, radians
    double aspect = 0.0; // perspective: width / height, 0 when the file gives none
    double xmag = 1.0;   // orthographic: half width
    double ymag = 1.0;   // orthographic: half height
    double znear = 0.01;
    double zfar = 0.0; // 0: infinite (perspective only)
    int node = -1;     // the node placing it in the drawn scene, -1 when none does
};

struct MeshRig {
    std::vector<RigNode> nodes;
    std::vector<int> roots;     // of the scene drawn
    std::vector<int> instances; // nodes of the drawn scene with a mesh, in drawing order
    std::vector<RigMesh> meshes;
    std::vector<RigSkin> skins;
    std::vector<Animation> animations;
    std::vector<RigCamera> cameras;
    std::vector<std::string> sceneNames; // of every scene of the file ("" when unnamed)
    int scene = -1;                      // the scene drawn, -1 for every root node
};

} // namespace rmsc
