// Tolerance semantics (DESIGN.md): both forms parse; bad and absurd values are refused with a message.
#include <gtest/gtest.h>

#include <cmath>

#include "brep/tolerance.h"

namespace cetview::brep {
namespace {

TEST(Tolerance, ParsesRelativeAndAbsolute) {
  Deflection d;
  EXPECT_EQ(parseDeflection("0.1%", d), "");
  EXPECT_TRUE(d.relative);
  EXPECT_DOUBLE_EQ(d.value, 0.001);
  EXPECT_EQ(parseDeflection("0.05", d), "");
  EXPECT_FALSE(d.relative);
  EXPECT_DOUBLE_EQ(d.value, 0.05);
  EXPECT_EQ(parseDeflection("5e-2", d), "");
  EXPECT_DOUBLE_EQ(d.value, 0.05);
}

TEST(Tolerance, RefusesBadDeflections) {
  Deflection d;
  for (const char* bad : {"", "%", "abc", "0.1%%", "1 ", " 1", "0", "-1", "-0.1%", "0%", "nan", "NaN%", "inf", "1e999",
                          "60%", "0.1mm", "1,5"}) {
    EXPECT_NE(parseDeflection(bad, d), "") << "'" << bad << "' was accepted";
  }
}

TEST(Tolerance, ParsesAngles) {
  double a = 0;
  EXPECT_EQ(parseAngle("20", a), "");
  EXPECT_DOUBLE_EQ(a, 20);
  EXPECT_EQ(parseAngle("90", a), "");
  for (const char* bad : {"", "0", "-5", "91", "nan", "x", "20deg"}) EXPECT_NE(parseAngle(bad, a), "") << bad;
}

TEST(Tolerance, ResolvesAgainstTheDiagonal) {
  double abs = 0;
  EXPECT_EQ(resolveDeflection({0.001, true}, 200.0, abs), "");
  EXPECT_DOUBLE_EQ(abs, 0.2);
  EXPECT_EQ(resolveDeflection({0.5, false}, 200.0, abs), "");
  EXPECT_DOUBLE_EQ(abs, 0.5);
  EXPECT_NE(resolveDeflection({1e-9, false}, 200.0, abs), "");  // below 1e-6 of the diagonal
  EXPECT_NE(resolveDeflection({150, false}, 200.0, abs), "");   // above half the diagonal
  EXPECT_NE(resolveDeflection({0.001, true}, 0.0, abs), "");    // no extent
  EXPECT_NE(resolveDeflection({0.001, true}, NAN, abs), "");
}

}  // namespace
}  // namespace cetview::brep
