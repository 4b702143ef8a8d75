// Where the glTF importer's checks report to: the file as the caller named it and the
// Diagnostics list, so every message carries file, glTF JSON pointer and what was expected.
#pragma once

#include "core/diagnostics.hpp"

#include <string>

namespace rmsc::gltf {

struct Reporter {
    std::string file;
    Diagnostics* diagnostics = nullptr;
    int errors = 0;

    void error(std::string pointer, std::string message) {
        ++errors;
        diagnostics->error(file, std::move(pointer), std::move(message));
    }
    void warning(std::string pointer, std::string message) {
        diagnostics->warning(file, std::move(pointer), std::move(message));
    }
};

} // namespace rmsc::gltf
