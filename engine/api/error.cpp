// Errors and problems of the public API, from the engine's diagnostics.
#include "rmsc/error.hpp"
#include "rmsc/version.hpp"

#include "scene_impl.hpp"

namespace rmsc::api {

std::string Problem::text() const {
    Diagnostic diagnostic{severity == Severity::Error ? ::rmsc::Severity::Error
                                                      : ::rmsc::Severity::Warning,
                          file, pointer, message};
    return diagnostic.format();
}

Error::Error(ErrorKind kind, const std::string& message, std::vector<Problem> problems)
    : std::runtime_error(message), kind_(kind), problems_(std::move(problems)) {}

std::vector<Problem> toProblems(const Diagnostics& diagnostics) {
    std::vector<Problem> problems;
    for (const Diagnostic& d : diagnostics.items)
        problems.push_back({d.severity == ::rmsc::Severity::Error ? Problem::Severity::Error
                                                                  : Problem::Severity::Warning,
                            d.file, d.location, d.message});
    if (diagnostics.omittedErrors() > 0)
        problems.push_back(
            {Problem::Severity::Error, "", "",
             std::to_string(diagnostics.omittedErrors()) + " more errors (not kept)"});
    return problems;
}

Error badInput(const Diagnostics& diagnostics) {
    std::string message = diagnostics.format();
    if (!message.empty() && message.back() == '\n') message.pop_back();
    return Error(ErrorKind::BadInput, message, toProblems(diagnostics));
}

const char* version() {
    return RMSC_VERSION_STRING;
}

} // namespace rmsc::api
