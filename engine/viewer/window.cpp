// GLFW window and GL 4.5 core context (see window.hpp).
#include "window.hpp"

#include "gl/gl.hpp"

#include <GLFW/glfw3.h>

namespace rmsc {
namespace {

// The last error GLFW reported on this thread: GLFW calls the callback on the thread whose call
// failed, and the render thread and the shader warmer call it too (make current, post an event),
// so one message shared by all would be written by two threads at once.
std::string& lastGlfwError() {
    thread_local std::string message;
    return message;
}

void onGlfwError(int code, const char* description) {
    lastGlfwError() = "GLFW error " + std::to_string(code) + ": " + description;
}

int openWindows = 0;

} // namespace

std::unique_ptr<Window> Window::open(int width, int height, const std::string& title,
                                     std::string& error) {
    glfwSetErrorCallback(onGlfwError);
    if (openWindows == 0 && !glfwInit()) {
        error = "cannot open a window (is a display available? DISPLAY or WAYLAND_DISPLAY): " +
                lastGlfwError();
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
    if (!window) {
        error = "cannot create a window with an OpenGL 4.5 core context: " + lastGlfwError();
        if (openWindows == 0) glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
        error = "cannot load the OpenGL 4.5 functions through GLFW";
        glfwDestroyWindow(window);
        if (openWindows == 0) glfwTerminate();
        return nullptr;
    }
    glfwSwapInterval(0);
    ++openWindows;
    return std::unique_ptr<Window>(new Window(window));
}

std::unique_ptr<Window> Window::openHidden(std::string& error, const Window* share) {
    if (openWindows == 0) {
        error = "open a window first";
        return nullptr;
    }
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWwindow* window =
        glfwCreateWindow(1, 1, "rmsc (hidden)", nullptr, share ? share->window_ : nullptr);
    glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
    if (!window) {
        error = "cannot create a second OpenGL 4.5 core context: " + lastGlfwError();
        return nullptr;
    }
    ++openWindows;
    return std::unique_ptr<Window>(new Window(window));
}

void Window::show() {
    glfwShowWindow(window_);
    shown_ = true;
}

void Window::makeCurrent() {
    glfwMakeContextCurrent(window_);
}

void Window::releaseCurrent() {
    glfwMakeContextCurrent(nullptr);
}

Window::~Window() {
    glfwDestroyWindow(window_);
    if (--openWindows == 0) glfwTerminate();
}

bool Window::shouldClose() const {
    return glfwWindowShouldClose(window_);
}
void Window::setShouldClose(bool close) {
    glfwSetWindowShouldClose(window_, close ? 1 : 0);
}
void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(window_, title.c_str());
}
void Window::swapBuffers() {
    glfwSwapBuffers(window_);
}
void Window::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(window_, &width, &height);
}
void Window::windowSize(int& width, int& height) const {
    glfwGetWindowSize(window_, &width, &height);
}

} // namespace rmsc
