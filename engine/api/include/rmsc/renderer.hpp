// rmsc public API: drawing. A Renderer belongs to the OpenGL context current when it was made
// and must be used (and destroyed) with that context current. It renders whole scenes to
// images in memory, and draws a scene's SDF objects into a host program's frame, depth-tested
// against the host's depth. See docs/embedding.md for the conventions and the GL state.
#pragma once

#include "rmsc/image.hpp"
#include "rmsc/light.hpp"
#include "rmsc/scene.hpp"

#include <array>
#include <memory>
#include <span>

namespace rmsc::api {

// How the host's depth works. rmsc reads the clip depth mode from the context
// (GL_CLIP_DEPTH_MODE) and refuses a convention that does not match it. Supported:
enum class DepthConvention {
    Default,   // OpenGL's: clip depth -1 to 1, depth 0 at near, 1 at far, GL_LESS
    ZeroToOne, // glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE): depth 0 at near, 1 at far
    ReversedZ, // glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) with a projection mapping near
               // to 1 and far (or infinity) to 0, GL_GREATER, cleared to 0
};
// Not supported (refused with Error Usage): GL_UPPER_LEFT clip origin, a depth range other
// than glDepthRange(0, 1), reversed-Z with -1 to 1 clip depth, orthographic projections.

// The host's camera for this frame. Matrices are column-major, as OpenGL takes them.
struct HostView {
    std::array<float, 16> view{};       // world to eye, a rotation and a translation
    std::array<float, 16> projection{}; // eye to clip, perspective
    int x = 0, y = 0;                   // the viewport: lower-left corner and size in pixels
    int width = 0, height = 0;
    DepthConvention depth = DepthConvention::Default;
};

// Where to draw: either the host's colour and depth textures, or a framebuffer whose depth
// attachment is a texture. The depth texture is GL_TEXTURE_2D of DEPTH_COMPONENT16/24/32/32F,
// DEPTH24_STENCIL8 or DEPTH32F_STENCIL8, not multisampled (resolve first).
struct HostTarget {
    unsigned colorTexture = 0; // GL_TEXTURE_2D, colour-renderable (with depthTexture)
    unsigned depthTexture = 0;
    unsigned framebuffer = 0; // or: a framebuffer object (not 0, the default framebuffer)
    // Colour written: the display colour `rmsc render` gives (exposure, ACES, sRGB encoded;
    // for RGBA8 targets), or linear HDR colour times the exposure (for RGBA16F/32F targets a
    // host tone-maps itself).
    bool linearColor = false;
};

// What the last call did about shaders.
struct RenderStats {
    bool compiledShaders = false; // programs were compiled and linked (not from the cache)
    double compileMilliseconds = 0.0;
};

class Renderer {
  public:
    // On the current context (its GL functions are loaded here). Throws Error (Context) when
    // none is current or it is not OpenGL 4.5.
    Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;
    // Deletes the renderer's GL objects when its context is current; otherwise leaves them to
    // the context (deleting them through another context could delete the host's objects).
    ~Renderer();

    // Uploads the scene and builds its shaders now, so the first draw does not wait for them.
    void compile(const Scene& scene);
    // Renders the scene with its own camera, meshes and lights, as `rmsc render` does, and
    // reads back one output.
    Image render(const Scene& scene, int width, int height, Aov aov = Aov::Color);
    // Draws the scene's SDF objects into the host's frame through its camera: each pixel marches
    // only up to the host's depth there, and where an SDF surface is nearer, its colour and
    // depth replace the host's. Other pixels are left as they are. The scene's own glTF meshes
    // are not drawn (they still cast shadows), nor its camera used. The GL state is as it was
    // after the call (docs/embedding.md lists what is saved).
    void drawInto(const Scene& scene, const HostTarget& target, const HostView& view);
    // The same, lit by the host's `lights` instead of the scene's (an empty list: by the
    // scene's sky and ambient light only). They are checked as a scene file's lights are: at
    // most 16, each value in its range; invalid ones throw Error (BadInput, a problem at
    // "/INDEX/KEY" of the file "host lights" for each) and nothing is drawn. The scene's
    // meshes cast their shadows of these lights.
    void drawInto(const Scene& scene, const HostTarget& target, const HostView& view,
                  std::span<const Light> lights);

    RenderStats lastStats() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace rmsc::api
