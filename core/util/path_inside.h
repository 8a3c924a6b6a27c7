// Where a file really is: projects and glTF files read and write only under their own folder,
// after symbolic links are resolved (docs/reliability.md, "Paths").
#pragma once

#include <filesystem>

namespace grass {

// `path` with every symbolic link of its existing part resolved, made absolute; the part that
// does not exist yet is kept as written (std::filesystem::weakly_canonical). On an error (a
// loop of links): the absolute, lexically normal path.
std::filesystem::path realPath(const std::filesystem::path& path);

// True when `path`, links resolved, lies inside `folder` (links resolved) or is `folder`.
bool isInsideFolder(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace grass
