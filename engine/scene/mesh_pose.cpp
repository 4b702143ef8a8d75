// Posing a glTF file's rig: node transforms from the animation's channels, morph weights and
// skins applied to each instanced primitive on the CPU, and the joint matrices the GPU skins
// with (see mesh_pose.hpp).
#include "scene/mesh_pose.hpp"

#include "scene/gltf_geometry.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace rmsc {

namespace {

struct NodeState {
    glm::dvec3 translation;
    glm::dquat rotation;
    glm::dvec3 scale;
    bool animated = false;
    std::vector<float> weights; // animated morph weights; empty when no channel drives them
};

// Node transforms and weights at the pose: the rest values, with the animation's channels
// (glTF 2.0 section 3.11) written over them, and the world matrices.
void evaluate(const MeshRig& rig, const MeshPose& pose, std::vector<glm::dmat4>& worlds,
              std::vector<NodeState>& states) {
    states.resize(rig.nodes.size());
    for (std::size_t n = 0; n < rig.nodes.size(); ++n)
        states[n] = {
            rig.nodes[n].translation, rig.nodes[n].rotation, rig.nodes[n].scale, false, {}};
    if (pose.animation >= 0 && std::size_t(pose.animation) < rig.animations.size()) {
        const Animation& animation = rig.animations[std::size_t(pose.animation)];
        std::vector<float> value;
        for (const AnimationChannel& channel : animation.channels) {
            const AnimationSampler& sampler = animation.samplers[std::size_t(channel.sampler)];
            NodeState& state = states[std::size_t(channel.node)];
            value.assign(std::size_t(sampler.width), 0.0f);
            sampleAnimation(sampler, pose.time, channel.path == AnimationPath::Rotation,
                            value.data());
            switch (channel.path) {
            case AnimationPath::Translation:
                state.translation = glm::dvec3(value[0], value[1], value[2]);
                break;
            case AnimationPath::Rotation:
                state.rotation = glm::dquat(value[3], value[0], value[1], value[2]);
                break;
            case AnimationPath::Scale:
                state.scale = glm::dvec3(value[0], value[1], value[2]);
                break;
            case AnimationPath::Weights:
                state.weights = value;
                break;
            }
            if (channel.path != AnimationPath::Weights) state.animated = true;
        }
    }
    worlds.assign(rig.nodes.size(), glm::dmat4(1.0));
    // The hierarchy is a tree no deeper than the node depth limit (checked when loading).
    std::vector<int> stack;
    for (std::size_t n = 0; n < rig.nodes.size(); ++n)
        if (rig.nodes[n].parent < 0) stack.push_back(int(n));
    while (!stack.empty()) {
        const std::size_t n = std::size_t(stack.back());
        stack.pop_back();
        const RigNode& node = rig.nodes[n];
        const NodeState& state = states[n];
        glm::dmat4 local = node.matrix;
        if (!node.hasMatrix || state.animated) {
            // glTF 2.0 section 3.5.3: the local transform is T * R * S.
            local = glm::translate(glm::dmat4(1.0), state.translation) *
                    glm::mat4_cast(glm::normalize(state.rotation)) *
                    glm::scale(glm::dmat4(1.0), state.scale);
        }
        worlds[n] = (node.parent >= 0 ? worlds[std::size_t(node.parent)] : glm::dmat4(1.0)) * local;
        for (int child : node.children)
            stack.push_back(child);
    }
}

// `source` with its morph targets applied at `weights` (glTF 2.0 section 3.7.2.2: each
// attribute is its base value plus the weighted sum of the targets' deltas).
RigPrimitive morphed(const RigPrimitive& source, const std::vector<float>& weights) {
    RigPrimitive out = source;
    const std::size_t count = std::min(weights.size(), source.targets.size());
    for (std::size_t t = 0; t < count; ++t) {
        const float w = weights[t];
        if (w == 0.0f) continue;
        const MorphTarget& target = source.targets[t];
        if (!target.positions.empty())
            for (std::size_t i = 0; i < out.positions.size(); ++i)
                out.positions[i] += w * target.positions[i];
        if (!target.normals.empty() && !out.normals.empty())
            for (std::size_t i = 0; i < out.normals.size(); ++i)
                out.normals[i] += w * target.normals[i];
        if (!target.tangents.empty() && !out.tangents.empty())
            for (std::size_t i = 0; i < out.tangents.size(); ++i)
                out.tangents[i] += glm::vec4(w * target.tangents[i], 0.0f);
    }
    return out;
}

// Each vertex's joints and weights of both sets; a joint whose weight is zero is written as 0,
// so that the GPU never reads a matrix the skin does not have.
std::vector<MeshSkinVertex> skinVerticesOf(const RigPrimitive& source) {
    std::vector<MeshSkinVertex> out(source.positions.size());
    for (std::size_t set = 0; set < 2; ++set) {
        if (source.joints[set].empty()) continue;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const glm::vec4 w = source.weights[set][i];
            glm::uvec4 j = source.joints[set][i];
            for (int c = 0; c < 4; ++c)
                if (w[c] == 0.0f) j[c] = 0u;
            (set == 0 ? out[i].joints0 : out[i].joints1) = j;
            (set == 0 ? out[i].weights0 : out[i].weights1) = w;
        }
    }
    return out;
}

// The bind vertices of `primitive` skinned (glTF 2.0 section 3.7.3, "Skins") into its
// vertices: each vertex moved by the weighted sum of its joints' matrices, jointMatrix =
// world(joint) * inverseBindMatrix (asset.jointMatrices from jointBase + 1), into the asset's
// root space (the transform of the skinned mesh's own node is not applied). A vertex whose
// weights are all zero keeps the mesh node's transform (the matrix at jointBase). Normals are
// moved by the inverse transpose of the blended matrix, tangents by the matrix itself; the
// vertex shaders (shaders/common/skinning.glsl) do the same on the GPU.
bool skinVertices(MeshPrimitive& primitive, const std::vector<glm::mat4>& matrices,
                  std::size_t jointCount, const std::string& pointer, gltf::Reporter& report) {
    const std::size_t base = std::size_t(primitive.jointBase);
    for (std::size_t i = 0; i < primitive.bindVertices.size(); ++i) {
        const MeshSkinVertex& s = primitive.skin[i];
        glm::dmat4 m(0.0);
        double total = 0.0;
        for (std::size_t set = 0; set < 2; ++set) {
            const glm::uvec4 joints = set == 0 ? s.joints0 : s.joints1;
            const glm::vec4 weights = set == 0 ? s.weights0 : s.weights1;
            for (int c = 0; c < 4; ++c) {
                const double w = weights[c];
                if (w == 0.0) continue;
                if (joints[c] >= jointCount) {
                    report.error(pointer + "/attributes/JOINTS_" + std::to_string(set),
                                 "vertex " + std::to_string(i) + " uses joint " +
                                     std::to_string(joints[c]) + " but the node's skin has " +
                                     std::to_string(jointCount) +
                                     " joints, expected an index below that");
                    return false;
                }
                m += w * glm::dmat4(matrices[base + 1 + joints[c]]);
                total += w;
            }
        }
        if (!(total > 0.0)) m = glm::dmat4(matrices[base]);
        const MeshVertex& bind = primitive.bindVertices[i];
        MeshVertex& out = primitive.vertices[i];
        out = bind;
        out.position = glm::vec3(m * glm::dvec4(glm::dvec3(bind.position), 1.0));
        if (!std::isfinite(out.position.x) || !std::isfinite(out.position.y) ||
            !std::isfinite(out.position.z)) {
            report.error(pointer, "the skin's joint matrices make positions infinite or NaN");
            return false;
        }
        const glm::dmat3 linear(m);
        const double det = glm::determinant(linear);
        const glm::dmat3 normalMatrix =
            std::abs(det) > 1e-300 ? glm::inverseTranspose(linear) : linear;
        const glm::dvec3 n = normalMatrix * glm::dvec3(bind.normal);
        const double length = glm::length(n);
        out.normal =
            length > 1e-12 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0.0f);
        glm::dvec3 t = linear * glm::dvec3(glm::vec3(bind.tangent));
        t -= glm::dvec3(out.normal) * glm::dot(glm::dvec3(out.normal), t);
        const double tangentLength = glm::length(t);
        if (tangentLength > 1e-12 && std::isfinite(tangentLength))
            out.tangent = glm::vec4(glm::vec3(t / tangentLength), bind.tangent.w);
    }
    return true;
}

} // namespace

std::vector<glm::dmat4> poseNodeWorlds(const MeshRig& rig, const MeshPose& pose) {
    std::vector<glm::dmat4> worlds;
    std::vector<NodeState> states;
    evaluate(rig, pose, worlds, states);
    return worlds;
}

namespace gltf {

bool bakePose(const MeshRig& rig, const MeshPose& pose, Reporter& report, MeshAsset& asset) {
    std::vector<glm::dmat4> worlds;
    std::vector<NodeState> states;
    evaluate(rig, pose, worlds, states);
    MeshAsset baked; // only its primitives and joint matrices are filled
    RigPrimitive scratch;
    for (const int n : rig.instances) {
        const RigNode& node = rig.nodes[std::size_t(n)];
        const RigMesh& mesh = rig.meshes[std::size_t(node.mesh)];
        const std::string pointer = "/nodes/" + std::to_string(n);
        // Animated weights, else the node's, else the mesh's (glTF 2.0 section 3.7.2.2).
        const std::vector<float>& weights = !states[std::size_t(n)].weights.empty()
                                                ? states[std::size_t(n)].weights
                                            : !node.weights.empty() ? node.weights
                                                                    : mesh.weights;
        const bool skin = node.skin >= 0 && std::size_t(node.skin) < rig.skins.size();
        const std::size_t jointBase = baked.jointMatrices.size();
        std::size_t jointCount = 0;
        if (skin) {
            const RigSkin& s = rig.skins[std::size_t(node.skin)];
            jointCount = s.joints.size();
            baked.jointMatrices.push_back(glm::mat4(worlds[std::size_t(n)]));
            for (std::size_t j = 0; j < s.joints.size(); ++j)
                baked.jointMatrices.push_back(
                    glm::mat4(worlds[std::size_t(s.joints[j])] * s.inverseBind[j]));
        }
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const RigPrimitive& primitive = mesh.primitives[p];
            if (!primitive.drawable) continue;
            const RigPrimitive* source = &primitive;
            const bool morph =
                std::any_of(weights.begin(), weights.end(), [](float w) { return w != 0.0f; }) &&
                !primitive.targets.empty();
            if (morph) {
                scratch = morphed(primitive, weights);
                source = &scratch;
            }
            if (skin && !primitive.joints[0].empty()) {
                // Baked in the skinned mesh's own space (the bind pose), then skinned.
                if (!bakePrimitive(*source, glm::dmat4(1.0), pointer, report, baked)) return false;
                MeshPrimitive& out = baked.primitives.back();
                out.bindVertices = out.vertices;
                out.skin = skinVerticesOf(primitive);
                out.jointBase = int(jointBase);
                out.morphed = !primitive.targets.empty();
                const std::string primPointer =
                    "/meshes/" + std::to_string(node.mesh) + "/primitives/" + std::to_string(p);
                if (!skinVertices(out, baked.jointMatrices, jointCount, primPointer, report))
                    return false;
                continue;
            }
            if (!bakePrimitive(*source, worlds[std::size_t(n)], pointer, report, baked))
                return false;
        }
    }
    asset.primitives = std::move(baked.primitives);
    asset.jointMatrices = std::move(baked.jointMatrices);
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const MeshPrimitive& p : asset.primitives)
        for (const MeshVertex& v : p.vertices) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
    if (asset.primitives.empty()) lo = hi = glm::vec3(0.0f);
    asset.boundsMin = lo;
    asset.boundsMax = hi;
    return true;
}

} // namespace gltf

bool poseMeshAsset(MeshAsset& asset, const MeshPose& pose, Diagnostics& diagnostics) {
    gltf::Reporter report{asset.path.string(), &diagnostics};
    const std::size_t animations = asset.rig ? asset.rig->animations.size() : 0;
    if (pose.animation >= 0 && std::size_t(pose.animation) >= animations) {
        report.error("/animations", "there is no animation " + std::to_string(pose.animation) +
                                        "; the file has " + std::to_string(animations));
        return false;
    }
    if (!asset.rig) return true; // an asset not loaded from a file has only its rest pose
    return gltf::bakePose(*asset.rig, pose, report, asset);
}

std::optional<int> findAnimation(const MeshRig& rig, const std::string& nameOrIndex,
                                 std::string& why) {
    const bool number = !nameOrIndex.empty() && nameOrIndex.size() < 10 &&
                        std::all_of(nameOrIndex.begin(), nameOrIndex.end(),
                                    [](unsigned char c) { return std::isdigit(c); });
    for (std::size_t a = 0; a < rig.animations.size(); ++a)
        if (rig.animations[a].name == nameOrIndex) return int(a);
    if (number && std::stoul(nameOrIndex) < rig.animations.size())
        return int(std::stoul(nameOrIndex));
    std::string names;
    for (std::size_t a = 0; a < rig.animations.size(); ++a)
        names += (a ? ", " : "") + std::to_string(a) +
                 (rig.animations[a].name.empty() ? "" : " \"" + rig.animations[a].name + "\"");
    why = "there is no animation \"" + nameOrIndex + "\"; the file has " +
          (rig.animations.empty() ? std::string("no animations") : "animations " + names);
    return std::nullopt;
}

} // namespace rmsc
