// A host program embedding rmsc: it draws a rotating glTF cube with its own shader into its own
// colour and depth textures, then asks rmsc to add the SDF objects of scene.json, which
// intersect the cube, through its own camera and lit by its own light
// (rmsc::api::Renderer::drawInto). In a window (GLFW) by default; `--headless OUT.png` renders
// one frame through EGL (rmsc's headless context) at `--angle` degrees and writes it. The camera
// is the scene file's, so `rmsc render` of the scene with the cube placed at that angle and the
// host's light in place of the file's draws the same picture.
//
//   rmsc_embed [--headless OUT.png] [--size WxH] [--angle DEG]
#include <rmsc/rmsc.hpp>

#include <glad/gl.h> // the loader first: it stands in for GL/gl.h

#define GLFW_INCLUDE_NONE
#include <EGL/egl.h>
#include <GLFW/glfw3.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stb/stb_image_write.h>

#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// The host's look: a flat grey lit by one direction, on a dark background (display values,
// written as they are).
constexpr float kMeshColor[3] = {0.80f, 0.80f, 0.84f};
constexpr float kLightDirection[3] = {0.3f, 0.9f, 0.5f}; // towards the light, normalized below
constexpr float kLightIntensity = 3.0f;                  // of the same light on the SDF objects
constexpr float kBackground[4] = {0.10f, 0.11f, 0.13f, 1.0f};

const char* kVertexShader = R"(#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 uModel;
uniform mat4 uViewProjection;
out vec3 vNormal;
void main() {
    vNormal = mat3(uModel) * normal;
    gl_Position = uViewProjection * uModel * vec4(position, 1.0);
})";
const char* kFragmentShader = R"(#version 450 core
in vec3 vNormal;
uniform vec3 uColor;
uniform vec3 uLight;
out vec4 outColor;
void main() {
    outColor = vec4(uColor * (0.55 + 0.45 * max(dot(normalize(vNormal), uLight), 0.0)), 1.0);
})";

// A JSON number or array of numbers, as Scene::get returns it.
std::vector<float> numbers(const std::string& json) {
    std::string text = json;
    for (char& c : text)
        if (c == '[' || c == ']' || c == ',') c = ' ';
    std::istringstream in(text);
    std::vector<float> values;
    for (float v; in >> v;)
        values.push_back(v);
    return values;
}

struct Host {
    GladGLContext gl{};
    GLuint program = 0, vertexArray = 0, buffers[3] = {};
    GLsizei indexCount = 0;
    GLuint color = 0, depth = 0, framebuffer = 0;
    int width = 0, height = 0;
    glm::mat4 view{1.0f}, projection{1.0f};

    GLuint compile(GLenum stage, const char* source) {
        const GLuint shader = gl.CreateShader(stage);
        gl.ShaderSource(shader, 1, &source, nullptr);
        gl.CompileShader(shader);
        GLint ok = 0;
        gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            char log[2048];
            gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
            throw std::runtime_error(std::string("host shader: ") + log);
        }
        return shader;
    }

    void create(const rmsc::api::Triangles& mesh, const rmsc::api::Scene& scene) {
        program = gl.CreateProgram();
        const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
        const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
        gl.AttachShader(program, vs);
        gl.AttachShader(program, fs);
        gl.LinkProgram(program);
        gl.DeleteShader(vs);
        gl.DeleteShader(fs);
        gl.CreateBuffers(3, buffers);
        gl.NamedBufferStorage(buffers[0], GLsizeiptr(mesh.positions.size() * sizeof(float)),
                              mesh.positions.data(), 0);
        gl.NamedBufferStorage(buffers[1], GLsizeiptr(mesh.normals.size() * sizeof(float)),
                              mesh.normals.data(), 0);
        gl.NamedBufferStorage(buffers[2], GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                              mesh.indices.data(), 0);
        indexCount = GLsizei(mesh.indices.size());
        gl.CreateVertexArrays(1, &vertexArray);
        for (GLuint attribute = 0; attribute < 2; ++attribute) {
            gl.VertexArrayVertexBuffer(vertexArray, attribute, buffers[attribute], 0,
                                       3 * sizeof(float));
            gl.VertexArrayAttribFormat(vertexArray, attribute, 3, GL_FLOAT, GL_FALSE, 0);
            gl.VertexArrayAttribBinding(vertexArray, attribute, attribute);
            gl.EnableVertexArrayAttrib(vertexArray, attribute);
        }
        gl.VertexArrayElementBuffer(vertexArray, buffers[2]);

        // The host's colour and depth textures, drawn into through one framebuffer.
        gl.CreateTextures(GL_TEXTURE_2D, 1, &color);
        gl.TextureStorage2D(color, 1, GL_RGBA8, width, height);
        gl.CreateTextures(GL_TEXTURE_2D, 1, &depth);
        gl.TextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, width, height);
        gl.CreateFramebuffers(1, &framebuffer);
        gl.NamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, color, 0);
        gl.NamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, depth, 0);

        // The camera of the scene file, as the host's own matrices.
        const std::vector<float> eye = numbers(scene.get("/camera/position"));
        const std::vector<float> target = numbers(scene.get("/camera/target"));
        view = glm::lookAt(glm::vec3(eye[0], eye[1], eye[2]),
                           glm::vec3(target[0], target[1], target[2]), glm::vec3(0, 1, 0));
        projection = glm::perspective(
            glm::radians(numbers(scene.get("/camera/fov"))[0]), float(width) / float(height),
            numbers(scene.get("/camera/near"))[0], numbers(scene.get("/camera/far"))[0]);
    }

    // One frame: the cube at `angleDegrees` about +y, then rmsc's SDF objects into it.
    void draw(rmsc::api::Renderer& renderer, const rmsc::api::Scene& scene, float angleDegrees) {
        gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        gl.Viewport(0, 0, width, height);
        gl.ClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, kBackground);
        const float far = 1.0f;
        gl.ClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &far);
        gl.Enable(GL_DEPTH_TEST);
        gl.DepthFunc(GL_LESS);
        gl.Enable(GL_CULL_FACE);
        gl.UseProgram(program);
        const glm::mat4 model =
            glm::rotate(glm::mat4(1.0f), glm::radians(angleDegrees), glm::vec3(0, 1, 0));
        const glm::mat4 viewProjection = projection * view;
        const glm::vec3 light = glm::normalize(glm::make_vec3(kLightDirection));
        gl.UniformMatrix4fv(gl.GetUniformLocation(program, "uModel"), 1, GL_FALSE,
                            glm::value_ptr(model));
        gl.UniformMatrix4fv(gl.GetUniformLocation(program, "uViewProjection"), 1, GL_FALSE,
                            glm::value_ptr(viewProjection));
        gl.Uniform3fv(gl.GetUniformLocation(program, "uColor"), 1, kMeshColor);
        gl.Uniform3fv(gl.GetUniformLocation(program, "uLight"), 1, glm::value_ptr(light));
        gl.BindVertexArray(vertexArray);
        gl.DrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);

        rmsc::api::HostView host;
        std::memcpy(host.view.data(), glm::value_ptr(view), sizeof(float) * 16);
        std::memcpy(host.projection.data(), glm::value_ptr(projection), sizeof(float) * 16);
        host.width = width;
        host.height = height;
        // The SDF objects lit by the host's own light, the one its cube is shaded with (the
        // direction it travels: away from the light), rather than by the scene file's.
        rmsc::api::Light sun;
        sun.direction = {-light.x, -light.y, -light.z};
        sun.intensity = kLightIntensity;
        renderer.drawInto(scene, {color, depth, 0, false}, host, {&sun, 1});
        // The host keeps drawing with its own state: rmsc restored it.
        gl.BindVertexArray(0);
    }

    std::vector<unsigned char> readTopRowFirst() {
        std::vector<unsigned char> rgba(std::size_t(width) * std::size_t(height) * 4);
        gl.GetTextureImage(color, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
        std::vector<unsigned char> flipped(rgba.size());
        const std::size_t row = std::size_t(width) * 4;
        for (int y = 0; y < height; ++y)
            std::memcpy(&flipped[std::size_t(y) * row], &rgba[std::size_t(height - 1 - y) * row],
                        row);
        return flipped;
    }
};

GLADapiproc eglLoader(const char* name) {
    return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

GLADapiproc glfwLoader(const char* name) {
    return reinterpret_cast<GLADapiproc>(glfwGetProcAddress(name));
}

int run(int argc, char** argv) {
    std::string headless;
    int width = 960, height = 540;
    float angle = 30.0f;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--headless" && i + 1 < argc) {
            headless = argv[++i];
        } else if (arg == "--size" && i + 1 < argc &&
                   std::sscanf(argv[i + 1], "%dx%d", &width, &height) == 2 && width > 0 &&
                   height > 0) {
            ++i;
        } else if (arg == "--angle" && i + 1 < argc) {
            angle = std::stof(argv[++i]);
        } else {
            std::fprintf(stderr,
                         "usage: rmsc_embed [--headless OUT.png] [--size WxH] [--angle DEG]\n");
            return 2;
        }
    }
    const rmsc::api::Scene scene = rmsc::api::Scene::load(RMSC_EMBED_DIR "/scene.json");
    const rmsc::api::Triangles cube =
        rmsc::api::loadTriangles(RMSC_EMBED_DIR "/../assets/cube.gltf");
    Host host;
    host.width = width;
    host.height = height;

    if (!headless.empty()) {
        rmsc::api::HeadlessContext context(rmsc::api::Backend::Egl);
        if (!gladLoadGLContext(&host.gl, eglLoader)) throw std::runtime_error("glad: no GL");
        rmsc::api::Renderer renderer;
        host.create(cube, scene);
        host.draw(renderer, scene, angle);
        const std::vector<unsigned char> pixels = host.readTopRowFirst();
        if (!stbi_write_png(headless.c_str(), width, height, 4, pixels.data(), width * 4)) {
            std::fprintf(stderr, "rmsc_embed: cannot write %s\n", headless.c_str());
            return 3;
        }
        return 0;
    }

    if (!glfwInit()) throw std::runtime_error("GLFW cannot start (no display?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    GLFWwindow* window =
        glfwCreateWindow(width, height, "rmsc embedded in a host", nullptr, nullptr);
    if (!window) throw std::runtime_error("GLFW cannot open an OpenGL 4.5 window");
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    if (!gladLoadGLContext(&host.gl, glfwLoader)) throw std::runtime_error("glad: no GL");
    {
        rmsc::api::Renderer renderer;
        host.create(cube, scene);
        while (!glfwWindowShouldClose(window)) {
            host.draw(renderer, scene, float(glfwGetTime()) * 30.0f);
            host.gl.BlitNamedFramebuffer(host.framebuffer, 0, 0, 0, width, height, 0, 0, width,
                                         height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            glfwSwapBuffers(window);
            glfwPollEvents();
        }
    } // the renderer goes while its context is current
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const rmsc::api::Error& error) {
        std::fprintf(stderr, "rmsc_embed: %s\n", error.what());
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "rmsc_embed: %s\n", error.what());
        return 3;
    }
}
