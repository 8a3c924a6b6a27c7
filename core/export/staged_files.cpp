#include "export/staged_files.h"

#include <system_error>

#include "util/atomic_file.h"

namespace grass::core {

namespace fs = std::filesystem;

StagedFiles::~StagedFiles() {
    std::error_code ignored;
    for (const Staged& staged : mStaged)
        fs::remove(staged.temporary, ignored);
}

// A folder (or anything but a file) where a file must go would make its rename fail half way
// through the commit, after other files were already replaced: refuse it before writing.
Result<void> StagedFiles::checkTarget(const fs::path& target) const {
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(target, ec);
    if (fs::exists(status) && !fs::is_regular_file(status))
        return makeError(target.string(),
                         "exists and is not a file (remove it or export to "
                         "another folder)");
    if (auto refused = refuseOverwritingInput(mProtected, target, "outDir"); !refused)
        return refused;
    for (const Staged& staged : mStaged)
        if (staged.target == target)
            return makeError(target.string(), "written twice by one export (a bug)");
    return {};
}

Result<void> StagedFiles::add(const std::string& name, std::string_view bytes) {
    const fs::path target = mFolder / name;
    if (auto checked = checkTarget(target); !checked)
        return checked.error();
    const fs::path temporary = temporaryPathFor(target);
    if (auto written = writeFileAtomic(temporary, bytes); !written)
        return makeError(target.string(), written.error().message);
    mStaged.push_back({temporary, target});
    return {};
}

Result<void> StagedFiles::addPng(const std::string& name, const MapImage& map) {
    const fs::path target = mFolder / name;
    if (auto checked = checkTarget(target); !checked)
        return checked.error();
    const fs::path temporary = temporaryPathFor(target);
    if (auto saved = saveMapImage(map, temporary, MapSampleFormat::UInt16); !saved)
        return makeError(target.string(), saved.error().message);
    mStaged.push_back({temporary, target});
    return {};
}

Result<std::vector<ExportedFile>> StagedFiles::commit() {
    std::vector<ExportedFile> files;
    for (const Staged& staged : mStaged) {
        std::error_code ec;
        const auto bytes = fs::file_size(staged.temporary, ec);
        if (auto committed = commitTemporaryFile(staged.temporary, staged.target); !committed)
            return committed.error();
        files.push_back({staged.target, ec ? 0 : static_cast<std::uint64_t>(bytes)});
    }
    mStaged.clear();
    return files;
}

}  // namespace grass::core
