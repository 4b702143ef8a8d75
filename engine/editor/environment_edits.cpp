// Editing the sky with a load check first (see environment_edits.hpp).
#include "editor/environment_edits.hpp"

#include "scene/scene_paths.hpp"
#include "scene/sky_image.hpp"

namespace rmsc::editor {

bool setSkyType(Environment& environment, SkyType type, std::string& error) {
    if (type == SkyType::Image && environment.imagePath.empty()) {
        error = "an image sky needs its file: type the name of an equirectangular .hdr image "
                "and apply it";
        return false;
    }
    environment.sky = type;
    return true;
}

bool setSkyImageFile(Scene& scene, const std::string& file, const FileSource& files,
                     std::string& error) {
    if (file.empty()) {
        error = "expected the path of an equirectangular .hdr image, got \"\"";
        return false;
    }
    const std::filesystem::path path = resolveScenePath(scene, file);
    Diagnostics diagnostics;
    if (!loadSkyImage(path, files, scene.file.string(), "/environment/sky/file", diagnostics)) {
        error = diagnostics.items.empty() ? "the sky image did not load"
                                          : diagnostics.items.front().message;
        return false;
    }
    Environment& environment = scene.environment;
    environment.sky = SkyType::Image;
    environment.imagePath = path;
    environment.imageFile = scene.file.empty() ? path.generic_string() : file;
    return true;
}

} // namespace rmsc::editor
