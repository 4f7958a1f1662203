// SPDX-License-Identifier: Apache-2.0
#include <preimage/render/svg.hpp>

#include <preimage/error.hpp>

#include <algorithm>
#include <cmath>
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

void SvgCanvas::region(const Point& start, const std::vector<RegionStep>& steps, const Style& s, const std::string& title, bool closed) {
  std::string d = "M";
  d.append(px(start));
  for (const auto& st : steps) {
    if (st.arc_radius <= 0) {
      d.append(" L").append(px(st.to));
    } else {
      // World counter-clockwise is sweep-flag 0 in SVG's y-down coordinates.
      const std::string r = num(st.arc_radius * scale_);
      d.append(" A").append(r).append(",").append(r).append(" 0 ").append(std::abs(st.arc_span) > 3.141592653589793 ? "1" : "0");
      d.append(st.arc_span < 0 ? " 1 " : " 0 ").append(px(st.to));
    }
  }
  if (closed) d.append(" Z");
  body_ += "<path d=\"" + d + "\"" + style_attr(s) + ">" + (title.empty() ? "" : "<title>" + escape(title) + "</title>") + "</path>\n";
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

void SvgCanvas::arrows(const std::vector<Point>& pts, const std::string& colour, double spacing, double size) {
  if (!(spacing > 0) || !std::isfinite(spacing)) return;  // no arrows (spacing 0 would never advance)
  double carry = spacing / 2;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double x0 = margin_ + (pts[i].x() - world_.xmin()) * scale_, y0 = margin_ + (world_.ymax() - pts[i].y()) * scale_;
    const double x1 = margin_ + (pts[i + 1].x() - world_.xmin()) * scale_, y1 = margin_ + (world_.ymax() - pts[i + 1].y()) * scale_;
    const double len = std::hypot(x1 - x0, y1 - y0);
    if (len == 0) continue;
    const double ux = (x1 - x0) / len, uy = (y1 - y0) / len;
    for (double t = carry; t < len; t += spacing) {
      const double cx = x0 + ux * t, cy = y0 + uy * t;
      body_ += "<polygon points=\"" + num(cx + ux * size) + "," + num(cy + uy * size) + " " + num(cx - ux * size - uy * size * 0.7) + "," +
               num(cy - uy * size + ux * size * 0.7) + " " + num(cx - ux * size + uy * size * 0.7) + "," + num(cy - uy * size - ux * size * 0.7) +
               "\" fill=\"" + escape(colour) + "\"/>\n";
    }
    carry = std::fmod(carry - len, spacing);
    if (carry < 0) carry += spacing;
  }
}

void SvgCanvas::path(const std::vector<Point>& pts, const Style& s, const std::string& title, double spacing, double size,
                     std::size_t first_step) {
  body_ += "<g data-path=\"" + std::to_string(first_step) + "\">\n";
  polyline(pts, s, title);
  body_ += "<g data-arrows=\"\">\n";
  arrows(pts, s.stroke, spacing, size);
  body_ += "</g>\n</g>\n";
}

namespace {
// A round tick spacing: 1, 2 or 5 times a power of ten, about `want` ticks over the range.
double tick_step(double range, double want) {
  const double raw = range / want, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}
std::string tick_text(double v, double step) {
  char b[32];
  const int digits = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step)));
  std::snprintf(b, sizeof b, "%.*f", digits, std::fabs(v) < step * 1e-9 ? 0.0 : v);
  return b;
}
constexpr double kAxisLeft = 44, kAxisBottom = 34;
}  // namespace

std::string SvgCanvas::axes() const {
  std::string out;
  const double x_left = margin_, x_right = width_ - margin_, y_top = margin_, y_bottom = height_ - margin_;
  const std::string line = " stroke=\"#555\" stroke-width=\"1\"";
  const std::string text = " font-family=\"sans-serif\" font-size=\"10\" fill=\"#444\"";
  const double wx = world_.xmax() - world_.xmin(), wy = world_.ymax() - world_.ymin();
  const double sx = tick_step(wx, 6), sy = tick_step(wy, std::max(2.0, 6 * wy / std::max(wx, 1e-300)));
  out += "<line x1=\"" + num(x_left) + "\" y1=\"" + num(height_) + "\" x2=\"" + num(x_right) + "\" y2=\"" + num(height_) + "\"" + line + "/>\n";
  for (double v = std::ceil(world_.xmin() / sx) * sx; v <= world_.xmax() + sx * 1e-9; v += sx) {
    const double x = margin_ + (v - world_.xmin()) * scale_;
    out += "<line x1=\"" + num(x) + "\" y1=\"" + num(height_) + "\" x2=\"" + num(x) + "\" y2=\"" + num(height_ + 4) + "\"" + line + "/>";
    out += "<text x=\"" + num(x) + "\" y=\"" + num(height_ + 14) + "\" text-anchor=\"middle\"" + text + ">" + tick_text(v, sx) + "</text>\n";
  }
  out += "<line x1=\"-2\" y1=\"" + num(y_top) + "\" x2=\"-2\" y2=\"" + num(y_bottom) + "\"" + line + "/>\n";
  for (double v = std::ceil(world_.ymin() / sy) * sy; v <= world_.ymax() + sy * 1e-9; v += sy) {
    const double y = margin_ + (world_.ymax() - v) * scale_;
    out += "<line x1=\"-6\" y1=\"" + num(y) + "\" x2=\"-2\" y2=\"" + num(y) + "\"" + line + "/>";
    out += "<text x=\"-8\" y=\"" + num(y + 3) + "\" text-anchor=\"end\"" + text + ">" + tick_text(v, sy) + "</text>\n";
  }
  // Scale bar: one tick step, labelled with its length.
  const double bar = sx * scale_;
  out += "<line x1=\"" + num(x_right - bar) + "\" y1=\"" + num(height_ + 26) + "\" x2=\"" + num(x_right) + "\" y2=\"" + num(height_ + 26) +
         "\" stroke=\"#222\" stroke-width=\"3\"/><text x=\"" + num(x_right - bar - 6) + "\" y=\"" + num(height_ + 30) + "\" text-anchor=\"end\"" +
         text + ">" + tick_text(sx, sx) + (sx == 1 ? " unit" : " units") + "</text>\n";
  return out;
}

void SvgCanvas::legend(const std::string& text, const Style& s) {
  for (auto& [t, st] : legend_)
    if (t == text) return;  // one entry per meaning, however many times it is drawn
  legend_.emplace_back(text, s);
}

std::string SvgCanvas::str() const {
  const double legend_h = legend_.empty() ? 0 : 8 + 18.0 * static_cast<double>(legend_.size());
  const double W = width_ + kAxisLeft, H = height_ + kAxisBottom + legend_h;
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(W) + "\" height=\"" + num(H) + "\" viewBox=\"0 0 " +
                    num(W) + " " + num(H) + "\">\n<rect x=\"0\" y=\"0\" width=\"" + num(W) + "\" height=\"" + num(H) + "\" fill=\"#ffffff\"/>\n";
  out += "<g transform=\"translate(" + num(kAxisLeft) + ",0)\">\n";
  out += body_;
  out += axes();
  double y = height_ + kAxisBottom + 4;
  for (auto& [text, s] : legend_) {
    Style sw = s;
    out += "<rect x=\"" + num(margin_) + "\" y=\"" + num(y + 2) + "\" width=\"22\" height=\"10\"" + style_attr(sw) + "/>";
    out += "<text x=\"" + num(margin_ + 30) + "\" y=\"" + num(y + 11) + "\" font-family=\"sans-serif\" font-size=\"12\">" +
           escape(text) + "</text>\n";
    y += 18;
  }
  out += "</g>\n</svg>\n";
  return out;
}

void SvgCanvas::save(const std::string& path) const {
  std::ofstream f(path);
  f << str();
  if (!f) throw InputError(path + ": cannot write file");
}

std::string panel_grid(const std::vector<std::string>& panels, std::size_t columns, const std::string& note) {
  constexpr double kGap = 8;
  columns = std::max<std::size_t>(1, columns);
  std::string body;
  double width = 0, height = 0, row_h = 0, x = 0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    std::string svg = panels[i];
    const auto root = svg.find("<svg");
    if (root == std::string::npos) continue;
    svg.erase(0, root);
    if (i % columns == 0) height += row_h, row_h = 0, x = 0;
    const double w = std::stod(svg.substr(svg.find("width=\"") + 7));
    const double h = std::stod(svg.substr(svg.find("height=\"") + 8));
    // Nest the panel: its root element placed at its grid position.
    svg.replace(0, 4, "<svg x=\"" + num(x) + "\" y=\"" + num(height) + "\"");
    body += svg;
    row_h = std::max(row_h, h + kGap);
    width = std::max(width, x + w);
    x += w + kGap;
  }
  height += row_h;
  const double total = height + (note.empty() ? 0 : 22);
  std::string text;
  if (!note.empty())
    text = "<text x=\"8\" y=\"" + num(height + 14) + "\" font-family=\"sans-serif\" font-size=\"12\">" + escape(note) + "</text>\n";
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) + "\" height=\"" + num(total) + "\" viewBox=\"0 0 " +
         num(width) + " " + num(total) + "\">\n" + body + text + "</svg>\n";
}

}  // namespace preimage::render
