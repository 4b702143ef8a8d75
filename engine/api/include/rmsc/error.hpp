// rmsc public API: errors. Everything the API refuses throws rmsc::api::Error, whose kind says
// whose fault it was and whose problems carry the file, JSON pointer and message of each problem
// in a scene, exactly as the rmsc command prints them.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace rmsc::api {

// One problem found in input: "scene.json: /sdf/children/3/radius: expected a number >= 0".
struct Problem {
    enum class Severity { Error, Warning };
    Severity severity = Severity::Error;
    std::string file;    // the file the problem is in ("" when not from a file)
    std::string pointer; // JSON pointer or glTF element, "" when the whole file is meant
    std::string message; // what was wrong and what was expected
    // The line `rmsc validate` prints for it: "FILE: POINTER: [warning: ]MESSAGE".
    std::string text() const;
};

enum class ErrorKind {
    BadInput, // a scene, glTF file or value given to an edit is invalid: see problems()
    Context,  // no OpenGL context is current, or not the one the object was made on, or it
              // cannot do what rmsc needs (OpenGL 4.5)
    Usage,    // an argument is wrong: a texture of the wrong format, a viewport outside it, an
              // unsupported depth convention, an unknown name
};

class Error : public std::runtime_error {
  public:
    Error(ErrorKind kind, const std::string& message, std::vector<Problem> problems = {});
    ErrorKind kind() const { return kind_; }
    // The problems of a BadInput error, in the order found (empty for the other kinds).
    const std::vector<Problem>& problems() const { return problems_; }

  private:
    ErrorKind kind_;
    std::vector<Problem> problems_;
};

} // namespace rmsc::api
