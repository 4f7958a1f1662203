// SPDX-License-Identifier: Apache-2.0
#include <preimage/pursuit/figures.hpp>

#include <algorithm>
#include <string>

namespace preimage::pursuit {

using geometry::Point;

namespace {
const char* kPursuerColour[] = {"#1a73e8", "#e37400", "#188038", "#a142f4", "#d01884", "#5f6368"};
CGAL::Bbox_2 padded(const geometry::Environment& env, double top = 0.03) {
  const auto b = env.bbox();
  const double m = std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin());
  return {b.xmin() - 0.03 * m, b.ymin() - 0.03 * m, b.xmax() + 0.03 * m, b.ymax() + top * m};
}
}  // namespace

void draw_cells(render::SvgCanvas& c, const ConservativeCells& C, bool labels) {
  const render::Style ext{"none", "#1a73e8", 1.0, 0.9, "4 3"}, bit{"none", "#d93025", 1.0, 0.9, "2 2"};
  for (const auto& s : C.critical()) {
    bool extension = false;
    for (auto& g : s.generators) extension = extension || g.kind == CriticalGenerator::Kind::Extension;
    c.segment(geometry::to_double(s.from), geometry::to_double(s.to), extension ? ext : bit);
  }
  c.legend("critical ray: extension of an edge at a reflex vertex", ext);
  c.legend("critical ray: beyond a bitangent", bit);
  if (!labels || C.size() > 400) return;
  const render::Style dot{"#5f6368", "none", 0, 1.0, ""};
  for (const auto& cell : C.cells()) {
    if (cell.tiny) continue;
    c.point(cell.sample, 1.5, dot);
    c.label(cell.sample, std::to_string(cell.shadows.gaps.size()), 8, "#5f6368");
  }
  c.legend("cell sample, labelled with its number of gaps", dot);
}

void draw_paths(render::SvgCanvas& c, const Paths& paths) {
  for (std::size_t l = 0; l < paths.size(); ++l) {
    const std::string col = kPursuerColour[l % 6];
    const render::Style st{"none", col, 2.0, 0.9, ""}, dot{col, "none", 0, 1.0, ""};
    // Waiting pursuers repeat points: draw distinct ones only.
    std::vector<Point> pts;
    for (auto& p : paths[l])
      if (pts.empty() || pts.back() != p) pts.push_back(p);
    c.path(pts, st, "pursuer " + std::to_string(l + 1));
    c.point(pts.front(), 4, dot, "start of pursuer " + std::to_string(l + 1));
    c.legend("pursuer " + std::to_string(l + 1), st);
  }
}

render::SvgCanvas plan_map_panel(const geometry::Environment& env, const Paths& paths, const std::vector<Point>& guards,
                                 const std::string& caption) {
  const CGAL::Bbox_2 box = padded(env, 0.1);  // room for the caption above
  render::SvgCanvas c(box, kFramePanelWidth, 8);
  c.environment(env);
  draw_paths(c, paths);
  const render::Style post{"#000", "#fff", 1.2, 1.0, ""};
  for (std::size_t i = 0; i < guards.size(); ++i) c.point(guards[i], 4.5, post, "static guard " + std::to_string(i + 1));
  if (!guards.empty()) c.legend("static guard's post", post);
  c.label(Point(box.xmin(), env.bbox().ymax() + 0.035 * (box.xmax() - box.xmin())), caption, 11);
  return c;
}

std::vector<std::size_t> frame_waypoints(std::size_t waypoints, std::size_t count) {
  std::vector<std::size_t> out;
  if (waypoints == 0) return out;
  count = std::max<std::size_t>(1, std::min(count, waypoints));
  for (std::size_t i = 0; i < count; ++i) out.push_back(count == 1 ? 0 : i * (waypoints - 1) / (count - 1));
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string plan_frames_figure(const geometry::Environment& env, const Paths& paths, const std::vector<CheckFrame>& frames,
                               std::size_t columns, const std::vector<std::string>& captions, const render::SvgCanvas* first_panel) {
  const std::size_t panels = frames.size() + (first_panel ? 1 : 0);
  columns = std::max<std::size_t>(1, std::min(columns, panels));
  const double panel = kFramePanelWidth;
  std::vector<std::string> drawn;
  if (first_panel) drawn.push_back(first_panel->str());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& f = frames[i];
    const CGAL::Bbox_2 box = padded(env, 0.1);  // room for the caption above
    render::SvgCanvas c(box, panel, 8);
    c.environment(env);
    const render::Style bad{"#d93025", "#a50e0e", 0.5, 0.55, ""};
    for (auto& region : f.contaminated) c.rings(region, bad);
    for (std::size_t l = 0; l < f.visible.size(); ++l) {
      const std::string col = kPursuerColour[l % 6];
      c.polygon(f.visible[l], {col, col, 0.5, 0.25, ""});
    }
    for (std::size_t l = 0; l < paths.size(); ++l) {
      std::vector<Point> walked(paths[l].begin(), paths[l].begin() + static_cast<std::ptrdiff_t>(std::min(f.waypoint + 1, paths[l].size())));
      c.polyline(walked, {"none", kPursuerColour[l % 6], 1.2, 0.8, "3 2"});
      c.point(f.pursuers[l], 3.5, {kPursuerColour[l % 6], "#000", 0.8, 1.0, ""});
    }
    const std::string caption =
        i < captions.size() ? captions[i]
                            : "waypoint " + std::to_string(f.waypoint) + ": " +
                                  (f.regions == 0 ? "all clear" : std::to_string(f.regions) + " contaminated region" + (f.regions > 1 ? "s" : ""));
    c.label(Point(box.xmin(), env.bbox().ymax() + 0.035 * (box.xmax() - box.xmin())), caption, 11);
    drawn.push_back(c.str());
  }
  return render::panel_grid(drawn, columns,
                            "red: contaminated (the evader may be there); tinted: seen now; white: cleared");
}

}  // namespace preimage::pursuit
