// Uploading a decoded RGBA8 image as a GL texture with a full mipmap chain, in the colour space
// its role needs (sRGB for base colour and emissive, linear for data maps), sampled as the
// given glTF-style sampler says. Each texture keeps the size of its image.
#pragma once

#include "gl/handles.hpp"
#include "scene/mesh_asset.hpp"

namespace rmsc {

gl::Texture uploadTexture(const Image& image, bool srgb, const MeshSampler& sampler = {});

} // namespace rmsc
