// Scenes built in code: the builder's parts written as the scene file's JSON document, which
// the scene reader then reads as it reads a file, so that a built scene and its JSON are one.
// The shapes and operations it lists come from the engine's catalogues.
#include "rmsc/scene_builder.hpp"

#include "scene_impl.hpp"

#include "sdf/operations.hpp"
#include "sdf/primitives.hpp"

#include <cmath>

namespace rmsc::api {

struct NodeAccess {
    static bool group(const Node& node) { return node.group_; }
    static const Params& keys(const Node& node) { return node.keys_; }
    static const std::vector<Node>& children(const Node& node) { return node.children_; }
    static const std::vector<std::pair<std::string, Params>>& modifiers(const Node& node) {
        return node.modifiers_;
    }
};

namespace {

using Json = nlohmann::ordered_json;

// RFC 6901: "a/b" -> "a~1b".
std::string escaped(const std::string& key) {
    std::string out;
    for (const char c : key)
        out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return out;
}

// Writes values, reporting the numbers JSON cannot hold at their pointers.
struct Writer {
    Diagnostics diagnostics;
    std::string file;

    // Whole numbers as JSON integers, as a file would write them (integer keys need them).
    Json number(double value, const std::string& pointer) {
        constexpr double kExactIntegers = 9007199254740992.0; // 2^53
        if (std::isfinite(value) && value == std::trunc(value) && std::abs(value) < kExactIntegers)
            return std::int64_t(value);
        if (!std::isfinite(value))
            diagnostics.error(file, pointer,
                              std::string("expected a finite number, got ") +
                                  (std::isnan(value) ? "nan"
                                   : value > 0       ? "inf"
                                                     : "-inf"));
        return value;
    }

    Json value(const Value& value, const std::string& pointer) {
        return std::visit(
            [&](const auto& v) -> Json {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, double>) {
                    return number(v, pointer);
                } else if constexpr (std::is_same_v<T, std::vector<double>>) {
                    Json array = Json::array();
                    for (std::size_t i = 0; i < v.size(); ++i)
                        array.push_back(number(v[i], pointer + "/" + std::to_string(i)));
                    return array;
                } else if constexpr (std::is_same_v<T, Value::Json>) {
                    Json parsed = Json::parse(v.text, nullptr, false);
                    if (parsed.is_discarded()) {
                        diagnostics.error(file, pointer,
                                          "expected JSON text (Value::json), got '" + v.text + "'");
                        return nullptr;
                    }
                    return parsed;
                } else {
                    return v;
                }
            },
            value.get());
    }

    Json object(const Params& params, const std::string& pointer, Json out = Json::object()) {
        for (const auto& [key, v] : params)
            out[key] = value(v, pointer + "/" + escaped(key));
        return out;
    }

    Json node(const Node& node, const std::string& pointer);
    Json light(const Light& light, const std::string& pointer);
};

std::string_view lightTypeName(Light::Type type) {
    switch (type) {
    case Light::Type::Point:
        return "point";
    case Light::Type::Spot:
        return "spot";
    default:
        return "directional";
    }
}

Json Writer::light(const Light& light, const std::string& pointer) {
    const auto vector = [&](const std::array<float, 3>& v, const char* key) {
        return value(Value({double(v[0]), double(v[1]), double(v[2])}), pointer + "/" + key);
    };
    const auto scalar = [&](float v, const char* key) {
        return number(double(v), pointer + "/" + key);
    };
    Json out = Json::object();
    if (light.type != Light::Type::Directional && light.type != Light::Type::Point &&
        light.type != Light::Type::Spot)
        diagnostics.error(file, pointer + "/type",
                          "unknown light type " + std::to_string(int(light.type)) +
                              "; known types: Directional, Point, Spot");
    out["type"] = std::string(lightTypeName(light.type));
    if (!light.name.empty()) out["name"] = light.name;
    if (light.type != Light::Type::Point) out["direction"] = vector(light.direction, "direction");
    if (light.type != Light::Type::Directional) {
        out["position"] = vector(light.position, "position");
        if (light.range != 0.0f) out["range"] = scalar(light.range, "range");
    }
    out["color"] = vector(light.color, "color");
    out["intensity"] = scalar(light.intensity, "intensity");
    if (light.type == Light::Type::Spot) {
        out["inner_angle"] = scalar(light.innerAngle, "inner_angle");
        out["outer_angle"] = scalar(light.outerAngle, "outer_angle");
    }
    if (!light.castShadows) out["shadows"] = false;
    if (!(light.shadowSoftness < 0.0f))
        out["shadow_softness"] = scalar(light.shadowSoftness, "shadow_softness");
    return out;
}

Json Writer::node(const Node& node, const std::string& pointer) {
    Json out = object(NodeAccess::keys(node), pointer);
    const auto& modifiers = NodeAccess::modifiers(node);
    if (!modifiers.empty()) {
        Json array = Json::array();
        for (std::size_t i = 0; i < modifiers.size(); ++i) {
            Json modifier = Json::object();
            modifier["type"] = modifiers[i].first;
            array.push_back(object(modifiers[i].second, pointer + "/modifiers/" + std::to_string(i),
                                   std::move(modifier)));
        }
        out["modifiers"] = std::move(array);
    }
    if (NodeAccess::group(node)) {
        const std::vector<Node>& children = NodeAccess::children(node);
        Json array = Json::array();
        for (std::size_t i = 0; i < children.size(); ++i)
            array.push_back(this->node(children[i], pointer + "/children/" + std::to_string(i)));
        out["children"] = std::move(array);
    }
    return out;
}

} // namespace

Node Node::shape(std::string name, Params params) {
    Node node;
    node.keys_.emplace_back("shape", std::move(name));
    node.keys_.insert(node.keys_.end(), params.begin(), params.end());
    return node;
}

Node Node::group(std::string operation, std::vector<Node> children, Params params) {
    Node node;
    node.group_ = true;
    node.keys_.emplace_back("op", std::move(operation));
    node.keys_.insert(node.keys_.end(), params.begin(), params.end());
    node.children_ = std::move(children);
    return node;
}

Node& Node::set(std::string key, Value value) {
    keys_.emplace_back(std::move(key), std::move(value));
    return *this;
}

Node& Node::add(Node child) {
    group_ = true;
    children_.push_back(std::move(child));
    return *this;
}

Node& Node::modifier(std::string type, Params params) {
    modifiers_.emplace_back(std::move(type), std::move(params));
    return *this;
}

SceneBuilder& SceneBuilder::camera(Params params) {
    camera_.insert(camera_.end(), params.begin(), params.end());
    return *this;
}

SceneBuilder& SceneBuilder::render(Params params) {
    render_.insert(render_.end(), params.begin(), params.end());
    return *this;
}

SceneBuilder& SceneBuilder::environment(Params params) {
    environment_.insert(environment_.end(), params.begin(), params.end());
    return *this;
}

SceneBuilder& SceneBuilder::material(std::string name, Params params) {
    materials_.emplace_back(std::move(name), std::move(params));
    return *this;
}

SceneBuilder& SceneBuilder::light(const Light& light) {
    lights_.push_back(light);
    return *this;
}

SceneBuilder& SceneBuilder::mesh(std::string file, Params params) {
    params.insert(params.begin(), {"file", std::move(file)});
    meshes_.push_back(std::move(params));
    return *this;
}

SceneBuilder& SceneBuilder::sdf(Node root) {
    sdf_.clear();
    sdf_.push_back(std::move(root));
    return *this;
}

namespace {

// The document and the problems found writing it.
Json writeDocument(Writer& writer, const Params& camera, const Params& render,
                   const Params& environment,
                   const std::vector<std::pair<std::string, Params>>& materials,
                   const std::vector<Light>& lights, const std::vector<Params>& meshes,
                   const std::vector<Node>& sdf) {
    Json document = Json::object();
    document["version"] = 1;
    if (!camera.empty()) document["camera"] = writer.object(camera, "/camera");
    if (!render.empty()) document["render"] = writer.object(render, "/render");
    if (!environment.empty()) document["environment"] = writer.object(environment, "/environment");
    if (!materials.empty()) {
        Json out = Json::object();
        for (const auto& [name, params] : materials)
            out[name] = writer.object(params, "/materials/" + escaped(name));
        document["materials"] = std::move(out);
    }
    if (!lights.empty()) {
        Json out = Json::array();
        for (std::size_t i = 0; i < lights.size(); ++i)
            out.push_back(writer.light(lights[i], "/lights/" + std::to_string(i)));
        document["lights"] = std::move(out);
    }
    if (!meshes.empty()) {
        Json out = Json::array();
        for (std::size_t i = 0; i < meshes.size(); ++i)
            out.push_back(writer.object(meshes[i], "/meshes/" + std::to_string(i)));
        document["meshes"] = std::move(out);
    }
    if (!sdf.empty()) document["sdf"] = writer.node(sdf.front(), "/sdf");
    return document;
}

} // namespace

std::string SceneBuilder::json() const {
    Writer writer;
    return writeDocument(writer, camera_, render_, environment_, materials_, lights_, meshes_, sdf_)
        .dump(2);
}

Scene SceneBuilder::build(const std::string& path) const {
    Writer writer;
    writer.file = path;
    const Json document =
        writeDocument(writer, camera_, render_, environment_, materials_, lights_, meshes_, sdf_);
    if (writer.diagnostics.hasErrors()) throw badInput(writer.diagnostics);
    return Scene::fromJson(document.dump(), path);
}

std::vector<ShapeInfo> SceneBuilder::shapes() {
    std::vector<ShapeInfo> shapes;
    for (const PrimitiveSpec& spec : primitiveCatalogue()) {
        ShapeInfo shape{std::string(spec.name), {}, std::string(spec.description)};
        for (const ParamSpec& param : spec.params)
            shape.parameters.push_back({std::string(param.name), param.components, param.value,
                                        param.minValue, param.maxValue,
                                        std::string(param.description)});
        shapes.push_back(std::move(shape));
    }
    return shapes;
}

std::vector<std::string> SceneBuilder::operations() {
    return operationNames();
}

} // namespace rmsc::api
