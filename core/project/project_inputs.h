// The files a project reads, so that no command writes its output over one of them: a report
// given the project's own project.json, a render given its density map, an export whose file
// name equals the project's mesh would each destroy the project and report success.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "project/project.h"
#include "util/result.h"

namespace grass::core {

struct ProjectInput {
    std::filesystem::path real;     // links resolved (util/path_inside.h realPath)
    std::filesystem::path display;  // as the project names it, for messages
    std::string what;               // "the project file", "/layers/0/density_map", ...
};

// project.json, every asset (mesh, maps, billboard texture, collider meshes) and the buffers and
// images a .gltf asset names. Assets that do not exist yet (a map to be painted) are listed too.
std::vector<ProjectInput> projectInputFiles(const LoadedProject& loaded);

// Refuses `output` when it is (links resolved) one of `inputs`; the error names the option, the
// output and the input it would overwrite.
Result<void> refuseOverwritingInput(const std::vector<ProjectInput>& inputs,
                                    const std::filesystem::path& output, const std::string& option);
Result<void> refuseOverwritingInput(const LoadedProject& loaded,
                                    const std::filesystem::path& output, const std::string& option);

}  // namespace grass::core
