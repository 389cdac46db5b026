// Triangle's file formats (J. R. Shewchuk's Triangle): .poly in, .node and .ele out.
// https://www.cs.cmu.edu/~quake/triangle.poly.html describes them; this is an independent reader.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "types.h"

namespace cet {

struct PolyData {
  int base = 0;                       // vertex numbering: 0 or 1, as the file's first vertex
  std::size_t attributeCount = 0;     // per vertex
  bool hasMarkers = false;            // vertex boundary markers present
  std::vector<Point2> points;
  std::vector<double> attributes;     // attributeCount per vertex, in vertex order
  std::vector<long long> markers;     // one per vertex when hasMarkers
  std::vector<std::array<std::uint32_t, 2>> segments;  // 0-based vertex indices
  std::vector<Point2> holes;
};

// Parses a .poly file (vertices inline, or from the sibling .node file when the vertex count is 0).
// '#' starts a comment; blank lines are skipped. On failure returns false and sets `error` to one
// line, "PATH:LINE: what is wrong".
bool readPoly(const std::string& path, PolyData& out, std::string& error);
// The same from text already in memory (`name` prefixes error messages; no sibling .node lookup).
bool parsePoly(const std::string& text, const std::string& name, PolyData& out, std::string& error);

// Writes OUT.node (every input vertex, input order and numbering base, attributes and markers kept)
// and OUT.ele (the given triangles, three 0-based vertex ids each, written in the same base).
bool writeNodeEle(const std::string& outBase, const PolyData& data, const std::vector<std::uint32_t>& triangles,
                  std::string& error);

}  // namespace cet
