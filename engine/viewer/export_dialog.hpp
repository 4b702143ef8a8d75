// File > Export scene / Export selection: the dialog with the options of `rmsc export` (the file,
// whose extension picks the format; the resolution or the voxel size; bounds, needed for
// unbounded content), and, while the export runs on its worker thread (editor/export_job.hpp),
// a small window over the view with its progress and a Cancel button. The view and the panels
// go on being drawn and edited meanwhile; the outcome becomes a notice, or a problem shown over
// the view.
#pragma once

#include "editor/document.hpp"
#include "editor/export_job.hpp"
#include "messages.hpp"
#include "panel_layout.hpp"

#include <glm/glm.hpp>

#include <string>

namespace rmsc::app {

struct ExportUi {
    bool ask = false;       // open the dialog on the next frame
    bool selection = false; // Export selection (else the whole SDF tree)
    editor::ExportForm form;
    editor::ExportContent content;
    std::string error; // why Export did not start, shown in the dialog
    editor::ExportJob job;
};

// Whether Export selection applies: one SDF node is the active selection.
bool canExportSelection(const editor::Document& document);

// Prepares the form for the scene's SDF tree, or the selected node: a file beside the scene
// named after it, the content's box as the bounds (or, for unbounded content, a box of 4 m
// around `focus`, the point the view looks at, with the bounds switched on). Opens the dialog.
void openExportDialog(ExportUi& ui, const editor::Document& document, bool selection,
                      glm::vec3 focus);

// The dialog, when asked for; Export starts the job (the scene as it is now) on all cores but one.
void drawExportDialog(ExportUi& ui, const editor::Document& document);

// While the job runs: its progress and Cancel at the bottom right of the view. When it has
// ended: its outcome as a notice (written, cancelled) or as messages.fileError.
void drawExportProgress(ExportUi& ui, const Rect& viewport, Messages& messages);

} // namespace rmsc::app
