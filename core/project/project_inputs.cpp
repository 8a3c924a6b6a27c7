#include "project/project_inputs.h"

#include "mesh/gltf_loader.h"
#include "util/file_extension.h"
#include "util/path_inside.h"

namespace grass::core {

namespace fs = std::filesystem;

namespace {

bool isGltfText(const fs::path& file) {
    return lowerExtension(file) == ".gltf";
}

}  // namespace

std::vector<ProjectInput> projectInputFiles(const LoadedProject& loaded) {
    std::vector<ProjectInput> inputs;
    const auto add = [&](const fs::path& file, const std::string& what) {
        inputs.push_back({realPath(file), file, what});
    };
    add(loaded.file, "the project file");
    const Project& project = loaded.project;
    const auto addAsset = [&](const std::string& relative, const std::string& field) {
        if (relative.empty())
            return;
        auto file = resolveAssetPath(loaded.folder, relative, field);
        if (!file)
            return;  // loading the scene refuses it with its reason
        add(*file, field);
        if (isGltfText(*file))
            for (const fs::path& part : gltfExternalFiles(*file))
                add(part, field + " (a file it names)");
    };
    if (project.mesh.isFile)
        addAsset(project.mesh.file, "/mesh/file");
    for (std::size_t i = 0; i < project.layers.size(); ++i) {
        const std::string at = "/layers/" + std::to_string(i) + "/";
        addAsset(project.layers[i].densityMap, at + "density_map");
        addAsset(project.layers[i].soilMap, at + "soil_map");
        addAsset(project.layers[i].lightMap, at + "light_map");
        addAsset(project.layers[i].cutMap, at + "cut_map");
    }
    addAsset(project.billboards.texture, "/billboards/texture");
    for (std::size_t i = 0; i < project.colliders.size(); ++i)
        if (project.colliders[i].shape == ColliderShape::Mesh)
            addAsset(project.colliders[i].file, "/colliders/" + std::to_string(i) + "/file");
    return inputs;
}

Result<void> refuseOverwritingInput(const std::vector<ProjectInput>& inputs, const fs::path& output,
                                    const std::string& option) {
    const fs::path real = realPath(output);
    for (const ProjectInput& input : inputs)
        if (input.real == real)
            return makeError(
                option, output.string() + " is " +
                            (input.what == "the project file" ? std::string("the project file")
                                                              : "the project's " + input.what) +
                            " (" + input.display.string() +
                            "); writing there would destroy the project: choose "
                            "another file name or folder");
    return {};
}

Result<void> refuseOverwritingInput(const LoadedProject& loaded, const fs::path& output,
                                    const std::string& option) {
    return refuseOverwritingInput(projectInputFiles(loaded), output, option);
}

}  // namespace grass::core
