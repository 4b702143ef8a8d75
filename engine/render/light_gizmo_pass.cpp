// Light gizmo pass (see light_gizmo_pass.hpp).
#include "render/light_gizmo_pass.hpp"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace rmsc {
namespace {

constexpr int kCircleSegments = 24;
constexpr float kDirectionLength = 1.5f;      // world units: a directional light's line
constexpr float kConeLength = 1.0f;           // world units: a spot light's cone along its axis
constexpr float kMaxDrawnConeDegrees = 80.0f; // wider cones are drawn this wide

// A line between two vertices.
void addLine(std::vector<GizmoVertex>& out, GizmoVertex a, GizmoVertex b) {
    out.push_back(a);
    out.push_back(b);
}

// A circle of `radius` pixels around `center` on screen.
void addScreenCircle(std::vector<GizmoVertex>& out, glm::vec3 center, float radius,
                     glm::vec3 color) {
    for (int i = 0; i < kCircleSegments; ++i) {
        const float a0 = 2.0f * glm::pi<float>() * float(i) / kCircleSegments;
        const float a1 = 2.0f * glm::pi<float>() * float(i + 1) / kCircleSegments;
        addLine(out, {center, radius * glm::vec2(std::cos(a0), std::sin(a0)), color},
                {center, radius * glm::vec2(std::cos(a1), std::sin(a1)), color});
    }
}

// Two unit vectors at right angles to each other and to unit vector `axis`.
void basisAround(glm::vec3 axis, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    u = glm::normalize(glm::cross(axis, helper));
    v = glm::cross(axis, u);
}

void addSpotCone(std::vector<GizmoVertex>& out, const Light& light, glm::vec3 axis,
                 glm::vec3 color) {
    const float angle = glm::radians(std::min(light.outerAngleDegrees, kMaxDrawnConeDegrees));
    const float radius = kConeLength * std::tan(angle);
    glm::vec3 u, v;
    basisAround(axis, u, v);
    const glm::vec3 end = light.position + axis * kConeLength;
    for (int i = 0; i < kCircleSegments; ++i) {
        const float a0 = 2.0f * glm::pi<float>() * float(i) / kCircleSegments;
        const float a1 = 2.0f * glm::pi<float>() * float(i + 1) / kCircleSegments;
        const glm::vec3 p0 = end + radius * (std::cos(a0) * u + std::sin(a0) * v);
        const glm::vec3 p1 = end + radius * (std::cos(a1) * u + std::sin(a1) * v);
        addLine(out, {p0, {}, color}, {p1, {}, color});
        if (i % (kCircleSegments / 4) == 0)
            addLine(out, {light.position, {}, color}, {p0, {}, color});
    }
    addLine(out, {light.position, {}, color}, {end, {}, color});
}

glm::vec3 gizmoColor(const Light& light, bool selected) {
    if (selected) return kSelectedGizmoColor;
    const float brightest = std::max({light.color.x, light.color.y, light.color.z});
    const glm::vec3 hue = brightest > 0.0f ? light.color / brightest : glm::vec3(1.0f);
    return glm::mix(hue, glm::vec3(1.0f), 0.6f);
}

} // namespace

std::vector<GizmoVertex> lightGizmoLines(std::span<const Light> lights, int selected) {
    std::vector<GizmoVertex> out;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        const bool isSelected = int(i) == selected;
        const glm::vec3 color = gizmoColor(light, isSelected);
        const float r = kLightMarkerRadiusPixels;
        addScreenCircle(out, light.position, r, color);
        if (isSelected) addScreenCircle(out, light.position, r - 1.0f, color); // bolder
        const float length = glm::length(light.direction);
        const glm::vec3 axis = length > 0.0f ? light.direction / length : glm::vec3(0, -1, 0);
        switch (light.type) {
        case LightType::Point:
            for (int k = 0; k < 8; ++k) {
                const float a = glm::pi<float>() * 0.25f * float(k);
                const glm::vec2 d(std::cos(a), std::sin(a));
                addLine(out, {light.position, d * (r + 3.0f), color},
                        {light.position, d * (r + 7.0f), color});
            }
            break;
        case LightType::Spot:
            addSpotCone(out, light, axis, color);
            break;
        case LightType::Directional:
            addLine(out, {light.position, {}, color},
                    {light.position + axis * kDirectionLength, {}, color});
            break;
        }
    }
    return out;
}

std::optional<LightGizmoPass> LightGizmoPass::create(const ShaderFiles& files, std::string& error) {
    std::optional<gl::Program> program =
        buildProgram(files, {"passes/light_gizmo.vert", "passes/light_gizmo.frag", ""}, error);
    if (!program) return std::nullopt;
    LightGizmoPass pass;
    pass.program_ = std::move(*program);
    pass.viewProjection_ = uniformLocation(pass.program_, "uViewProjection");
    pass.viewportSize_ = uniformLocation(pass.program_, "uViewportSize");
    pass.vertices_ = gl::createBuffer();
    pass.vertexArray_ = gl::createVertexArray();
    const GLuint vao = pass.vertexArray_.id();
    glVertexArrayVertexBuffer(vao, 0, pass.vertices_.id(), 0, sizeof(GizmoVertex));
    glEnableVertexArrayAttrib(vao, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glEnableVertexArrayAttrib(vao, 2);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(GizmoVertex, anchor));
    glVertexArrayAttribFormat(vao, 1, 2, GL_FLOAT, GL_FALSE, offsetof(GizmoVertex, offsetPixels));
    glVertexArrayAttribFormat(vao, 2, 3, GL_FLOAT, GL_FALSE, offsetof(GizmoVertex, color));
    for (GLuint attribute = 0; attribute < 3; ++attribute)
        glVertexArrayAttribBinding(vao, attribute, 0);
    return pass;
}

void LightGizmoPass::draw(const GizmoTarget& target, const glm::mat4& viewProjection,
                          std::span<const Light> lights, int selected) const {
    const std::vector<GizmoVertex> lines = lightGizmoLines(lights, selected);
    if (lines.empty()) return;
    // A fresh store each frame: a handful of lights, a few hundred vertices.
    glNamedBufferData(vertices_.id(), GLsizeiptr(lines.size() * sizeof(GizmoVertex)), lines.data(),
                      GL_STREAM_DRAW);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    glViewport(target.x, target.y, target.width, target.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glProgramUniformMatrix4fv(program_.id(), viewProjection_, 1, GL_FALSE, &viewProjection[0][0]);
    glProgramUniform2f(program_.id(), viewportSize_, float(target.width), float(target.height));
    glBindVertexArray(vertexArray_.id());
    glDrawArrays(GL_LINES, 0, GLsizei(lines.size()));
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace rmsc
