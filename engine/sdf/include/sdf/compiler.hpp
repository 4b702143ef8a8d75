// The SDF compiler: turns the SDF tree of a scene into the postfix program the shader and the
// CPU evaluator run. The only module that knows how the tree becomes what `map()` reads.
#pragma once

#include "core/diagnostics.hpp"
#include "core/limits.hpp"
#include "core/material.hpp"
#include "sdf/program.hpp"
#include "sdf/sdf_tree.hpp"

#include <optional>
#include <vector>

namespace rmsc {

// The factor a node's modifiers divide its distance field by so that sphere tracing stays
// safe (the step corrections): the product of the Lipschitz constants of its twists and bends
// times 1 + the gradient bound of its displacements. 1 for a node with none of them. The
// compiler converts the node's lengths (distance modifiers, its children's fields) with it.
double sdfFieldShrink(const std::vector<SdfModifier>& modifiers);

struct SdfCompileOptions {
    // Bounds: the plain unions at the top of the tree (the root's, and those of groups nested in
    // it) are emitted as a bounding-volume hierarchy of their exact parts' boxes
    // (sdf/bounds.hpp), so a point far from a part skips it, and the value stays exactly what it
    // would be without. Off: the tree as it is, for comparisons.
    bool bounds = true;
};

// Compiles `root`. Group transforms are folded into each shape's world-to-local matrix;
// material -1 inherits the parent's, and at the root means `defaultMaterial` (the renderer
// appends a default material after the scene's). Children of commutative operations are
// reordered so the deepest subtree comes first (Sethi-Ullman order), minimizing the stack.
// Refuses, with diagnostics naming the node's JSON pointer and the limit: a program needing
// more than kSdfMaxStack stack entries, kSdfMaxPointStack point-stack entries,
// kSdfMaxInstructions instructions or kSdfMaxData polygon points; a group with no children (at
// any depth, the root included: there is no empty SDF tree, a scene without SDF objects has no
// "sdf" key); a subtraction with one child; a group whose children are all "cut"; a "cut"
// root; a smooth operation without a finite smoothness > 0; a transform that cannot be
// inverted. Shells (SdfNode::shell) are compiled like any other node: this is the program that
// draws the whole tree in the fullscreen pass.
std::optional<SdfProgram> compileSdf(const SdfNode& root, std::uint32_t defaultMaterial,
                                     const std::string& file, Diagnostics& diagnostics,
                                     const SdfCompileOptions& options = {});

// The most shapes one shell may hold: its map is always generated code (kMaxGeneratedLeaves).
constexpr int kMaxShellShapes = limits::kShellShapes;

// A subtree marked as a shell, compiled on its own in the node's frame ("object space": the
// node's transform and its groups' are not applied; objectToWorld applies them). Object ids are
// those the node has in the whole tree.
struct SdfShellProgram {
    const SdfNode* node = nullptr; // in the tree that was compiled; valid while it is
    std::string pointer;           // the node's JSON pointer
    SdfProgram program;
    glm::mat4 objectToWorld{1.0f};
    glm::mat4 worldToObject{1.0f};
    // Smallest scale factor of objectToWorld: object lengths times this are world lengths or
    // lower bounds of them. The program's distances are in world units already (it is compiled
    // with this scale), so the smoothness of operations means what it does in the scene.
    float distanceScale = 1.0f;
    float parentFieldScale = 1.0f; // the same for the parent's frame (sdf/bounds.hpp)
};

// The scene's fullscreen program without the shells, and each shell on its own. A shell must sit
// in plain union groups without modifiers or cut children (it meets the rest of the scene
// through the depth buffer), must not be cut and must not hold another shell; errors name the
// shell's JSON pointer. A group whose children are all shells is left out of `main` (it is not
// an empty group); `main` is empty when every shape is in a shell; main.nodePointers still
// lists every node of the tree.
struct CompiledSdfScene {
    SdfProgram main;
    std::vector<SdfShellProgram> shells;
};
std::optional<CompiledSdfScene> compileSdfScene(const SdfNode& root, std::uint32_t defaultMaterial,
                                                const std::string& file, Diagnostics& diagnostics,
                                                const SdfCompileOptions& options = {});

} // namespace rmsc
