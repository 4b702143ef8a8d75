// libFuzzer harness of the glTF importer: the input is served by an in-memory FileSource as
// "fuzz/model.glb" when it starts with the binary glTF magic and as "fuzz/model.gltf"
// otherwise; any other file it refers to ("cube_external.bin", "../x") is looked up among the
// sample assets embedded in the binary, so external buffers and images are exercised too.
// loadGltf must give an asset or diagnostics, never a crash, a sanitizer report or a hang.
#include "scene/mesh_asset.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const bool glb = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    const std::filesystem::path entry = glb ? "fuzz/model.glb" : "fuzz/model.gltf";
    static const rmsc::FileSource embedded = rmsc::embeddedFileSource();
    const rmsc::FileSource files{
        [&](const std::filesystem::path& path, std::string& error) -> std::optional<std::string> {
            if (path == entry) return bytes;
            // The importer confines URIs to the glTF's folder; anything else is a bug.
            const std::filesystem::path relative = path.lexically_relative("fuzz");
            if (relative.empty() || *relative.begin() == "..") __builtin_trap();
            return embedded.read(std::filesystem::path("samples/assets") / path.filename(), error);
        }};
    rmsc::Diagnostics diagnostics;
    const auto asset = rmsc::loadGltf(entry, files, diagnostics);
    if (asset.has_value() == diagnostics.hasErrors()) __builtin_trap();
    return 0;
}
