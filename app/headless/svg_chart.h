// SvgChart: charts as SVG documents, for the reports in docs/. A line chart
// (the accuracy report: image error against time, one curve per knob) and
// stacked bars (where a reload's time goes, per example). Small and
// dependency-free: axes with round ticks, a legend.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace rm {

struct ChartSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in the given order
};

// How the y axis maps values: evenly, or by powers of ten, so that curves
// that differ a hundredfold can be read on one chart. A log axis leaves out
// the points at or below 0.
enum class YAxis { Linear, Log };

std::string svg_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                      const std::vector<ChartSeries>& series, YAxis y_axis = YAxis::Linear);

// One horizontal bar per category, made of one segment per series, in order.
struct BarSeries {
  std::string name;
  std::vector<double> values;  // one per category; a missing or negative one counts 0
};

std::string svg_stacked_bars(const std::string& title, const std::string& value_label,
                             const std::vector<std::string>& categories, const std::vector<BarSeries>& series);

}  // namespace rm
