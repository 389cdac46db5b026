#include "cet/poly_format.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace cet {
namespace {

TEST(PolyFormat, ReadsOneBasedWithAttributesMarkersCommentsAndHoles) {
  const std::string text = R"(# a square with a hole
4 2 1 1   # header
1 0 0  7.5 1
2 4 0  7.5 1

3 4 4  7.5 1
4 0 4  7.5   # marker omitted
4 1
1 1 2 5
2 2 3
3 3 4
4 4 1
1
1 2 2
0
)";
  PolyData d;
  std::string error;
  ASSERT_TRUE(parsePoly(text, "t.poly", d, error)) << error;
  EXPECT_EQ(d.base, 1);
  ASSERT_EQ(d.points.size(), 4u);
  EXPECT_EQ(d.points[2].x, 4);
  EXPECT_EQ(d.attributeCount, 1u);
  EXPECT_EQ(d.attributes[3], 7.5);
  EXPECT_TRUE(d.hasMarkers);
  EXPECT_EQ(d.markers[0], 1);
  EXPECT_EQ(d.markers[3], 0);
  ASSERT_EQ(d.segments.size(), 4u);
  EXPECT_EQ(d.segments[3][0], 3u);
  EXPECT_EQ(d.segments[3][1], 0u);
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_EQ(d.holes[0].x, 2);
}

TEST(PolyFormat, ZeroBasedAndNoHoleSection) {
  PolyData d;
  std::string error;
  ASSERT_TRUE(parsePoly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 2\n", "t", d, error)) << error;
  EXPECT_EQ(d.base, 0);
  EXPECT_EQ(d.segments[0][1], 2u);
  EXPECT_TRUE(d.holes.empty());
}

struct BadCase {
  const char* text;
  const char* expected;  // a fragment of the one-line error
};

TEST(PolyFormat, MalformedInputGivesOneLineWithTheLine) {
  const BadCase cases[] = {
      {"", "file ends"},
      {"3 2 0 0\n1 0 0\n2 1 0\n", "only 2 lines follow"},
      {"-3 2 0 0\n", "negative"},
      {"3 3 0 0\n", "dimension must be 2"},
      {"x 2 0 0\n", "not an integer"},
      {"3 2 0 0\n1 0 0\n2 1 0\n3 nan 1\n0 0\n", "not finite"},
      {"3 2 0 0\n1 0 0\n2 1 inf\n3 0 1\n0 0\n", "not finite"},
      {"3 2 0 0\n1 0 0\n2 1 0\n3 0 1e999\n0 0\n", "not finite"},
      {"3 2 0 0\n1 0 0\n2 1 0x\n3 0 1\n0 0\n", "not a number"},
      {"3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 4\n", "out of range [1, 3]"},
      {"3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 0 2\n", "out of range"},
      {"3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n5 0\n1 1 2\n", "declares 5 segments"},
      {"3 2 0 0\n1 0 0\n3 1 0\n4 0 1\n0 0\n", "should be 2"},
      {"3 2 0 0\n2 0 0\n3 1 0\n4 0 1\n0 0\n", "numbered 0 or 1"},
      {"3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1\n", "needs 3 fields"},
      {"3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n2\n1 0 0\n", "declares 2 holes"},
      {"3 2 0 2\n", "marker count must be 0 or 1"},
      {"3 2 0 0\n1 0 0\n2 1e300 0\n3 0 1\n0 0\n", "outside the supported range"},
      {"3 2 0 0\n1 0 0\n2 1 1e-300\n3 0 1\n0 0\n", "outside the supported range"},
      {"99999999999 2 0 0\n1 0 0\n", "declares 99999999999 vertices"},
  };
  for (const BadCase& c : cases) {
    PolyData d;
    std::string error;
    EXPECT_FALSE(parsePoly(c.text, "bad.poly", d, error)) << c.text;
    EXPECT_NE(error.find(c.expected), std::string::npos) << "got: " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
    EXPECT_EQ(error.rfind("bad.poly:", 0), 0u) << error;
  }
}

TEST(PolyFormat, VerticesFromSiblingNodeFile) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream(dir + "/sib.node") << "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n";
    std::ofstream(dir + "/sib.poly") << "0 2 0 0\n3 0\n0 0 1\n1 1 2\n2 2 0\n0\n";
  }
  PolyData d;
  std::string error;
  ASSERT_TRUE(readPoly(dir + "/sib.poly", d, error)) << error;
  EXPECT_EQ(d.points.size(), 3u);
  EXPECT_EQ(d.segments.size(), 3u);
  EXPECT_FALSE(readPoly(dir + "/does-not-exist.poly", d, error));
  EXPECT_NE(error.find("cannot open"), std::string::npos);
}

TEST(PolyFormat, WritesNodeAndEleInTheInputBase) {
  PolyData d;
  d.base = 1;
  d.points = {{0, 0}, {1, 0}, {0.1, 1.0 / 3.0}};
  d.hasMarkers = true;
  d.markers = {1, 0, 2};
  const std::string out = ::testing::TempDir() + "/w";
  std::string error;
  ASSERT_TRUE(writeNodeEle(out, d, {0, 1, 2}, error)) << error;
  std::ifstream node(out + ".node"), ele(out + ".ele");
  std::string line;
  std::getline(node, line);
  EXPECT_EQ(line, "3 2 0 1");
  std::getline(node, line);
  std::getline(node, line);
  std::getline(node, line);
  EXPECT_EQ(line, "3 0.1 0.3333333333333333 2");  // shortest round-trip digits
  std::getline(ele, line);
  EXPECT_EQ(line, "1 3 0");
  std::getline(ele, line);
  EXPECT_EQ(line, "1 1 2 3");
}

}  // namespace
}  // namespace cet
