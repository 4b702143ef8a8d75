// Scenes: loading through the engine's reader and preparation (the path `rmsc render` takes),
// and edits by JSON pointer, which re-read the edited document so that a bad value is reported
// exactly as in a file.
#include "rmsc/scene.hpp"

#include "scene_impl.hpp"

#include "prepare/sdf_cost.hpp"
#include "scene/scene_json.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>

namespace rmsc::api {
namespace {

std::atomic<std::uint64_t> nextSceneId{1};

bool isGltf(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension == ".gltf" || extension == ".glb";
}

// Checks and prepares scene text (shells in the fullscreen pass: drawInto has no proxies to
// draw them with, and the image is the same). nullopt with the problems in `diagnostics`.
std::optional<PreparedScene> prepareText(std::string_view text, const std::filesystem::path& path,
                                         Diagnostics& diagnostics) {
    std::optional<::rmsc::Scene> scene = parseScene(text, path, diagnostics);
    if (!scene) return std::nullopt;
    std::optional<PreparedScene> prepared =
        prepareScene(std::move(*scene), diskFileSource(), diagnostics, ShellMode::Fullscreen);
    if (prepared && !checkSdfCost(*prepared, diagnostics)) return std::nullopt;
    return prepared;
}

std::vector<Problem> warningsOf(const Diagnostics& diagnostics) {
    std::vector<Problem> warnings = toProblems(diagnostics);
    std::erase_if(warnings,
                  [](const Problem& p) { return p.severity != Problem::Severity::Warning; });
    return warnings;
}

} // namespace

Scene::Scene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;
Scene::~Scene() = default;

Scene Scene::fromJson(std::string_view text, const std::string& path) {
    Diagnostics diagnostics;
    std::optional<PreparedScene> prepared = prepareText(text, path, diagnostics);
    if (!prepared) throw badInput(diagnostics);
    auto impl = std::make_unique<Impl>();
    impl->id = nextSceneId++;
    impl->path = path;
    impl->document = nlohmann::json::parse(text); // parseScene accepted it
    impl->prepared = std::move(*prepared);
    impl->warnings = warningsOf(diagnostics);
    return Scene(std::move(impl));
}

Scene Scene::load(const std::string& path) {
    if (isGltf(path)) {
        Diagnostics diagnostics;
        std::optional<PreparedScene> prepared = openScene(path, diagnostics, ShellMode::Fullscreen);
        if (!prepared) throw badInput(diagnostics);
        auto impl = std::make_unique<Impl>();
        impl->id = nextSceneId++;
        impl->path = path;
        impl->document = nlohmann::json::parse(sceneToJson(prepared->scene));
        impl->prepared = std::move(*prepared);
        impl->warnings = warningsOf(diagnostics);
        return Scene(std::move(impl));
    }
    std::string error;
    std::optional<std::string> text = diskFileSource().read(path, error);
    if (!text) {
        Diagnostics diagnostics;
        diagnostics.error(path, "", "cannot read the scene file: " + error);
        throw badInput(diagnostics);
    }
    return fromJson(*text, path);
}

std::vector<Problem> Scene::validate(const std::string& path) {
    Diagnostics diagnostics;
    openScene(path, diagnostics);
    return toProblems(diagnostics);
}

const std::vector<Problem>& Scene::warnings() const {
    return impl_->warnings;
}

std::string Scene::json() const {
    return impl_->document.dump(2);
}

std::uint64_t Scene::revision() const {
    return impl_->revision;
}

namespace {

nlohmann::json::json_pointer parsePointer(std::string_view pointer) {
    try {
        return nlohmann::json::json_pointer(std::string(pointer));
    } catch (const nlohmann::json::exception&) {
        throw Error(ErrorKind::Usage, "'" + std::string(pointer) +
                                          "' is not a JSON pointer (RFC 6901: \"/key/0/key\")");
    }
}

} // namespace

std::string Scene::get(std::string_view pointer) const {
    const nlohmann::json::json_pointer at = parsePointer(pointer);
    if (!impl_->document.contains(at))
        throw Error(ErrorKind::Usage, impl_->path.string() + ": " + std::string(pointer) +
                                          ": no such value in the scene");
    return impl_->document.at(at).dump();
}

void Scene::set(std::string_view pointer, std::string_view value) {
    const nlohmann::json::json_pointer at = parsePointer(pointer);
    const std::string file = impl_->path.string();
    if (at.empty())
        throw Error(ErrorKind::Usage, "set: the pointer names the whole scene; load a new one");
    const nlohmann::json::json_pointer parent = at.parent_pointer();
    if (!impl_->document.contains(parent))
        throw Error(ErrorKind::Usage, file + ": " + parent.to_string() +
                                          ": no such value in the scene (set changes or adds a "
                                          "value in an existing object or array)");
    const nlohmann::json& container = impl_->document.at(parent);
    if (container.is_array() && !impl_->document.contains(at))
        throw Error(ErrorKind::Usage, file + ": " + std::string(pointer) +
                                          ": past the end of the array (set replaces elements; "
                                          "it does not add them)");
    if (!container.is_object() && !container.is_array())
        throw Error(ErrorKind::Usage,
                    file + ": " + parent.to_string() + ": is neither an object nor an array");
    nlohmann::json parsed = nlohmann::json::parse(value, nullptr, false);
    if (parsed.is_discarded()) {
        Diagnostics diagnostics;
        diagnostics.error(
            file, std::string(pointer),
            "expected a JSON value (a number, a string in quotes, an array...), got '" +
                std::string(value) + "'");
        throw badInput(diagnostics);
    }
    nlohmann::json edited = impl_->document;
    edited[at] = std::move(parsed);
    Diagnostics diagnostics;
    std::optional<PreparedScene> prepared = prepareText(edited.dump(), impl_->path, diagnostics);
    if (!prepared) throw badInput(diagnostics);
    impl_->document = std::move(edited);
    impl_->prepared = std::move(*prepared);
    impl_->warnings = warningsOf(diagnostics);
    ++impl_->revision;
}

} // namespace rmsc::api
