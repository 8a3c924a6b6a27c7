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

}  // namespace
}  // namespace grass::ui
