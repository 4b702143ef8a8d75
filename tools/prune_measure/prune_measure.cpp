// rmsc_prune_measure: where per-cell pruning should run, measured (docs/performance.md, "Where
// pruning runs"). Prunes a scene whose SDF is a plain union of shapes (the bench grids) twice:
// with the engine's CPU pruner (sdf/cell_pruning.hpp, buildSdfCells, on every core) and with a
// compute-shader pruner written here for the comparison, and checks that both give every leaf
// cell the same shapes.
//
// The compute pruner goes coarse to fine as "Lipschitz Pruning" (Barbier et al., Eurographics
// 2025) does: level by level, each cell tests only the shapes its parent kept. A shape's value
// over a cell lies within v +- r (v at the centre, r the half-diagonal: the shapes are
// 1-Lipschitz as compiled); a shape is kept when its lower end is at most the least upper end
// (the union's rule, sdfOperationPrune), so a shape a parent dropped is dropped by each child.
// The CPU pruner keeps the same shapes (sdf/cell_pruning.cpp, pruneCellDirect, with the same
// margins) but finds them in a bounding-volume hierarchy instead. Per level: a count pass, the
// counts read back (the refinement decision and the list offsets are made on the CPU, as a
// prefix sum), a write pass, the lists read back (the cell table is packed on the CPU). Far
// cells and the refinement threshold follow SdfCellOptions. The cell budget is not modelled: the
// tool says when the CPU grid reached it.
//
//   rmsc_prune_measure SCENE [--runs N] [--levels L]
// Prints one JSON object; exits 1 when the two pruners disagree on a leaf cell or on how many
// there are.
#include "core/file_source.hpp"
#include "gl/context.hpp"
#include "gl/handles.hpp"
#include "gl/program.hpp"
#include "render/frame.hpp"
#include "render/gpu_layout.hpp"
#include "render/sdf_program_buffer.hpp"
#include "render/shader_library.hpp"
#include "scene/scene_json.hpp"
#include "sdf/cell_pruning.hpp"
#include "sdf/compiler.hpp"
#include "sdf/glsl_codegen.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace rmsc;

namespace {

constexpr unsigned kCellsBinding = 10, kParentsBinding = 11, kInListsBinding = 12,
                   kCountsBinding = 13, kOutListsBinding = 14;
constexpr GLuint kGroupSize = 64;
constexpr std::uint32_t kNoList = 0xffffffffu;

// The count pass (pass 0: kept shapes and the least lower end, per cell) and the write pass
// (pass 1: the kept shapes at the offset the CPU gave), over the shapes the parent kept.
constexpr const char* kPruneShader = R"(#version 450 core
#include "common/sdf_scene.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 10) readonly buffer Cells { vec4 cells[]; };      // centre, edge
layout(std430, binding = 11) readonly buffer Parents { uvec2 parents[]; }; // offset, count
layout(std430, binding = 12) readonly buffer InLists { uint inLists[]; };
layout(std430, binding = 13) buffer Counts { uvec2 counts[]; };
layout(std430, binding = 14) writeonly buffer OutLists { uint outLists[]; };
uniform uvec4 info; // x = cells, y = pass, z = the dispatch's first cell
uniform float slack; // added to every interval (rounding), as the CPU pruner does

void main() {
    uint i = info.z + gl_GlobalInvocationID.x;
    if (i >= info.x) return;
    vec4 cell = cells[i];
    uvec2 parent = parents[i];
    float reach = 0.8660254 * cell.w + slack;
    float leastHi = 1e30, minLo = 1e30;
    for (uint k = 0u; k < parent.y; ++k) {
        float v = sdfLeafDistance(inLists[parent.x + k], cell.xyz);
        float e = reach + 1e-6 * abs(v);
        leastHi = min(leastHi, v + e);
        minLo = min(minLo, v - e);
    }
    uint out0 = info.y == 0u ? 0u : counts[i].x;
    if (info.y == 1u && out0 == 0xffffffffu) return;
    uint kept = 0u;
    for (uint k = 0u; k < parent.y; ++k) {
        uint s = inLists[parent.x + k];
        float v = sdfLeafDistance(s, cell.xyz);
        if (v - (reach + 1e-6 * abs(v)) <= leastHi) {
            if (info.y == 1u) outLists[out0 + kept] = s;
            ++kept;
        }
    }
    if (info.y == 0u) counts[i] = uvec2(kept, floatBitsToUint(minLo));
}
)";

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

struct GpuLeaf {
    int level = 0;
    glm::ivec3 cell{0};
    bool constant = false;
    std::vector<std::uint32_t> shapes;
};

struct GpuPruneResult {
    std::vector<int> cellsPerLevel;
    std::vector<GpuLeaf> leaves;
    double dispatchMs = 0.0; // the passes alone (glFinish after each)
    double totalMs = 0.0;    // with the uploads, read-backs and the CPU's share
};

class GpuPruner {
  public:
    bool create(const SdfProgram& program, std::string& error) {
        ShaderFiles files = embeddedShaderFiles();
        files.files["generated/sdf_map.glsl"] = generateSdfMap(program, SdfStrategy::Interpreter);
        files.files["tools/cell_prune.comp"] = kPruneShader;
        std::optional<gl::Program> built =
            buildComputeProgram(files, "tools/cell_prune.comp", "", error);
        if (!built) return false;
        program_ = std::move(*built);
        info_ = uniformLocation(program_, "info");
        slack_ = uniformLocation(program_, "slack");
        GpuSdfHeader header;
        header.instructionCount = std::uint32_t(program.instructions.size());
        header.stackDepth = std::uint32_t(program.stackDepth);
        header.pointStackDepth = std::uint32_t(program.pointStackDepth);
        header.dataCount = std::uint32_t(program.data.size());
        sdfProgram_ = createSdfProgramBuffer(header, program.instructions);
        std::vector<glm::vec4> data = program.data;
        if (data.empty()) data.emplace_back(0.0f);
        sdfData_ =
            gl::createBufferWithData(GLsizeiptr(data.size() * sizeof(glm::vec4)), data.data());
        GpuFrame frame{};
        frame.march = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
        frame.viewport = glm::vec4(1.0f, 1.0f, 4294967296.0f, 1.0f);
        frame_ = gl::createBufferWithData(GLsizeiptr(sizeof frame), &frame);
        return true;
    }

    GpuPruneResult prune(const std::vector<std::uint32_t>& shapes, glm::vec3 origin, float size,
                         const SdfCellOptions& o) const {
        const auto started = std::chrono::steady_clock::now();
        GpuPruneResult result;
        glUseProgram(program_.id());
        bindSdfProgramBuffer(sdfProgram_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSdfDataBinding, sdfData_.id());
        glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBinding, frame_.id());
        glUniform1f(slack_, 1e-5f * size); // the CPU pruner's slack (Pruner::slack)

        std::vector<glm::ivec3> cells;
        std::vector<glm::uvec2> parents;
        for (int j = 0; j < 64; ++j) {
            cells.emplace_back(j % 4, (j / 4) % 4, j / 16);
            parents.emplace_back(0u, std::uint32_t(shapes.size()));
        }
        std::vector<std::uint32_t> lists = shapes;
        gl::Buffer inLists = bufferOf(lists);
        for (int level = 1; level <= o.levels && !cells.empty(); ++level) {
            result.cellsPerLevel.push_back(int(cells.size()));
            const float edge = size / float(1 << (2 * level));
            std::vector<glm::vec4> centres(cells.size());
            for (std::size_t i = 0; i < cells.size(); ++i)
                centres[i] = glm::vec4(origin + (glm::vec3(cells[i]) + 0.5f) * edge, edge);
            const gl::Buffer cellBuffer = bufferOf(centres);
            const gl::Buffer parentBuffer = bufferOf(parents);
            const gl::Buffer counts =
                gl::createBufferWithData(GLsizeiptr(cells.size() * sizeof(glm::uvec2)), nullptr);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCellsBinding, cellBuffer.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kParentsBinding, parentBuffer.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInListsBinding, inLists.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountsBinding, counts.id());
            dispatch(cells.size(), 0u, result.dispatchMs);
            std::vector<glm::uvec2> kept(cells.size());
            glGetNamedBufferSubData(counts.id(), 0, GLsizeiptr(kept.size() * sizeof(glm::uvec2)),
                                    kept.data());
            // The CPU's share: which cells are refined, far constants or leaves, and where each
            // list goes.
            std::vector<std::uint8_t> refine(cells.size(), 0);
            std::uint32_t words = 0;
            for (std::size_t i = 0; i < cells.size(); ++i) {
                float minLo;
                std::memcpy(&minLo, &kept[i].y, sizeof minLo);
                const int leaves = int(kept[i].x);
                const bool far = o.farConstants && minLo >= edge;
                if (far && leaves > o.refineLeaves) {
                    result.leaves.push_back({level, cells[i], true, {}});
                    kept[i] = glm::uvec2(kNoList, 0u);
                    continue;
                }
                refine[i] = !far && level < o.levels && leaves > o.refineLeaves;
                kept[i] = glm::uvec2(words, kept[i].x);
                words += kept[i].y;
            }
            glNamedBufferSubData(counts.id(), 0, GLsizeiptr(kept.size() * sizeof(glm::uvec2)),
                                 kept.data());
            gl::Buffer outLists = gl::createBufferWithData(
                GLsizeiptr(std::max<std::uint32_t>(words, 1u) * sizeof(std::uint32_t)), nullptr);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOutListsBinding, outLists.id());
            dispatch(cells.size(), 1u, result.dispatchMs);
            std::vector<std::uint32_t> written(words);
            glGetNamedBufferSubData(outLists.id(), 0, GLsizeiptr(words * sizeof(std::uint32_t)),
                                    written.data());
            std::vector<glm::ivec3> nextCells;
            std::vector<glm::uvec2> nextParents;
            for (std::size_t i = 0; i < cells.size(); ++i) {
                if (kept[i].x == kNoList) continue;
                if (!refine[i]) {
                    result.leaves.push_back(
                        {level, cells[i], false,
                         std::vector<std::uint32_t>(written.begin() + kept[i].x,
                                                    written.begin() + kept[i].x + kept[i].y)});
                    continue;
                }
                for (int j = 0; j < 64; ++j) {
                    nextCells.push_back(cells[i] * 4 + glm::ivec3(j % 4, (j / 4) % 4, j / 16));
                    nextParents.push_back(kept[i]);
                }
            }
            cells = std::move(nextCells);
            parents = std::move(nextParents);
            inLists = std::move(outLists);
        }
        for (unsigned b :
             {kCellsBinding, kParentsBinding, kInListsBinding, kCountsBinding, kOutListsBinding})
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0);
        glUseProgram(0);
        result.totalMs = msSince(started);
        return result;
    }

  private:
    template <typename T> static gl::Buffer bufferOf(const std::vector<T>& v) {
        return gl::createBufferWithData(GLsizeiptr(std::max<std::size_t>(v.size(), 1) * sizeof(T)),
                                        v.empty() ? nullptr : v.data());
    }

    void dispatch(std::size_t cells, unsigned pass, double& ms) const {
        const auto started = std::chrono::steady_clock::now();
        const std::size_t perDispatch = std::size_t(65535) * kGroupSize;
        for (std::size_t first = 0; first < cells; first += perDispatch) {
            const std::size_t n = std::min(perDispatch, cells - first);
            glUniform4ui(info_, GLuint(cells), pass, GLuint(first), 0u);
            glDispatchCompute(GLuint((n + kGroupSize - 1) / kGroupSize), 1, 1);
        }
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        glFinish();
        ms += msSince(started);
    }

    gl::Program program_;
    SdfProgramBuffer sdfProgram_;
    gl::Buffer sdfData_, frame_;
    GLint info_ = -1, slack_ = -1;
};

int fail(const std::string& message) {
    std::fprintf(stderr, "rmsc_prune_measure: %s\n", message.c_str());
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) return fail("usage: rmsc_prune_measure SCENE [--runs N] [--levels L]");
    int runs = 3;
    SdfCellOptions options;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--runs")
            runs = std::max(1, std::atoi(argv[i + 1]));
        else if (flag == "--levels")
            options.levels = std::clamp(std::atoi(argv[i + 1]), 1, 6);
        else
            return fail("unknown option " + flag);
    }
    Diagnostics diagnostics;
    const std::optional<Scene> scene = loadScene(argv[1], diskFileSource(), diagnostics);
    if (!scene || !scene->sdf) return fail(diagnostics.format() + "no SDF scene in " + argv[1]);
    const std::optional<CompiledSdfScene> compiled =
        compileSdfScene(*scene->sdf, std::uint32_t(scene->materials.size()), argv[1], diagnostics,
                        {.bounds = false});
    if (!compiled) return fail(diagnostics.format());
    const SdfProgram& program = compiled->main;
    // A plain union of shapes: shapes and union instructions only.
    std::vector<std::uint32_t> shapes;
    for (std::uint32_t i = 0; i < program.instructions.size(); ++i) {
        const GpuSdfInstruction& in = program.instructions[i];
        if (SdfOpcode(in.opcode) == SdfOpcode::Shape)
            shapes.push_back(i);
        else if (SdfOpcode(in.opcode) != SdfOpcode::Combine || SdfOp(in.kind) != SdfOp::Union)
            return fail("the compute pruner here prunes plain unions of shapes only");
    }
    const Aabb content = sdfContentBox(*scene->sdf);

    // The CPU pruner, as the renderer runs it.
    std::vector<double> cpuMs;
    SdfCellGrid grid;
    for (int r = 0; r < runs; ++r) {
        const auto started = std::chrono::steady_clock::now();
        grid = buildSdfCells(program, content, options);
        cpuMs.push_back(msSince(started));
    }
    if (grid.levels == 0) return fail("the CPU pruner made no grid");

    std::string error;
    std::unique_ptr<HeadlessContext> context = createHeadlessContext(GlBackend::Auto, false, error);
    if (!context) return fail(error);
    GpuPruner gpu;
    if (!gpu.create(program, error)) return fail(error);
    std::vector<double> gpuMs, dispatchMs;
    GpuPruneResult pruned;
    for (int r = 0; r < runs; ++r) {
        pruned = gpu.prune(shapes, grid.origin, grid.size, options);
        gpuMs.push_back(pruned.totalMs);
        dispatchMs.push_back(pruned.dispatchMs);
    }

    // Every leaf cell of the compute pruner against the CPU's program at its centre.
    std::size_t agree = 0, constants = 0, listed = 0;
    std::string firstDifference;
    for (const GpuLeaf& leaf : pruned.leaves) {
        const float edge = grid.size / float(1 << (2 * leaf.level));
        const glm::vec3 centre = grid.origin + (glm::vec3(leaf.cell) + 0.5f) * edge;
        const SdfCellRange range = sdfCellRange(grid, centre);
        // The CPU's list: the program's shapes and unions, or one far constant (a shape the
        // pruning added after the program's instructions).
        std::vector<std::uint32_t> cpuShapes;
        bool cpuConstant = false;
        for (std::uint32_t k = 0; k < range.length; ++k) {
            const std::uint32_t index = grid.words[range.offset + k];
            if (index >= program.instructions.size())
                cpuConstant = true;
            else if (SdfOpcode(grid.code[index].opcode) == SdfOpcode::Shape)
                cpuShapes.push_back(index);
        }
        // (The grid's planes are in no CPU list: every point evaluates them.)
        std::vector<std::uint32_t> gpuShapes = leaf.shapes;
        std::erase_if(gpuShapes, [&](std::uint32_t i) {
            return std::any_of(grid.planes.begin(), grid.planes.end(),
                               [&](const SdfCellPlane& plane) { return plane.instruction == i; });
        });
        std::sort(cpuShapes.begin(), cpuShapes.end());
        std::sort(gpuShapes.begin(), gpuShapes.end());
        const bool same = range.level == leaf.level &&
                          (leaf.constant ? cpuConstant : !cpuConstant && cpuShapes == gpuShapes);
        constants += leaf.constant;
        listed += gpuShapes.size();
        if (same)
            ++agree;
        else if (firstDifference.empty())
            firstDifference = "level " + std::to_string(leaf.level) + " (CPU " +
                              std::to_string(range.level) + "), " +
                              std::to_string(gpuShapes.size()) + " shapes (CPU " +
                              std::to_string(cpuShapes.size()) + ")";
    }
    std::printf("{\"scene\": \"%s\", \"shapes\": %zu, \"levels\": %d, \"renderer\": \"%s\", "
                "\"cpu_ms\": %.1f, \"gpu_ms\": %.1f, \"gpu_dispatch_ms\": %.1f, "
                "\"cpu_leaf_cells\": %d, \"gpu_leaf_cells\": %zu, \"gpu_far_constants\": %zu, "
                "\"gpu_mean_shapes\": %.2f, \"cpu_budget_reached\": %s, \"gpu_cells_per_level\": [",
                argv[1], shapes.size(), options.levels, context->renderer().c_str(), median(cpuMs),
                median(gpuMs), median(dispatchMs), grid.stats.leafCells, pruned.leaves.size(),
                constants,
                double(listed) / double(std::max<std::size_t>(1, pruned.leaves.size() - constants)),
                grid.stats.leafCells + 64 >= int(options.maxCells) ? "true" : "false");
    for (std::size_t i = 0; i < pruned.cellsPerLevel.size(); ++i)
        std::printf("%s%d", i ? ", " : "", pruned.cellsPerLevel[i]);
    std::printf("], \"agreeing_leaf_cells\": %zu, \"first_difference\": \"%s\"}\n", agree,
                firstDifference.c_str());
    const bool same = !pruned.leaves.empty() && agree == pruned.leaves.size() &&
                      int(pruned.leaves.size()) == grid.stats.leafCells;
    return same ? 0 : 1;
}
