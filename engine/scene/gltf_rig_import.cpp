// Skins, cameras and animations of a glTF file into the rig (see gltf_rig_import.hpp).
#include "gltf_rig_import.hpp"

#include "gltf_accessors.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::gltf {

namespace {

bool validAccessor(const tinygltf::Model& model, int index) {
    return index >= 0 && std::size_t(index) < model.accessors.size();
}

// glTF 2.0 section 3.7.3 ("Skins"): joints are nodes, at most limits::kGltfJoints; the
// inverse bind matrices, when given, a MAT4 FLOAT accessor with one matrix per joint.
bool readSkins(const tinygltf::Model& model, Reporter& report, MeshRig& rig) {
    std::vector<float> values;
    for (std::size_t s = 0; s < model.skins.size(); ++s) {
        const tinygltf::Skin& skin = model.skins[s];
        const std::string pointer = "/skins/" + std::to_string(s);
        if (skin.joints.empty() || skin.joints.size() > std::size_t(limits::kGltfJoints)) {
            report.error(pointer + "/joints",
                         "has " + std::to_string(skin.joints.size()) + " joints, expected 1 to " +
                             std::to_string(limits::kGltfJoints) + " (the limit)");
            return false;
        }
        RigSkin out;
        for (std::size_t j = 0; j < skin.joints.size(); ++j) {
            const int joint = skin.joints[j];
            if (joint < 0 || std::size_t(joint) >= rig.nodes.size()) {
                report.error(pointer + "/joints/" + std::to_string(j), "refers to a missing node");
                return false;
            }
            out.joints.push_back(joint);
        }
        out.inverseBind.assign(out.joints.size(), glm::dmat4(1.0));
        if (skin.inverseBindMatrices >= 0) {
            const int a = skin.inverseBindMatrices;
            if (!validAccessor(model, a)) {
                report.error(pointer + "/inverseBindMatrices", "refers to a missing accessor");
                return false;
            }
            if (model.accessors[std::size_t(a)].count < out.joints.size()) {
                report.error(pointer + "/inverseBindMatrices",
                             "accessor has " +
                                 std::to_string(model.accessors[std::size_t(a)].count) +
                                 " matrices for " + std::to_string(out.joints.size()) +
                                 " joints, expected one per joint");
                return false;
            }
            if (!readFloatAttribute(model, a, 16, kFloat, "inverseBindMatrices of " + pointer,
                                    values, report))
                return false;
            for (std::size_t j = 0; j < out.joints.size(); ++j)
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r)
                        out.inverseBind[j][c][r] = values[16 * j + std::size_t(4 * c + r)];
        }
        rig.skins.push_back(std::move(out));
    }
    for (std::size_t n = 0; n < rig.nodes.size(); ++n)
        if (rig.nodes[n].skin >= 0 && std::size_t(rig.nodes[n].skin) >= rig.skins.size()) {
            report.error("/nodes/" + std::to_string(n) + "/skin", "refers to a missing skin");
            return false;
        }
    return true;
}

// glTF 2.0 section 3.10 ("Cameras"); the nodes placing them are found by walkNodes.
bool readCameras(const tinygltf::Model& model, Reporter& report, MeshRig& rig) {
    for (std::size_t c = 0; c < model.cameras.size(); ++c) {
        const tinygltf::Camera& camera = model.cameras[c];
        const std::string pointer = "/cameras/" + std::to_string(c);
        RigCamera out;
        out.name = camera.name;
        const auto positive = [&](double v, const std::string& at) {
            if (std::isfinite(v) && v > 0.0) return true;
            report.error(pointer + at, "expected a positive number, got " + std::to_string(v));
            return false;
        };
        if (camera.type == "perspective") {
            const tinygltf::PerspectiveCamera& p = camera.perspective;
            if (!positive(p.yfov, "/perspective/yfov") || !positive(p.znear, "/perspective/znear"))
                return false;
            if (p.yfov >= 3.14159) {
                report.error(pointer + "/perspective/yfov",
                             "expected a field of view below pi radians");
                return false;
            }
            if (p.zfar != 0.0 && !(p.zfar > p.znear && std::isfinite(p.zfar))) {
                report.error(pointer + "/perspective/zfar", "expected a number above znear");
                return false;
            }
            out.yfov = p.yfov;
            out.aspect = std::isfinite(p.aspectRatio) && p.aspectRatio > 0 ? p.aspectRatio : 0.0;
            out.znear = p.znear;
            out.zfar = p.zfar;
        } else if (camera.type == "orthographic") {
            const tinygltf::OrthographicCamera& o = camera.orthographic;
            if (!std::isfinite(o.xmag) || o.xmag == 0.0 || !std::isfinite(o.ymag) ||
                o.ymag == 0.0) {
                report.error(pointer + "/orthographic", "expected non-zero xmag and ymag");
                return false;
            }
            if (!(o.znear >= 0.0) || !(o.zfar > o.znear) || !std::isfinite(o.zfar)) {
                report.error(pointer + "/orthographic", "expected 0 <= znear < zfar");
                return false;
            }
            out.orthographic = true;
            out.xmag = std::abs(o.xmag);
            out.ymag = std::abs(o.ymag);
            out.znear = o.znear;
            out.zfar = o.zfar;
        } else {
            report.error(pointer + "/type", "expected \"perspective\" or \"orthographic\", got \"" +
                                                camera.type + "\"");
            return false;
        }
        rig.cameras.push_back(out);
    }
    return true;
}

// The morph target count of node `n`'s mesh (0 without a mesh).
std::size_t nodeTargets(const tinygltf::Model& model, int n) {
    const int mesh = model.nodes[std::size_t(n)].mesh;
    if (mesh < 0 || std::size_t(mesh) >= model.meshes.size() ||
        model.meshes[std::size_t(mesh)].primitives.empty())
        return 0;
    return model.meshes[std::size_t(mesh)].primitives[0].targets.size();
}

// One sampler, read the first time a channel uses it, with the value width that channel needs
// (glTF 2.0 section 3.11: input SCALAR FLOAT key times, increasing; output one value per key,
// three for CUBICSPLINE).
bool readSampler(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler, int width,
                 bool scalar, const std::string& pointer, std::uint64_t& keys, Reporter& report,
                 AnimationSampler& out) {
    if (sampler.interpolation == "LINEAR")
        out.interpolation = AnimationInterpolation::Linear;
    else if (sampler.interpolation == "STEP")
        out.interpolation = AnimationInterpolation::Step;
    else if (sampler.interpolation == "CUBICSPLINE")
        out.interpolation = AnimationInterpolation::CubicSpline;
    else {
        report.error(pointer + "/interpolation",
                     "expected LINEAR, STEP or CUBICSPLINE, got \"" + sampler.interpolation + "\"");
        return false;
    }
    if (!validAccessor(model, sampler.input) || !validAccessor(model, sampler.output)) {
        report.error(pointer, "expected valid input and output accessors");
        return false;
    }
    const std::uint64_t count = model.accessors[std::size_t(sampler.input)].count;
    if (count == 0) {
        report.error(pointer + "/input", "has no keys, expected at least one");
        return false;
    }
    if (count > limits::kGltfAnimationKeys - std::min(keys, limits::kGltfAnimationKeys)) {
        report.error(pointer + "/input", "brings the file's animation keys to " +
                                             std::to_string(keys + count) + "; at most " +
                                             std::to_string(limits::kGltfAnimationKeys) +
                                             " are supported (the limit)");
        return false;
    }
    keys += count;
    std::vector<float> values;
    if (!readFloatAttribute(model, sampler.input, 1, kFloat, "input of " + pointer, out.times,
                            report))
        return false;
    for (std::size_t k = 1; k < out.times.size(); ++k)
        if (out.times[k] < out.times[k - 1]) {
            report.error("/accessors/" + std::to_string(sampler.input),
                         "key time " + std::to_string(k) + " (input of " + pointer +
                             ") is before the one ahead of it, expected increasing times");
            return false;
        }
    const std::uint64_t perKey =
        std::uint64_t(out.interpolation == AnimationInterpolation::CubicSpline ? 3 : 1);
    const tinygltf::Accessor& output = model.accessors[std::size_t(sampler.output)];
    // Morph weights are SCALAR, one per target and key; the others one VEC3 or VEC4 per key.
    const int components = scalar ? 1 : width;
    const std::uint64_t expected = count * perKey * std::uint64_t(scalar ? width : 1);
    if (output.count != expected) {
        report.error(pointer + "/output", "accessor has " + std::to_string(output.count) +
                                              " elements for " + std::to_string(count) +
                                              " keys, expected " + std::to_string(expected));
        return false;
    }
    // Rotations and weights may be normalized integers (glTF 2.0 section 3.11, table of
    // channel target types).
    const unsigned formats =
        components == 3 ? kFloat : kFloat | kSnorm8 | kUnorm8 | kSnorm16 | kUnorm16;
    if (!scalar && output.type != (width == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3)) {
        report.error(pointer + "/output", std::string("expected a ") +
                                              (width == 4 ? "VEC4" : "VEC3") + " accessor, got " +
                                              typeName(output.type));
        return false;
    }
    if (!readFloatAttribute(model, sampler.output, components, formats, "output of " + pointer,
                            out.values, report))
        return false;
    out.width = width;
    return true;
}

bool readAnimations(const tinygltf::Model& model, Reporter& report, MeshRig& rig) {
    std::uint64_t keys = 0;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& animation = model.animations[a];
        const std::string pointer = "/animations/" + std::to_string(a);
        Animation out;
        out.name = animation.name;
        std::vector<int> samplerSlot(animation.samplers.size(), -1);
        for (std::size_t c = 0; c < animation.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = animation.channels[c];
            const std::string at = pointer + "/channels/" + std::to_string(c);
            if (channel.target_node < 0) continue; // allowed: an extension may target it
            if (std::size_t(channel.target_node) >= rig.nodes.size()) {
                report.error(at + "/target/node", "refers to a missing node");
                return false;
            }
            AnimationChannel result;
            result.node = channel.target_node;
            int width = 3;
            if (channel.target_path == "translation") {
                result.path = AnimationPath::Translation;
            } else if (channel.target_path == "rotation") {
                result.path = AnimationPath::Rotation;
                width = 4;
            } else if (channel.target_path == "scale") {
                result.path = AnimationPath::Scale;
            } else if (channel.target_path == "weights") {
                result.path = AnimationPath::Weights;
                width = int(nodeTargets(model, channel.target_node));
                if (width == 0) {
                    report.error(at + "/target/node",
                                 "animates the morph weights of a node whose mesh has no morph "
                                 "targets");
                    return false;
                }
            } else {
                report.warning(at + "/target/path", "animating \"" + channel.target_path +
                                                        "\" is not supported; channel ignored");
                continue;
            }
            if (result.path != AnimationPath::Weights &&
                rig.nodes[std::size_t(channel.target_node)].hasMatrix) {
                report.error(at + "/target/node",
                             "animates a node that has a matrix, expected translation, rotation "
                             "and scale (glTF 2.0 section 3.11)");
                return false;
            }
            if (channel.sampler < 0 || std::size_t(channel.sampler) >= animation.samplers.size()) {
                report.error(at + "/sampler", "refers to a missing sampler");
                return false;
            }
            int& slot = samplerSlot[std::size_t(channel.sampler)];
            const std::string samplerPointer =
                pointer + "/samplers/" + std::to_string(channel.sampler);
            if (slot < 0) {
                AnimationSampler sampler;
                if (!readSampler(model, animation.samplers[std::size_t(channel.sampler)], width,
                                 result.path == AnimationPath::Weights, samplerPointer, keys,
                                 report, sampler))
                    return false;
                slot = int(out.samplers.size());
                out.duration = std::max(out.duration, sampler.times.back());
                out.samplers.push_back(std::move(sampler));
            } else if (out.samplers[std::size_t(slot)].width != width) {
                report.error(at + "/sampler",
                             "the sampler already drives values of " +
                                 std::to_string(out.samplers[std::size_t(slot)].width) +
                                 " numbers, this channel needs " + std::to_string(width));
                return false;
            }
            result.sampler = slot;
            out.channels.push_back(result);
        }
        rig.animations.push_back(std::move(out));
    }
    return true;
}

// node.weights, when given, has one weight per morph target of the node's mesh.
bool checkNodeWeights(const tinygltf::Model& model, Reporter& report) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const std::size_t given = model.nodes[n].weights.size();
        if (given == 0) continue;
        const std::size_t targets = nodeTargets(model, int(n));
        if (given != targets) {
            report.error("/nodes/" + std::to_string(n) + "/weights",
                         "has " + std::to_string(given) + " weights for " +
                             std::to_string(targets) + " morph targets, expected one per target");
            return false;
        }
    }
    return true;
}

} // namespace

bool readRigExtras(const tinygltf::Model& model, Reporter& report, MeshRig& rig) {
    return checkNodeWeights(model, report) && readSkins(model, report, rig) &&
           readCameras(model, report, rig) && readAnimations(model, report, rig);
}

} // namespace rmsc::gltf
