// libFuzzer harness of the scene reader: any bytes given to parseScene must give a scene or
// diagnostics, never a crash, a sanitizer report or a hang. Build with -DRMSC_FUZZ=ON (clang);
// run with tools/fuzz.sh.
#include "scene/scene_json.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    rmsc::Diagnostics diagnostics;
    const auto scene = rmsc::parseScene(text, "fuzz/scene.json", diagnostics);
    // The reader's contract: no scene exactly when there is an error.
    if (scene.has_value() == diagnostics.hasErrors()) __builtin_trap();
    if (scene) {
        // What was read must also write and read back without errors.
        rmsc::Diagnostics again;
        if (!rmsc::parseScene(rmsc::sceneToJson(*scene), "fuzz/again.json", again))
            __builtin_trap();
    }
    return 0;
}
