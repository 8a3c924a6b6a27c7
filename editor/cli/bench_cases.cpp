#include "cli/bench_cases.h"

#include <algorithm>

namespace grass::cli {

Result<std::vector<const BenchCase*>> selectCases(const std::string& list, bool quick) {
    std::vector<const BenchCase*> chosen;
    std::string known;
    for (const BenchCase& c : BENCH_CASES)
        known += (known.empty() ? "" : ", ") + std::string(c.name);
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        start = comma + 1;
        const auto found = std::find_if(BENCH_CASES.begin(), BENCH_CASES.end(),
                                        [&](const BenchCase& c) { return name == c.name; });
        if (found == BENCH_CASES.end())
            return makeError("--cases", "unknown case \"" + name + "\" (cases: " + known + ")");
        if (std::find(chosen.begin(), chosen.end(), &*found) != chosen.end())
            return makeError("--cases", "case \"" + name + "\" given twice");
        if (!quick || !isLargeCase(*found))
            chosen.push_back(&*found);
    }
    if (chosen.empty())
        return makeError("--quick",
                         "leaves none of the --cases (--quick runs only the cases of "
                         "100k blades or fewer)");
    return chosen;
}

}  // namespace grass::cli
