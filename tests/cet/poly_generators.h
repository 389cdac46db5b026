// Input generators for the triangulator's property tests and benchmarks: random, grid, circle,
// clustered, long-thin, and a trimmed-face-like polygon with many holes.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "cet/poly_format.h"

namespace cet::generators {

inline PolyData randomPoints(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PolyData d;
  d.points.resize(n);
  for (auto& p : d.points) p = {u(rng), u(rng)};
  return d;
}

inline PolyData grid(std::size_t side) {
  PolyData d;
  for (std::size_t i = 0; i < side; ++i)
    for (std::size_t j = 0; j < side; ++j) d.points.push_back({static_cast<double>(i), static_cast<double>(j)});
  return d;
}

inline PolyData circle(std::size_t n, bool centre) {
  PolyData d;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * 3.14159265358979323846 * static_cast<double>(i) / static_cast<double>(n);
    d.points.push_back({std::cos(t), std::sin(t)});
  }
  if (centre) d.points.push_back({0, 0});
  return d;
}

inline PolyData clustered(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  PolyData d;
  const std::size_t clusters = std::max<std::size_t>(1, n / 1000);
  for (std::size_t c = 0; c < clusters; ++c) {
    const Point2 centre{g(rng) * 100, g(rng) * 100};
    for (std::size_t i = 0; i < n / clusters; ++i) d.points.push_back({centre.x + g(rng) * 1e-4, centre.y + g(rng) * 1e-4});
  }
  return d;
}

inline PolyData longThin(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PolyData d;
  d.points.resize(n);
  for (auto& p : d.points) p = {u(rng) * 1e4, u(rng) * 1e-3};
  return d;
}

// A trimmed-face-like domain: a wavy outer loop, many small circular holes (as loops of segments, each
// with a hole point), and random interior points kept clear of the holes.
inline PolyData polygonWithHoles(std::size_t outer, std::size_t holes, std::size_t perHole, std::size_t interior, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PolyData d;
  for (std::size_t i = 0; i < outer; ++i) {
    const double t = 2 * 3.14159265358979323846 * static_cast<double>(i) / static_cast<double>(outer);
    const double r = 10.0 + 0.5 * std::sin(7 * t);
    d.points.push_back({r * std::cos(t), r * std::sin(t)});
    d.segments.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>((i + 1) % outer)});
  }
  const std::size_t side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(holes))));
  const double cell = 12.0 / static_cast<double>(side), radius = 0.3 * cell;
  std::vector<Point2> centres;
  for (std::size_t h = 0; h < holes; ++h) {
    const Point2 c{-6.0 + cell * (static_cast<double>(h % side) + 0.5), -6.0 + cell * (static_cast<double>(h / side) + 0.5)};
    centres.push_back(c);
    const auto first = static_cast<std::uint32_t>(d.points.size());
    for (std::size_t k = 0; k < perHole; ++k) {
      const double t = -2 * 3.14159265358979323846 * static_cast<double>(k) / static_cast<double>(perHole);  // clockwise
      d.points.push_back({c.x + radius * std::cos(t), c.y + radius * std::sin(t)});
      d.segments.push_back({first + static_cast<std::uint32_t>(k),
                            first + static_cast<std::uint32_t>((k + 1) % perHole)});
    }
    d.holes.push_back(c);
  }
  while (interior > 0) {
    const Point2 p{-9 + 18 * u(rng), -9 + 18 * u(rng)};
    bool clear = std::hypot(p.x, p.y) < 9.4;
    for (const Point2& c : centres) clear = clear && std::hypot(p.x - c.x, p.y - c.y) > radius * 1.2;
    if (!clear) continue;
    d.points.push_back(p);
    --interior;
  }
  return d;
}

}  // namespace cet::generators
