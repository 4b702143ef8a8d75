// Light gizmo pass: the viewer's markers for the scene's lights, drawn as lines over the view
// (no depth test: a light inside or behind an object still shows). Every light gets a circle of
// kLightMarkerRadiusPixels around its position, the same size on screen at any distance; a
// point light adds short rays around it, a spot light its cone (a unit along its direction,
// opened to its outer angle), a directional light a line along its direction. The selected
// light is drawn in the selection colour, the others in a light tint of their colour. Only the
// viewer draws it (after its display pass), so renders never contain it.
#pragma once

#include "gl/program.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rmsc {

// The marker circle's radius, in framebuffer pixels.
constexpr float kLightMarkerRadiusPixels = 8.0f;
// The colour of the selected light's marker (the viewer's selection colour).
constexpr glm::vec3 kSelectedGizmoColor{1.0f, 0.6f, 0.15f};

// One end of a gizmo line: a world point moved by a screen offset (pixels), and its colour.
struct GizmoVertex {
    glm::vec3 anchor{0.0f};
    glm::vec2 offsetPixels{0.0f};
    glm::vec3 color{1.0f};
};

// The lines (pairs of vertices) of every light's gizmo; `selected` is the index of the selected
// light, -1 for none.
std::vector<GizmoVertex> lightGizmoLines(std::span<const Light> lights, int selected);

// Where the pass draws: a framebuffer and the viewport rectangle in it (pixels, y from the
// bottom), whose size the screen offsets are measured in.
struct GizmoTarget {
    GLuint framebuffer = 0;
    int x = 0, y = 0, width = 1, height = 1;
};

class LightGizmoPass {
  public:
    static std::optional<LightGizmoPass> create(const ShaderFiles& files, std::string& error);
    // Draws the gizmos of `lights` seen through `viewProjection` over what `target` holds. Sets
    // the GL state it needs and restores what it changed.
    void draw(const GizmoTarget& target, const glm::mat4& viewProjection,
              std::span<const Light> lights, int selected) const;

  private:
    gl::Program program_;
    gl::VertexArray vertexArray_;
    gl::Buffer vertices_;
    GLint viewProjection_ = -1, viewportSize_ = -1;
};

} // namespace rmsc
