// Background work that must not take the CPU from the UI: the viewer's first pruning of a large
// scene's cells (seconds of both cores) lowers its threads' scheduling priority, so on a
// machine with few cores the frames (the panels, the display, llvmpipe's rasterizer threads)
// come first and the pruning gets what is left. Threads it starts inherit it (Linux: the nice
// value is per thread and copied by pthread_create). Not for work someone waits on (an export,
// a shader build the view needs next): under load a niced thread gets a tenth of a core.
#pragma once

namespace rmsc {

// Lowers the calling thread's priority (its nice value 10 higher, at most 19, on Linux;
// nothing elsewhere).
void lowerThisThreadsPriority();

} // namespace rmsc
