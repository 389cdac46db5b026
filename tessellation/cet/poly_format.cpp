#include "poly_format.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

namespace cet {
namespace {

// The file as lines of whitespace-separated tokens, comments and blank lines dropped.
struct Line {
  std::size_t number;  // 1-based line number in the file
  std::vector<std::string> tokens;
};

std::vector<Line> tokenize(const std::string& text) {
  std::vector<Line> lines;
  std::size_t number = 0, pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    ++number;
    std::string_view line(text.data() + pos, end - pos);
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    Line l{number, {}};
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      std::size_t j = i;
      while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
      if (j > i) l.tokens.emplace_back(line.substr(i, j - i));
      i = j;
    }
    if (!l.tokens.empty()) lines.push_back(std::move(l));
    pos = end + 1;
  }
  return lines;
}

class Parser {
 public:
  Parser(std::vector<Line> lines, std::string name, std::string& error)
      : lines_(std::move(lines)), name_(std::move(name)), error_(error) {}

  bool atEnd() const { return next_ >= lines_.size(); }
  std::size_t remaining() const { return lines_.size() - next_; }

  // The next line, which must have at least `minTokens` tokens.
  const Line* take(std::size_t minTokens, const char* what) {
    if (atEnd()) {
      fail(lastLine(), std::string("file ends where ") + what + " was expected");
      return nullptr;
    }
    const Line& l = lines_[next_++];
    if (l.tokens.size() < minTokens) {
      fail(l.number, std::string(what) + " needs " + std::to_string(minTokens) + " fields, found " +
                         std::to_string(l.tokens.size()));
      return nullptr;
    }
    return &l;
  }

  bool integer(const Line& l, std::size_t k, long long& value, const char* what) {
    const std::string& s = l.tokens[k];
    const char* end = s.data() + s.size();
    auto [ptr, ec] = std::from_chars(s.data(), end, value);
    if (ec != std::errc() || ptr != end) return fail(l.number, std::string(what) + " '" + s + "' is not an integer");
    return true;
  }

  bool real(const Line& l, std::size_t k, double& value, const char* what) {
    const std::string& s = l.tokens[k];
    char* end = nullptr;
    value = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || s.empty()) return fail(l.number, std::string(what) + " '" + s + "' is not a number");
    if (!std::isfinite(value)) return fail(l.number, std::string(what) + " '" + s + "' is not finite");
    return true;
  }

  // A coordinate the exact predicates can handle (see supportedCoordinate()).
  bool coordinate(const Line& l, std::size_t k, double& value, const char* what) {
    if (!real(l, k, value, what)) return false;
    if (!supportedCoordinate(value)) {
      return fail(l.number, std::string(what) + " '" + l.tokens[k] + "' is outside the supported range (0 or 1e-50 to 1e50 in magnitude)");
    }
    return true;
  }

  bool count(const Line& l, std::size_t k, long long& value, const char* what) {
    if (!integer(l, k, value, what)) return false;
    if (value < 0) return fail(l.number, std::string(what) + " is negative");
    return true;
  }

  bool fail(std::size_t line, const std::string& message) {
    error_ = name_ + ":" + std::to_string(line) + ": " + message;
    return false;
  }
  std::size_t lastLine() const { return lines_.empty() ? 1 : lines_.back().number; }
  const std::string& name() const { return name_; }

 private:
  std::vector<Line> lines_;
  std::size_t next_ = 0;
  std::string name_;
  std::string& error_;
};

// Reads the vertex section: a header "<count> <dim> <attributes> <markers>" then the vertices.
// With allowEmpty, a count of 0 is accepted (the caller then reads the .node file).
bool readVertices(Parser& p, PolyData& out, bool allowEmpty, bool& empty) {
  const Line* h = p.take(1, "the vertex header");
  if (!h) return false;
  long long n = 0, dim = 2, attributes = 0, markers = 0;
  if (!p.count(*h, 0, n, "vertex count")) return false;
  if (h->tokens.size() > 1 && !p.count(*h, 1, dim, "dimension")) return false;
  if (h->tokens.size() > 2 && !p.count(*h, 2, attributes, "attribute count")) return false;
  if (h->tokens.size() > 3 && !p.count(*h, 3, markers, "marker count")) return false;
  if (dim != 2) return p.fail(h->number, "dimension must be 2, not " + std::to_string(dim));
  if (markers > 1) return p.fail(h->number, "marker count must be 0 or 1");
  if (attributes > 1000) return p.fail(h->number, "attribute count " + std::to_string(attributes) + " is absurd");
  empty = n == 0;
  if (empty) {
    if (allowEmpty) return true;
    return p.fail(h->number, "the .node file has no vertices");
  }
  if (static_cast<unsigned long long>(n) > p.remaining()) {
    return p.fail(h->number, "declares " + std::to_string(n) + " vertices but only " + std::to_string(p.remaining()) +
                                 " lines follow");
  }
  out.attributeCount = static_cast<std::size_t>(attributes);
  out.hasMarkers = markers == 1;
  const std::size_t fields = 3 + out.attributeCount;  // the marker may be omitted per line
  out.points.reserve(static_cast<std::size_t>(n));
  for (long long i = 0; i < n; ++i) {
    const Line* l = p.take(fields, "a vertex");
    if (!l) return false;
    long long id = 0;
    if (!p.integer(*l, 0, id, "vertex number")) return false;
    if (i == 0) {
      if (id != 0 && id != 1) return p.fail(l->number, "the first vertex must be numbered 0 or 1");
      out.base = static_cast<int>(id);
    } else if (id != out.base + i) {
      return p.fail(l->number, "vertex number " + std::to_string(id) + " should be " + std::to_string(out.base + i));
    }
    Point2 q;
    if (!p.coordinate(*l, 1, q.x, "x") || !p.coordinate(*l, 2, q.y, "y")) return false;
    out.points.push_back(q);
    for (std::size_t a = 0; a < out.attributeCount; ++a) {
      double v = 0;
      if (!p.real(*l, 3 + a, v, "attribute")) return false;
      out.attributes.push_back(v);
    }
    if (out.hasMarkers) {
      long long marker = 0;
      if (l->tokens.size() > fields && !p.integer(*l, fields, marker, "boundary marker")) return false;
      out.markers.push_back(marker);
    }
  }
  return true;
}

bool readRest(Parser& p, PolyData& out) {
  const Line* h = p.take(1, "the segment header");
  if (!h) return false;
  long long ns = 0;
  if (!p.count(*h, 0, ns, "segment count")) return false;
  if (static_cast<unsigned long long>(ns) > p.remaining()) {
    return p.fail(h->number, "declares " + std::to_string(ns) + " segments but only " + std::to_string(p.remaining()) +
                                 " lines follow");
  }
  const long long lo = out.base, hi = out.base + static_cast<long long>(out.points.size()) - 1;
  out.segments.reserve(static_cast<std::size_t>(ns));
  for (long long i = 0; i < ns; ++i) {
    const Line* l = p.take(3, "a segment");
    if (!l) return false;
    long long id = 0, a = 0, b = 0;
    if (!p.integer(*l, 0, id, "segment number") || !p.integer(*l, 1, a, "segment endpoint") ||
        !p.integer(*l, 2, b, "segment endpoint")) {
      return false;
    }
    for (long long e : {a, b}) {
      if (e < lo || e > hi) {
        return p.fail(l->number, "segment " + std::to_string(id) + " endpoint " + std::to_string(e) +
                                     " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
      }
    }
    out.segments.push_back({static_cast<std::uint32_t>(a - lo), static_cast<std::uint32_t>(b - lo)});
  }
  if (p.atEnd()) return true;  // no hole section: no holes
  const Line* hh = p.take(1, "the hole header");
  long long nh = 0;
  if (!p.count(*hh, 0, nh, "hole count")) return false;
  if (static_cast<unsigned long long>(nh) > p.remaining()) {
    return p.fail(hh->number, "declares " + std::to_string(nh) + " holes but only " + std::to_string(p.remaining()) +
                                  " lines follow");
  }
  for (long long i = 0; i < nh; ++i) {
    const Line* l = p.take(3, "a hole");
    if (!l) return false;
    Point2 q;
    if (!p.coordinate(*l, 1, q.x, "hole x") || !p.coordinate(*l, 2, q.y, "hole y")) return false;
    out.holes.push_back(q);
  }
  // Regional attributes and area constraints may follow; the triangulator does not use them.
  return true;
}

bool readFile(const std::string& path, std::string& text, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = path + ": cannot open file";
    return false;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) {
    error = path + ": read error";
    return false;
  }
  text = buffer.str();
  if (text.find('\0') != std::string::npos) {
    error = path + ": binary data, not a .poly file";
    return false;
  }
  return true;
}

bool parse(const std::string& text, const std::string& name, const std::string* nodePath, PolyData& out,
           std::string& error) {
  out = PolyData{};
  Parser p(tokenize(text), name, error);
  bool empty = false;
  if (!readVertices(p, out, nodePath != nullptr, empty)) return false;
  if (empty) {
    std::string nodeText;
    if (!readFile(*nodePath, nodeText, error)) return false;
    Parser nodeParser(tokenize(nodeText), *nodePath, error);
    bool nodeEmpty = false;
    if (!readVertices(nodeParser, out, false, nodeEmpty)) return false;
  }
  return readRest(p, out);
}

void appendNumber(std::string& s, double v) {
  char buffer[32];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  s.append(buffer, ec == std::errc() ? ptr : buffer);
}

void appendInteger(std::string& s, long long v) {
  char buffer[24];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  s.append(buffer, ec == std::errc() ? ptr : buffer);
}

bool writeText(const std::string& path, const std::string& text, std::string& error) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) {
    error = path + ": cannot write file";
    return false;
  }
  return true;
}

}  // namespace

bool parsePoly(const std::string& text, const std::string& name, PolyData& out, std::string& error) {
  return parse(text, name, nullptr, out, error);
}

bool readPoly(const std::string& path, PolyData& out, std::string& error) {
  std::string text;
  if (!readFile(path, text, error)) return false;
  std::string nodePath = path;
  const std::size_t dot = nodePath.rfind('.');
  const std::size_t slash = nodePath.rfind('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) nodePath.resize(dot);
  nodePath += ".node";
  return parse(text, path, &nodePath, out, error);
}

bool writeNodeEle(const std::string& outBase, const PolyData& data, const std::vector<std::uint32_t>& triangles,
                  std::string& error) {
  std::string node;
  node.reserve(data.points.size() * 48 + 64);
  appendInteger(node, static_cast<long long>(data.points.size()));
  node += " 2 ";
  appendInteger(node, static_cast<long long>(data.attributeCount));
  node += data.hasMarkers ? " 1\n" : " 0\n";
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    appendInteger(node, static_cast<long long>(i) + data.base);
    node += ' ';
    appendNumber(node, data.points[i].x);
    node += ' ';
    appendNumber(node, data.points[i].y);
    for (std::size_t a = 0; a < data.attributeCount; ++a) {
      node += ' ';
      appendNumber(node, data.attributes[i * data.attributeCount + a]);
    }
    if (data.hasMarkers) {
      node += ' ';
      appendInteger(node, data.markers[i]);
    }
    node += '\n';
  }
  std::string ele;
  const std::size_t count = triangles.size() / 3;
  ele.reserve(count * 40 + 32);
  appendInteger(ele, static_cast<long long>(count));
  ele += " 3 0\n";
  for (std::size_t t = 0; t < count; ++t) {
    appendInteger(ele, static_cast<long long>(t) + data.base);
    for (int k = 0; k < 3; ++k) {
      ele += ' ';
      appendInteger(ele, static_cast<long long>(triangles[3 * t + static_cast<std::size_t>(k)]) + data.base);
    }
    ele += '\n';
  }
  return writeText(outBase + ".node", node, error) && writeText(outBase + ".ele", ele, error);
}

}  // namespace cet
