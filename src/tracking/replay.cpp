// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/tracking/replay.hpp>

#include <chrono>
#include <cmath>
#include <sstream>
#include <vector>

namespace preimage::tracking {

namespace {

struct Tokens {
  std::vector<std::string> t;
  const std::string& where;
  [[noreturn]] void fail(std::size_t k, const std::string& why) const {
    throw InputError(where + ": token " + std::to_string(k + 1) + (k < t.size() ? " (\"" + t[k] + "\")" : " (missing)") +
                     ": " + why);
  }
  double num(std::size_t k) const {
    if (k >= t.size()) fail(k, "expected a number, the line ends");
    try {
      std::size_t used = 0;
      const double v = std::stod(t[k], &used);
      if (used != t[k].size()) fail(k, "expected a number");
      return v;
    } catch (const std::logic_error&) {
      fail(k, "expected a number");
    }
  }
  std::size_t count(std::size_t k) const {
    const double v = num(k);
    if (v < 2 || v > 100000 || v != std::floor(v)) fail(k, "expected a beam count (an integer from 2 to 100000)");
    return static_cast<std::size_t>(v);
  }
};

}  // namespace

double flaser_angle_increment(std::size_t n) {
  // carmen_laser_get_angle_increment: 180 and 360 beams are 181 and 361 with the last
  // beam dropped, so their spacing is not pi / (n - 1).
  if (n == 180 || n == 181) return M_PI / 180;
  if (n == 360 || n == 361) return M_PI / 360;
  if (n == 400 || n == 401) return M_PI / 720;
  return M_PI / static_cast<double>(n - 1);
}

std::optional<Scan> parse_log_line(const std::string& line, double max_range, const std::string& where) {
  std::istringstream in(line);
  Tokens tk{{}, where};
  for (std::string s; in >> s;) tk.t.push_back(s);
  if (tk.t.empty() || tk.t[0][0] == '#') return std::nullopt;
  Scan scan;
  scan.max_range = max_range;
  const std::string& head = tk.t[0];
  if (head == "FLASER") {
    const std::size_t n = tk.count(1);
    scan.angle_min = -M_PI / 2;
    scan.angle_increment = flaser_angle_increment(n);
    for (std::size_t i = 0; i < n; ++i) scan.ranges.push_back(tk.num(2 + i));
    scan.timestamp = tk.num(2 + n + 6);  // after x y theta odom_x odom_y odom_theta
  } else if (head == "ROBOTLASER1") {
    scan.angle_min = tk.num(2);
    const double fov = tk.num(3);
    scan.angle_increment = tk.num(4);
    scan.max_range = tk.num(5);
    const std::size_t n = tk.count(8);
    (void)fov;
    for (std::size_t i = 0; i < n; ++i) scan.ranges.push_back(tk.num(9 + i));
  } else if (std::isalpha(static_cast<unsigned char>(head[0]))) {
    return std::nullopt;  // another CARMEN message (ODOM, PARAM, NEFF, ...)
  } else {
    scan.timestamp = tk.num(0);
    scan.angle_min = tk.num(1);
    scan.angle_increment = tk.num(2);
    for (std::size_t k = 3; k < tk.t.size(); ++k) scan.ranges.push_back(tk.num(k));
  }
  scan.validate(where);
  return scan;
}

ReplayScan replay_scan(const Scan& scan, const TrackerParams& tp, double ahead) {
  ReplayScan r;
  r.timestamp = scan.timestamp;
  const auto t0 = std::chrono::steady_clock::now();
  const Detection det = detect_target(scan, tp.detect);
  const LocalMap map = local_map_without_target(scan, det, tp.map);
  r.vertices = map.size();
  r.solid = map.count(EdgeKind::Solid);
  r.occlusion = map.count(EdgeKind::Occlusion);
  r.range = map.count(EdgeKind::Range);
  std::optional<EscapePathTree> tree;
  if (det.found && (tree = try_escape_path_tree(map, det.center))) {
    r.target_rule = "detected";
  } else {
    // Straight ahead: the beam nearest angle 0.
    const double k0 = std::round(-scan.angle_min / scan.angle_increment);
    std::vector<std::size_t> beams;
    if (k0 >= 0 && k0 < static_cast<double>(scan.ranges.size())) beams.push_back(static_cast<std::size_t>(k0));
    std::size_t longest = 0;
    for (std::size_t i = 1; i < scan.ranges.size(); ++i)
      if (scan.ranges[i] > scan.ranges[longest]) longest = i;
    beams.push_back(longest);
    for (std::size_t b : beams) {
      const double d = std::min(ahead, 0.5 * std::min(scan.ranges[b], scan.max_range));
      const Point p(d * std::cos(scan.angle(b)), d * std::sin(scan.angle(b)));
      if (d > 0 && (tree = try_escape_path_tree(map, p))) {
        r.target_rule = b == beams.front() && beams.size() == 2 ? "ahead" : "longest beam";
        break;
      }
    }
  }
  if (tree) {
    r.target = tree->target;
    const auto risks = escape_risks(map, *tree, tp.risk);
    r.gradient = recursive_average(*tree, risks).gradient;
    r.has_tree = true;
    r.sde = tree->sde();
    r.tree_nodes = tree->nodes.size();
    r.escape_paths = tree->paths.size();
  } else {
    r.target_rule = "none";
  }
  r.micros = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t i = 0; i < scan.ranges.size(); ++i)
    if (scan.ranges[i] < scan.max_range)
      r.points.emplace_back(scan.ranges[i] * std::cos(scan.angle(i)), scan.ranges[i] * std::sin(scan.angle(i)));
  r.map = map;
  r.tree = std::move(tree);
  if (det.found) r.detected = det.center, r.detected_radius = tp.detect.radius;
  return r;
}

}  // namespace preimage::tracking
