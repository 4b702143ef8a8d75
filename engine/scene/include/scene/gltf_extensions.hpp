// The glTF extensions rmsc reads: one table, from which the importer decides what a file may
// require (an extension marked required that is not in it refuses the file, by name) and what
// it warns about (one warning per extension used but not in it), and from which the docs'
// list is checked (tests/unit/test_gltf_extensions.cpp).
#pragma once

#include <span>
#include <string_view>

namespace rmsc {

struct GltfExtensionInfo {
    std::string_view name;  // "KHR_texture_transform"
    std::string_view reads; // what rmsc does with it, one line for the docs
};

// Every extension the importer supports, in the order the docs list them.
std::span<const GltfExtensionInfo> gltfExtensions();

// Whether `name` is in gltfExtensions().
bool gltfExtensionSupported(std::string_view name);

} // namespace rmsc
