// The files a command writes when asked (sim and soak --report, render --stats, bench --out):
// tried for writing before the work, so a bad path fails at once instead of after a long run,
// and written atomically after it, each announced on stdout as "wrote <file>". An empty file
// name is an output not asked for: nothing to check or write.
#pragma once

#include <string>
#include <string_view>

#include "util/result.h"

namespace grass::cli {

// Fails when `file` cannot be written; the error names `option` ("--report: ...").
// `example` is a file name the error may suggest ("report.json").
Result<void> checkOutputWritable(const std::string& file, const std::string& option,
                                 std::string_view example);

// Writes `text` to `file` atomically and prints "wrote <file>".
Result<void> writeOutputFile(const std::string& file, const std::string& text);

}  // namespace grass::cli
