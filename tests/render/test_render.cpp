#include <gtest/gtest.h>
#include <preimage/geometry/generators.hpp>
#include <preimage/render/figures.hpp>
#include <preimage/render/html.hpp>

#include <cmath>
#include <cstdio>

using namespace preimage;

namespace {
std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST(Svg, MapsWorldToPixelsWithYUp) {
  render::SvgCanvas c(CGAL::Bbox_2(0, 0, 10, 5), 120, 10);  // 10 px per unit
  c.point(geometry::Point(0, 5), 2, render::Style{});
  c.point(geometry::Point(10, 0), 2, render::Style{});
  const std::string svg = c.str();
  EXPECT_NE(svg.find("cx=\"10.00\" cy=\"10.00\""), std::string::npos) << svg;   // top-left corner
  EXPECT_NE(svg.find("cx=\"110.00\" cy=\"60.00\""), std::string::npos) << svg;  // bottom-right corner
  EXPECT_NE(svg.find("height=\"104.00\""), std::string::npos) << svg;  // 70 for the drawing, 34 for the x axis
  // Axes in world units along the left and bottom edges, and a scale bar.
  EXPECT_NE(svg.find(">10</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">4</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(" units</text>"), std::string::npos) << svg;
}

TEST(Svg, ArrowsPointTheWayThePathRuns) {
  render::SvgCanvas c(CGAL::Bbox_2(0, 0, 10, 5), 120, 10);
  c.arrows({geometry::Point(0, 1), geometry::Point(10, 1)}, "#000", 30, 5);
  const std::string svg = c.str();
  // Rightward: each arrowhead's tip (first point) lies right of its base.
  std::size_t at = svg.find("<polygon points=\""), arrows = 0;
  while (at != std::string::npos) {
    double tx, ty, bx, by;
    ASSERT_EQ(std::sscanf(svg.c_str() + at + 17, "%lf,%lf %lf,%lf", &tx, &ty, &bx, &by), 4);
    EXPECT_GT(tx, bx);
    ++arrows;
    at = svg.find("<polygon points=\"", at + 1);
  }
  EXPECT_EQ(arrows, 3u);  // 100 px of line: at 15, 45 and 75 px
}

// Arrow spacing 0 (or negative, or NaN) once never advanced along the segment and hung the
// drawing; it draws no arrowheads and the polyline of path() is still there.
TEST(Svg, ArrowSpacingZeroDrawsNoArrows) {
  for (double spacing : {0.0, -5.0, std::nan("")}) {
    render::SvgCanvas c(CGAL::Bbox_2(0, 0, 10, 5), 120, 10);
    c.path({geometry::Point(0, 1), geometry::Point(10, 1), geometry::Point(10, 4)}, render::Style{"none", "#000", 1, 1, ""}, "p", spacing);
    const std::string svg = c.str();
    EXPECT_EQ(svg.find("<polygon points=\""), std::string::npos) << spacing;
    EXPECT_NE(svg.find("<polyline"), std::string::npos) << spacing;
  }
}

TEST(Svg, EscapesTextAndDeduplicatesLegend) {
  render::SvgCanvas c(CGAL::Bbox_2(0, 0, 1, 1));
  c.label(geometry::Point(0.5, 0.5), "a<b & \"c\"");
  c.legend("walls", render::Style{});
  c.legend("walls", render::Style{});
  const std::string svg = c.str();
  EXPECT_NE(svg.find("a&lt;b &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_EQ(count(svg, ">walls</text>"), 1u);
}

TEST(Svg, VisibilityFigureDrawsEveryEdgeWithItsKind) {
  auto env = geometry::generators::office(1, 2);
  geometry::VisibilityIndex index(env);
  auto v = index.compute(geometry::Point(2, 2));
  std::size_t free = 0;
  for (auto& e : v.edges) free += e.kind == geometry::VisibilityEdge::Kind::Free;
  ASSERT_GT(free, 0u);
  render::SvgCanvas c(env.bbox());
  render::draw_visibility(c, v);
  const std::string svg = c.str();
  EXPECT_EQ(count(svg, "<title>free edge"), free);
  EXPECT_EQ(count(svg, "<title>on edge"), v.edges.size() - free);
}

TEST(Html, ReportHoldsSectionsResultsAndFigures) {
  render::HtmlReport r("demo <1>");
  r.section("Geometry");
  r.result("one");
  r.result("two");
  r.figure("<svg></svg>\n", "caption & more");
  const std::string html = r.str();
  EXPECT_NE(html.find("<title>demo &lt;1&gt;</title>"), std::string::npos);
  EXPECT_EQ(count(html, "<li>"), 2u);
  EXPECT_EQ(count(html, "<ul>"), count(html, "</ul>"));
  EXPECT_NE(html.find("<figcaption>caption &amp; more</figcaption>"), std::string::npos);
}
