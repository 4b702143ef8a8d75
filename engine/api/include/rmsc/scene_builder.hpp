// rmsc public API: building a scene in code. A SceneBuilder writes the scene file a program
// would otherwise write as JSON text (docs/scene-format.md): shapes of the primitive catalogue
// with their parameters, groups of the operation catalogue over their children, materials,
// lights, meshes, the camera and the render settings. build() reads it with the scene reader,
// so the Scene is the one the same JSON gives, and a bad value is the reader's problem at its
// JSON pointer.
#pragma once

#include "rmsc/light.hpp"
#include "rmsc/scene.hpp"

#include <array>
#include <initializer_list>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rmsc::api {

// One value of the scene format: a number, a boolean, a string, a list of numbers (a vector, a
// colour), or any JSON text (Value::json("{\"type\": \"twist\"}")) for what the others cannot
// say.
class Value {
  public:
    Value(double number) : value_(number) {}
    Value(int number) : value_(double(number)) {}
    Value(bool flag) : value_(flag) {}
    Value(const char* text) : value_(std::string(text)) {}
    Value(std::string text) : value_(std::move(text)) {}
    Value(std::initializer_list<double> numbers) : value_(std::vector<double>(numbers)) {}
    Value(std::vector<double> numbers) : value_(std::move(numbers)) {}
    static Value json(std::string text) {
        Value value(0.0);
        value.value_ = Json{std::move(text)};
        return value;
    }

    struct Json {
        std::string text;
    };
    using Variant = std::variant<double, bool, std::string, std::vector<double>, Json>;
    const Variant& get() const { return value_; }

  private:
    Variant value_;
};

// Keys and values of an object of the format, in order; a key given twice keeps the last.
using Params = std::vector<std::pair<std::string, Value>>;

struct NodeAccess; // the library's own

// A node of the SDF tree: a shape or a group, with the keys every node takes ("name",
// "position", "rotation", "scale", "material", "cut", ...).
class Node {
  public:
    // A shape: `name` is a primitive of the catalogue (SceneBuilder::shapes()) or a profile
    // solid ("extrusion", "revolution"); `params` its parameters and node keys.
    static Node shape(std::string name, Params params = {});
    // A group: `operation` is one of SceneBuilder::operations(), combining `children`;
    // `params` its keys ("smoothness", "blend", node keys).
    static Node group(std::string operation, std::vector<Node> children, Params params = {});

    Node& set(std::string key, Value value);              // one more key (or a new value for one)
    Node& add(Node child);                                // one more child of a group
    Node& modifier(std::string type, Params params = {}); // appended to "modifiers"

  private:
    friend struct NodeAccess;
    bool group_ = false;
    Params keys_; // "shape" or "op" first
    std::vector<Node> children_;
    std::vector<std::pair<std::string, Params>> modifiers_;
};

// A parameter of a shape, as the primitive catalogue describes it.
struct ShapeParameter {
    std::string key;
    int components = 1; // 1: a number, 3: a vector
    std::array<float, 3> defaultValue{};
    float min = 0, max = 0; // of each component, inclusive
    std::string description;
};

struct ShapeInfo {
    std::string name; // the value of "shape"
    std::vector<ShapeParameter> parameters;
    std::string description;
};

class SceneBuilder {
  public:
    SceneBuilder& camera(Params params);      // "camera": position, target, fov, ...
    SceneBuilder& render(Params params);      // "render": max_steps, background, ...
    SceneBuilder& environment(Params params); // "environment": sky, fog
    SceneBuilder& material(std::string name, Params params);
    SceneBuilder& light(const Light& light);
    SceneBuilder& mesh(std::string file, Params params = {}); // a glTF placement
    SceneBuilder& sdf(Node root);

    // The scene file the builder makes.
    std::string json() const;
    // The scene, as Scene::fromJson(json(), path) reads it: throws Error (BadInput) with the
    // reader's problems at their pointers (a number that JSON cannot hold is one too).
    Scene build(const std::string& path = "scene.json") const;

    // What shapes and operations there are: the engine's catalogues, in their order.
    static std::vector<ShapeInfo> shapes();
    static std::vector<std::string> operations();

  private:
    Params camera_, render_, environment_;
    std::vector<std::pair<std::string, Params>> materials_;
    std::vector<Light> lights_;
    std::vector<Params> meshes_;
    std::vector<Node> sdf_; // none or one
};

} // namespace rmsc::api
