// Sampling an SDF program's distance on lattices of points with a compute shader: the exporter's
// block passes (export/dual_contouring.hpp, SdfField::lattice) on the GPU. The shader runs the
// generic interpreter (its text depends on the primitive kinds used only, so no compile grows
// with the program) on the program as the CPU evaluator has it.
#pragma once

#include "gl/handles.hpp"
#include "render/sdf_program_buffer.hpp"
#include "sdf/program.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace rmsc {

class GpuFieldSampler {
  public:
    // Uploads `program` and builds the shader, on the current context (4.5 core, compute).
    // nullopt with the reason in `error` when the shader does not build.
    static std::optional<GpuFieldSampler> create(const SdfProgram& program, std::string& error);

    // For each of the `count` starts s, side^3 distances at origin + spacing * (s + (x, y, z)),
    // x fastest, then y, then z, into out (start after start). False on a GL error.
    bool sample(glm::vec3 origin, float spacing, const glm::ivec3* starts, std::size_t count,
                int side, float* out) const;

  private:
    GpuFieldSampler() = default;
    gl::Program program_;
    SdfProgramBuffer sdfProgram_;
    gl::Buffer sdfData_, frame_;
    GLint latticeLocation_ = -1, infoLocation_ = -1;
};

} // namespace rmsc
