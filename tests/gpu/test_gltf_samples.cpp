// The Khronos glTF sample models, opened as `rmsc render MODEL.gltf` opens them, checked for
// what their README says a correct viewer shows: VertexColorTest's checks are clean (no cyan,
// magenta or yellow X of an ignored COLOR_0), TextureSettingsTest's single- and double-sided rows
// show no red X (a single-sided back face culled), AlphaBlendModeTest's mask panels end at 1 -
// cutoff of their height, TextureTransformTest's panels show their textures where
// KHR_texture_transform puts them (the arrows turned and scaled), and NormalTangentMirrorTest's
// gold half is lit by the default studio sky. Regions come from the models' own geometry, projected
// through the scene camera.
#include "gltf_builder.hpp"
#include "gpu_test_support.hpp"

#include "render/frame.hpp"

#include <cmath>

using namespace rmsc;
using namespace rmsc::test;

namespace {

struct SampleRender {
    PreparedScene prepared;
    Pixels<std::uint8_t> display; // sRGB, rows top first
    Pixels<std::uint32_t> ids;
    int width = 0, height = 0;
};

std::optional<SampleRender> renderSample(const std::string& name, int width, int height) {
    Diagnostics d;
    std::optional<PreparedScene> prepared = openScene(gltfSamples() / name, d);
    EXPECT_TRUE(prepared) << d.format();
    if (!prepared) return std::nullopt;
    SampleRender out;
    const FrameTargets targets = renderPrepared(*prepared, width, height);
    out.display = readDisplayColor(targets);
    out.ids = readObjectIds(targets);
    out.prepared = std::move(*prepared);
    out.width = width;
    out.height = height;
    return out;
}

const MeshAsset& assetOf(const SampleRender& s) {
    return s.prepared.assets.at(0);
}

int materialIndex(const MeshAsset& asset, const std::string& name) {
    for (std::size_t i = 0; i < asset.materials.size(); ++i)
        if (asset.materials[i].name == name) return int(i);
    ADD_FAILURE() << "no material " << name;
    return -2;
}

// The bounds of the primitives drawn with material `name` (the asset is placed as it is).
std::pair<glm::vec3, glm::vec3> materialBounds(const MeshAsset& asset, const std::string& name) {
    const int m = materialIndex(asset, name);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const MeshPrimitive& p : asset.primitives)
        if (p.material == m)
            for (const MeshVertex& v : p.vertices) {
                lo = glm::min(lo, v.position);
                hi = glm::max(hi, v.position);
            }
    return {lo, hi};
}

// The bounds of the tallest primitive drawn with material `name` (a test panel, where the same
// material also draws labels and markers).
std::pair<glm::vec3, glm::vec3> tallestBounds(const MeshAsset& asset, const std::string& name) {
    const int m = materialIndex(asset, name);
    std::pair<glm::vec3, glm::vec3> best{glm::vec3(0.0f), glm::vec3(0.0f)};
    for (const MeshPrimitive& p : asset.primitives) {
        if (p.material != m || p.vertices.empty()) continue;
        glm::vec3 lo = p.vertices[0].position, hi = lo;
        for (const MeshVertex& v : p.vertices) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
        if (hi.y - lo.y > best.second.y - best.first.y) best = {lo, hi};
    }
    return best;
}

glm::vec2 project(const SampleRender& s, glm::vec3 p) {
    const FrameCamera camera = makeFrameCamera(s.prepared.scene.camera, s.width, s.height);
    const glm::vec4 clip = camera.viewProjection * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * float(s.width), (0.5f - ndc.y * 0.5f) * float(s.height)};
}

// The pixels inside the projection of box [lo, hi], shrunk by `inset` pixels.
struct Rect {
    int x0, y0, x1, y1; // inclusive
};
Rect screenRect(const SampleRender& s, glm::vec3 lo, glm::vec3 hi, int inset) {
    glm::vec2 a(1e30f), b(-1e30f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        const glm::vec2 p = project(s, corner);
        a = glm::min(a, p);
        b = glm::max(b, p);
    }
    return {int(std::ceil(a.x)) + inset, int(std::ceil(a.y)) + inset,
            int(std::floor(b.x)) - 1 - inset, int(std::floor(b.y)) - 1 - inset};
}

// Pixels of `rect` whose sRGB colour passes `test`.
template <typename Test> int countPixels(const SampleRender& s, const Rect& rect, Test test) {
    int n = 0;
    for (int y = std::max(rect.y0, 0); y <= std::min(rect.y1, s.height - 1); ++y)
        for (int x = std::max(rect.x0, 0); x <= std::min(rect.x1, s.width - 1); ++x) {
            const std::uint8_t* c = s.display.at(x, y);
            n += test(int(c[0]), int(c[1]), int(c[2])) ? 1 : 0;
        }
    return n;
}

bool isRed(int r, int g, int b) {
    return r > 140 && g < 90 && b < 90;
}
bool isGreen(int r, int g, int b) {
    return g > 140 && r < 100 && b < 100;
}
bool isBlue(int r, int g, int b) {
    return b > 140 && r < 90 && g < 90;
}
// The colours of the X marks an ignored COLOR_0 leaves visible (cyan, magenta, yellow).
bool isSecondary(int r, int g, int b) {
    const int hi = 130, lo = 100;
    return (g > hi && b > hi && r < lo) || (r > hi && b > hi && g < lo) ||
           (r > hi && g > hi && b < lo);
}

} // namespace

TEST(GltfSamples, VertexColorTestShowsCleanChecks) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    const auto s = renderSample("VertexColorTest.gltf", 96, 96);
    ASSERT_TRUE(s);
    const auto [lo, hi] = materialBounds(assetOf(*s), "VC_Checks_Mat");
    const Rect rect = screenRect(*s, lo, hi, 1);
    const int red = countPixels(*s, rect, isRed), green = countPixels(*s, rect, isGreen),
              blue = countPixels(*s, rect, isBlue), xs = countPixels(*s, rect, isSecondary);
    EXPECT_GT(red, 20);
    EXPECT_GT(green, 20);
    EXPECT_GT(blue, 20);
    EXPECT_EQ(xs, 0) << "cyan, magenta or yellow X marks: COLOR_0 ignored";
    expectNoGlErrors();
}

TEST(GltfSamples, TextureSettingsTestCullsSingleSidedBackFaces) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    const auto s = renderSample("TextureSettingsTest.gltf", 160, 160);
    ASSERT_TRUE(s);
    for (const char* material : {"SingleSidedMaterial", "DoubleSidedMaterial"}) {
        const auto [lo, hi] = materialBounds(assetOf(*s), material);
        const Rect rect = screenRect(*s, lo, hi, 0);
        // Red-dominant pixels: only the X is red (the checks are green, the board blue).
        EXPECT_EQ(
            countPixels(*s, rect,
                        [](int r, int g, int b) { return r > 100 && r > g + 40 && r > b + 40; }),
            0)
            << material << ": a red X";
        EXPECT_GT(rect.x1 - rect.x0, 2) << material << ": the cell is not in view";
    }
    expectNoGlErrors();
}

namespace {

// Whether a display pixel shows one of AlphaBlendModeTest's green / blue stripes rather than
// the grey marble behind the panels.
bool isStripe(const std::uint8_t* c) {
    return std::max(int(c[1]), int(c[2])) - int(c[0]) > 15;
}

} // namespace

TEST(GltfSamples, AlphaBlendModeTestMaskPanelsEndAtTheirCutoffs) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    const auto s = renderSample("AlphaBlendModeTest.gltf", 192, 80);
    ASSERT_TRUE(s);
    // Each MASK panel's alpha falls from 1 at the bottom to 0 at the top: it must show stripes
    // up to 1 - cutoff of its height and the marble above.
    for (const auto& [material, cutoff] :
         {std::pair{"MatCutoff25", 0.25f}, {"MatCutoffDefault", 0.5f}, {"MatCutoff75", 0.75f}}) {
        const auto [lo, hi] = tallestBounds(assetOf(*s), material);
        const float x = 0.5f * (lo.x + hi.x);
        float top = 0.0f; // the highest height fraction showing a stripe
        int samples = 0;
        for (float f = 0.02f; f < 0.99f; f += 0.02f) {
            const glm::vec2 p = project(*s, {x, lo.y + f * (hi.y - lo.y), hi.z});
            if (isStripe(s->display.at(int(p.x), int(p.y)))) top = f;
            ++samples;
        }
        EXPECT_NEAR(top, 1.0f - cutoff, 0.07f) << material;
    }
    // The OPAQUE panel shows its stripes to the top; the BLEND panel is see-through: near its
    // top, where the alpha ramp is low, the marble shows through.
    for (const auto& [material, stripesAtTop] :
         {std::pair{"MatOpaque", true}, {"MatBlend", false}}) {
        const auto [lo, hi] = tallestBounds(assetOf(*s), material);
        const glm::vec2 p = project(*s, {0.5f * (lo.x + hi.x), lo.y + 0.93f * (hi.y - lo.y), hi.z});
        EXPECT_EQ(isStripe(s->display.at(int(p.x), int(p.y))), stripesAtTop) << material;
    }
    expectNoGlErrors();
}

namespace {

// Texel (x, y) of `image` at texture coordinate uv, clamped to the edge (the sample's sampler).
const std::uint8_t* texelAt(const Image& image, glm::vec2 uv) {
    const int x = std::clamp(int(std::floor(uv.x * float(image.width))), 0, image.width - 1);
    const int y = std::clamp(int(std::floor(uv.y * float(image.height))), 0, image.height - 1);
    return &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
}

int luminance(const std::uint8_t* c) {
    return (2 * int(c[0]) + 5 * int(c[1]) + int(c[2])) / 8;
}

// For a panel drawn with `material` (a planar quad): among the sample points where the texel
// that `transform` maps the texture coordinate to and the texel without the transform are of
// opposite kinds (dark and bright, each in its whole neighbourhood), the share where the
// rendered pixel is of the transformed kind. An ignored transform gives about 0.
double panelAgreement(const SampleRender& s, const std::string& material,
                      const TextureTransform& transform, int& points) {
    const MeshAsset& asset = assetOf(s);
    const int m = materialIndex(asset, material);
    const MeshPrimitive* quad = nullptr;
    for (const MeshPrimitive& p : asset.primitives)
        if (p.material == m) quad = &p;
    points = 0;
    if (!quad || quad->vertices.size() < 3) {
        ADD_FAILURE() << material << ": no quad";
        return 0.0;
    }
    const Image& image =
        asset.images.at(std::size_t(asset.materials[std::size_t(m)].baseColorTexture.image));
    // uv as an affine function of (x, y) on the quad, from three of its corners.
    const MeshVertex &a = quad->vertices[0], &b = quad->vertices[1], &c = quad->vertices[2];
    const glm::mat2 xy(glm::vec2(b.position - a.position), glm::vec2(c.position - a.position));
    const glm::mat2 uv(b.uv - a.uv, c.uv - a.uv);
    const glm::mat2 toUv = uv * glm::inverse(xy);
    const auto [lo, hi] = materialBounds(asset, material);
    // The texels within about a pixel's footprint (the panel is some 50 pixels wide).
    const float reach = (hi.x - lo.x) / 50.0f;
    // 1: all bright, -1: all dark, 0: mixed.
    const auto kind = [&](glm::vec3 p, const TextureTransform& t) {
        bool dark = true, bright = true;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const glm::vec2 q = glm::vec2(p) + reach * glm::vec2(dx, dy);
                const int l =
                    luminance(texelAt(image, t.apply(a.uv + toUv * (q - glm::vec2(a.position)))));
                dark = dark && l < 70;
                bright = bright && l > 180;
            }
        return bright ? 1 : dark ? -1 : 0;
    };
    int agree = 0;
    for (float fy = 0.05f; fy < 0.96f; fy += 0.02f)
        for (float fx = 0.05f; fx < 0.96f; fx += 0.02f) {
            const glm::vec3 p(lo.x + fx * (hi.x - lo.x), lo.y + fy * (hi.y - lo.y), hi.z);
            const int expected = kind(p, transform), untransformed = kind(p, TextureTransform{});
            if (expected == 0 || untransformed == 0 || expected == untransformed) continue;
            const glm::vec2 pixel = project(s, p);
            const int l = luminance(s.display.at(int(pixel.x), int(pixel.y)));
            agree += (expected > 0 ? l > 120 : l < 90) ? 1 : 0;
            ++points;
        }
    return points > 0 ? double(agree) / double(points) : 0.0;
}

} // namespace

TEST(GltfSamples, TextureTransformTestPanelsShowTheirTransformedTextures) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    const auto s = renderSample("TextureTransformTest.gltf", 192, 128);
    ASSERT_TRUE(s);
    const MeshAsset& asset = assetOf(*s);
    // The arrow panels (black on white); the offset panels are checked on a file of the test's
    // own (tests/gpu/test_gltf_features.cpp).
    for (const char* material : {"Rotation", "Scale", "All"}) {
        const TextureTransform& transform =
            asset.materials[std::size_t(materialIndex(asset, material))].baseColorTexture.transform;
        int points = 0;
        const double agreement = panelAgreement(*s, material, transform, points);
        EXPECT_GE(points, 8) << material;
        EXPECT_GT(agreement, 0.8) << material << " (" << points << " points)";
    }
    expectNoGlErrors();
}

TEST(GltfSamples, NormalTangentMirrorTestGoldIsLitByTheStudioSky) {
    RMSC_REQUIRE_GLTF_SAMPLES();
    const auto s = renderSample("NormalTangentMirrorTest.gltf", 96, 48);
    ASSERT_TRUE(s);
    // The right half of the model is gold metal: with no environment it reflects nothing and
    // renders near-black; under the studio sky it is bright and yellow.
    const MeshAsset& asset = assetOf(*s);
    const float middle = 0.5f * (asset.boundsMin.x + asset.boundsMax.x);
    const int split = int(
        project(*s, {middle, 0.5f * (asset.boundsMin.y + asset.boundsMax.y), asset.boundsMax.z}).x);
    long sum[3] = {0, 0, 0};
    int count = 0;
    for (int y = 0; y < s->height; ++y)
        for (int x = split + 2; x < s->width; ++x)
            if (s->ids.at(x, y)[0] != 0) {
                for (int c = 0; c < 3; ++c)
                    sum[c] += s->display.at(x, y)[c];
                ++count;
            }
    ASSERT_GT(count, 100);
    const double r = double(sum[0]) / count, b = double(sum[2]) / count;
    EXPECT_GT(r, 90.0) << "the gold half is dark";
    EXPECT_GT(r, b + 30.0) << "the gold half is not yellow";
    expectNoGlErrors();
}
