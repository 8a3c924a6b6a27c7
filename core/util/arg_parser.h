// ArgParser: the command-line options of one sub-command, with --help generated from the same
// table that parses, so help and behaviour cannot drift. Bad values give one line naming the
// option, the allowed range and what was given: "--width: expected an integer from 1 to 16384,
// got 'abc'".
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass {

class ArgParser {
public:
    ArgParser(std::string usage, std::string summary);

    void flag(const std::string& name, const std::string& help, bool* out);
    void integer(const std::string& name, const std::string& help, int* out, int min, int max);
    // A finite number in [min, max]; `defaultText` is shown in --help ("the project's").
    void number(const std::string& name, const std::string& metavar, const std::string& help,
                double* out, double min, double max, const std::string& defaultText);
    void unsignedInteger(const std::string& name, const std::string& help, std::uint64_t* out);
    void text(const std::string& name, const std::string& metavar, const std::string& help,
              std::string* out);
    // One-of: the value must be one of `choices`.
    void choice(const std::string& name, const std::vector<std::string>& choices,
                const std::string& help, std::string* out);
    // Positional arguments in order; `required` ones must be given.
    void positional(const std::string& name, const std::string& help, std::string* out,
                    bool required);

    // False result = an error to print; `helpRequested()` true = print help() and exit 0.
    Result<void> parse(const std::vector<std::string>& args);
    bool helpRequested() const { return mHelp; }
    std::string help() const;
    // Options the user actually gave (for "--x only applies with --y" checks).
    bool given(const std::string& name) const;

private:
    struct Option {
        std::string name, metavar, help;
        bool takesValue;
        std::function<Result<void>(const std::string&)> apply;
    };
    struct Positional {
        std::string name, help;
        std::string* out;
        bool required;
    };
    std::string mUsage, mSummary;
    std::vector<Option> mOptions;
    std::vector<Positional> mPositionals;
    std::vector<std::string> mGiven;
    bool mHelp = false;
};

}  // namespace grass
