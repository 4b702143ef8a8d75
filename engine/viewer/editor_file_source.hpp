// The files the editor's scenes read: scene files and the glTF files they name, from disk (each
// file once per session, so an edit does not read every mesh again), falling back to the
// embedded samples (the demo).
#pragma once

#include "core/file_source.hpp"

namespace rmsc::app {

FileSource editorFileSource();

} // namespace rmsc::app
