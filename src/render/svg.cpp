// SPDX-License-Identifier: Apache-2.0
#include <preimage/render/svg.hpp>

#include <preimage/error.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace preimage::render {

std::string escape(const std::string& t) {
  std::string o;
  o.reserve(t.size());
  for (char c : t) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

namespace {
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}
}  // namespace

SvgCanvas::SvgCanvas(CGAL::Bbox_2 world, double width_px, double margin_px) : world_(world), margin_(margin_px) {
  const double w = std::max(world.xmax() - world.xmin(), 1e-9), h = std::max(world.ymax() - world.ymin(), 1e-9);
  scale_ = (width_px - 2 * margin_px) / w;
  width_ = width_px;
  height_ = h * scale_ + 2 * margin_px;
}

std::string SvgCanvas::px(const Point& p) const {
  return num(margin_ + (p.x() - world_.xmin()) * scale_) + "," + num(margin_ + (world_.ymax() - p.y()) * scale_);
}

std::string SvgCanvas::style_attr(const Style& s) const {
  std::string a = " fill=\"" + escape(s.fill) + "\" stroke=\"" + escape(s.stroke) + "\" stroke-width=\"" +
                  num(s.stroke_width) + "\" stroke-linejoin=\"round\"";
  if (s.opacity < 1) a += " opacity=\"" + num(s.opacity) + "\"";
  if (!s.dash.empty()) a += " stroke-dasharray=\"" + escape(s.dash) + "\"";
  return a;
}

void SvgCanvas::environment(const geometry::Environment& env) {
  // One path with even-odd fill: free space is the outer ring minus the holes.
  std::string d;
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    d += "M";
    for (std::size_t v = env.ring_begin(r); v < env.ring_end(r); ++v) d += px(env.vertex(v)) + " ";
    d += "Z ";
  }
  body_ += "<rect x=\"0\" y=\"0\" width=\"" + num(width_) + "\" height=\"" + num(height_) + "\" fill=\"#d9d9d9\"/>\n";
  body_ += "<path d=\"" + d + "\" fill=\"#ffffff\" fill-rule=\"evenodd\" stroke=\"#333\" stroke-width=\"1.5\"/>\n";
}

void SvgCanvas::polygon(const std::vector<Point>& pts, const Style& s, const std::string& title) {
  std::string p;
  for (auto& q : pts) p += px(q) + " ";
  body_ += "<polygon points=\"" + p + "\"" + style_attr(s) + ">" + (title.empty() ? "" : "<title>" + escape(title) + "</title>") + "</polygon>\n";
}

void SvgCanvas::rings(const std::vector<std::vector<Point>>& rings, const Style& s, const std::string& title) {
  std::string d;
  for (auto& r : rings) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      const std::string xy = px(r[i]);
      // Appends only: GCC 12 flags "literal" + std::string with a false -Wrestrict at -O3.
      std::string cmd = xy;
      cmd[cmd.find(',')] = ' ';
      d.append(i ? "L" : "M").append(cmd).append(" ");
    }
    d += "Z ";
  }
  body_ += "<path fill-rule=\"evenodd\" d=\"" + d + "\"" + style_attr(s) + ">" + (title.empty() ? "" : "<title>" + escape(title) + "</title>") + "</path>\n";
}

void SvgCanvas::polyline(const std::vector<Point>& pts, const Style& s, const std::string& title) {
  std::string p;
  for (auto& q : pts) p += px(q) + " ";
  body_ += "<polyline points=\"" + p + "\"" + style_attr(s) + ">" + (title.empty() ? "" : "<title>" + escape(title) + "</title>") + "</polyline>\n";
}

void SvgCanvas::segment(const Point& a, const Point& b, const Style& s, const std::string& title) {
  polyline({a, b}, s, title);
}

void SvgCanvas::point(const Point& p, double r, const Style& s, const std::string& title) {
  auto xy = px(p);
  auto comma = xy.find(',');
  body_ += "<circle cx=\"" + xy.substr(0, comma) + "\" cy=\"" + xy.substr(comma + 1) + "\" r=\"" + num(r) + "\"" +
           style_attr(s) + ">" + (title.empty() ? "" : "<title>" + escape(title) + "</title>") + "</circle>\n";
}

void SvgCanvas::label(const Point& p, const std::string& text, double size, const std::string& colour) {
  auto xy = px(p);
  auto comma = xy.find(',');
  body_ += "<text x=\"" + xy.substr(0, comma) + "\" y=\"" + xy.substr(comma + 1) + "\" font-family=\"sans-serif\" font-size=\"" +
           num(size) + "\" fill=\"" + escape(colour) + "\">" + escape(text) + "</text>\n";
}

void SvgCanvas::legend(const std::string& text, const Style& s) {
  for (auto& [t, st] : legend_)
    if (t == text) return;  // one entry per meaning, however many times it is drawn
  legend_.emplace_back(text, s);
}

std::string SvgCanvas::str() const {
  const double legend_h = legend_.empty() ? 0 : 8 + 18.0 * static_cast<double>(legend_.size());
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width_) + "\" height=\"" +
                    num(height_ + legend_h) + "\" viewBox=\"0 0 " + num(width_) + " " + num(height_ + legend_h) + "\">\n";
  out += body_;
  double y = height_ + 4;
  for (auto& [text, s] : legend_) {
    Style sw = s;
    out += "<rect x=\"" + num(margin_) + "\" y=\"" + num(y + 2) + "\" width=\"22\" height=\"10\"" + style_attr(sw) + "/>";
    out += "<text x=\"" + num(margin_ + 30) + "\" y=\"" + num(y + 11) + "\" font-family=\"sans-serif\" font-size=\"12\">" +
           escape(text) + "</text>\n";
    y += 18;
  }
  out += "</svg>\n";
  return out;
}

void SvgCanvas::save(const std::string& path) const {
  std::ofstream f(path);
  f << str();
  if (!f) throw InputError(path + ": cannot write file");
}

}  // namespace preimage::render
