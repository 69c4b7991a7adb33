// Coverage figures that stay readable without colour and with many configurations.
#include "analysis/plots.h"

#include <gtest/gtest.h>

#include <set>

#include "analysis/figure_pdf.h"

namespace canopy::analysis {
namespace {

// `n` configurations of two targets over 21 steps, every curve the same (the worst case for
// lines hiding each other).
std::vector<ConfigStatistics> equalConfigs(int n) {
  std::vector<ConfigStatistics> out(n);
  for (ConfigStatistics& s : out) {
    s.dt = 0.5;
    s.uavs = 2;
    s.coverage.assign(2, std::vector<double>(21, 1.0));
    s.coverage_ci.assign(2, std::vector<ConfidenceInterval>(21, ConfidenceInterval{0.8, 1.2}));
  }
  return out;
}

struct Drawn {
  int headings = 0;
  std::vector<const Line*> curves;  // width 2.5 in a panel (not the legend's 40 px samples)
  int markers = 0;
};

Drawn drawn(const Figure& f) {
  Drawn d;
  for (const Shape& shape : f.shapes) {
    if (const auto* l = std::get_if<Label>(&shape); l && l->text.rfind("trajectory ", 0) == 0)
      ++d.headings;
    if (const auto* l = std::get_if<Line>(&shape); l && l->width == 2.5 && l->points.size() > 2)
      d.curves.push_back(l);
    // Opaque polygons are markers: bands and the occlusion shade are translucent.
    if (const auto* p = std::get_if<FilledPolygon>(&shape); p && p->fill.alpha == 1.0) ++d.markers;
  }
  return d;
}

TEST(CoverageFigure, UpToFourConfigurationsShareAPanelEachWithItsOwnDashAndMarker) {
  const std::vector<ConfigStatistics> configs = equalConfigs(4);
  std::vector<const ConfigStatistics*> ptrs;
  for (const ConfigStatistics& s : configs) ptrs.push_back(&s);
  const Figure f = coverageFigure(ptrs, {"a", "b", "c", "d"}, {"I"}, "t");
  const Drawn d = drawn(f);
  EXPECT_EQ(d.headings, 1);
  ASSERT_EQ(d.curves.size(), 4u);
  std::set<Dash> dashes;
  for (const Line* l : d.curves) dashes.insert(l->dash);
  EXPECT_EQ(dashes.size(), 4u);  // solid, dashed, dotted, dash-dot
  // Markers: one per legend row, and on each curve every 4th step (at least 4 steps apart, so
  // that the four series' starts 0, 1, 2, 3 differ): 6, 5, 5, 5 of the 21 steps.
  EXPECT_EQ(d.markers, 4 + 6 + 5 + 5 + 5);
}

TEST(CoverageFigure, MoreThanFourConfigurationsAreFacetedEvenly) {
  EXPECT_EQ(coverageFacets(4), (std::vector<int>{0, 0, 0, 0}));
  EXPECT_EQ(coverageFacets(6), (std::vector<int>{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(coverageFacets(9), (std::vector<int>{0, 0, 0, 1, 1, 1, 2, 2, 2}));
  const std::vector<ConfigStatistics> configs = equalConfigs(6);
  std::vector<const ConfigStatistics*> ptrs;
  for (const ConfigStatistics& s : configs) ptrs.push_back(&s);
  const Figure f = coverageFigure(ptrs, {"a", "b", "c", "d", "e", "f"}, {"I", "II"}, "t");
  const Drawn d = drawn(f);
  EXPECT_EQ(d.headings, 4);  // two targets × two panels
  ASSERT_EQ(d.curves.size(), 12u);
  // Within a panel (three curves in a row) the dashes differ.
  for (std::size_t panel = 0; panel < 4; ++panel) {
    std::set<Dash> dashes;
    for (std::size_t i = 0; i < 3; ++i) dashes.insert(d.curves[3 * panel + i]->dash);
    EXPECT_EQ(dashes.size(), 3u) << "panel " << panel;
  }
}

TEST(Figure, DashPiecesCutALineByItsPattern) {
  // 0 → 30 px along x with 10 on, 5 off: drawn 0–10, 15–25, and 30 exactly ends an "on" run.
  const Line line{{Vec2(0, 0), Vec2(20, 0), Vec2(30, 0)}, 1, {}, Dash::dashed};
  const auto pieces = dashPieces(line);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_DOUBLE_EQ(pieces[0].front().x(), 0.0);
  EXPECT_DOUBLE_EQ(pieces[0].back().x(), 10.0);
  EXPECT_DOUBLE_EQ(pieces[1].front().x(), 15.0);
  EXPECT_DOUBLE_EQ(pieces[1][1].x(), 20.0);  // the corner is kept
  EXPECT_DOUBLE_EQ(pieces[1].back().x(), 25.0);
  EXPECT_EQ(dashPieces(Line{{Vec2(0, 0), Vec2(5, 0)}, 1, {}, Dash::solid}).size(), 1u);
}

// A figure as PDF (issue 51: figures for a paper): one page of the figure's size in points,
// the same bytes for the same figure (no creation date), and the shapes inside it.
TEST(FigurePdf, OnePageOfTheFiguresSizeAndTheSameBytesEveryTime) {
  Figure figure;
  figure.width = 320;
  figure.height = 200;
  addRect(figure, 10, 10, 100, 60, seriesColour(1));
  figure.shapes.emplace_back(Line{{Vec2(0, 0), Vec2(300, 190)}, 2, kInk, Dash::dash_dot});
  figure.shapes.emplace_back(Label{Vec2(160, 100), "coverage", 12, Anchor::middle, kInk});
  const std::string pdf = toPdf(figure);
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("/MediaBox [ 0 0 320 200 ]"), std::string::npos) << pdf.substr(0, 2000);
  EXPECT_EQ(pdf.find("/CreationDate"), std::string::npos);
  EXPECT_EQ(toPdf(figure), pdf);
  Figure empty = figure;
  empty.shapes.clear();
  EXPECT_LT(toPdf(empty).size(), pdf.size());
}

}  // namespace
}  // namespace canopy::analysis
