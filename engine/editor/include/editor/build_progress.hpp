// What the overlay says while shaders build in the background (render/shader_warmer.hpp): how
// many of the shader sets asked for are built, which one is being built and for how long, as a
// progress bar's fraction and its text. GL-free.
#pragma once

#include <string>

namespace rmsc::editor {

struct BuildProgress {
    int done = 0;         // shader sets of the current request built (or failed)
    int total = 0;        // shader sets in it; 0: nothing is being built
    double seconds = 0.0; // since the set being built was started
    std::string building; // what it is for ("the interpreter map"); may be empty
};

// The bar's fill: `done` of `total`, plus half a set for the one under way (0 when idle).
float buildProgressFraction(const BuildProgress& progress);
// "building shaders 2 of 3 (the interpreter map), 4.1 s"; "" when nothing is being built.
std::string buildProgressText(const BuildProgress& progress);

} // namespace rmsc::editor
