// Formatting of diagnostics: "file: location: message", and the cap on how many are kept.
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
    add({Severity::Error, std::move(file), std::move(location), std::move(message)});
}

void Diagnostics::warning(std::string file, std::string location, std::string message) {
    add({Severity::Warning, std::move(file), std::move(location), std::move(message)});
}

void Diagnostics::add(Diagnostic diagnostic) {
    if (diagnostic.severity == Severity::Error)
        ++errors;
    else
        ++warnings;
    if (items.size() < std::size_t(limits::kDiagnosticsKept))
        items.push_back(std::move(diagnostic));
}

void Diagnostics::addOmitted(int omittedErrorCount, int omittedWarningCount) {
    errors += omittedErrorCount;
    warnings += omittedWarningCount;
}

bool Diagnostics::hasErrors() const {
    return errors > 0;
}

int Diagnostics::errorCount() const {
    return errors;
}

namespace {

int keptOf(const std::vector<Diagnostic>& items, Severity severity) {
    int n = 0;
    for (const Diagnostic& d : items)
        n += d.severity == severity ? 1 : 0;
    return n;
}

std::string countText(int n, const char* noun) {
    return std::to_string(n) + " more " + noun + (n == 1 ? "" : "s");
}

} // namespace

int Diagnostics::omittedErrors() const {
    return errors - keptOf(items, Severity::Error);
}

int Diagnostics::omittedWarnings() const {
    return warnings - keptOf(items, Severity::Warning);
}

std::string Diagnostics::format() const {
    std::string out;
    for (const Diagnostic& d : items)
        out += d.format() + "\n";
    const int moreErrors = omittedErrors(), moreWarnings = omittedWarnings();
    if (moreErrors > 0 || moreWarnings > 0) {
        out += "... and ";
        if (moreErrors > 0) out += countText(moreErrors, "error");
        if (moreErrors > 0 && moreWarnings > 0) out += " and ";
        if (moreWarnings > 0) out += countText(moreWarnings, "warning");
        out +=
            " (not shown; only the first " + std::to_string(limits::kDiagnosticsKept) + " are)\n";
    }
    return out;
}

} // namespace rmsc
