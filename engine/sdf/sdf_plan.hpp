// The planning pass of the SDF compiler (compiler.cpp): resolves each node's transform,
// material, object id and point frame, finds every error, orders a group's children (Sethi-Ullman)
// and counts the stack, point stack and instructions each subtree needs. Emission (sdf_emit.cpp,
// sdf_bvh.cpp) reads the PlannedNode tree it makes. Internal to the sdf layer.
#pragma once

#include "core/diagnostics.hpp"
#include "sdf/sdf_tree.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace rmsc::compiler {

// A node with everything resolved, children in the order they are emitted.
struct PlannedNode {
    const SdfNode* node = nullptr;
    std::uint32_t objectId = 0;
    std::uint32_t material = 0;
    // The node's local frame to the frame of the current point: world space, or below a node
    // with its own point frame (hasPointFrame), that node's modified local frame.
    glm::dmat4 world{1.0};
    glm::dmat4 parentWorld{1.0}; // the parent's frame to the frame of the current point
    double spaceScale = 1.0;     // world units per unit of the current point's frame
    // Shapes: rows of world^-1 and the distance scale (see resolveShape).
    glm::vec4 worldToLocal[3]{};
    float distanceScale = 1.0f;
    // Nodes with point modifiers or displacement evaluate their subtree in their own frame:
    // PushPoint (rows of world^-1), the point modifiers, the subtree, PopPoint.
    bool hasPointFrame = false;
    glm::vec4 pushRows[3]{};
    // World units of the node's field per unit of its local (modified) frame, Lipschitz
    // corrections included: converts the lengths of distance modifiers.
    double nodeScale = 1.0;
    bool cut = false;
    std::uint32_t dataOffset = 0; // profile polygons: first point in SdfProgram::data
    int stackNeed = 0;            // entries the subtree needs on the stack
    int pointNeed = 0;            // entries the subtree needs on the point stack
    long instructionCount = 0;    // instructions the subtree compiles to
    bool skipped = false;         // a shell, or a group of shells only: not in this program
    std::vector<PlannedNode> children;
};

// Where a shell sits in the tree, found while planning the scene's program.
struct ShellSite {
    const SdfNode* node = nullptr;
    glm::dmat4 parentWorld{1.0}; // the parent's frame to world (shells sit in plain unions)
    std::uint32_t parentMaterial = 0;
    std::uint32_t idBase = 0; // pre-order index of the shell node in the whole tree
};

// Cells a point modifier evaluates the rest of its chain in (ModifierSpec::cells).
int neighbourCells(const SdfModifier& m);

// Smallest singular value of the linear part of `m`: the least a world-space length can shrink
// to. It is the square root of the smallest eigenvalue of the symmetric A = L^T L, found with the
// closed form for symmetric 3x3 matrices (O. K. Smith, "Eigenvalues of a symmetric 3 x 3
// matrix", Communications of the ACM 4(4), 1961).
double smallestScaleFactor(const glm::dmat4& m);

// Does `m` scale every direction alike (a rotation times a uniform scale)?
bool isUniformScale(const glm::dmat4& m);

class Planner {
  public:
    Planner(const std::string& file, Diagnostics& diagnostics,
            std::vector<std::string>& nodePointers)
        : file_(file), diagnostics_(diagnostics), nodePointers_(nodePointers) {}

    // Leave shells out of the program and list them (shells()) instead.
    void splitShells() { splitShells_ = true; }
    // Plan `root` in its own frame (its transform not applied) with ids from `idBase` on: a
    // shell's program, in object space.
    void planInObjectSpace(const SdfNode& root, std::uint32_t idBase) {
        objectSpaceRoot_ = &root;
        idBase_ = idBase;
    }
    const std::vector<ShellSite>& shells() const { return shells_; }

    // Resolves `node` and its subtree. `parentWorld` maps the parent's frame to the current
    // point's frame, `spaceScale` is the world units per unit of the current point's frame,
    // `parentMaterial` the parent's resolved material. Object ids count every node in pre-order
    // (file order).
    PlannedNode plan(const SdfNode& node, const glm::dmat4& parentWorld, double spaceScale,
                     std::uint32_t parentMaterial);

    // The pointer of the first group (in the order groups finish planning) that needs more than
    // kSdfMaxStack while none of its children does: where the limit is crossed. "" if none.
    const std::string& firstOverflow() const { return firstOverflow_; }
    // The same for the point stack (kSdfMaxPointStack).
    const std::string& firstPointOverflow() const { return firstPointOverflow_; }

  private:
    // Why a shell cannot sit below `group` ("" if it can). A shell is composited with the rest
    // of the scene through the depth buffer, which is a plain union.
    static std::string shellBlocker(const SdfNode& group);

    // Records a shell found in the scene's program and counts its subtree's ids.
    void planShell(const SdfNode& node, const glm::dmat4& parentWorld, std::uint32_t material);

    // Gives the subtree's nodes their pre-order ids; nested shells are an error.
    void countIds(const SdfNode& node, bool isShellRoot);

    // Rows of m^-1 and the smallest scale factor of m; false if m cannot be inverted.
    static bool invertFrame(const glm::dmat4& m, glm::vec4 rows[3], double& scale);

    // The primitive is evaluated at q = world^-1 p (`world`: the shape's frame to the current
    // point's frame, the identity when the shape has its own point frame). A local distance d
    // maps to world units within [d * smallest, d * largest] scale factor, times `spaceScale`
    // (world units per unit of the current point's frame, Lipschitz corrections included);
    // d * smallest is exact for a uniform scale and a lower bound (safe for sphere tracing,
    // never overshooting) for a non-uniform one.
    void resolveShape(PlannedNode& planned, const glm::dmat4& world, double spaceScale);

    void checkGroup(const SdfNode& node);

    // Emission order of a group's children. Union and intersection are commutative and
    // associative, so the deepest child goes first (Sethi-Ullman): the fold then needs
    // max(deepest, 1 + second deepest). So is xor: for exact children it gives
    // sign(a) sign(b) min(|a|, |b|), which folds to sign(a b c) min(|a|, |b|, |c|) in any order.
    // Subtraction keeps its first child; the order of the subtracted ones would not change the
    // stack the fold needs, so they keep file order. Smooth, chamfer and round operations are not
    // associative (smin(smin(a, b), c) != smin(a, smin(b, c))) and keep file order.
    static void order(SdfOp op, std::vector<PlannedNode>& children);

    const std::string& file_;
    Diagnostics& diagnostics_;
    std::vector<std::string>& nodePointers_;
    std::string firstOverflow_;
    std::string firstPointOverflow_;
    bool splitShells_ = false;
    const SdfNode* objectSpaceRoot_ = nullptr;
    std::uint32_t idBase_ = 0;
    std::vector<ShellSite> shells_;
    std::string shellBlocker_; // why a shell cannot sit here ("" if it can)

  public:
    std::vector<glm::vec4> data_; // SdfProgram::data, filled while planning
};

} // namespace rmsc::compiler
