// Object ids: what the `id` AOV shows and picking returns, for meshes and SDF nodes alike.
#pragma once

namespace rmsc {

// Object ids shown by the `id` AOV and used for picking: 0 is the background, mesh instance i
// is kMeshIdBase + i, the SDF node with pre-order index n (root = 0) is kSdfIdBase + n.
constexpr unsigned kMeshIdBase = 1;
constexpr unsigned kSdfIdBase = 0x10000;

} // namespace rmsc
