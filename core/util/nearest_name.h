// "Did you mean …?" for a mistyped command or option: the known name nearest to what was typed,
// when it is near enough to be the one meant (a letter or two off, or two letters swapped).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace grass::core {

// Edits (insert, delete, replace, swap two neighbours) from `a` to `b`, case-insensitive.
std::size_t editDistance(std::string_view a, std::string_view b);

// The name of `names` fewest edits from `typed`, if at most 1 edit for names up to 4 characters
// and 2 beyond; the first of equals. Never `typed` itself.
std::optional<std::string> nearestName(std::string_view typed, std::span<const std::string> names);

}  // namespace grass::core
