// grass bench: the project's standard benchmark set (issue 10, item 4). Each case loads a
// project, scales its layers' densities to a blade count, and measures on one headless GL
// context (bench_measure.cpp); bench_report.cpp prints the table, writes the JSON and compares
// runs. This file is the command line around them.
#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/bench_cases.h"
#include "cli/bench_measure.h"
#include "cli/bench_options.h"
#include "cli/bench_report.h"
#include "cli/commands.h"
#include "cli/output_files.h"
#include "tools/ms_since.h"
#include "util/atomic_file.h"
#include "util/interrupt_stop.h"

namespace grass::cli {

namespace {

using tools::Clock;
using tools::msSince;

// --compare OLD.json, read before anything else (none: nothing to compare with).
Result<std::optional<BenchRun>> readOldRun(const BenchArgs& args) {
    if (args.compare.empty())
        return std::optional<BenchRun>();
    auto read = readBenchRun(args.compare);
    if (!read)
        return read.error();
    return std::optional<BenchRun>(std::move(*read));
}

// Prints the table of `run` and, with --compare, its comparison with the old run.
Result<void> printRun(const BenchArgs& args, const BenchRun& run,
                      const std::optional<BenchRun>& old) {
    printBenchTable(run);
    if (old)
        if (auto compared = printBenchComparison(run, *old, args.compare); !compared)
            return compared;
    return {};
}

// --results: prints a saved run (and its comparison), measures nothing.
int printSavedRun(const BenchArgs& args, const std::optional<BenchRun>& old) {
    if (!args.measuringOption.empty())
        return reportFailure("bench",
                             makeError(args.measuringOption,
                                       "not with --results, which prints a saved run "
                                       "and measures nothing"),
                             EXIT_USAGE);
    auto saved = readBenchRun(args.results);
    if (!saved)
        return reportFailure("bench", saved.error(), EXIT_FAILED);
    if (auto printed = printRun(args, *saved, old); !printed)
        return reportFailure("bench", printed.error(), EXIT_FAILED);
    return 0;
}

// The cases to measure, each project there under --root, and --out writable: refuted before
// minutes of measuring.
Result<std::vector<const BenchCase*>> chooseCases(const BenchArgs& args) {
    auto cases = selectCases(args.cases, args.quick);
    if (!cases)
        return cases;
    for (const BenchCase* c : *cases)
        if (const auto project = std::filesystem::path(args.root) / c->project;
            !std::filesystem::exists(project))
            return makeError("--root", project.string() +
                                           ": no such project (--root names the folder "
                                           "holding projects/ and tests/data/)");
    if (!args.out.empty())
        if (auto writable = checkFileWritable(args.out, "bench.json"); !writable)
            return writable.error();
    return cases;
}

// A file that cannot be compared fails now, not after minutes of measuring.
Result<void> checkOldComparable(const BenchArgs& args, const std::optional<BenchRun>& old,
                                const std::vector<const BenchCase*>& cases) {
    if (!old)
        return {};
    std::vector<std::string> names;
    for (const BenchCase* c : cases)
        names.emplace_back(c->name);
    return checkComparable(*old, args.compare, names, args.width, args.height);
}

}  // namespace

int runBench(const std::vector<std::string>& argv) {
    BenchArgs args;
    if (const auto exitCode = parseBenchArgs(argv, args))
        return *exitCode;
    const auto old = readOldRun(args);
    if (!old)
        return reportFailure("bench", old.error(), EXIT_FAILED);
    if (!args.results.empty())
        return printSavedRun(args, *old);
    const auto cases = chooseCases(args);
    if (!cases)
        return reportFailure("bench", cases.error(), EXIT_USAGE);
    if (auto comparable = checkOldComparable(args, *old, *cases); !comparable)
        return reportFailure("bench", comparable.error(), EXIT_FAILED);

    const auto start = Clock::now();
    // Ctrl+C ends the run after the case under way; the cases measured are printed and saved.
    const core::InterruptStop interrupt;
    auto run = measureRun(args, *cases, interrupt.token());
    if (!run)
        return reportFailure("bench", run.error(), EXIT_FAILED);
    if (auto printed = printRun(args, *run, *old); !printed)
        return reportFailure("bench", printed.error(), EXIT_FAILED);
    std::printf("wall time %.1f s for %zu case(s)\n", msSince(start) / 1000.0, run->cases.size());
    if (auto written = writeOutputFile(args.out, benchRunJson(*run)); !written)
        return reportFailure("bench", written.error(), EXIT_FAILED);
    return interrupt.exitCodeOr(0);
}

}  // namespace grass::cli
