// svg_chart: where the points of a chart land, on a linear and a log axis.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "headless/svg_chart.h"

namespace rm {
namespace {

// The y of each point drawn, in the SVG's coordinates, in order.
std::vector<double> point_ys(const std::string& svg) {
  std::vector<double> ys;
  const std::regex circle(R"re(<circle cx="[-0-9.e]+" cy="([-0-9.e]+)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it)
    ys.push_back(std::stod((*it)[1]));
  return ys;
}

// The tick labels of the y axis (right-aligned left of the plot), in order.
std::vector<std::string> y_ticks(const std::string& svg) {
  std::vector<std::string> labels;
  const std::regex tick(R"re(text-anchor="end">([^<]*)</text>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), tick); it != std::sregex_iterator(); ++it)
    labels.push_back((*it)[1]);
  return labels;
}

TEST(SvgChart, ALogAxisSpacesPowersOfTenEvenly) {
  const std::vector<ChartSeries> series{{"fast", {{0, 10}, {1, 100}, {2, 1000}}}, {"slow", {{0, 5000}}}};
  const std::string svg = svg_chart("t", "x", "ms", series, YAxis::Log);
  const std::vector<double> ys = point_ys(svg);
  ASSERT_EQ(ys.size(), 4u);
  EXPECT_NEAR(ys[0] - ys[1], ys[1] - ys[2], 1e-3) << "10, 100 and 1000 are a decade apart each";
  EXPECT_GT(ys[0] - ys[1], 50) << "and a decade is a good part of the plot";
  EXPECT_EQ(y_ticks(svg), (std::vector<std::string>{"10", "100", "1000"}));

  const std::vector<double> linear = point_ys(svg_chart("t", "x", "ms", series));
  ASSERT_EQ(linear.size(), 4u);
  EXPECT_LT(linear[0] - linear[1], 0.1 * (linear[1] - linear[2])) << "on a linear axis 10 and 100 are close";
}

TEST(SvgChart, ALogAxisLeavesOutWhatItCannotShow) {
  const std::vector<ChartSeries> series{{"s", {{0, 0}, {1, -3}, {2, 2}, {3, 8}, {4, std::nan("")}}}};
  EXPECT_EQ(point_ys(svg_chart("t", "x", "y", series, YAxis::Log)).size(), 2u) << "0 and -3 have no logarithm";
  EXPECT_EQ(point_ys(svg_chart("t", "x", "y", series)).size(), 4u) << "a linear axis shows all but NaN";
  // Less than a decade: its 2 and 5 multiples mark it too.
  EXPECT_EQ(y_ticks(svg_chart("t", "x", "y", series, YAxis::Log)), (std::vector<std::string>{"2", "5"}));
}

}  // namespace
}  // namespace rm
