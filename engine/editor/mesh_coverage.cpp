// Which points of a mesh the raster pass draws (see mesh_coverage.hpp).
#include "editor/mesh_coverage.hpp"

#include <algorithm>
#include <cmath>

namespace rmsc::editor {

namespace {

// A texel coordinate under a glTF wrap mode (GL enums: REPEAT, MIRRORED_REPEAT, CLAMP).
int wrap(float coordinate, int size, int mode) {
    const int i = int(std::floor(coordinate * float(size)));
    if (mode == 0x2901) return ((i % size) + size) % size; // GL_REPEAT
    if (mode == 0x8370) {                                  // GL_MIRRORED_REPEAT
        const int period = 2 * size;
        const int m = ((i % period) + period) % period;
        return m < size ? m : period - 1 - m;
    }
    return std::clamp(i, 0, size - 1); // GL_CLAMP_TO_EDGE
}

} // namespace

float meshAlphaAt(const MeshAsset& asset, const MeshMaterial& m, const MeshVertex& a,
                  const MeshVertex& b, const MeshVertex& c, float u, float v) {
    const float w = 1.0f - u - v;
    float alpha = m.baseColorFactor.w * (w * a.color.w + u * b.color.w + v * c.color.w);
    const MeshTextureRef& t = m.baseColorTexture;
    if (t.present() && std::size_t(t.image) < asset.images.size()) {
        const Image& image = asset.images[std::size_t(t.image)];
        if (image.width > 0 && image.height > 0 &&
            image.rgba.size() >= std::size_t(image.width) * std::size_t(image.height) * 4) {
            const glm::vec2 raw = t.texCoord == 1 ? w * a.uv1 + u * b.uv1 + v * c.uv1
                                                  : w * a.uv + u * b.uv + v * c.uv;
            const glm::vec2 uv = t.transform.apply(raw);
            const int x = wrap(uv.x, image.width, t.sampler.wrapS);
            const int y = wrap(uv.y, image.height, t.sampler.wrapT); // rows top first, as glTF
            alpha *=
                float(image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4 +
                                 3]) /
                255.0f;
        }
    }
    return alpha;
}

bool meshPointDrawn(const MeshAsset& asset, const MeshPrimitive& primitive, const MeshVertex& a,
                    const MeshVertex& b, const MeshVertex& c, float u, float v, bool frontFace) {
    if (primitive.material < 0 || std::size_t(primitive.material) >= asset.materials.size())
        return frontFace; // the glTF default material: single-sided, opaque
    const MeshMaterial& m = asset.materials[std::size_t(primitive.material)];
    if (!frontFace && !m.doubleSided) return false;
    if (m.alphaMode != AlphaMode::Mask) return true;
    return meshAlphaAt(asset, m, a, b, c, u, v) >= m.alphaCutoff;
}

} // namespace rmsc::editor
