// The cone pass's tiles (passes/cone.frag): each texel of its target stands for a square of
// CONE_TILE_SIZE x CONE_TILE_SIZE pixels, the texel (x, y) for the pixels (x, y) * size and up.
// Mirrored by kConeTileSize in engine/render/include/render/cone_pass.hpp.
#define CONE_TILE_SIZE 8
