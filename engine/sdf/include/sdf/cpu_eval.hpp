// The CPU evaluator: runs a compiled SdfProgram exactly as shaders/common/sdf_scene.glsl does
// (same formulas in GLM). It is the oracle the GPU renders are tested against and serves
// picking and bounds.
#pragma once

#include "core/material.hpp"
#include "core/render_settings.hpp"
#include "sdf/program.hpp"
#include "sdf/sdf_tree.hpp"

#include <optional>
#include <span>

namespace rmsc {

// Surface properties at a point: the distance, the dominant object, and the material blended
// through smooth operations with the same factor as the distances.
struct SdfSurface {
    float distance = 0.0f;
    std::uint32_t objectId = 0;
    glm::vec3 baseColor{0.8f};
    float metallic = 0.0f;
    float roughness = 0.5f;
    glm::vec3 emissive{0.0f};
    std::uint32_t material = 0xffffffffu; // of the dominant shape (textures are not blended)
    glm::vec3 localPoint{0.0f}; // the point in the dominant shape's local frame (triplanar)
};

// `evaluations`, when given, is increased by the number of primitives evaluated (parts a
// program's bounds skip are not).
float sdfDistance(const SdfProgram& program, glm::vec3 p, int* evaluations = nullptr);
// The shape or profile instruction whose own distance at p is the smallest (its index; ~0u when
// the program has none). In a program of one-shape parts (what the lean interpreter runs,
// shaders/common/sdf_parts_loop.glsl) that is the part nearest p: the interpreter evaluates the
// one nearest the camera first.
std::uint32_t sdfNearestLeaf(const SdfProgram& program, glm::vec3 p);
// `materials` is indexed by GpuSdfInstruction::material.
SdfSurface sdfSurface(const SdfProgram& program, std::span<const Material> materials, glm::vec3 p);
// The same for the instructions `order` names, in that order, out of `code` (a per-cell
// program of sdf/cell_pruning.hpp; `program` gives the data buffer), read as `reading` says.
// A BoundSkip skips positions of `order`.
float sdfDistanceOrdered(const SdfProgram& program, std::span<const GpuSdfInstruction> code,
                         std::span<const std::uint32_t> order, glm::vec3 p,
                         int* evaluations = nullptr,
                         SdfListReading reading = SdfListReading::Postfix);
SdfSurface sdfSurfaceOrdered(const SdfProgram& program, std::span<const GpuSdfInstruction> code,
                             std::span<const std::uint32_t> order,
                             std::span<const Material> materials, glm::vec3 p,
                             SdfListReading reading = SdfListReading::Postfix);
// The distance of one shape or profile instruction at world point p.
float sdfLeafDistance(const SdfProgram& program, const GpuSdfInstruction& instruction, glm::vec3 p);
// Normalized gradient by the tetrahedron technique (4 evaluations; Quilez, "normals for an SDF").
glm::vec3 sdfNormal(const SdfProgram& program, glm::vec3 p, float h);

struct SdfHit {
    float t = 0.0f; // distance along the normalized direction
    glm::vec3 position{0.0f};
    int steps = 0;
};

// The over-relaxation factor of the marches (sdfCastRay here, sdfMarch and shellMarch in the
// shaders, which get it in the frame block): each step is this times the distance, with the
// fallback of Keinert et al. 2014 where that is not safe (cpu_eval.cpp, relaxedMarch). 1.2
// lowered the march steps per pixel of every benchmark scene and sample measured (by 2% to
// 14%); 1.4 and 1.6 saved more on some and nothing on the chessboard.
constexpr float kSdfMarchRelaxation = 1.2f;

// Over-relaxed sphere tracing as the march pass does it: starts at t = tMin, steps by
// relaxation * d while that is safe, hits when d < settings.surfaceEpsilon * max(t, 1), gives
// up after settings.maxSteps evaluations or t > tMax. relaxation 1 is plain sphere tracing.
std::optional<SdfHit> sdfCastRay(const SdfProgram& program, const RenderSettings& settings,
                                 glm::vec3 origin, glm::vec3 direction, float tMin, float tMax,
                                 float relaxation = kSdfMarchRelaxation);

// The same for a program read in another frame, as the shell pass marches a shell
// (sdf/compiler.hpp, SdfShellProgram): the world ray's points are evaluated at
// worldToFrame * point, and the program's distances are world units. The hit's position is
// in world space.
std::optional<SdfHit> sdfCastRayInFrame(const SdfProgram& program, const glm::mat4& worldToFrame,
                                        const RenderSettings& settings, glm::vec3 origin,
                                        glm::vec3 direction, float tMin, float tMax,
                                        float relaxation = kSdfMarchRelaxation);

// The march of a cone, as the cone pass does it for a tile of pixels (shaders/passes/cone.frag
// derives the step): `axis` a unit direction from `origin`, `chord` the largest |u - axis|
// over the unit directions u the cone holds. From s = `start`, steps while every ray of the
// cone stays outside its hit threshold, and stops where the cone (nearly) touches a surface,
// after settings.maxSteps evaluations or past settings.maxDistance. sdfCastRay along any ray
// of the cone hits nothing nearer than `distance`. A `radius` > 0 widens it by that much at
// every distance: a cylinder, with chord 0, holds the parallel rays of an orthographic camera.
struct SdfConeMarch {
    float distance = 0.0f;
    int steps = 0;
};
SdfConeMarch sdfMarchCone(const SdfProgram& program, const RenderSettings& settings,
                          glm::vec3 origin, glm::vec3 axis, float chord, float start,
                          float radius = 0.0f);

// The evaluations sdfCastRay makes, hit or miss: what the steps AOV shows for the ray.
int sdfMarchSteps(const SdfProgram& program, const RenderSettings& settings, glm::vec3 origin,
                  glm::vec3 direction, float tMin, float tMax,
                  float relaxation = kSdfMarchRelaxation);

} // namespace rmsc
