// Parsing and resolution of chordal and angular deflections (DESIGN.md "Tolerance semantics").
#include "brep/tolerance.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace cetview::brep {
namespace {

// Parses a finite double that fills the whole string.
bool parseNumber(const std::string& text, double& out) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  errno = 0;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno == 0 && std::isfinite(out);
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::string parseDeflection(const std::string& text, Deflection& out) {
  const bool relative = !text.empty() && text.back() == '%';
  const std::string digits = relative ? text.substr(0, text.size() - 1) : text;
  double v = 0;
  if (!parseNumber(digits, v))
    return "deflection '" + text + "' is not a number (use e.g. 0.1% or 0.05)";
  if (!(v > 0)) return "deflection '" + text + "' must be greater than zero";
  if (relative) {
    if (v > 50) return "deflection '" + text + "' is absurd: at most 50% of the model's diagonal";
    out = {v / 100.0, true};
  } else {
    out = {v, false};
  }
  return {};
}

std::string parseAngle(const std::string& text, double& degrees) {
  double v = 0;
  if (!parseNumber(text, v)) return "angle '" + text + "' is not a number of degrees";
  if (!(v > 0) || v > 90) return "angle '" + text + "' must be in (0, 90] degrees";
  degrees = v;
  return {};
}

std::string resolveDeflection(const Deflection& d, double diagonal, double& absolute) {
  if (!(diagonal > 0) || !std::isfinite(diagonal)) return "the model has no extent";
  absolute = d.relative ? d.value * diagonal : d.value;
  if (!(absolute > 0) || !std::isfinite(absolute)) return "deflection must be a positive number";
  if (absolute < 1e-6 * diagonal)
    return "deflection " + number(absolute) + " is below 1e-6 of the model's diagonal (" + number(diagonal) +
           "): the mesh would not fit in memory";
  if (absolute > 0.5 * diagonal)
    return "deflection " + number(absolute) + " exceeds half of the model's diagonal (" + number(diagonal) + ")";
  return {};
}

}  // namespace cetview::brep
