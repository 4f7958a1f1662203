// SPDX-License-Identifier: Apache-2.0
// WKT POLYGON / MULTIPOLYGON (one polygon) in: a small recursive-descent reader; POLYGON out.
#include <preimage/error.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/wkt.hpp>

#include <cctype>
#include <charconv>
#include <cstring>

namespace preimage::scene {

namespace {
class WktReader {
 public:
  WktReader(const std::string& text, const std::string& source, const ImportOptions& options)
      : t_(text), source_(source), options_(options) {}

  Scene read() {
    const std::string tag = word();
    bool multi = false;
    if (tag == "MULTIPOLYGON") multi = true;
    else if (tag != "POLYGON") fail(tag.empty() ? "expected POLYGON or MULTIPOLYGON" : "expected POLYGON or MULTIPOLYGON, got '" + tag + "'");
    skip();
    if (pos_ < t_.size() && std::isalpha(static_cast<unsigned char>(t_[pos_]))) {
      const std::string dim = word();
      fail(dim == "EMPTY" ? "the polygon is EMPTY" : "only 2-D coordinates are read, got '" + dim + "'");
    }
    if (multi) expect('(');
    std::vector<geometry::Ring> rings = polygon();
    if (multi) {
      skip();
      if (pos_ < t_.size() && t_[pos_] == ',') fail("expected a MULTIPOLYGON of exactly one polygon (one floor plan)");
      expect(')');
    }
    skip();
    if (pos_ != t_.size()) fail("unexpected text after the polygon");
    Scene s;
    s.source = source_;
    s.name = source_;
    s.description = "WKT polygon";
    geometry::Ring outer = std::move(rings[0]);
    rings.erase(rings.begin());
    try {
      apply_import_options(rings, options_);
      s.environment = geometry::Environment::make(std::move(outer), std::move(rings), "ring 1 (boundary)", "holes");
    } catch (const InputError& e) {
      throw InputError(source_ + ": " + e.what());
    }
    return s;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_ + ": character " + std::to_string(pos_ + 1) + ": " + what);
  }
  void skip() {
    while (pos_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[pos_]))) ++pos_;
  }
  std::string word() {
    skip();
    std::string w;
    while (pos_ < t_.size() && std::isalpha(static_cast<unsigned char>(t_[pos_]))) w += static_cast<char>(std::toupper(static_cast<unsigned char>(t_[pos_++])));
    return w;
  }
  void expect(char c) {
    skip();
    if (pos_ >= t_.size()) fail(std::string("expected '") + c + "', got the end of the text");
    if (t_[pos_] != c) fail(std::string("expected '") + c + "', got '" + t_[pos_] + "'");
    ++pos_;
  }
  double number() {
    skip();
    double v = 0;
    const char* b = t_.data() + pos_;
    const auto [end, ec] = std::from_chars(b, t_.data() + t_.size(), v);
    if (ec != std::errc() || end == b) {
      std::size_t n = 0;
      while (pos_ + n < t_.size() && !std::isspace(static_cast<unsigned char>(t_[pos_ + n])) && std::strchr(",()", t_[pos_ + n]) == nullptr) ++n;
      fail("expected a number, got '" + (n ? t_.substr(pos_, n) : pos_ < t_.size() ? t_.substr(pos_, 1) : std::string("end of text")) + "'");
    }
    pos_ = static_cast<std::size_t>(end - t_.data());
    return v;
  }
  geometry::Ring ring() {
    expect('(');
    geometry::Ring r;
    for (;;) {
      const double x = number(), y = number();
      skip();
      if (pos_ < t_.size() && (std::isdigit(static_cast<unsigned char>(t_[pos_])) || t_[pos_] == '-' || t_[pos_] == '+' || t_[pos_] == '.'))
        fail("only 2-D coordinates are read (a third number follows x y)");
      r.emplace_back(x, y);
      skip();
      if (pos_ < t_.size() && t_[pos_] == ',') {
        ++pos_;
        continue;
      }
      expect(')');
      break;
    }
    if (r.size() > 1 && r.front() == r.back()) r.pop_back();  // WKT rings are closed
    return r;
  }
  std::vector<geometry::Ring> polygon() {
    expect('(');
    std::vector<geometry::Ring> rings{ring()};
    for (;;) {
      skip();
      if (pos_ < t_.size() && t_[pos_] == ',') {
        ++pos_;
        rings.push_back(ring());
        continue;
      }
      expect(')');
      return rings;
    }
  }

  const std::string& t_;
  const std::string& source_;
  const ImportOptions options_;
  std::size_t pos_ = 0;
};
}  // namespace

Scene import_wkt(const std::string& text, const std::string& source, const ImportOptions& options) {
  return WktReader(text, source, options).read();
}

Scene import_wkt(const std::string& path, const ImportOptions& options) { return import_wkt(read_file(path), path, options); }

std::string to_wkt(const geometry::Environment& env) {
  std::string out = "POLYGON (";
  auto number = [&out](double v) {
    char buf[32];
    // std::to_chars without a precision: the shortest text that reads back to v.
    const auto end = std::to_chars(buf, buf + sizeof buf, v + 0.0).ptr;
    out.append(buf, end);
  };
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    out += r ? ", (" : "(";
    for (std::size_t v = env.ring_begin(r); v <= env.ring_end(r); ++v) {  // the first vertex again closes the ring
      const auto& p = env.vertex(v < env.ring_end(r) ? v : env.ring_begin(r));
      if (v > env.ring_begin(r)) out += ", ";
      number(p.x());
      out += ' ';
      number(p.y());
    }
    out += ')';
  }
  return out + ")";
}

}  // namespace preimage::scene
