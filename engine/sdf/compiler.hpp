// The SDF compiler: turns the SDF tree of a scene into the postfix program the shader and the
// CPU evaluator run. The only module that knows how the tree becomes what `map()` reads.
#pragma once

#include "core/diagnostics.hpp"
#include "scene/scene.hpp"
#include "sdf/program.hpp"

#include <optional>

namespace rmsc {

// Compiles `root`. Group transforms are folded into each shape's world-to-local matrix;
// material -1 inherits the parent's, and at the root means `defaultMaterial` (the renderer
// appends a default material after the scene's). Children of commutative operations are
// reordered so the deepest subtree comes first (Sethi-Ullman order), minimizing the stack.
// Refuses (with diagnostics naming the node's JSON pointer and the limit) a program needing
// more than kSdfMaxStack stack entries or kSdfMaxInstructions instructions, empty groups and
// subtractions with fewer than two children.
std::optional<SdfProgram> compileSdf(const SdfNode& root, std::uint32_t defaultMaterial,
                                     const std::string& file, Diagnostics& diagnostics);

// The factor a node's modifiers divide its distance field by so that sphere tracing stays
// safe (the step corrections): the product of the Lipschitz constants of its twists and bends
// times 1 + the gradient bound of its displacements. 1 for a node with none of them. The
// compiler converts the node's lengths (distance modifiers, its children's fields) with it.
double sdfFieldShrink(const std::vector<SdfModifier>& modifiers);

} // namespace rmsc
