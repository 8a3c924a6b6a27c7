// A widget's number shows no more digits than a float carries (7 significant), so the unbounded
// altitude range's ±1000000 reads as such and its box keeps to the digits that mean something.
#include <gtest/gtest.h>

#include "ui/number_text.h"

namespace grass::ui {
namespace {

TEST(NumberText, ShowsTheDecimalsAskedWhileAFloatCarriesThem) {
    EXPECT_EQ(numberText(0.5, 2), "0.50");
    EXPECT_EQ(numberText(144.0, 0), "144");
    EXPECT_EQ(numberText(0.0123456, 4), "0.0123");
    EXPECT_EQ(numberText(12345.678, 2), "12345.68");
    EXPECT_EQ(numberText(-2.5, -1), "-2");  // fewer than 0 decimals count as 0 (printf rounds)
}

TEST(NumberText, DropsTheDecimalsBeyondSevenSignificantDigits) {
    EXPECT_EQ(numberText(1000000.0, 2), "1000000");
    EXPECT_EQ(numberText(-1000000.0, 2), "-1000000");
    EXPECT_EQ(numberText(123456.78, 3), "123456.8");
    EXPECT_EQ(numberText(1.0e9, 2), "1000000000");
    EXPECT_EQ(shownDecimals(9999.5, 6), 3);
}

// A logarithmic slider's value below 1 keeps three significant digits: a 60 km mesh's
// 3.45e-6 blades /m² read "0" on the density slider of whole blades.
TEST(NumberText, SmallValuesKeepTheirSignificantDigits) {
    EXPECT_EQ(numberText(3.45e-6, significantDecimals(3.45e-6, 0)), "0.00000345");
    EXPECT_EQ(numberText(-0.0123456, significantDecimals(-0.0123456, 2)), "-0.0123");
    EXPECT_EQ(numberText(0.5, significantDecimals(0.5, 0)), "0.500");
    // Never fewer decimals than asked, and values of 1 and more as before.
    EXPECT_EQ(numberText(0.25, significantDecimals(0.25, 4)), "0.2500");
    EXPECT_EQ(numberText(144.0, significantDecimals(144.0, 0)), "144");
    EXPECT_EQ(numberText(1000000.0, significantDecimals(1000000.0, 2)), "1000000");
    EXPECT_EQ(numberText(0.0, significantDecimals(0.0, 0)), "0");
    // Below 1e-10 a value reads 0, not 40 zeros.
    EXPECT_EQ(significantDecimals(1e-30, 0), MAX_SIGNIFICANT_DECIMALS);
    EXPECT_EQ(significantDecimals(1e-30, 12), 12);
}

}  // namespace
}  // namespace grass::ui
