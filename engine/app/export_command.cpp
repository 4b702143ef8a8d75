// rmsc export: an SDF tree, or one node of it, as a triangle mesh file (export/sdf_export.hpp).
#include "commands.hpp"

#include "core/file_source.hpp"
#include "core/limits.hpp"
#include "export/mesh_writers.hpp"
#include "export/sdf_export.hpp"
#include "gl/context.hpp"
#include "render/gpu_field_sampler.hpp"
#include "scene/scene_json.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <unistd.h>

namespace rmsc::app {
namespace {

const OptionSpec kOptions[] = {
    {"--output", "-o", "FILE",
     "mesh to write: .glb, .gltf (buffer embedded), .obj (+ .mtl) or .stl"},
    {"--node", nullptr, "POINTER",
     "JSON pointer of the SDF node to export (default /sdf: the whole tree)"},
    {"--voxel", nullptr, "SIZE", "cell size of the sampling grid, in world units"},
    {"--resolution", nullptr, "N",
     "cells along the longest side of the content's box (default 128; ignored with --voxel)"},
    {"--bounds", nullptr, "X0,Y0,Z0,X1,Y1,Z1",
     "world box the content is cut to (closed at its faces); needed for unbounded content"},
    {"--tolerance", nullptr, "T",
     "how far, in voxels, the adaptive octree may move the surface where it joins cells "
     "(default 0.1; 0: one vertex per cell)"},
    {"--threads", nullptr, "N", "sampling threads (default: every core)"},
    {"--sampler", nullptr, "S",
     "cpu | gpu: what samples the grid's blocks (default cpu; gpu: a compute shader, "
     "docs/export.md)"},
    {"--backend", nullptr, "NAME", "with --sampler gpu: auto | egl | osmesa (default auto)"},
    kSandboxOption,
};

std::atomic<bool> interrupted{false};
extern "C" void onInterrupt(int) {
    interrupted = true;
}

bool parseFloat(const std::string& text, float& value) {
    char* end = nullptr;
    value = std::strtof(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
}

bool parseBounds(const std::string& text, Aabb& box) {
    std::stringstream in(text);
    std::string part;
    float v[6];
    int n = 0;
    while (std::getline(in, part, ',')) {
        if (n == 6 || !parseFloat(part, v[n])) return false;
        ++n;
    }
    if (n != 6) return false;
    box.min = {v[0], v[1], v[2]};
    box.max = {v[3], v[4], v[5]};
    return !box.empty();
}

// "[#######.............]  35%" on stderr, redrawn in place.
void drawProgress(double fraction) {
    const int width = 40;
    const int filled = int(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(std::size_t(filled), '#').c_str(),
                 std::string(std::size_t(width - filled), '.').c_str(), int(fraction * 100 + 0.5));
    std::fflush(stderr);
}

} // namespace

const CommandSpec kExportSpec = {
    "export",
    "SCENE -o OUT.glb",
    "export the SDF tree or one node as a triangle mesh (glTF, OBJ, STL)",
    "rmsc export SCENE -o OUT.glb|.gltf|.obj|.stl [--node POINTER] [--voxel SIZE | "
    "--resolution N] [--bounds X0,Y0,Z0,X1,Y1,Z1] [--tolerance T] [--sampler cpu|gpu]",
    "Samples the SDF tree of SCENE (or the node at --node, in its place in the scene) on a\n"
    "grid and extracts a closed, consistently oriented mesh by dual contouring, so edges and\n"
    "corners stay sharp; an adaptive octree joins the cells of flat regions, so they take few\n"
    "triangles. Normals come from the SDF gradient; each rmsc material becomes a glTF\n"
    "material, and colours blended by smooth operations go to COLOR_0. Unbounded content\n"
    "(planes, infinite repetition) needs --bounds or the node's shell \"bound\". The output is\n"
    "written atomically: an error or Ctrl-C leaves no partial file. docs/export.md has more.",
    kOptions,
    1};

int runExport(const ParsedArgs& args) {
    if (args.positionals.empty()) {
        std::fprintf(stderr, "rmsc export: no scene given\n");
        return kExitUsage;
    }
    const std::filesystem::path output = args.get("--output", "");
    if (output.empty()) {
        std::fprintf(stderr, "rmsc export: no output file given (-o OUT.glb)\n");
        return kExitUsage;
    }
    MeshFormat format;
    if (!meshFormatOf(output, format)) {
        std::fprintf(stderr, "rmsc export: %s: expected a .glb, .gltf, .obj or .stl file name\n",
                     output.string().c_str());
        return kExitUsage;
    }
    ExportSettings settings;
    settings.node = args.get("--node", "");
    if (args.has("--voxel")) {
        float voxel = 0.0f;
        if (!parseFloat(args.get("--voxel", ""), voxel) || !(voxel > 0.0f)) {
            std::fprintf(stderr, "rmsc export: --voxel: expected a positive number, got '%s'\n",
                         args.get("--voxel", "").c_str());
            return kExitUsage;
        }
        settings.voxel = voxel;
    }
    if (args.has("--resolution")) {
        int resolution = 0;
        if (!parsePositiveInt(args.get("--resolution", ""), 1 << 20, resolution)) {
            std::fprintf(stderr,
                         "rmsc export: --resolution: expected a positive whole number, got '%s'\n",
                         args.get("--resolution", "").c_str());
            return kExitUsage;
        }
        settings.resolution = resolution;
    }
    if (args.has("--bounds")) {
        Aabb box;
        if (!parseBounds(args.get("--bounds", ""), box)) {
            std::fprintf(stderr,
                         "rmsc export: --bounds: expected six numbers X0,Y0,Z0,X1,Y1,Z1 with "
                         "X0 <= X1, Y0 <= Y1, Z0 <= Z1, got '%s'\n",
                         args.get("--bounds", "").c_str());
            return kExitUsage;
        }
        settings.bounds = box;
    }
    if (args.has("--tolerance")) {
        float tolerance = 0.0f;
        if (!parseFloat(args.get("--tolerance", ""), tolerance) || tolerance < 0.0f) {
            std::fprintf(stderr,
                         "rmsc export: --tolerance: expected a number of voxels >= 0, got '%s'\n",
                         args.get("--tolerance", "").c_str());
            return kExitUsage;
        }
        settings.tolerance = tolerance;
    }
    if (args.has("--threads")) {
        if (!parsePositiveInt(args.get("--threads", ""), 1024, settings.threads)) {
            std::fprintf(stderr, "rmsc export: --threads: expected 1 to 1024, got '%s'\n",
                         args.get("--threads", "").c_str());
            return kExitUsage;
        }
    }
    const std::string samplerName = args.get("--sampler", "cpu");
    if (samplerName != "cpu" && samplerName != "gpu") {
        std::fprintf(stderr, "rmsc export: --sampler: expected cpu or gpu, got '%s'\n",
                     samplerName.c_str());
        return kExitUsage;
    }
    GlBackend backend = GlBackend::Auto;
    if (!parseGlBackend(args.get("--backend", "auto"), backend)) {
        std::fprintf(stderr, "rmsc export: --backend: expected auto, egl or osmesa, got '%s'\n",
                     args.get("--backend", "").c_str());
        return kExitUsage;
    }
    // The GPU sampler's context and shader, made when the node is compiled; a failure to make
    // either is an error, not a silent fall back to the CPU.
    std::unique_ptr<HeadlessContext> context;
    std::optional<GpuFieldSampler> sampler;
    std::string samplerError;
    if (samplerName == "gpu")
        settings.latticeSampler = [&](const SdfProgram& program) -> SdfLattice {
            context = createHeadlessContext(backend, false, samplerError);
            if (!context) return {};
            sampler = GpuFieldSampler::create(program, samplerError);
            if (!sampler) return {};
            return [&](glm::vec3 origin, float spacing, const glm::ivec3* starts, std::size_t count,
                       int side, float* out) {
                if (sampler->sample(origin, spacing, starts, count, side, out)) return true;
                samplerError = "a GL error while sampling";
                return false;
            };
        };
    // The output's folder must exist and be writable before any sampling is spent on it.
    const std::filesystem::path folder =
        output.parent_path().empty() ? std::filesystem::path(".") : output.parent_path();
    if (::access(folder.c_str(), W_OK) != 0) {
        std::fprintf(stderr, "rmsc export: %s: cannot write there (%s is not a writable folder)\n",
                     output.string().c_str(), folder.string().c_str());
        return kExitSystem;
    }

    const std::string scenePath = args.positionals[0];
    Diagnostics diagnostics;
    const std::optional<Scene> scene = loadScene(scenePath, diskFileSource(), diagnostics);
    if (!scene) {
        std::fputs(diagnostics.format().c_str(), stderr);
        return kExitBadInput;
    }
    const bool showProgress = ::isatty(STDERR_FILENO) == 1;
    if (showProgress) settings.progress = drawProgress;
    interrupted = false;
    settings.cancel = &interrupted;
    auto previous = std::signal(SIGINT, onInterrupt);
    const auto start = std::chrono::steady_clock::now();
    std::optional<SdfExport> exported = exportSdf(*scene, settings, diagnostics);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (showProgress && exported) std::fputs("\n", stderr);
    std::fputs(diagnostics.format().c_str(), stderr);
    if (!exported) {
        std::signal(SIGINT, previous);
        return kExitBadInput;
    }
    if (samplerName == "gpu" && !exported->cancelled && !exported->latticeSampled) {
        std::signal(SIGINT, previous);
        std::fprintf(stderr, "rmsc export: --sampler gpu: %s; nothing was written\n",
                     samplerError.empty() ? "the GPU did not sample the grid"
                                          : samplerError.c_str());
        return kExitSystem;
    }
    if (exported->cancelled || interrupted) {
        std::signal(SIGINT, previous);
        std::fprintf(stderr, "rmsc export: interrupted; %s was not written\n",
                     output.string().c_str());
        return 130;
    }
    std::string error;
    const MeshFile file{exported->mesh, exported->materials, exported->name};
    const bool written = writeMeshFile(output, format, file, &interrupted, error);
    std::signal(SIGINT, previous);
    if (!written) {
        std::fprintf(stderr, "rmsc export: %s: cannot write it: %s; nothing was written\n",
                     output.string().c_str(), error.c_str());
        return interrupted ? 130 : kExitSystem;
    }
    const MeshTopology topology = meshTopology(exported->mesh);
    const glm::ivec3 cells = exported->grid.cells;
    std::printf("%s: %zu triangles, %zu vertices, %zu materials from %s (voxel %g, grid %dx%dx%d) "
                "in %.2f s (sampling %.2f s on the %s)\n",
                output.string().c_str(), exported->mesh.triangles.size(),
                exported->mesh.positions.size(), exported->materials.size(),
                exported->pointer.c_str(), double(exported->grid.voxel), cells.x, cells.y, cells.z,
                seconds, exported->samplingSeconds, exported->latticeSampled ? "GPU" : "CPU");
    if (!topology.closedManifold())
        std::fprintf(stderr,
                     "rmsc export: warning: the mesh is not a closed 2-manifold everywhere "
                     "(%lld boundary, %lld over-shared, %lld misoriented edges, %lld pinched "
                     "vertices): the content has features thinner than a voxel; a smaller "
                     "--voxel resolves them\n",
                     (long long)topology.boundaryEdges, (long long)topology.overSharedEdges,
                     (long long)topology.misorientedEdges, (long long)topology.pinchedVertices);
    if (const std::int64_t crossings = countSelfIntersections(exported->mesh); crossings > 0)
        std::fprintf(stderr,
                     "rmsc export: warning: %lld pairs of triangles intersect (the content has "
                     "features thinner than a voxel; a smaller --voxel resolves them)\n",
                     (long long)crossings);
    return kExitOk;
}

} // namespace rmsc::app
