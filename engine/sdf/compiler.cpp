// The SDF compiler: flattens the SDF tree into the postfix program of sdf/program.hpp. A first
// pass resolves transforms, materials, object ids and the stack each subtree needs (and finds
// every error; sdf_plan.cpp); a second pass emits the instructions, deepest subtree first where
// the operation allows it (Sethi-Ullman order; sdf_emit.cpp), the plain unions at the top through
// a bounding-volume hierarchy (sdf_bvh.cpp). This file holds the entry points, the limits of a
// whole program and the shells.
#include "sdf/compiler.hpp"

#include "sdf/cost_model.hpp"
#include "sdf/modifiers.hpp"
#include "sdf_emit.hpp"
#include "sdf_plan.hpp"

#include <cmath>

namespace rmsc {

using compiler::emit;
using compiler::emitProgram;
using compiler::isUniformScale;
using compiler::PlannedNode;
using compiler::Planner;
using compiler::ShellSite;
using compiler::smallestScaleFactor;

namespace {

// Checks the limits of a planned program and emits it (nullopt when there were errors).
std::optional<SdfProgram> finishProgram(Planner& planner, const PlannedNode& planned,
                                        const SdfNode& root, SdfProgram program,
                                        const std::string& file, Diagnostics& diagnostics,
                                        int errorsBefore, const SdfCompileOptions& options) {
    if (root.cut && !root.shell) // a cut shell is reported where the shell is found
        diagnostics.error(file, root.pointer,
                          "the root node cannot be \"cut\": it has no siblings to be cut from");
    if (planned.pointNeed > kSdfMaxPointStack) {
        diagnostics.error(
            file, root.pointer,
            "the SDF tree needs a point stack of " + std::to_string(planned.pointNeed) +
                " entries, the shader supports " + std::to_string(kSdfMaxPointStack) + " (" +
                std::to_string(planned.pointNeed - kSdfMaxPointStack) +
                " over); it first goes over at " + planner.firstPointOverflow() +
                " (every node with point modifiers or displacement, and every repetition with "
                "the neighbour check, nests one entry)");
    }
    if (planner.data_.size() > std::size_t(kSdfMaxData)) {
        diagnostics.error(file, root.pointer,
                          "the SDF tree's polygon profiles have " +
                              std::to_string(planner.data_.size()) + " points in all, the " +
                              "data buffer holds " + std::to_string(kSdfMaxData) + " (" +
                              std::to_string(planner.data_.size() - kSdfMaxData) + " over)");
    }

    if (planned.stackNeed > kSdfMaxStack) {
        diagnostics.error(file, root.pointer,
                          "the SDF tree needs a stack of " + std::to_string(planned.stackNeed) +
                              " entries, the shader supports " + std::to_string(kSdfMaxStack) +
                              " (" + std::to_string(planned.stackNeed - kSdfMaxStack) +
                              " over); it first goes over at " + planner.firstOverflow() +
                              " (smooth operations and the first child of a subtraction keep "
                              "their order: nest groups in their first child)");
    }
    if (planned.instructionCount > kSdfMaxInstructions) {
        diagnostics.error(
            file, root.pointer,
            "the SDF tree compiles to " + std::to_string(planned.instructionCount) +
                " instructions, the shader supports " + std::to_string(kSdfMaxInstructions) + " (" +
                std::to_string(planned.instructionCount - kSdfMaxInstructions) + " over)");
    }
    if (diagnostics.errorCount() > errorsBefore) return std::nullopt;
    if (planned.skipped) return program; // everything is in shells

    program.instructions.reserve(std::size_t(planned.instructionCount));
    emitProgram(planned, options.bounds, program.instructions);
    if (program.instructions.size() > std::size_t(kSdfMaxInstructions)) {
        // The hierarchy's box tests do not fit beside the tree: the tree as it is does.
        program.instructions.clear();
        emit(planned, program.instructions);
    }
    program.stackDepth = planned.stackNeed;
    program.pointStackDepth = planned.pointNeed;
    program.data = std::move(planner.data_);
    return program;
}

} // namespace

double sdfFieldShrink(const std::vector<SdfModifier>& modifiers) {
    double lipschitz = 1.0;
    double gradient = 1.0;
    for (const SdfModifier& m : modifiers) {
        const ModifierSpec& spec = modifierSpec(m.type);
        if (spec.lipschitz) lipschitz *= spec.lipschitz(m);
        if (spec.gradientGain) gradient += spec.gradientGain(m);
    }
    return lipschitz * gradient;
}

std::optional<SdfProgram> compileSdf(const SdfNode& root, std::uint32_t defaultMaterial,
                                     const std::string& file, Diagnostics& diagnostics,
                                     const SdfCompileOptions& options) {
    const int errorsBefore = diagnostics.errorCount();
    SdfProgram program;
    Planner planner(file, diagnostics, program.nodePointers);
    const PlannedNode planned = planner.plan(root, glm::dmat4(1.0), 1.0, defaultMaterial);
    return finishProgram(planner, planned, root, std::move(program), file, diagnostics,
                         errorsBefore, options);
}

std::optional<CompiledSdfScene> compileSdfScene(const SdfNode& root, std::uint32_t defaultMaterial,
                                                const std::string& file, Diagnostics& diagnostics,
                                                const SdfCompileOptions& options) {
    const int errorsBefore = diagnostics.errorCount();
    CompiledSdfScene compiled;
    SdfProgram program;
    Planner planner(file, diagnostics, program.nodePointers);
    planner.splitShells();
    const PlannedNode planned = planner.plan(root, glm::dmat4(1.0), 1.0, defaultMaterial);
    std::optional<SdfProgram> main = finishProgram(planner, planned, root, std::move(program), file,
                                                   diagnostics, errorsBefore, options);
    if (!main) return std::nullopt;
    compiled.main = std::move(*main);

    for (const ShellSite& site : planner.shells()) {
        const int shellErrorsBefore = diagnostics.errorCount();
        SdfShellProgram shell;
        shell.node = site.node;
        shell.pointer = site.node->pointer;
        const glm::dmat4 objectToWorld =
            site.parentWorld * glm::dmat4(site.node->transform.matrix());
        shell.objectToWorld = glm::mat4(objectToWorld);
        shell.worldToObject = glm::mat4(glm::inverse(objectToWorld));
        shell.distanceScale = float(smallestScaleFactor(objectToWorld));
        shell.parentFieldScale = float(smallestScaleFactor(site.parentWorld));
        if (!(shell.distanceScale > 1e-12f) || !std::isfinite(shell.distanceScale))
            diagnostics.error(file, site.node->pointer,
                              "the shell's transform (with its groups') cannot be inverted; is "
                              "a scale 0?");
        // The hierarchy's exactness needs the world distance to be the object distance times
        // one scale: a shell stretched unevenly gets none.
        SdfCompileOptions shellOptions = options;
        shellOptions.bounds = options.bounds && isUniformScale(objectToWorld);
        SdfProgram shellProgram;
        Planner shellPlanner(file, diagnostics, shellProgram.nodePointers);
        shellPlanner.planInObjectSpace(*site.node, site.idBase);
        // Distances in world units, as in the scene's program (the smoothness of operations and
        // the lengths of modifiers are world units): object units times the frame's scale.
        const PlannedNode plannedShell = shellPlanner.plan(
            *site.node, glm::dmat4(1.0), double(shell.distanceScale), site.parentMaterial);
        std::optional<SdfProgram> compiledShell =
            finishProgram(shellPlanner, plannedShell, *site.node, std::move(shellProgram), file,
                          diagnostics, shellErrorsBefore, shellOptions);
        if (!compiledShell) continue;
        int leaves = 0;
        for (const GpuSdfInstruction& in : compiledShell->instructions)
            leaves += SdfOpcode(in.opcode) == SdfOpcode::Shape ||
                      SdfOpcode(in.opcode) == SdfOpcode::Profile;
        if (leaves > kMaxShellShapes) {
            diagnostics.error(file, site.node->shell->pointer,
                              "a shell holds at most " + std::to_string(kMaxShellShapes) +
                                  " shapes (its shader is generated), this one has " +
                                  std::to_string(leaves) + "; split it into several shells");
            continue;
        }
        const long statements = sdfGeneratedStatements(*compiledShell);
        if (statements > limits::kGeneratedCodeStatements) {
            diagnostics.error(file, site.node->shell->pointer,
                              "a shell's generated code is at most " +
                                  std::to_string(limits::kGeneratedCodeStatements) +
                                  " statements (the limit \"Generated code statements\"), this "
                                  "one has " +
                                  std::to_string(statements) +
                                  " (about one per shape, operation and modifier); split it "
                                  "into several shells");
            continue;
        }
        shell.program = std::move(*compiledShell);
        compiled.shells.push_back(std::move(shell));
    }
    if (diagnostics.errorCount() > errorsBefore) return std::nullopt;
    return compiled;
}

} // namespace rmsc