// The OpenGL context current on this thread when it was made by someone else (a host program
// embedding rmsc): which one it is, and loading the GL functions through the API that made it
// (EGL, OSMesa or GLX).
#pragma once

#include <string>

namespace rmsc {

// An opaque identity of the context current on this thread (EGL, OSMesa or GLX, whichever
// is), or nullptr when none is. Two calls return the same value for the same context.
const void* currentGlContext();

// Loads the GL functions for the current context through the API that made it. False with
// `error` when no context is current, the functions cannot be loaded, or the context is not
// OpenGL 4.5.
bool loadGlForCurrentContext(std::string& error);

} // namespace rmsc
