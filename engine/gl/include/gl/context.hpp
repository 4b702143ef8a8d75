// Headless OpenGL 4.5 core contexts: EGL on the surfaceless platform, or OSMesa. Both render
// only into framebuffer objects; one interface, chosen by name or automatically.
#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace rmsc {

enum class GlBackend { Auto, Egl, OsMesa };

// Parses "auto" | "egl" | "osmesa"; returns false for anything else.
bool parseGlBackend(std::string_view name, GlBackend& backend);

// A current GL context. Destroying it releases the context.
class HeadlessContext {
  public:
    virtual ~HeadlessContext() = default;
    virtual std::string_view backendName() const = 0;
    // Makes this context current on the calling thread again; false if the back end refuses.
    virtual bool makeCurrent() = 0;
    std::string renderer() const; // GL_RENDERER and GL_VERSION, for logs
};

// Creates a GL 4.5 core context and makes it current, with KHR_debug output on when `debug` is
// set. Auto tries EGL surfaceless, then OSMesa. Returns nullptr and sets `error` (which says
// what each back end answered) when no context can be made.
//
// `secondary`: a second context, for another thread of a process whose first context came from
// the same back end. It neither reloads the GL functions (the first thread is using them; both
// contexts resolve them alike) nor, when destroyed, terminates the EGL display it shares with
// the first.
std::unique_ptr<HeadlessContext> createHeadlessContext(GlBackend backend, bool debug,
                                                       std::string& error, bool secondary = false);

// GL errors reported through KHR_debug since the last call (empty when none).
std::string takeGlDebugErrors();

} // namespace rmsc
