// Editing the scene's environment from the editor: the sky's type, and an image sky's file set
// only after the image has loaded, so a missing or broken image leaves the scene as it was and
// says why. The colours, rotation, intensity and fog are plain fields whose ranges come from
// scene/environment_spec.hpp, the table the reader checks them against. GL-free.
#pragma once

#include "core/file_source.hpp"
#include "scene/scene.hpp"

#include <string>

namespace rmsc::editor {

// Sets the sky's type. An image sky needs its file: choosing Image while the environment has no
// image file returns false with `error` saying so, and changes nothing (set the file with
// setSkyImageFile instead, which makes the sky an image sky).
bool setSkyType(Environment& environment, SkyType type, std::string& error);

// Makes the sky an image sky showing `file` (relative files are resolved against the scene
// file's folder, or for a scene without a file the current folder, and then stored absolute).
// The image is read and decoded first, as the scene preparation does; when it fails (no such
// file, not an image, too large, empty name) returns false with `error` saying why and `scene`
// unchanged. The sky's rotation is kept.
bool setSkyImageFile(Scene& scene, const std::string& file, const FileSource& files,
                     std::string& error);

} // namespace rmsc::editor
