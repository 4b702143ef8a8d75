// The editor's export: the form checked, the content described, and the worker thread that
// runs exportSdf and writes the file (see export_job.hpp).
#include "editor/export_job.hpp"

#include "core/number_text.hpp"
#include "scene/scene_json.hpp"

#include <cmath>
#include <unistd.h>

namespace rmsc::editor {
namespace {

// The scene as its file would be read: its text as a save writes it, read back. The node
// pointers of an edited scene are those it had when it was read; these are the current ones.
std::optional<Scene> reread(const Scene& scene, Diagnostics& diagnostics) {
    return parseScene(sceneToJson(scene), scene.file, diagnostics);
}

// The first error, as "POINTER: MESSAGE" (the scene file is the one being edited).
std::string firstError(const Diagnostics& diagnostics) {
    for (const Diagnostic& d : diagnostics.items)
        if (d.severity == Severity::Error)
            return (d.location.empty() ? "" : d.location + ": ") + d.message;
    return "the export failed";
}

} // namespace

std::string sdfNodePointer(const std::vector<int>& path) {
    std::string pointer = "/sdf";
    for (int index : path)
        pointer += "/children/" + std::to_string(index);
    return pointer;
}

ExportContent describeExportContent(const Scene& scene, const std::string& node) {
    ExportContent out;
    Diagnostics diagnostics;
    const std::optional<Scene> current = reread(scene, diagnostics);
    if (!current) {
        out.error = firstError(diagnostics);
        return out;
    }
    const std::optional<SdfBounds> bounds = exportContentBounds(*current, node, diagnostics);
    if (!bounds) {
        out.error = firstError(diagnostics);
        return out;
    }
    out.found = true;
    out.bounded = bounds->bounded;
    out.unboundedBy = bounds->unboundedBy.empty() ? node : bounds->unboundedBy;
    if (out.bounded) out.box = bounds->box;
    return out;
}

bool exportSettingsFrom(const ExportForm& form, ExportSettings& settings, MeshFormat& format,
                        std::string& error) {
    const std::filesystem::path output = form.path;
    if (form.path.empty()) {
        error = "File: give the file to write (.glb, .gltf, .obj or .stl)";
        return false;
    }
    if (!meshFormatOf(output, format)) {
        error = "File: " + form.path +
                ": expected a .glb, .gltf, .obj or .stl file name (the extension picks the format)";
        return false;
    }
    const std::filesystem::path folder =
        output.parent_path().empty() ? std::filesystem::path(".") : output.parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec) || ::access(folder.c_str(), W_OK) != 0) {
        error = "File: " + form.path + ": cannot write there (" + folder.string() +
                " is not a writable folder)";
        return false;
    }
    settings = ExportSettings{};
    settings.node = form.node;
    if (form.byVoxel) {
        if (!(form.voxel > 0.0f) || !std::isfinite(form.voxel)) {
            error = "Voxel size: expected a positive number, got " + shortestNumberText(form.voxel);
            return false;
        }
        settings.voxel = form.voxel;
    } else {
        // As `rmsc export --resolution` takes it; exportSdf refuses a grid over the voxel limit.
        const int most = 1 << 20;
        if (form.resolution < 1 || form.resolution > most) {
            error = "Resolution: expected 1 to " + std::to_string(most) + " cells, got " +
                    std::to_string(form.resolution);
            return false;
        }
        settings.resolution = form.resolution;
    }
    if (!(form.tolerance >= 0.0f) || !std::isfinite(form.tolerance)) {
        error = "Tolerance: expected a number of voxels >= 0, got " +
                shortestNumberText(form.tolerance);
        return false;
    }
    settings.tolerance = form.tolerance;
    if (form.clip) {
        if (form.bounds.empty() ||
            glm::any(glm::greaterThanEqual(form.bounds.min, form.bounds.max))) {
            error = "Bounds: each minimum must be below its maximum";
            return false;
        }
        settings.bounds = form.bounds;
    }
    return true;
}

ExportJob::~ExportJob() {
    cancel();
    wait();
}

std::filesystem::path ExportJob::output() const {
    std::lock_guard lock(mutex_);
    return output_;
}

bool ExportJob::start(const Scene& scene, const ExportForm& form, int threads, std::string& error) {
    if (running_) {
        error = "an export is running: wait for it, or cancel it";
        return false;
    }
    ExportSettings settings;
    MeshFormat format;
    if (!exportSettingsFrom(form, settings, format, error)) return false;
    settings.threads = threads;
    wait(); // the thread of the last export, which has ended
    {
        std::lock_guard lock(mutex_);
        outcome_.reset();
        output_ = form.path;
    }
    cancel_ = false;
    progress_ = 0.0;
    running_ = true;
    thread_ = std::thread(&ExportJob::run, this, scene, std::move(settings), format,
                          std::filesystem::path(form.path));
    return true;
}

void ExportJob::run(Scene scene, ExportSettings settings, MeshFormat format,
                    std::filesystem::path output) {
    ExportOutcome outcome;
    outcome.output = output;
    Diagnostics diagnostics;
    settings.progress = [this](double fraction) { progress_ = 0.95 * fraction; };
    settings.cancel = &cancel_;
    std::optional<SdfExport> exported;
    if (std::optional<Scene> current = reread(scene, diagnostics))
        exported = exportSdf(*current, settings, diagnostics);
    if (!exported) {
        outcome.message = firstError(diagnostics);
    } else if (exported->cancelled || cancel_) {
        outcome.cancelled = true;
        outcome.message = "cancelled; " + output.string() + " was not written";
    } else {
        std::string error;
        const MeshFile file{exported->mesh, exported->materials, exported->name};
        if (writeMeshFile(output, format, file, &cancel_, error)) {
            outcome.written = true;
            outcome.triangles = exported->mesh.triangles.size();
            outcome.vertices = exported->mesh.positions.size();
            outcome.materials = exported->materials.size();
            outcome.message = "exported " + exported->pointer + " to " + output.string() + ": " +
                              std::to_string(outcome.triangles) + " triangles, " +
                              std::to_string(outcome.vertices) + " vertices, " +
                              std::to_string(outcome.materials) + " material" +
                              (outcome.materials == 1 ? "" : "s") + " (voxel " +
                              shortestNumberText(exported->grid.voxel) + ")";
        } else if (cancel_) {
            outcome.cancelled = true;
            outcome.message = "cancelled; " + output.string() + " was not written";
        } else {
            outcome.message =
                output.string() + ": cannot write it: " + error + "; nothing was written";
        }
    }
    progress_ = 1.0;
    {
        std::lock_guard lock(mutex_);
        outcome_ = std::move(outcome);
    }
    running_ = false;
}

std::optional<ExportOutcome> ExportJob::takeOutcome() {
    if (running_) return std::nullopt;
    std::lock_guard lock(mutex_);
    std::optional<ExportOutcome> out = std::move(outcome_);
    outcome_.reset();
    return out;
}

void ExportJob::wait() {
    if (thread_.joinable()) thread_.join();
}

} // namespace rmsc::editor
