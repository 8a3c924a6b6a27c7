// The first step of every sub-command: its command line read by its ArgParser, with the two ways
// the command can end there (a bad option, or --help) handled the same way everywhere.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "util/arg_parser.h"

namespace grass::cli {

// Parses `argv` into the parser's outputs. Returns the exit code when the command ends here:
// EXIT_USAGE after printing the parse error as "grass <command>: ...", 0 after printing --help;
// nothing when the command goes on.
std::optional<int> parseArguments(ArgParser& parser, const std::vector<std::string>& argv,
                                  const std::string& command);

// Registers the positional project argument of the commands that read a project.
void addProjectArgument(ArgParser& parser, std::string* project, bool required);

}  // namespace grass::cli
