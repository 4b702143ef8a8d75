// Background work that must not take the CPU from the UI: threads that prune cells, build
// shaders or export while the viewer runs lower their own scheduling priority, so on a machine
// with few cores the frames (the panels, the display, llvmpipe's rasterizer threads) come first
// and the background gets what is left. Threads they start inherit it (Linux: the nice value is
// per thread and copied by pthread_create).
#pragma once

namespace rmsc {

// Lowers the calling thread's priority (its nice value 10 higher, at most 19, on Linux;
// nothing elsewhere).
void lowerThisThreadsPriority();

} // namespace rmsc
