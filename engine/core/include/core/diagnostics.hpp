// Problems found in user input (scene files, glTF, images, shaders), each naming the file,
// the place in it (a JSON pointer, a glTF element or a line) and what was expected.
#pragma once

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

// An ordered list of diagnostics collected while reading one input.
struct Diagnostics {
    std::vector<Diagnostic> items;

    void error(std::string file, std::string location, std::string message);
    void warning(std::string file, std::string location, std::string message);
    bool hasErrors() const;
    int errorCount() const;
    // All diagnostics, one per line, errors and warnings in the order found.
    std::string format() const;
};

} // namespace rmsc
