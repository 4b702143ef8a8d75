// The compute-shader sampler of the exporter (render/gpu_field_sampler.hpp).
#include "render/gpu_field_sampler.hpp"

#include "gl/program.hpp"
#include "render/frame.hpp"
#include "render/gpu_layout.hpp"
#include "render/shader_library.hpp"
#include "sdf/glsl_codegen.hpp"

#include <algorithm>
#include <vector>

namespace rmsc {
namespace {

constexpr GLuint kGroupSize = 64;           // local_size_x of passes/field_sample.comp
constexpr GLuint kMaxGroups = 65535;        // per dispatch (GL_MAX_COMPUTE_WORK_GROUP_COUNT >=)
constexpr std::size_t kMaxPoints = 1 << 22; // per dispatch, so no driver's watchdog fires

} // namespace

std::optional<GpuFieldSampler> GpuFieldSampler::create(const SdfProgram& program,
                                                       std::string& error) {
    ShaderFiles files = embeddedShaderFiles();
    files.files["generated/sdf_map.glsl"] = generateSdfMap(program, SdfStrategy::Interpreter);
    std::optional<gl::Program> built =
        buildComputeProgram(files, "passes/field_sample.comp", "", error);
    if (!built) return std::nullopt;
    GpuFieldSampler sampler;
    sampler.program_ = std::move(*built);
    sampler.latticeLocation_ = uniformLocation(sampler.program_, "lattice");
    sampler.infoLocation_ = uniformLocation(sampler.program_, "info");

    // The program buffer as the renderer lays it out (render/gpu_scene.cpp): the header, the
    // instructions, at least as long as its uniform window.
    GpuSdfHeader header;
    header.instructionCount = std::uint32_t(program.instructions.size());
    header.stackDepth = std::uint32_t(program.stackDepth);
    header.pointStackDepth = std::uint32_t(program.pointStackDepth);
    header.dataCount = std::uint32_t(program.data.size());
    sampler.sdfProgram_ = createSdfProgramBuffer(header, program.instructions);
    std::vector<glm::vec4> data = program.data;
    if (data.empty()) data.emplace_back(0.0f); // a buffer is never empty
    sampler.sdfData_ =
        gl::createBufferWithData(GLsizeiptr(data.size() * sizeof(glm::vec4)), data.data());
    // The frame block the scene's functions read: the step budget (the loops' SDF_ZERO) and no
    // nearest part (the parts loop's first guess).
    GpuFrame frame{};
    frame.march = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    frame.viewport = glm::vec4(1.0f, 1.0f, 4294967296.0f, 1.0f);
    sampler.frame_ = gl::createBufferWithData(GLsizeiptr(sizeof frame), &frame);
    return sampler;
}

bool GpuFieldSampler::sample(glm::vec3 origin, float spacing, const glm::ivec3* starts,
                             std::size_t count, int side, float* out) const {
    if (count == 0) return true;
    const std::size_t perStart = std::size_t(side) * std::size_t(side) * std::size_t(side);
    const std::size_t points = count * perStart;
    std::vector<glm::ivec4> packed(count);
    for (std::size_t i = 0; i < count; ++i)
        packed[i] = glm::ivec4(starts[i], 0);
    const gl::Buffer startBuffer =
        gl::createBufferWithData(GLsizeiptr(count * sizeof(glm::ivec4)), packed.data());
    const gl::Buffer distances =
        gl::createBufferWithData(GLsizeiptr(points * sizeof(float)), nullptr);
    glUseProgram(program_.id());
    bindSdfProgramBuffer(sdfProgram_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSdfDataBinding, sdfData_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBinding, frame_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFieldSampleStartBinding, startBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFieldSampleDistanceBinding, distances.id());
    glUniform4f(latticeLocation_, origin.x, origin.y, origin.z, spacing);
    const std::size_t perDispatch = std::min(kMaxPoints, std::size_t(kMaxGroups) * kGroupSize);
    for (std::size_t first = 0; first < points; first += perDispatch) {
        const std::size_t n = std::min(perDispatch, points - first);
        glUniform4ui(infoLocation_, GLuint(side), GLuint(points), GLuint(first), 0u);
        glDispatchCompute(GLuint((n + kGroupSize - 1) / kGroupSize), 1, 1);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(distances.id(), 0, GLsizeiptr(points * sizeof(float)), out);
    for (GLuint binding : {GLuint(kFieldSampleStartBinding), GLuint(kFieldSampleDistanceBinding)})
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
    glUseProgram(0);
    return glGetError() == GL_NO_ERROR;
}

} // namespace rmsc
