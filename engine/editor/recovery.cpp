// Crash recovery files (see recovery.hpp).
#include "editor/recovery.hpp"

#include "core/atomic_file.hpp"
#include "editor/scene_check.hpp"
#include "scene/scene_json.hpp"

namespace rmsc::editor {

std::filesystem::path recoveryPath(const std::filesystem::path& sceneFile) {
    if (sceneFile.empty())
        return std::filesystem::temp_directory_path() / "rmsc-untitled.json.recovery";
    std::filesystem::path path = sceneFile;
    path += ".recovery"; // not *.json: folders of scenes globbed by tools stay clean
    return path;
}

bool writeRecovery(const Scene& scene, const std::filesystem::path& sceneFile, std::string& error) {
    const std::filesystem::path path = recoveryPath(sceneFile);
    const std::string text = sceneToJson(scene);
    Diagnostics problems;
    if (!checkSceneText(text, path, problems)) {
        error = "the scene is not valid, so the recovery file was not written:\n" +
                firstErrors(problems);
        return false;
    }
    return saveTextFileAtomically(path, text, false, error);
}

std::optional<std::filesystem::path> findRecovery(const std::filesystem::path& sceneFile) {
    namespace fs = std::filesystem;
    const fs::path path = recoveryPath(sceneFile);
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
    if (sceneFile.empty() || !fs::exists(sceneFile, ec)) return path;
    const auto recoveryTime = fs::last_write_time(path, ec);
    if (ec) return std::nullopt;
    const auto sceneTime = fs::last_write_time(sceneFile, ec);
    if (ec || recoveryTime > sceneTime) return path;
    return std::nullopt; // saved after the recovery was written: nothing was lost
}

void removeRecovery(const std::filesystem::path& sceneFile) {
    std::error_code ec;
    std::filesystem::remove(recoveryPath(sceneFile), ec);
}

} // namespace rmsc::editor
