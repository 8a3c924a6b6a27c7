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
// For a quantity that spans orders of magnitude (a logarithmic slider's): `decimals`, or more
// where a value below 1 would read fewer than `significant` digits, so that it never reads "0"
// (a 60 km mesh's 3.45e-6 blades /m² did, on a slider of whole blades /m²). At most
// MAX_SIGNIFICANT_DECIMALS: below 1e-10 a value reads 0.
inline constexpr int MAX_SIGNIFICANT_DECIMALS = 10;
int significantDecimals(double value, int decimals, int significant = 3);
std::string numberText(double value, int decimals);

}  // namespace grass::ui
