// The check every save makes before it writes (Save, Save As, the recovery file): the scene's
// text, exactly as it would be written, read back by the scene reader and its SDF tree
// compiled, as `rmsc validate` does; text that fails is not written. The files the scene names
// (glTF models, textures, sky images) are not read: a save cannot change them. GL-free.
#pragma once

#include "core/diagnostics.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace rmsc::editor {

// True when `text`, to be written to `file`, loads: no errors (warnings are allowed, as
// `rmsc validate` allows them). Otherwise false, with every problem in `diagnostics`.
bool checkSceneText(std::string_view text, const std::filesystem::path& file,
                    Diagnostics& diagnostics);

// The first `most` errors, one per line as "JSON-POINTER: MESSAGE", and how many more there are.
std::string firstErrors(const Diagnostics& diagnostics, int most = 5);

} // namespace rmsc::editor
