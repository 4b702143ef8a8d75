// The TEXCOORD set a glTF textureInfo reads: its texCoord, or the texCoord of its
// KHR_texture_transform extension when that has one (the extension's override).
#pragma once

#include "scene/gltf_tinygltf.hpp"

namespace rmsc::gltf {

template <typename Info> int textureTexCoord(const Info& info) {
    const auto ext = info.extensions.find("KHR_texture_transform");
    if (ext != info.extensions.end() && ext->second.IsObject() && ext->second.Has("texCoord") &&
        ext->second.Get("texCoord").IsNumber())
        return int(ext->second.Get("texCoord").GetNumberAsDouble());
    return info.texCoord;
}

} // namespace rmsc::gltf
