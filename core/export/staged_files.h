// StagedFiles: the files of one export, written under temporary names in the target folder and
// renamed into place together at the end (commit). Until then nothing the reader sees changes;
// a failure, or dropping the object uncommitted, removes every temporary (atomic_file.h).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "export/export.h"
#include "maps/map_image.h"
#include "project/project_inputs.h"
#include "util/result.h"

namespace grass::core {

class StagedFiles {
public:
    explicit StagedFiles(std::filesystem::path folder) : mFolder(std::move(folder)) {}
    ~StagedFiles();
    StagedFiles(const StagedFiles&) = delete;
    StagedFiles& operator=(const StagedFiles&) = delete;

    // Files no target may be (the project's own inputs): staging one of them is refused.
    void protect(std::vector<ProjectInput> inputs) { mProtected = std::move(inputs); }
    // `name` is a plain file name inside the folder; errors name the target file.
    Result<void> add(const std::string& name, std::string_view bytes);
    // A map as a 16-bit greyscale PNG (map_image.h): 1/65535 steps, what the editor saves.
    Result<void> addPng(const std::string& name, const MapImage& map);
    // Renames every staged file into place, in the order staged: stage the files an entry point
    // names before the entry point (content_names.h), so a kill never separates them.
    Result<std::vector<ExportedFile>> commit();

private:
    struct Staged {
        std::filesystem::path temporary, target;
    };
    Result<void> checkTarget(const std::filesystem::path& target) const;

    std::filesystem::path mFolder;
    std::vector<Staged> mStaged;
    std::vector<ProjectInput> mProtected;
};

}  // namespace grass::core
