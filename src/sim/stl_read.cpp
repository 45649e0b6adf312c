// STL files read: binary (the count checked against the size before any allocation) and ASCII
// (solid / facet normal / outer loop / vertex x3 / endloop / endfacet / endsolid).
#include "sim/stl_read.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace ncurve::sim {
namespace {

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
  throw std::runtime_error(fmt::format("{}: error: {}", origin, what));
}

std::uint32_t get_u32(const char* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

float get_f32(const char* p) {
  static_assert(std::numeric_limits<float>::is_iec559);
  return std::bit_cast<float>(get_u32(p));
}

Mesh parse_binary(std::string_view bytes, const std::string& origin, double scale, std::uint32_t count) {
  Mesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(count) * 3);
  mesh.triangles.reserve(count);
  for (std::uint32_t k = 0; k < count; ++k) {
    const char* t = bytes.data() + kStlHeaderBytes + 4 + static_cast<std::size_t>(k) * kStlTriangleBytes + 12;
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    for (int v = 0; v < 3; ++v) {
      Point3 p;
      for (int a = 0; a < 3; ++a) {
        const float x = get_f32(t + 12 * v + 4 * a);
        if (!std::isfinite(x))
          fail(origin, fmt::format("triangle {} (byte {}): vertex {} has {} = {}, not a finite number", k + 1,
                                   kStlHeaderBytes + 4 + static_cast<std::size_t>(k) * kStlTriangleBytes, v + 1,
                                   "xyz"[a], x));
        p[a] = x * scale;
      }
      mesh.vertices.push_back(p);
    }
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

// A word of the file as a message shows it: 40 characters at most, control bytes as '?'.
std::string shown(std::string_view w) {
  std::string s(w.substr(0, 40));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
  return w.size() > 40 ? s + "..." : s;
}

// An ASCII STL's words, each with its line and column.
class Words {
public:
  Words(std::string_view text, const std::string& origin) : text_(text), origin_(origin) {}
  bool done() {
    skip();
    return at_ >= text_.size();
  }
  std::string_view next(const char* expected) {
    skip();
    if (at_ >= text_.size()) fail_here(fmt::format("the file ends where {} was expected", expected));
    word_line_ = line_, word_column_ = at_ - line_start_ + 1;
    const std::size_t from = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return text_.substr(from, at_ - from);
  }
  void expect(std::string_view word) {
    const std::string quoted = fmt::format("'{}'", word);
    const std::string_view w = next(quoted.c_str());
    if (w != word) fail_word(fmt::format("'{}' where {} was expected", shown(w), quoted));
  }
  double number(const char* what) {
    const std::string_view w = next(what);
    double v = 0;
    const char* end = w.data() + w.size();
    const char* from = w.size() > 1 && w[0] == '+' && w[1] != '-' ? w.data() + 1 : w.data();  // "+1.5" too
    const auto [p, ec] = std::from_chars(from, end, v);
    if (ec == std::errc::result_out_of_range) fail_word(fmt::format("{} '{}' is out of range", what, shown(w)));
    if (ec != std::errc() || p != end) fail_word(fmt::format("'{}' where {} (a number) was expected", shown(w), what));
    if (!std::isfinite(v)) fail_word(fmt::format("{} is {}, not a finite number", what, shown(w)));
    return v;
  }
  void rest_of_line() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }
  [[noreturn]] void fail_word(const std::string& what) const {
    throw std::runtime_error(fmt::format("{}:{}:{}: error: {}", origin_, word_line_, word_column_, what));
  }

private:
  void skip() {
    for (; at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])); ++at_)
      if (text_[at_] == '\n') ++line_, line_start_ = at_ + 1;
  }
  [[noreturn]] void fail_here(const std::string& what) const {
    throw std::runtime_error(fmt::format("{}:{}:{}: error: {}", origin_, line_, at_ - line_start_ + 1, what));
  }
  std::string_view text_;
  const std::string& origin_;
  std::size_t at_ = 0, line_ = 1, line_start_ = 0;
  std::size_t word_line_ = 1, word_column_ = 1;
};

Mesh parse_ascii(std::string_view text, const std::string& origin, double scale) {
  Mesh mesh;
  Words w(text, origin);
  while (!w.done()) {  // one or more solids
    w.expect("solid");
    w.rest_of_line();  // its name
    for (;;) {
      const std::string_view word = w.next("'facet' or 'endsolid'");
      if (word == "endsolid") {
        w.rest_of_line();
        break;
      }
      if (word != "facet") w.fail_word(fmt::format("'{}' where 'facet' or 'endsolid' was expected", shown(word)));
      if (mesh.triangles.size() >= kMostStlTriangles)
        w.fail_word(fmt::format("more than {} triangles: too large a file", kMostStlTriangles));
      w.expect("normal");
      for (int a = 0; a < 3; ++a) (void)w.number("the normal's coordinate");  // ignored, but a number
      w.expect("outer");
      w.expect("loop");
      const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      for (int v = 0; v < 3; ++v) {
        w.expect("vertex");
        Point3 p;
        for (int a = 0; a < 3; ++a) p[a] = w.number(a == 0 ? "the vertex's x" : a == 1 ? "the vertex's y" : "the vertex's z") * scale;
        mesh.vertices.push_back(p);
      }
      w.expect("endloop");
      w.expect("endfacet");
      mesh.triangles.push_back({first, first + 1, first + 2});
    }
  }
  return mesh;
}

bool starts_with_solid(std::string_view bytes) {
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && bytes.substr(first, 5) == "solid";
}

// A solid has extent on every axis.
void check_solid(const Mesh& mesh, const std::string& origin) {
  if (mesh.triangles.empty()) fail(origin, "the STL has no triangle: not a solid");
  Point3 lo = mesh.vertices[0], hi = lo;
  for (const Point3& p : mesh.vertices)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  for (int a = 0; a < 3; ++a)
    if (!(hi[a] > lo[a]))
      fail(origin, fmt::format("every vertex of the STL has {} = {:g}: a flat surface, not a solid", "XYZ"[a], lo[a]));
}

}  // namespace

Mesh parse_stl(std::string_view bytes, const std::string& origin, double scale) {
  if (!(scale > 0) || !std::isfinite(scale)) throw std::invalid_argument("an STL's scale must be a positive number");
  const std::size_t head = kStlHeaderBytes + 4;
  const bool binary_size = bytes.size() >= head && (bytes.size() - head) % kStlTriangleBytes == 0 &&
                           (bytes.size() - head) / kStlTriangleBytes == get_u32(bytes.data() + kStlHeaderBytes);
  Mesh mesh;
  if (!binary_size && starts_with_solid(bytes)) {
    mesh = parse_ascii(bytes, origin, scale);
  } else {
    if (bytes.size() < head)
      fail(origin, fmt::format("{} bytes: too short for a binary STL (its header and count take {}), and not an "
                               "ASCII one (it does not start with 'solid')",
                               bytes.size(), head));
    const std::uint32_t count = get_u32(bytes.data() + kStlHeaderBytes);
    const auto want = static_cast<std::uint64_t>(count) * kStlTriangleBytes + head;
    if (want > bytes.size())
      fail(origin, fmt::format("the header counts {} triangles, {} bytes, but the file has {}: truncated", count, want,
                               bytes.size()));
    if (want < bytes.size())
      fail(origin, fmt::format("the header counts {} triangles, {} bytes, but the file has {}: not a binary STL of "
                               "that count, and not an ASCII one (it does not start with 'solid')",
                               count, want, bytes.size()));
    if (count > kMostStlTriangles) fail(origin, fmt::format("{} triangles: more than the {} read", count, kMostStlTriangles));
    mesh = parse_binary(bytes, origin, scale, count);
  }
  check_solid(mesh, origin);
  return mesh;
}

Mesh read_stl(const std::string& path, double scale) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) fail(path, fmt::format("cannot read the STL file: {}", ec.message()));
  const std::uint64_t most = static_cast<std::uint64_t>(kMostStlTriangles) * kStlTriangleBytes + kStlHeaderBytes + 4;
  if (size > most)  // the largest binary of kMostStlTriangles
    fail(path, fmt::format("{} bytes: more than the {} read from an STL file", size, most));
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the STL file");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(in.gcount()) != size) fail(path, "cannot read the whole STL file");
  return parse_stl(bytes, path, scale);
}

}  // namespace ncurve::sim
