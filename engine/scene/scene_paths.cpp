// The path keys of a scene and their rewriting for another folder (see scene_paths.hpp).
#include "scene/scene_paths.hpp"

#include "material_texture_json.hpp"

namespace rmsc {
namespace {

void visitShells(SdfNode& node, const std::function<void(const ScenePath&)>& visit) {
    if (node.shell && node.shell->proxy == ShellProxy::Mesh)
        visit({node.shell->meshFile, node.shell->meshPath, node.shell->pointer});
    for (SdfNode& child : node.children)
        visitShells(child, visit);
}

} // namespace

void forEachScenePath(Scene& scene, const std::function<void(const ScenePath&)>& visit) {
    for (MeshInstance& mesh : scene.meshes)
        visit({mesh.file, mesh.path, mesh.pointer});
    for (Material& material : scene.materials) {
        for (MaterialTexture Material::*member : materialTextureMembers()) {
            MaterialTexture& texture = material.*member;
            if (texture.present()) visit({texture.file, texture.path, texture.pointer});
        }
    }
    static const std::string kSkyPointer = "/environment/sky/file";
    if (scene.environment.sky == SkyType::Image)
        visit({scene.environment.imageFile, scene.environment.imagePath, kSkyPointer});
    if (scene.sdf) visitShells(*scene.sdf, visit);
}

void rebaseScenePaths(Scene& scene, const std::filesystem::path& folder) {
    namespace fs = std::filesystem;
    const fs::path base = fs::absolute(folder).lexically_normal();
    forEachScenePath(scene, [&](const ScenePath& p) {
        if (p.path.empty() || fs::path(p.file).is_absolute()) return;
        // Lexical, as the reader resolves paths (scene folder / file, normalized).
        const fs::path target = fs::absolute(p.path).lexically_normal();
        const fs::path relative = target.lexically_relative(base);
        p.file = (relative.empty() ? target : relative).generic_string();
    });
}

std::filesystem::path resolveScenePath(const Scene& scene, const std::string& file) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path folder =
        scene.file.empty() ? fs::current_path(ec) : fs::absolute(scene.file, ec).parent_path();
    const fs::path named(file);
    return (named.is_absolute() ? named : folder / named).lexically_normal();
}

} // namespace rmsc
