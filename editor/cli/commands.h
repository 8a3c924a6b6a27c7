// The sub-commands of `grass`. Each takes its arguments (after the sub-command name), prints
// errors as one line "grass <command>: <file or option>: <problem>" and returns the exit code.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass::cli {

int runRender(const std::vector<std::string>& args);
int runSim(const std::vector<std::string>& args);
int runMeshInfo(const std::vector<std::string>& args);
int runPaint(const std::vector<std::string>& args);
int runExport(const std::vector<std::string>& args);
int runBench(const std::vector<std::string>& args);
int runTradeoff(const std::vector<std::string>& args);
int runPresets(const std::vector<std::string>& args);
int runSoak(const std::vector<std::string>& args);

// Exit codes: 0 success, 1 failed (bad file, GL failure), 2 bad command line.
inline constexpr int EXIT_FAILED = 1;
inline constexpr int EXIT_USAGE = 2;

// Prints "grass <command>: <message>" on stderr.
void printError(const std::string& command, const std::string& message);
// Prints `error` as printError does and returns `exitCode`, so a failed step of a command ends
// it in one line: `return reportFailure("sim", run.error(), EXIT_FAILED);`.
int reportFailure(const std::string& command, const Error& error, int exitCode);
// Prints each note as "note: <note>" on stderr: what a loader or builder chose for the user
// (a default, a fallback) that is not an error.
void printNotes(const std::vector<std::string>& notes);
// A build's stages (core::BuildProgress) as notes on stderr, "note: reading ground.glb ...", for
// the commands that grow a field: a large mesh's read and growing took seconds in silence.
std::function<void(const std::string&)> buildProgressNotes();

}  // namespace grass::cli
