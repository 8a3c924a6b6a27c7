#include "cli/output_files.h"

#include <cstdio>

#include "util/atomic_file.h"

namespace grass::cli {

Result<void> checkOutputWritable(const std::string& file, const std::string& option,
                                 std::string_view example) {
    if (file.empty())
        return {};
    if (auto writable = checkFileWritable(file, example); !writable)
        return makeError(option, writable.error().str());
    return {};
}

Result<void> writeOutputFile(const std::string& file, const std::string& text) {
    if (file.empty())
        return {};
    if (auto written = writeFileAtomic(file, text); !written)
        return written;
    std::printf("wrote %s\n", file.c_str());
    return {};
}

}  // namespace grass::cli
