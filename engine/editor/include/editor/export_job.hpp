// A mesh export started from the editor (the viewer's File > Export scene / Export selection):
// the options of `rmsc export` as a form, what the form needs to know about the content before
// anything runs, and the job that exports on a worker thread while the editor goes on drawing,
// with its progress, a cancel and its outcome. The file is written atomically
// (export/mesh_writers.hpp): a failed or cancelled export leaves nothing. GL-free.
#pragma once

#include "export/mesh_writers.hpp"
#include "export/sdf_export.hpp"
#include "scene/scene.hpp"
#include "sdf/bounds.hpp"

#include <atomic>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace rmsc::editor {

// What `rmsc export` takes on its command line.
struct ExportForm {
    std::string path;          // the output; its extension picks the format (.glb .gltf .obj .stl)
    std::string node = "/sdf"; // the JSON pointer of the node (Export selection: the selected one)
    bool byVoxel = false;      // the voxel size sets the grid, else the resolution does
    float voxel = 0.01f;
    int resolution = kExportDefaultResolution;
    float tolerance = kExportDefaultTolerance; // the adaptive octree's, in voxels (0: off)
    bool clip = false; // cut the content to `bounds` (needed for unbounded content)
    Aabb bounds{glm::vec3(-1.0f), glm::vec3(1.0f)};
};

// The JSON pointer of the SDF node at `path` (child indices from the root): "/sdf",
// "/sdf/children/1/children/0".
std::string sdfNodePointer(const std::vector<int>& path);

// What the export dialog shows before it runs: whether the node is there, and its box, or the
// pointer of what makes it unbounded (then the form needs bounds).
struct ExportContent {
    bool found = false;
    bool bounded = false;
    std::string unboundedBy; // the node or modifier that reaches infinity
    Aabb box;                // the content's box (bounded only)
    std::string error;       // why it was not found or does not compile
};
ExportContent describeExportContent(const Scene& scene, const std::string& node);

// The form's settings for exportSdf, and the format; false with `error` (naming the field) when
// the form cannot be run: an output whose extension names no format, a folder that does not
// exist or is not writable, a voxel size or resolution out of range, empty bounds.
bool exportSettingsFrom(const ExportForm& form, ExportSettings& settings, MeshFormat& format,
                        std::string& error);

struct ExportOutcome {
    bool written = false;
    bool cancelled = false;
    std::filesystem::path output;
    std::string message; // a summary when written; why not otherwise (file: pointer: problem)
    std::size_t triangles = 0, vertices = 0, materials = 0;
};

class ExportJob {
  public:
    ExportJob() = default;
    ~ExportJob(); // cancels a running export and waits for its thread
    ExportJob(const ExportJob&) = delete;
    ExportJob& operator=(const ExportJob&) = delete;

    // Starts exporting `scene` (copied: the document may change meanwhile) as `form` says, on
    // `threads` sampling threads (0: every core). The scene is exported as its file would be
    // read: its text as a save writes it, read back, so the pointers are those of the scene as
    // it is now. False, with `error`, when an export is already running or the form cannot be
    // run (exportSettingsFrom); then nothing starts.
    bool start(const Scene& scene, const ExportForm& form, int threads, std::string& error);
    bool running() const { return running_.load(); }
    // The running (or last) export's progress, 0 to 1.
    double progress() const { return progress_.load(); }
    std::filesystem::path output() const;
    // Asks the running export to stop: it ends soon, writing nothing.
    void cancel() { cancel_ = true; }
    // The outcome of an export that ended, once; nullopt while it runs or once taken.
    std::optional<ExportOutcome> takeOutcome();
    // Blocks until the running export (if any) has ended.
    void wait();

  private:
    void run(Scene scene, ExportSettings settings, MeshFormat format, std::filesystem::path output);

    std::thread thread_;
    std::atomic<bool> running_{false};
    std::atomic<bool> cancel_{false};
    std::atomic<double> progress_{0.0};
    mutable std::mutex mutex_; // guards outcome_ and output_
    std::optional<ExportOutcome> outcome_;
    std::filesystem::path output_;
};

} // namespace rmsc::editor
