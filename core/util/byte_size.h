// Memory sizes in messages: what a refused request would have needed ("96 TiB"), so the user sees
// why a number is too big, not just that it is.
#pragma once

#include <string>

namespace grass {

// 3 significant digits in the largest binary unit that keeps the number at least 1: "512 B",
// "1.5 KiB", "256 MiB", "16 GiB", "96 TiB"; "inf B" when the request is beyond counting.
std::string byteSizeText(double bytes);

}  // namespace grass
