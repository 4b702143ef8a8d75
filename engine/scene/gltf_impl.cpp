// The single translation unit that compiles tinygltf's implementation, with the
// configuration from gltf_tinygltf.hpp (no stb, no file system, no external images).
// tinygltf 2.7.0's writer still names std::ofstream under TINYGLTF_NO_FS, so <fstream> is
// included for it to compile; rmsc never calls the writer.
#include <fstream>

#define TINYGLTF_IMPLEMENTATION
#include "scene/gltf_tinygltf.hpp"
