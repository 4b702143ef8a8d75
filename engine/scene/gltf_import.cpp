// loadGltf: reads a .gltf or .glb through a FileSource, checks it, lets tinygltf parse it
// with file access confined to the glTF file's folder and images decoded by stb_image, then
// validates the model and bakes its scene into a MeshAsset.
#include "scene/mesh_asset.hpp"

#include "gltf_files.hpp"
#include "gltf_json_checks.hpp"
#include "gltf_unsupported.hpp"
#include "gltf_validate.hpp"
#include "scene/gltf_budget.hpp"
#include "scene/gltf_geometry.hpp"
#include "scene/gltf_report.hpp"
#include "scene/gltf_tinygltf.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <map>
#include <new>
#include <sstream>
#include <string_view>
#include <unordered_map>

namespace rmsc {

namespace {

using gltf::Reporter;

// The base folder handed to tinygltf. It is not a real path: the file callbacks accept only
// paths below it, which also stops tinygltf's fallback search of the current directory.
const std::string kFolderToken = "\x1f"
                                 "gltf-folder";

struct LoadContext {
    const FileSource* files = nullptr;
    std::filesystem::path folder; // of the glTF file, as given
    Reporter* report = nullptr;
    const tinygltf::Model* model = nullptr;            // being filled by tinygltf
    std::map<std::string, std::string> bufferPointers; // resolved file -> "/buffers/i/uri"
    gltf::FileBudget* budget = nullptr;
    // Per image: the first image with the same data (the same resolved URI, data URI or buffer
    // view), which alone is decoded; itself when there is none.
    std::vector<int> imageSource;
};

// Whether image `index` is decoded (the first of those with its data).
bool decodesImage(const LoadContext& context, int index) {
    return index < 0 || std::size_t(index) >= context.imageSource.size() ||
           context.imageSource[std::size_t(index)] == index;
}

// The image's size from its header, taken out of the texel budget before it is decoded.
bool decodeInBudget(const unsigned char* bytes, std::size_t size, LoadContext& context,
                    const std::string& pointer, const std::string& what, Image& out) {
    std::string why;
    const auto stated = gltf::readImageSize(bytes, size, why);
    if (!stated) {
        context.report->error(pointer, what + why);
        return false;
    }
    const std::uint64_t texels = std::uint64_t(stated->width) * std::uint64_t(stated->height);
    gltf::Allowance& budget = context.budget->texels;
    if (!budget.take(texels)) {
        context.report->error(pointer, what + "image is " + std::to_string(stated->width) + "x" +
                                           std::to_string(stated->height) +
                                           ", which brings the file's images to " +
                                           budget.refusal(budget.used + texels));
        return false;
    }
    if (!gltf::decodeImage(bytes, size, out, why)) {
        context.report->error(pointer, what + why);
        return false;
    }
    return true;
}

// The file below the glTF folder that tinygltf asks for, or nullopt for any other path.
std::optional<std::filesystem::path> confinedPath(const std::string& path, std::string& why) {
    const std::string prefix = kFolderToken + "/";
    if (path.rfind(prefix, 0) != 0) {
        why = "outside the glTF file's folder";
        return std::nullopt;
    }
    return gltf::resolveInFolder(std::string_view(path).substr(prefix.size()), why);
}

bool fileExists(const std::string& path, void* user) {
    auto& context = *static_cast<LoadContext*>(user);
    std::string why;
    if (path.rfind(kFolderToken, 0) != 0) return false; // the current-directory fallback
    if (!confinedPath(path, why)) {
        context.report->error("", "refusing to read \"" + path.substr(kFolderToken.size() + 1) +
                                      "\": " + why);
        return false;
    }
    return true; // whether it can be read is found out by readWholeFile
}

std::string expandFilePath(const std::string& path, void*) {
    return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* user) {
    auto& context = *static_cast<LoadContext*>(user);
    std::string why;
    const auto relative = confinedPath(path, why);
    if (relative) {
        // Straight into tinygltf's vector: a copy would hold a 1 GiB buffer twice.
        if (readInsideFolderBytes(*context.files, context.folder, *relative, *out, why))
            return true;
    }
    const std::string name = relative ? relative->generic_string() : path;
    const auto pointer = context.bufferPointers.find(name);
    context.report->error(pointer != context.bufferPointers.end() ? pointer->second : "",
                          "cannot read \"" + name + "\": " + why);
    if (err) *err = why;
    return false;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&,
                    void*) {
    if (err) *err = "rmsc does not write glTF files";
    return false;
}

void storeImage(Image&& decoded, tinygltf::Image& image) {
    image.width = decoded.width;
    image.height = decoded.height;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image = std::move(decoded.rgba);
}

// tinygltf's image callback: embedded (data URI) and buffer view images.
bool loadImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
               const unsigned char* bytes, int size, void* user) {
    auto& context = *static_cast<LoadContext*>(user);
    const std::string pointer = "/images/" + std::to_string(index);
    if (image->bufferView >= 0) {
        const tinygltf::Model& model = *context.model;
        const std::size_t v = std::size_t(image->bufferView);
        bool inside = v < model.bufferViews.size();
        if (inside) {
            const tinygltf::BufferView& view = model.bufferViews[v];
            std::uint64_t end = 0;
            inside = view.buffer >= 0 && std::size_t(view.buffer) < model.buffers.size() &&
                     !__builtin_add_overflow(std::uint64_t(view.byteOffset),
                                             std::uint64_t(view.byteLength), &end) &&
                     end <= model.buffers[std::size_t(view.buffer)].data.size() &&
                     view.byteLength <= std::uint64_t(std::numeric_limits<int>::max());
        }
        if (!inside) {
            context.report->error(pointer + "/bufferView",
                                  "image data lies outside its buffer, expected /bufferViews/" +
                                      std::to_string(v) + " to fit in its buffer");
            return false;
        }
    }
    if (!decodesImage(context, index)) return true; // the same data as an earlier image
    if (size <= 0) {
        context.report->error(pointer, "image data is empty");
        return false;
    }
    Image decoded;
    if (!decodeInBudget(bytes, std::size_t(size), context, pointer, "", decoded)) return false;
    storeImage(std::move(decoded), *image);
    return true;
}

// tinygltf's messages, one diagnostic per line, without the folder token and cut to a
// readable length (they may quote whole data URIs).
void reportTinygltf(const std::string& text, bool asError, Reporter& report) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        for (std::size_t at; (at = line.find(kFolderToken + "/")) != std::string::npos;)
            line.erase(at, kFolderToken.size() + 1);
        if (line.size() > 200) line = line.substr(0, 200) + "...";
        if (line.empty()) continue;
        if (asError)
            report.error("", line);
        else
            report.warning("", "glTF parser: " + line);
    }
}

// External image files, which tinygltf leaves to us (TINYGLTF_NO_EXTERNAL_IMAGE).
bool loadExternalImages(tinygltf::Model& model, LoadContext& context) {
    bool ok = true;
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        tinygltf::Image& image = model.images[i];
        if (!image.image.empty() || image.uri.empty() || gltf::isDataUri(image.uri)) continue;
        if (!decodesImage(context, int(i))) continue; // the same file as an earlier image
        const std::string pointer = "/images/" + std::to_string(i) + "/uri";
        std::string why;
        const auto decoded = gltf::percentDecode(image.uri);
        const auto relative =
            decoded ? gltf::resolveInFolder(*decoded, why) : std::optional<std::filesystem::path>();
        if (!decoded) why = "malformed percent escape in URI";
        std::optional<std::string> bytes;
        if (relative) bytes = readInsideFolder(*context.files, context.folder, *relative, why);
        Image rgba;
        if (!bytes) {
            context.report->error(pointer, "cannot read image \"" + image.uri + "\": " + why);
            ok = false;
        } else if (!decodeInBudget(reinterpret_cast<const unsigned char*>(bytes->data()),
                                   bytes->size(), context, pointer,
                                   "image \"" + image.uri + "\": ", rgba)) {
            ok = false;
        } else {
            storeImage(std::move(rgba), image);
        }
    }
    return ok;
}

// KHR_texture_transform of a textureInfo (values checked by validateModel): its transform,
// and its texCoord in place of the textureInfo's when it has one.
void readTextureTransform(const tinygltf::ExtensionMap& extensions, MeshTextureRef& out,
                          int& texCoord) {
    const auto ext = extensions.find("KHR_texture_transform");
    if (ext == extensions.end() || !ext->second.IsObject()) return;
    const tinygltf::Value& v = ext->second;
    const auto pair = [&](const char* key, glm::vec2& into) {
        if (!v.Has(key)) return;
        const tinygltf::Value& a = v.Get(key);
        if (a.IsArray() && a.ArrayLen() == 2 && a.Get(0).IsNumber() && a.Get(1).IsNumber())
            into =
                glm::vec2(float(a.Get(0).GetNumberAsDouble()), float(a.Get(1).GetNumberAsDouble()));
    };
    pair("offset", out.transform.offset);
    pair("scale", out.transform.scale);
    if (v.Has("rotation") && v.Get("rotation").IsNumber())
        out.transform.rotation = float(v.Get("rotation").GetNumberAsDouble());
    if (v.Has("texCoord") && v.Get("texCoord").IsNumber())
        texCoord = int(v.Get("texCoord").GetNumberAsDouble());
}

// One textureInfo of a material: resolves texture -> image and sampler. Indices were range
// checked on the JSON and by validateModel; what is left here is what rmsc cannot use.
MeshTextureRef convertTexture(const tinygltf::Model& model, const std::vector<int>& imageSlots,
                              int index, int texCoord, const tinygltf::ExtensionMap& extensions,
                              const std::string& pointer, Reporter& report) {
    MeshTextureRef out;
    if (index < 0) return out;
    readTextureTransform(extensions, out, texCoord);
    if (std::size_t(index) >= model.textures.size()) {
        report.error(pointer + "/index", "refers to a texture that does not exist");
        return out;
    }
    const tinygltf::Texture& texture = model.textures[std::size_t(index)];
    if (texture.source < 0 || std::size_t(texture.source) >= model.images.size()) {
        report.warning("/textures/" + std::to_string(index),
                       "texture has no image source rmsc can use (PNG or JPEG); ignored");
        return out;
    }
    if (texCoord != 0 && texCoord != 1) {
        report.warning(pointer + "/texCoord", "TEXCOORD_" + std::to_string(texCoord) +
                                                  " is not supported (only TEXCOORD_0 and "
                                                  "TEXCOORD_1); the texture is ignored");
        return out;
    }
    out.image = imageSlots[std::size_t(texture.source)];
    out.texCoord = texCoord;
    if (texture.sampler >= 0 && std::size_t(texture.sampler) < model.samplers.size()) {
        const tinygltf::Sampler& sampler = model.samplers[std::size_t(texture.sampler)];
        if (sampler.magFilter >= 0) out.sampler.magFilter = sampler.magFilter;
        if (sampler.minFilter >= 0) out.sampler.minFilter = sampler.minFilter;
        out.sampler.wrapS = sampler.wrapS;
        out.sampler.wrapT = sampler.wrapT;
    }
    return out;
}

void convertMaterials(const tinygltf::Model& model, const std::vector<int>& imageSlots,
                      Reporter& report, MeshAsset& asset) {
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& m = model.materials[i];
        const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
        const std::string pointer = "/materials/" + std::to_string(i);
        MeshMaterial out;
        out.name = m.name;
        out.baseColorFactor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1],
                                        pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
        out.metallicFactor = float(pbr.metallicFactor);
        out.roughnessFactor = float(pbr.roughnessFactor);
        out.emissiveFactor =
            glm::vec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
        out.doubleSided = m.doubleSided;
        const auto texture = [&](const auto& info, const std::string& name) {
            return convertTexture(model, imageSlots, info.index, info.texCoord, info.extensions,
                                  pointer + name, report);
        };
        out.baseColorTexture =
            texture(pbr.baseColorTexture, "/pbrMetallicRoughness/baseColorTexture");
        out.metallicRoughnessTexture =
            texture(pbr.metallicRoughnessTexture, "/pbrMetallicRoughness/metallicRoughnessTexture");
        out.normalTexture = texture(m.normalTexture, "/normalTexture");
        out.normalScale = float(m.normalTexture.scale);
        out.emissiveTexture = texture(m.emissiveTexture, "/emissiveTexture");
        out.occlusionTexture = texture(m.occlusionTexture, "/occlusionTexture");
        // glTF 2.0 section 3.9.4 (alpha coverage); the mode was checked by validateModel.
        out.alphaMode = m.alphaMode == "MASK"    ? AlphaMode::Mask
                        : m.alphaMode == "BLEND" ? AlphaMode::Blend
                                                 : AlphaMode::Opaque;
        out.alphaCutoff = float(m.alphaCutoff);
        out.unlit = m.extensions.find("KHR_materials_unlit") != m.extensions.end();
        out.occlusionStrength = float(m.occlusionTexture.strength);
        // KHR_materials_emissive_strength; the value was checked by validateModel.
        if (const auto ext = m.extensions.find("KHR_materials_emissive_strength");
            ext != m.extensions.end() && ext->second.Has("emissiveStrength") &&
            ext->second.Get("emissiveStrength").IsNumber())
            out.emissiveStrength = float(ext->second.Get("emissiveStrength").GetNumberAsDouble());
        asset.materials.push_back(std::move(out));
    }
}

// A GLB holding exactly the chunks we checked, so tinygltf's own GLB reader agrees with ours.
std::string canonicalGlb(const gltf::GlbChunks& chunks) {
    std::string out;
    const auto u32 = [&out](std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            out += char((v >> (8 * i)) & 0xff);
    };
    const std::uint64_t length =
        12 + 8 + chunks.json.size() + (chunks.hasBin ? 8 + chunks.bin.size() : 0);
    out += "glTF";
    u32(2);
    u32(std::uint32_t(length));
    u32(std::uint32_t(chunks.json.size()));
    u32(0x4E4F534A);
    out += chunks.json;
    if (chunks.hasBin) {
        u32(std::uint32_t(chunks.bin.size()));
        u32(0x004E4942);
        out += chunks.bin;
    }
    return out;
}

// Takes every buffer's declared byteLength (checked to be a number by checkGltfJson) out of
// the budget, before tinygltf reads any.
bool budgetBuffers(const nlohmann::json& document, gltf::Allowance& budget, Reporter& report) {
    const auto buffers = document.find("buffers");
    if (buffers == document.end() || !buffers->is_array()) return true;
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        const nlohmann::json& buffer = (*buffers)[i];
        const auto length = buffer.is_object() ? buffer.find("byteLength") : buffer.end();
        if (length == buffer.end() || !length->is_number_unsigned()) continue;
        const std::uint64_t bytes = length->get<std::uint64_t>();
        if (!budget.take(bytes)) {
            const std::uint64_t needed =
                bytes > std::numeric_limits<std::uint64_t>::max() - budget.used
                    ? std::numeric_limits<std::uint64_t>::max()
                    : budget.used + bytes;
            report.error("/buffers/" + std::to_string(i) + "/byteLength",
                         "this buffer brings the file's buffers to " + budget.refusal(needed));
            return false;
        }
    }
    return true;
}

// For each image, the first image with the same data: the same buffer view, the same data URI
// or the same file once resolved in the glTF folder.
std::vector<int> imageSources(const nlohmann::json& document) {
    std::vector<int> sources;
    const auto images = document.find("images");
    if (images == document.end() || !images->is_array()) return sources;
    std::unordered_map<std::string, int> byName;         // "view N", "file <path>"
    std::unordered_map<std::string_view, int> byDataUri; // views into `document`
    for (std::size_t i = 0; i < images->size(); ++i) {
        const nlohmann::json& image = (*images)[i];
        int source = int(i);
        const auto view = image.is_object() ? image.find("bufferView") : image.end();
        const auto uri = image.is_object() ? image.find("uri") : image.end();
        if (view != image.end() && view->is_number_unsigned()) {
            source = byName.try_emplace("view " + view->dump(), int(i)).first->second;
        } else if (uri != image.end() && uri->is_string()) {
            const std::string& text = uri->get_ref<const std::string&>();
            std::string why;
            if (gltf::isDataUri(text)) {
                source = byDataUri.try_emplace(text, int(i)).first->second;
            } else if (const auto decoded = gltf::percentDecode(text)) {
                if (const auto relative = gltf::resolveInFolder(*decoded, why))
                    source = byName.try_emplace("file " + relative->generic_string(), int(i))
                                 .first->second;
            }
        }
        sources.push_back(source);
    }
    return sources;
}

std::optional<MeshAsset> load(const std::filesystem::path& path, const FileSource& files,
                              GltfBudget& sceneBudget, int scene, Reporter& report) {
    std::string why;
    const auto bytes = files.read(path, why);
    if (!bytes) {
        report.error("", "cannot read glTF file: " + why);
        return std::nullopt;
    }
    if (bytes->empty()) {
        report.error("", "file is empty, expected glTF JSON or binary glTF");
        return std::nullopt;
    }
    if (bytes->size() >= std::numeric_limits<std::uint32_t>::max()) {
        report.error("", "file is 4 GiB or larger, more than glTF allows");
        return std::nullopt;
    }
    const bool isGlb = gltf::hasGlbMagic(*bytes);
    gltf::GlbChunks chunks;
    std::string_view jsonText = *bytes;
    if (isGlb) {
        const auto split = gltf::splitGlb(*bytes, why);
        if (!split) {
            report.error("", "invalid binary glTF: " + why);
            return std::nullopt;
        }
        chunks = *split;
        jsonText = chunks.json;
    }
    if (gltf::jsonNestingDepth(jsonText, gltf::kMaxJsonDepth) > gltf::kMaxJsonDepth) {
        report.error("", "JSON is nested more than " + std::to_string(gltf::kMaxJsonDepth) +
                             " levels deep");
        return std::nullopt;
    }
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(jsonText.begin(), jsonText.end());
    } catch (const nlohmann::json::exception& e) {
        report.error("", std::string("invalid JSON: ") + e.what());
        return std::nullopt;
    }
    gltf::JsonCheckInput input;
    input.isGlb = isGlb;
    input.hasBinChunk = chunks.hasBin;
    input.binSize = chunks.bin.size();
    if (!gltf::checkGltfJson(document, input, report)) return std::nullopt;
    gltf::FileBudget budget = gltf::fileBudget(sceneBudget);
    if (!budgetBuffers(document, budget.bufferBytes, report)) return std::nullopt;

    tinygltf::Model model;
    LoadContext context;
    context.files = &files;
    context.folder = path.parent_path();
    context.report = &report;
    context.model = &model;
    context.budget = &budget;
    context.imageSource = imageSources(document);
    if (const auto buffers = document.find("buffers");
        buffers != document.end() && buffers->is_array()) {
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            const nlohmann::json& buffer = (*buffers)[i];
            const auto uri = buffer.is_object() ? buffer.find("uri") : buffer.end();
            if (uri == buffer.end() || !uri->is_string() ||
                gltf::isDataUri(uri->get_ref<const std::string&>()))
                continue;
            const auto decoded = gltf::percentDecode(uri->get_ref<const std::string&>());
            if (const auto relative = gltf::resolveInFolder(decoded.value_or(""), why))
                context.bufferPointers.emplace(relative->generic_string(),
                                               "/buffers/" + std::to_string(i) + "/uri");
        }
    }
    document = nlohmann::json(); // free it before tinygltf parses its own copy

    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(
        {&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, &context});
    loader.SetImageLoader(&loadImage, &context);
    std::string err, warn;
    const int errorsBefore = report.errors;
    bool ok = false;
    try {
        if (isGlb) {
            const std::string glb = canonicalGlb(chunks);
            ok = loader.LoadBinaryFromMemory(&model, &err, &warn,
                                             reinterpret_cast<const unsigned char*>(glb.data()),
                                             unsigned(glb.size()), kFolderToken);
        } else {
            ok = loader.LoadASCIIFromString(&model, &err, &warn, jsonText.data(),
                                            unsigned(jsonText.size()), kFolderToken);
        }
    } catch (const std::exception& e) {
        report.error("", std::string("glTF parser failed: ") + e.what());
        return std::nullopt;
    } catch (...) {
        report.error("", "glTF parser failed with an unknown exception");
        return std::nullopt;
    }
    reportTinygltf(warn, false, report);
    reportTinygltf(err, true, report);
    if (!ok && report.errors == errorsBefore)
        report.error("", "glTF parser failed without saying why");
    if (report.errors > 0) return std::nullopt;

    if (!gltf::validateModel(model, report)) return std::nullopt;
    gltf::warnUnsupportedFeatures(model, report);
    if (!loadExternalImages(model, context)) return std::nullopt;

    MeshAsset asset;
    asset.path = path;
    // One asset image per distinct image; the others use the slot of the first with their data.
    std::vector<int> imageSlots(model.images.size(), -1);
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        if (!decodesImage(context, int(i))) {
            imageSlots[i] = imageSlots[std::size_t(context.imageSource[i])];
            continue;
        }
        tinygltf::Image& image = model.images[i];
        Image out;
        out.width = image.width;
        out.height = image.height;
        out.rgba = std::move(image.image);
        imageSlots[i] = int(asset.images.size());
        asset.images.push_back(std::move(out));
    }
    convertMaterials(model, imageSlots, report, asset);
    if (!gltf::buildGeometry(model, scene, budget.vertices, budget.indices, report, asset))
        return std::nullopt;
    if (report.errors > 0) return std::nullopt;
    sceneBudget.vertices -= budget.vertices.used;
    sceneBudget.indices -= budget.indices.used;
    sceneBudget.texels -= budget.texels.used;
    return asset;
}

} // namespace

std::optional<MeshAsset> loadGltf(const std::filesystem::path& path, const FileSource& files,
                                  Diagnostics& diagnostics) {
    GltfBudget budget;
    return loadGltf(path, files, diagnostics, budget);
}

std::optional<MeshAsset> loadGltf(const std::filesystem::path& path, const FileSource& files,
                                  Diagnostics& diagnostics, GltfBudget& sceneBudget, int scene) {
    Reporter report{path.string(), &diagnostics};
    try {
        return load(path, files, sceneBudget, scene, report);
    } catch (const std::bad_alloc&) {
        report.error("", "out of memory while loading the glTF file");
    } catch (const std::exception& e) {
        report.error("", std::string("unexpected error while loading: ") + e.what());
    } catch (...) {
        report.error("", "unexpected error while loading");
    }
    return std::nullopt;
}

} // namespace rmsc
