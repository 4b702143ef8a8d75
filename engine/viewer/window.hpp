// A window with an OpenGL 4.5 core context (GLFW), for the viewer. glad is loaded through
// glfwGetProcAddress once the context is current. Move-only; destroying it closes the window.
#pragma once

#include <memory>
#include <string>

struct GLFWwindow;

namespace rmsc {

class Window {
  public:
    // Opens a `width` x `height` window titled `title`, hidden until show(), and makes its
    // context current. Returns nullptr with `error` saying why (no display, no GL 4.5 core) on
    // failure.
    static std::unique_ptr<Window> open(int width, int height, const std::string& title,
                                        std::string& error);
    // A hidden window whose GL 4.5 core context can be made current on another thread (for
    // background work such as render/shader_warmer.hpp); open() a window first. The context
    // stays current on no thread. With `share`, its context shares that window's objects
    // (textures, buffers, sync objects), as the view's render thread does with the UI's.
    static std::unique_ptr<Window> openHidden(std::string& error, const Window* share = nullptr);
    // Makes this window's context current on the calling thread; releaseCurrent() lets go.
    void makeCurrent();
    static void releaseCurrent();
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool shouldClose() const;
    void setShouldClose(bool close);
    void setTitle(const std::string& title);
    void swapBuffers();
    void show();
    // show() was called (the window may still be covered or minimised). Kept here, not asked
    // of the window system: on X11 that is a round trip, and the frame loop asks every frame.
    bool shown() const { return shown_; }
    // Size of the drawable in pixels, and of the window in screen coordinates.
    void framebufferSize(int& width, int& height) const;
    void windowSize(int& width, int& height) const;

  private:
    explicit Window(GLFWwindow* window) : window_(window) {}
    GLFWwindow* window_ = nullptr;
    bool shown_ = false;
};

} // namespace rmsc
