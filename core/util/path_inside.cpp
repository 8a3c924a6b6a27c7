#include "util/path_inside.h"

#include <system_error>

namespace grass {

namespace fs = std::filesystem;

namespace {

// Enough for any real chain of links; a loop ends here instead of running for ever.
constexpr int MAX_LINKS = 40;

fs::path realPath(const fs::path& path, int linksLeft) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec).lexically_normal();
    if (ec)
        return path.lexically_normal();
    // The longest part that exists (links followed); the first missing part may still be a
    // dangling link, which a write would follow: it is resolved too.
    fs::path existing = absolute.root_path();
    auto part = absolute.begin();
    for (++part; part != absolute.end(); ++part) {
        const fs::path next = existing / *part;
        if (fs::exists(next, ec)) {
            existing = next;
            continue;
        }
        if (linksLeft > 0 && fs::is_symlink(fs::symlink_status(next, ec))) {
            const fs::path target = fs::read_symlink(next, ec);
            if (!ec) {
                fs::path rest = target.is_absolute() ? target : existing / target;
                for (++part; part != absolute.end(); ++part)
                    rest /= *part;
                return realPath(rest, linksLeft - 1);
            }
        }
        break;
    }
    fs::path real = fs::weakly_canonical(absolute, ec);
    return ec ? absolute : real;
}

}  // namespace

fs::path realPath(const fs::path& path) {
    return realPath(path, MAX_LINKS);
}

bool isInsideFolder(const fs::path& path, const fs::path& folder) {
    const fs::path relative = realPath(path).lexically_relative(realPath(folder));
    return !relative.empty() && *relative.begin() != "..";
}

}  // namespace grass
