// rmsc public API: a headless OpenGL context, for programs that have none of their own (scripts,
// pipelines, tests). Hosts with a window or a context of their own do not need one: a Renderer
// uses whatever context is current.
#pragma once

#include <memory>
#include <string>

namespace rmsc::api {

enum class Backend {
    Auto,   // EGL's surfaceless platform, then OSMesa
    Egl,    // EGL, surfaceless (Mesa): GPU drivers or llvmpipe
    OsMesa, // OSMesa: Mesa's software rasterizer, no display at all
};

// "auto", "egl", "osmesa"; throws Error (Usage) for anything else.
Backend parseBackend(const std::string& name);

// An OpenGL 4.5 core context with no window, current on the calling thread from construction.
class HeadlessContext {
  public:
    // Throws Error (Context) saying what each back end answered when none can make one.
    explicit HeadlessContext(Backend backend = Backend::Auto);
    HeadlessContext(HeadlessContext&&) noexcept;
    HeadlessContext& operator=(HeadlessContext&&) noexcept;
    ~HeadlessContext();

    // Makes this context current on the calling thread again.
    void makeCurrent();
    std::string backend() const;  // "egl" or "osmesa"
    std::string renderer() const; // GL_RENDERER and GL_VERSION

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace rmsc::api
