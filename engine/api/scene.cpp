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

std::vector<Problem> Scene::validateJson(std::string_view text, const std::string& path) {
    Diagnostics diagnostics;
    std::optional<::rmsc::Scene> scene = parseScene(text, path, diagnostics);
    if (scene) {
        std::optional<PreparedScene> prepared =
            prepareScene(std::move(*scene), diskFileSource(), diagnostics);
        if (prepared) checkSdfCost(*prepared, diagnostics);
    }
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

namespace {

constexpr std::uint32_t kSdfIdBase = 65536; // docs/scene-format.md, "Object ids"

// The pointers of the SDF nodes under `node` (at `pointer`), in pre-order: the numbering of
// their object ids.
void sdfNodePointers(const nlohmann::json& node, const std::string& pointer,
                     std::vector<std::string>& out) {
    out.push_back(pointer);
    if (!node.is_object()) return;
    const auto children = node.find("children");
    if (children == node.end() || !children->is_array()) return;
    for (std::size_t i = 0; i < children->size(); ++i)
        sdfNodePointers((*children)[i], pointer + "/children/" + std::to_string(i), out);
}

std::vector<std::string> sdfNodePointers(const nlohmann::json& document) {
    std::vector<std::string> pointers;
    if (document.contains("sdf")) sdfNodePointers(document["sdf"], "/sdf", pointers);
    return pointers;
}

std::size_t arraySize(const nlohmann::json& document, const char* key) {
    const auto found = document.find(key);
    return found != document.end() && found->is_array() ? found->size() : 0;
}

std::string jsonString(std::string_view text) {
    return nlohmann::json(std::string(text)).dump();
}

} // namespace

std::string Scene::nodePointer(std::uint32_t objectId) const {
    const nlohmann::json& document = impl_->document;
    const std::vector<std::string> sdf = sdfNodePointers(document);
    const std::size_t meshes = arraySize(document, "meshes");
    if (objectId >= kSdfIdBase && objectId - kSdfIdBase < sdf.size())
        return sdf[objectId - kSdfIdBase];
    if (objectId >= 1 && objectId < kSdfIdBase && objectId - 1 < meshes)
        return "/meshes/" + std::to_string(objectId - 1);
    std::string known;
    if (!sdf.empty())
        known += "SDF nodes " + std::to_string(kSdfIdBase) + " to " +
                 std::to_string(kSdfIdBase + sdf.size() - 1);
    if (meshes > 0)
        known += std::string(known.empty() ? "" : ", ") + "mesh placements 1 to " +
                 std::to_string(meshes);
    throw Error(ErrorKind::Usage, impl_->path.string() + ": no node has the object id " +
                                      std::to_string(objectId) + " (" +
                                      (known.empty() ? "the scene has no nodes" : known) + ")");
}

std::string Scene::nodePointer(std::string_view name) const {
    if (name.empty())
        throw Error(ErrorKind::Usage, "nodePointer: an empty name names no node; give a name or "
                                      "an object id");
    const nlohmann::json& document = impl_->document;
    std::vector<std::string> candidates = sdfNodePointers(document);
    for (const char* array : {"meshes", "lights"})
        for (std::size_t i = 0; i < arraySize(document, array); ++i)
            candidates.push_back(std::string("/") + array + "/" + std::to_string(i));
    std::vector<std::string> found, names;
    for (const std::string& pointer : candidates) {
        const nlohmann::json& node = document.at(nlohmann::json::json_pointer(pointer));
        const auto key = node.is_object() ? node.find("name") : node.end();
        if (key == node.end() || !key->is_string()) continue;
        const std::string& text = key->get_ref<const std::string&>();
        if (text == name) found.push_back(pointer);
        if (!text.empty() && std::find(names.begin(), names.end(), text) == names.end())
            names.push_back(text);
    }
    if (found.size() == 1) return found[0];
    const std::string file = impl_->path.string();
    if (found.size() > 1) {
        std::string list;
        for (const std::string& pointer : found)
            list += (list.empty() ? "" : ", ") + pointer;
        throw Error(ErrorKind::Usage, file + ": the name " + jsonString(name) + " is not unique (" +
                                          list + "); address the node by object id or pointer");
    }
    std::string list;
    constexpr std::size_t kListed = 16;
    for (std::size_t i = 0; i < names.size() && i < kListed; ++i)
        list += (i ? ", " : "") + jsonString(names[i]);
    if (names.size() > kListed) list += " and " + std::to_string(names.size() - kListed) + " more";
    throw Error(ErrorKind::Usage,
                file + ": no SDF node, mesh placement or light is named " + jsonString(name) +
                    (names.empty() ? " (none has a name)" : " (names: " + list + ")"));
}

namespace {

std::string underNode(const std::string& node, std::string_view key) {
    if (key.starts_with('/')) key.remove_prefix(1);
    if (key.empty())
        throw Error(ErrorKind::Usage, "setNode: no key given (\"radius\", \"position\", ...)");
    return node + "/" + std::string(key);
}

} // namespace

void Scene::setNode(std::uint32_t objectId, std::string_view key, std::string_view value) {
    set(underNode(nodePointer(objectId), key), value);
}

void Scene::setNode(std::string_view name, std::string_view key, std::string_view value) {
    set(underNode(nodePointer(name), key), value);
}

} // namespace rmsc::api
