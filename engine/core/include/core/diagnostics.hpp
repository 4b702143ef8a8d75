// Problems found in user input (scene files, glTF, images, shaders), each naming the file,
// the place in it (a JSON pointer, a glTF element or a line) and what was expected.
#pragma once

#include "core/limits.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace rmsc {

enum class Severity { Error, Warning };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;     // the file the problem is in ("" when not from a file)
    std::string location; // JSON pointer ("/sdf/children/3/radius"), glTF element or "line:col"
    std::string message;  // what was wrong and what was expected

    // "scene.json: /sdf/children/3/radius: expected a number >= 0, got -1"
    std::string format() const;
};

// An ordered list of diagnostics collected while reading one input. Only the first
// limits::kDiagnosticsKept are kept (a hostile file may have millions of problems); every one
// is counted, so errorCount() and hasErrors() stay exact and format() ends with
// "... and N more errors". Add through error(), warning() or add() only, which count.
struct Diagnostics {
    std::vector<Diagnostic> items; // the first kDiagnosticsKept, in the order found
    int errors = 0;                // every error reported, kept or not
    int warnings = 0;              // every warning reported, kept or not

    void error(std::string file, std::string location, std::string message);
    void warning(std::string file, std::string location, std::string message);
    void add(Diagnostic diagnostic);
    // Counts problems reported elsewhere and not kept there (when copying another list's items).
    void addOmitted(int omittedErrors, int omittedWarnings);
    // Whether the next diagnostic will be kept (callers may skip building long messages).
    bool keeps() const { return items.size() < std::size_t(limits::kDiagnosticsKept); }
    bool hasErrors() const;
    int errorCount() const;
    // How many were counted but not kept.
    int omittedErrors() const;
    int omittedWarnings() const;
    // The kept diagnostics, one per line, errors and warnings in the order found, then
    // "... and N more errors and M more warnings (not shown)" when some were not kept.
    std::string format() const;
};

} // namespace rmsc
