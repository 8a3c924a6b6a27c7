#include "util/arg_parser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "util/nearest_name.h"

namespace grass {

ArgParser::ArgParser(std::string usage, std::string summary)
    : mUsage(std::move(usage)), mSummary(std::move(summary)) {}

void ArgParser::flag(const std::string& name, const std::string& help, bool* out) {
    mOptions.push_back({name, "", help, false, [out](const std::string&) -> Result<void> {
                            *out = true;
                            return {};
                        }});
}

void ArgParser::integer(const std::string& name, const std::string& help, int* out, int min,
                        int max) {
    const std::string range =
        "an integer from " + std::to_string(min) + " to " + std::to_string(max);
    mOptions.push_back(
        {name, "N",
         help + " (" + std::to_string(min) + ".." + std::to_string(max) + ", default " +
             std::to_string(*out) + ")",
         true, [=](const std::string& value) -> Result<void> {
             long long parsed = 0;
             const char* end = value.data() + value.size();
             const auto [ptr, ec] = std::from_chars(value.data(), end, parsed);
             if (ec != std::errc() || ptr != end || value.empty() || parsed < min || parsed > max)
                 return makeError(name, "expected " + range + ", got '" + value + "'");
             *out = static_cast<int>(parsed);
             return {};
         }});
}

void ArgParser::number(const std::string& name, const std::string& metavar, const std::string& help,
                       double* out, double min, double max, const std::string& defaultText) {
    char range[96];
    std::snprintf(range, sizeof range, "a number from %g to %g", min, max);
    mOptions.push_back({name, metavar, help + " (" + range + ", default " + defaultText + ")", true,
                        [=, range = std::string(range)](const std::string& value) -> Result<void> {
                            double parsed = 0.0;
                            const char* end = value.data() + value.size();
                            const auto [ptr, ec] = std::from_chars(value.data(), end, parsed);
                            if (ec != std::errc() || ptr != end || value.empty() ||
                                !std::isfinite(parsed) || parsed < min || parsed > max)
                                return makeError(name,
                                                 "expected " + range + ", got '" + value + "'");
                            *out = parsed;
                            return {};
                        }});
}

void ArgParser::unsignedInteger(const std::string& name, const std::string& help,
                                std::uint64_t* out) {
    mOptions.push_back({name, "N", help + " (default " + std::to_string(*out) + ")", true,
                        [=](const std::string& value) -> Result<void> {
                            std::uint64_t parsed = 0;
                            const char* end = value.data() + value.size();
                            const auto [ptr, ec] = std::from_chars(value.data(), end, parsed);
                            if (ec != std::errc() || ptr != end || value.empty())
                                return makeError(
                                    name, "expected a non-negative integer, got '" + value + "'");
                            *out = parsed;
                            return {};
                        }});
}

void ArgParser::text(const std::string& name, const std::string& metavar, const std::string& help,
                     std::string* out) {
    mOptions.push_back({name, metavar, help, true, [=](const std::string& value) -> Result<void> {
                            if (value.empty())
                                return makeError(name, "expected " + metavar + ", got nothing");
                            *out = value;
                            return {};
                        }});
}

void ArgParser::choice(const std::string& name, const std::vector<std::string>& choices,
                       const std::string& help, std::string* out) {
    std::string list;
    for (const auto& c : choices)
        list += (list.empty() ? "" : "|") + c;
    mOptions.push_back({name, list, help + " (default " + *out + ")", true,
                        [=](const std::string& value) -> Result<void> {
                            if (std::find(choices.begin(), choices.end(), value) == choices.end())
                                return makeError(
                                    name, "expected one of " + list + ", got '" + value + "'");
                            *out = value;
                            return {};
                        }});
}

void ArgParser::positional(const std::string& name, const std::string& help, std::string* out,
                           bool required) {
    mPositionals.push_back({name, help, out, required});
}

bool ArgParser::given(const std::string& name) const {
    return std::find(mGiven.begin(), mGiven.end(), name) != mGiven.end();
}

Result<void> ArgParser::parse(const std::vector<std::string>& args) {
    std::size_t nextPositional = 0;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string arg = args[i];
        if (arg == "--help" || arg == "-h") {
            mHelp = true;
            return {};
        }
        if (arg.rfind("--", 0) == 0 && arg.size() > 2) {
            std::string value;
            bool inlineValue = false;
            if (const auto eq = arg.find('='); eq != std::string::npos) {
                value = arg.substr(eq + 1);
                arg = arg.substr(0, eq);
                inlineValue = true;
            }
            const auto option = std::find_if(mOptions.begin(), mOptions.end(),
                                             [&](const Option& o) { return o.name == arg; });
            if (option == mOptions.end()) {
                std::vector<std::string_view> names;
                for (const Option& o : mOptions)
                    names.push_back(o.name);
                const std::optional<std::string_view> meant = core::closestMatch(arg, names);
                return makeError(arg,
                                 "unknown option" +
                                     (meant ? "; did you mean " + std::string(*meant) + "?" : "") +
                                     " (see --help)");
            }
            if (option->takesValue && !inlineValue) {
                if (i + 1 >= args.size())
                    return makeError(arg, "needs a value: " + arg + " " + option->metavar);
                value = args[++i];
            } else if (!option->takesValue && inlineValue) {
                return makeError(arg, "takes no value");
            }
            if (auto applied = option->apply(value); !applied)
                return applied;
            mGiven.push_back(arg);
            continue;
        }
        if (nextPositional >= mPositionals.size())
            return makeError(arg, "unexpected argument (see --help)");
        *mPositionals[nextPositional++].out = arg;
        mGiven.push_back(mPositionals[nextPositional - 1].name);
    }
    for (const auto& p : mPositionals)
        if (p.required && !given(p.name))
            return makeError(p.name, "missing: give " + p.help + " (usage: " + mUsage + ")");
    return {};
}

std::string ArgParser::help() const {
    std::string text = "usage: " + mUsage + "\n\n" + mSummary + "\n";
    if (!mPositionals.empty()) {
        text += "\narguments:\n";
        for (const auto& p : mPositionals)
            text += "  " + p.name + "\n      " + p.help + "\n";
    }
    text += "\noptions:\n";
    for (const auto& o : mOptions)
        text +=
            "  " + o.name + (o.metavar.empty() ? "" : " " + o.metavar) + "\n      " + o.help + "\n";
    text += "  --help\n      show this help and exit\n";
    return text;
}

}  // namespace grass
