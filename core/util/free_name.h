// A name none of a list's items has: `base`, else "base 2", "base 3", … (layers, colliders).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace grass::core {

template <class Named>
std::string freeName(const std::vector<Named>& items, const std::string& base) {
    const auto taken = [&](const std::string& name) {
        return std::any_of(items.begin(), items.end(),
                           [&](const Named& item) { return item.name == name; });
    };
    if (!taken(base))
        return base;
    for (std::size_t n = 2;; ++n)
        if (std::string name = base + " " + std::to_string(n); !taken(name))
            return name;
}

}  // namespace grass::core
