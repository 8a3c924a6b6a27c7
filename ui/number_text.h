// The text of a number in a widget (slider value, drag box, typing box): `decimals` digits after
// the point, but no more than a float carries (7 significant digits), so an unbounded range's
// ±1000000 reads "1000000", not "1000000.00" whose last digits are noise, and its box keeps to the
// width of the digits that mean something. One rule for every widget, so a box shows what its
// typing starts from.
#pragma once

#include <string>

namespace grass::ui {

inline constexpr int FLOAT_SIGNIFICANT_DIGITS = 7;

// `decimals` < 0 counts as 0.
int shownDecimals(double value, int decimals);
std::string numberText(double value, int decimals);

}  // namespace grass::ui
