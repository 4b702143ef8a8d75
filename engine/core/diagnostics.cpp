// Formatting of diagnostics: "file: location: message".
#include "core/diagnostics.hpp"

namespace rmsc {

std::string Diagnostic::format() const {
    std::string out;
    if (!file.empty()) out += file + ": ";
    if (!location.empty()) out += location + ": ";
    if (severity == Severity::Warning) out += "warning: ";
    out += message;
    return out;
}

void Diagnostics::error(std::string file, std::string location, std::string message) {
    items.push_back({Severity::Error, std::move(file), std::move(location), std::move(message)});
}

void Diagnostics::warning(std::string file, std::string location, std::string message) {
    items.push_back({Severity::Warning, std::move(file), std::move(location), std::move(message)});
}

bool Diagnostics::hasErrors() const { return errorCount() > 0; }

int Diagnostics::errorCount() const {
    int n = 0;
    for (const Diagnostic& d : items) n += d.severity == Severity::Error ? 1 : 0;
    return n;
}

std::string Diagnostics::format() const {
    std::string out;
    for (const Diagnostic& d : items) out += d.format() + "\n";
    return out;
}

} // namespace rmsc
