#include "cli/parse_arguments.h"

#include <cstdio>

#include "cli/commands.h"

namespace grass::cli {

std::optional<int> parseArguments(ArgParser& parser, const std::vector<std::string>& argv,
                                  const std::string& command) {
    if (auto parsed = parser.parse(argv); !parsed) {
        printError(command, parsed.error().str());
        return EXIT_USAGE;
    }
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    return std::nullopt;
}

void addProjectArgument(ArgParser& parser, std::string* project, bool required) {
    parser.positional("project", "a project folder (with project.json) or a project .json file",
                      project, required);
}

}  // namespace grass::cli
