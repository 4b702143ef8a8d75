// rmsc public API: scenes. A Scene is a scene file's content, checked and with its SDF tree
// compiled on the CPU; it holds no OpenGL objects, so any Renderer can draw it. Edits address
// values by JSON pointer, as the scene format (docs/scene-format.md) lays them out, or by the
// object id or name of a node and a key under it.
#pragma once

#include "rmsc/error.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rmsc::api {

class Scene {
  public:
    // Loads a scene file (.json), or a glTF model (.gltf / .glb, opened with a default light
    // and a framing camera), with every file it names. Throws Error (BadInput) with every
    // problem found, as `rmsc render` prints them.
    static Scene load(const std::string& path);
    // Parses scene JSON text. `path` names the text in messages and is the folder relative
    // mesh and texture paths resolve against (the file need not exist).
    static Scene fromJson(std::string_view text, const std::string& path = "scene.json");
    // What `rmsc validate PATH` reports: every error and warning, in order; empty when the
    // scene is valid and has nothing to warn about. Never throws for bad input.
    static std::vector<Problem> validate(const std::string& path);
    // The same for scene JSON text (SceneBuilder::json(), a host's own text), as if it were
    // the file `path`: what `rmsc validate` would report for that file.
    static std::vector<Problem> validateJson(std::string_view text,
                                             const std::string& path = "scene.json");

    Scene(Scene&&) noexcept;
    Scene& operator=(Scene&&) noexcept;
    ~Scene();

    // Warnings of the last load or edit (unknown keys, ...).
    const std::vector<Problem>& warnings() const;
    // The scene as JSON text, with every edit applied.
    std::string json() const;
    // The JSON text of the value at `pointer` ("/sdf/children/0/radius"); throws Error
    // (Usage) when there is none.
    std::string get(std::string_view pointer) const;
    // Sets the value at `pointer` to the JSON text `value` ("0.4", "[0, 1, 0]", "\"red\"") and
    // checks and compiles the scene again. The parent of the pointer must exist. An edit that
    // would make the scene invalid throws Error (BadInput, the problems at their pointers) and
    // changes nothing. Edits of numbers (parameters, transforms, material values) keep the
    // scene's structure: a Renderer compiles shaders for the scene's first edit once, and none
    // for the edits of numbers after it.
    void set(std::string_view pointer, std::string_view value);

    // Nodes by id rather than by pointer. An object id is what the Id output shows (docs/
    // scene-format.md, "Object ids"): 65536 + n for the SDF node n in pre-order (the root is
    // 65536), 1 + i for the mesh placement i. A name is the "name" of an SDF node, a mesh
    // placement or a light, and must name exactly one of them. The JSON pointer of the node
    // ("/sdf/children/1"); throws Error (Usage) naming the id or name when none (or, for a name,
    // more than one) has it.
    std::string nodePointer(std::uint32_t objectId) const;
    std::string nodePointer(std::string_view name) const;
    // set() of `key` under the node: a key of the node ("radius", "position") or a path below it
    // ("modifiers/0/radius"). Errors as nodePointer's and set's.
    void setNode(std::uint32_t objectId, std::string_view key, std::string_view value);
    void setNode(std::string_view name, std::string_view key, std::string_view value);

    // Changes with every successful edit.
    std::uint64_t revision() const;

    struct Impl;
    const Impl& impl() const { return *impl_; } // for the library's own use

  private:
    explicit Scene(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

} // namespace rmsc::api
