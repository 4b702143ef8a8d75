// The rmsc Python module: scenes, edits by JSON pointer or node id, validation and rendering to
// NumPy arrays, over the public C++ API (rmsc/rmsc.hpp). Rendering uses one headless context and
// one renderer per process, made on first use (or by use_backend) and released at exit.
#include <rmsc/rmsc.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <mutex>
#include <optional>

namespace py = pybind11;
using namespace rmsc::api;

namespace {

struct Gl {
    std::mutex mutex;
    std::optional<HeadlessContext> context;
    std::optional<Renderer> renderer;
    std::string backend; // as asked for
};

Gl& gl() {
    static Gl* state = new Gl; // released by the atexit hook, never by a static destructor
    return *state;
}

void useBackend(const std::string& name) {
    Gl& state = gl();
    const Backend backend = parseBackend(name);
    std::lock_guard lock(state.mutex);
    if (state.context) {
        if (name == state.backend) return;
        throw Error(ErrorKind::Usage, "use_backend: the process already renders through '" +
                                          state.backend +
                                          "'; choose the back end before the "
                                          "first render");
    }
    state.context.emplace(backend);
    state.renderer.emplace();
    state.backend = name;
}

void releaseGl() {
    Gl& state = gl();
    std::lock_guard lock(state.mutex);
    if (!state.context) return;
    try {
        state.context->makeCurrent();
    } catch (const Error&) {
    }
    state.renderer.reset();
    state.context.reset();
}

template <class T> py::array toArray(const Image& image) {
    std::vector<py::ssize_t> shape = {image.height, image.width};
    if (image.channels > 1) shape.push_back(image.channels);
    py::array_t<T> array(shape);
    std::memcpy(array.mutable_data(), image.bytes.data(), image.bytes.size());
    return array;
}

py::array render(const Scene& scene, std::pair<int, int> size, const std::string& aovName) {
    const Aov aov = parseAov(aovName);
    if (!gl().context) useBackend("auto");
    Gl& state = gl();
    Image image;
    {
        py::gil_scoped_release release;
        std::lock_guard lock(state.mutex);
        state.context->makeCurrent();
        image = state.renderer->render(scene, size.first, size.second, aov);
    }
    switch (image.type) {
    case Image::Type::UInt8:
        return toArray<std::uint8_t>(image);
    case Image::Type::Float32:
        return toArray<float>(image);
    case Image::Type::UInt32:
        return toArray<std::uint32_t>(image);
    }
    return {};
}

std::string toJson(const py::handle& value) {
    return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

py::object fromJson(const std::string& text) {
    return py::module_::import("json").attr("loads")(text);
}

// The JSON pointer of a node given as an object id (int) or a name (str).
std::string nodePointer(const Scene& scene, const py::object& node) {
    if (py::isinstance<py::str>(node)) return scene.nodePointer(node.cast<std::string>());
    if (py::isinstance<py::int_>(node) && !py::isinstance<py::bool_>(node)) {
        const long long id = node.cast<long long>();
        if (id < 0 || id > 0xffffffffLL)
            throw Error(ErrorKind::Usage, "no node has the object id " + std::to_string(id) +
                                              " (object ids are 0 to 2^32 - 1)");
        return scene.nodePointer(std::uint32_t(id));
    }
    throw py::type_error("a node is an object id (int) or a name (str), not " +
                         std::string(py::str(node.get_type().attr("__name__"))));
}

// "/sdf/children/1" and "radius" (or "/radius") -> "/sdf/children/1/radius".
std::string underNode(const std::string& pointer, std::string key) {
    if (!key.empty() && key.front() == '/') key.erase(0, 1);
    if (key.empty()) throw Error(ErrorKind::Usage, "no key given (\"radius\", \"position\", ...)");
    return pointer + "/" + key;
}

} // namespace

PYBIND11_MODULE(rmsc, m) {
    m.doc() = "rmsc: load, edit, validate and render scenes of glTF meshes and SDF objects "
              "headless (docs/embedding.md).";
    m.attr("__version__") = version();

    static py::exception<Error> errorType(m, "Error");
    errorType.doc() = "A refused call: .kind is 'bad_input', 'context' or 'usage'; .problems "
                      "lists the problems of bad input (file, pointer, message).";
    py::class_<Problem>(m, "Problem", "One problem in a scene, as `rmsc validate` prints it.")
        .def_property_readonly(
            "severity",
            [](const Problem& p) {
                return p.severity == Problem::Severity::Error ? "error" : "warning";
            },
            "'error' or 'warning'.")
        .def_readonly("file", &Problem::file, "The file the problem is in.")
        .def_readonly("pointer", &Problem::pointer, "JSON pointer (or glTF element) of the value.")
        .def_readonly("message", &Problem::message, "What was wrong and what was expected.")
        .def("__str__", &Problem::text, "The line `rmsc validate` prints: FILE: POINTER: MESSAGE.")
        .def("__repr__", [](const Problem& p) { return "<rmsc.Problem " + p.text() + ">"; });
    py::register_exception_translator([](std::exception_ptr pointer) {
        try {
            if (pointer) std::rethrow_exception(pointer);
        } catch (const Error& error) {
            py::object instance = py::reinterpret_borrow<py::object>(errorType.ptr())(error.what());
            instance.attr("kind") = error.kind() == ErrorKind::BadInput  ? "bad_input"
                                    : error.kind() == ErrorKind::Context ? "context"
                                                                         : "usage";
            instance.attr("problems") = py::cast(error.problems());
            PyErr_SetObject(errorType.ptr(), instance.ptr());
        }
    });

    m.def("use_backend", &useBackend, py::arg("name"),
          "Chooses the headless OpenGL back end ('auto', 'egl' or 'osmesa', as `rmsc render "
          "--backend`) and creates the context. Call it before the first render; without it the "
          "first render uses 'auto'.");
    m.def(
        "backend", [] { return gl().context ? gl().context->backend() : std::string(); },
        "The back end in use ('egl' or 'osmesa'), '' before the first render.");
    m.def("validate", &Scene::validate, py::arg("path"),
          "Checks a scene file as `rmsc validate` does: returns the list of rmsc.Problem found "
          "(errors and warnings, in order), empty when there is nothing to report.");
    m.def("validate_json", &Scene::validateJson, py::arg("text"), py::arg("path") = "scene.json",
          "Checks scene JSON text as `rmsc validate` checks the file `path` holding it: the "
          "list of rmsc.Problem, as validate() returns it.");

    py::class_<Scene>(m, "Scene",
                      "A scene file's content, checked and compiled; edits by JSON "
                      "pointer; render() draws it headless.")
        .def_static("load", &Scene::load, py::arg("path"),
                    "Loads a scene (.json) or a glTF model (.gltf/.glb). Raises rmsc.Error with "
                    "every problem (file, JSON pointer, message).")
        .def_static("from_json", &Scene::fromJson, py::arg("text"), py::arg("path") = "scene.json",
                    "Parses scene JSON text; `path` names it in messages and is where relative "
                    "paths resolve from.")
        .def("render", &render, py::arg("size") = std::pair<int, int>(640, 360),
             py::arg("aov") = "color",
             "Renders with the scene's camera at size=(width, height). aov='color': uint8 "
             "array (height, width, 3), sRGB; 'depth': float32 (height, width), view depth in "
             "metres, inf where nothing was hit; 'normal': float32 (height, width, 3); 'id': "
             "uint32 (height, width); 'steps': float32 (height, width).")
        .def(
            "set",
            [](Scene& scene, const std::string& pointer, const py::object& value) {
                scene.set(pointer, toJson(value));
            },
            py::arg("pointer"), py::arg("value"),
            "Sets the value at a JSON pointer ('/sdf/children/0/radius') to a Python value "
            "(number, list, str, dict) and recompiles the scene; an invalid value raises "
            "rmsc.Error and leaves the scene unchanged. Number edits draw without compiling "
            "shaders again.")
        .def(
            "get",
            [](const Scene& scene, const std::string& pointer) {
                return fromJson(scene.get(pointer));
            },
            py::arg("pointer"), "The value at a JSON pointer, as a Python value.")
        .def(
            "node_pointer",
            [](const Scene& scene, const py::object& node) { return nodePointer(scene, node); },
            py::arg("node"),
            "The JSON pointer of a node: `node` is an object id as the 'id' output shows it "
            "(65536 + n for the SDF node n in pre-order, 1 + i for the mesh placement i) or "
            "the name of an SDF node, mesh placement or light. An unknown id or name (or a "
            "name two nodes share) raises rmsc.Error naming it.")
        .def(
            "set_node",
            [](Scene& scene, const py::object& node, const std::string& key,
               const py::object& value) {
                scene.set(underNode(nodePointer(scene, node), key), toJson(value));
            },
            py::arg("node"), py::arg("key"), py::arg("value"),
            "set() of `key` under a node given by object id or name (see node_pointer): "
            "scene.set_node('ball', 'radius', 0.3), scene.set_node(65537, 'position', "
            "[0, 1, 0]); `key` may be a path below the node ('modifiers/0/radius').")
        .def(
            "get_node",
            [](const Scene& scene, const py::object& node, const std::string& key) {
                return fromJson(scene.get(underNode(nodePointer(scene, node), key)));
            },
            py::arg("node"), py::arg("key"),
            "get() of `key` under a node given by object id or name (see node_pointer).")
        .def("json", &Scene::json, "The scene as JSON text, edits applied.")
        .def_property_readonly("warnings", &Scene::warnings,
                               "Warnings of the last load or edit, as rmsc.Problem.")
        .def_property_readonly("revision", &Scene::revision,
                               "A number that changes with every successful edit.");

    py::module_::import("atexit").attr("register")(
        py::cpp_function(&releaseGl, "Releases the renderer and the context at exit."));
}
