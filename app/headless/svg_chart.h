// SvgChart: a line chart as an SVG document, for the accuracy report (image
// error against time, one curve per knob). Small and dependency-free: axes
// with round ticks, one polyline with dots per series, a legend.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace rm {

struct ChartSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in the given order
};

std::string svg_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                      const std::vector<ChartSeries>& series);

}  // namespace rm
