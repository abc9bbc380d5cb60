#include "headless/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rm {
namespace {

constexpr double kWidth = 860, kHeight = 520, kLeft = 70, kRight = 230, kTop = 40, kBottom = 60;

// Twenty distinguishable colours (Tableau 20 order), so no two curves share one.
const char* const kColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
                                "#7f7f7f", "#bcbd22", "#17becf", "#000000", "#aec7e8", "#ffbb78", "#98df8a",
                                "#ff9896", "#c5b0d5", "#c49c94", "#f7b6d2", "#dbdb8d", "#9edae5"};

// About five round tick values covering [lo, hi].
std::vector<double> ticks(double lo, double hi) {
  const double raw = (hi - lo) / 5.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * magnitude) {
      step = m * magnitude;
      break;
    }
  std::vector<double> out;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) out.push_back(v);
  return out;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v == 0.0 ? 0.0 : v);  // a tick at -0 reads "-0"
  return buf;
}

}  // namespace

std::string svg_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                      const std::vector<ChartSeries>& series) {
  double x0 = std::numeric_limits<double>::max(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : series)
    for (auto [x, y] : s.points) {
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (x0 > x1) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  const double padx = std::max(1e-6, (x1 - x0) * 0.05), pady = std::max(1e-6, (y1 - y0) * 0.05);
  x0 = std::max(0.0, x0 - padx), x1 += padx, y0 -= pady, y1 += pady;
  const double plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
  auto px = [&](double x) { return kLeft + (x - x0) / (x1 - x0) * plot_w; };
  auto py = [&](double y) { return kTop + (1.0 - (y - y0) / (y1 - y0)) * plot_h; };

  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(kWidth) + "\" height=\"" +
                    number(kHeight) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += "<text x=\"" + number(kLeft) + "\" y=\"24\" font-size=\"15\">" + escape(title) + "</text>\n";
  for (double t : ticks(x0, x1)) {
    svg += "<line x1=\"" + number(px(t)) + "\" y1=\"" + number(kTop) + "\" x2=\"" + number(px(t)) + "\" y2=\"" +
           number(kTop + plot_h) + "\" stroke=\"#eee\"/>\n";
    svg += "<text x=\"" + number(px(t)) + "\" y=\"" + number(kTop + plot_h + 16) + "\" text-anchor=\"middle\">" +
           number(t) + "</text>\n";
  }
  for (double t : ticks(y0, y1)) {
    svg += "<line x1=\"" + number(kLeft) + "\" y1=\"" + number(py(t)) + "\" x2=\"" + number(kLeft + plot_w) +
           "\" y2=\"" + number(py(t)) + "\" stroke=\"#eee\"/>\n";
    svg += "<text x=\"" + number(kLeft - 6) + "\" y=\"" + number(py(t) + 4) + "\" text-anchor=\"end\">" + number(t) +
           "</text>\n";
  }
  svg += "<rect x=\"" + number(kLeft) + "\" y=\"" + number(kTop) + "\" width=\"" + number(plot_w) + "\" height=\"" +
         number(plot_h) + "\" fill=\"none\" stroke=\"#333\"/>\n";
  svg += "<text x=\"" + number(kLeft + plot_w / 2) + "\" y=\"" + number(kHeight - 18) + "\" text-anchor=\"middle\">" +
         escape(x_label) + "</text>\n";
  svg += "<text transform=\"translate(18," + number(kTop + plot_h / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
         escape(y_label) + "</text>\n";
  for (size_t i = 0; i < series.size(); ++i) {
    const std::string colour = kColours[i % (sizeof kColours / sizeof *kColours)];
    std::string line;
    for (auto [x, y] : series[i].points)
      if (std::isfinite(x) && std::isfinite(y)) line += number(px(x)) + "," + number(py(y)) + " ";
    svg += "<polyline points=\"" + line + "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"1.5\"/>\n";
    for (auto [x, y] : series[i].points)
      if (std::isfinite(x) && std::isfinite(y))
        svg += "<circle cx=\"" + number(px(x)) + "\" cy=\"" + number(py(y)) + "\" r=\"3\" fill=\"" + colour + "\"/>\n";
    const double ly = kTop + 14 + 18.0 * static_cast<double>(i);
    svg += "<line x1=\"" + number(kWidth - kRight + 16) + "\" y1=\"" + number(ly - 4) + "\" x2=\"" +
           number(kWidth - kRight + 36) + "\" y2=\"" + number(ly - 4) + "\" stroke=\"" + colour +
           "\" stroke-width=\"3\"/>\n";
    svg += "<text x=\"" + number(kWidth - kRight + 42) + "\" y=\"" + number(ly) + "\">" + escape(series[i].name) +
           "</text>\n";
  }
  return svg + "</svg>\n";
}

}  // namespace rm
