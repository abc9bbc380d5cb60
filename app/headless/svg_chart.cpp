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

// Ticks for a log axis over [lo, hi] (both > 0): the powers of ten, and
// their 2 and 5 multiples too when the range holds fewer than three powers.
std::vector<double> log_ticks(double lo, double hi) {
  std::vector<double> out;
  for (const bool multiples : {false, true}) {
    out.clear();
    for (double decade = std::pow(10.0, std::floor(std::log10(lo))); decade <= hi; decade *= 10)
      for (double m : multiples ? std::vector<double>{1, 2, 5} : std::vector<double>{1})
        if (m * decade >= lo * (1 - 1e-9) && m * decade <= hi * (1 + 1e-9)) out.push_back(m * decade);
    if (out.size() >= 3) break;
  }
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

const char* colour_of(size_t i) { return kColours[i % (sizeof kColours / sizeof *kColours)]; }

// The document's start: white ground and the title.
std::string begin_svg(const std::string& title, double height) {
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(kWidth) + "\" height=\"" +
                    number(height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  return svg + "<text x=\"" + number(kLeft) + "\" y=\"24\" font-size=\"15\">" + escape(title) + "</text>\n";
}

// Series i's colour and name, right of the plot.
std::string legend_entry(size_t i, const std::string& name) {
  const double ly = kTop + 14 + 18.0 * static_cast<double>(i);
  return "<line x1=\"" + number(kWidth - kRight + 16) + "\" y1=\"" + number(ly - 4) + "\" x2=\"" +
         number(kWidth - kRight + 36) + "\" y2=\"" + number(ly - 4) + "\" stroke=\"" + colour_of(i) +
         "\" stroke-width=\"3\"/>\n<text x=\"" + number(kWidth - kRight + 42) + "\" y=\"" + number(ly) + "\">" +
         escape(name) + "</text>\n";
}

}  // namespace

std::string svg_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                      const std::vector<ChartSeries>& series, YAxis y_axis) {
  // y0 and y1 are on the axis's own scale: log10 of the values on a log axis.
  const bool log_y = y_axis == YAxis::Log;
  auto shown = [&](double x, double y) { return std::isfinite(x) && std::isfinite(y) && (!log_y || y > 0); };
  auto on_axis = [&](double y) { return log_y ? std::log10(y) : y; };
  double x0 = std::numeric_limits<double>::max(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : series)
    for (auto [x, y] : s.points) {
      if (!shown(x, y)) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, on_axis(y)), y1 = std::max(y1, on_axis(y));
    }
  if (x0 > x1) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  const double padx = std::max(1e-6, (x1 - x0) * 0.05), pady = std::max(1e-6, (y1 - y0) * 0.05);
  x0 = std::max(0.0, x0 - padx), x1 += padx, y0 -= pady, y1 += pady;
  const double plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
  auto px = [&](double x) { return kLeft + (x - x0) / (x1 - x0) * plot_w; };
  auto py = [&](double y) { return kTop + (1.0 - (on_axis(y) - y0) / (y1 - y0)) * plot_h; };

  std::string svg = begin_svg(title, kHeight);
  for (double t : ticks(x0, x1)) {
    svg += "<line x1=\"" + number(px(t)) + "\" y1=\"" + number(kTop) + "\" x2=\"" + number(px(t)) + "\" y2=\"" +
           number(kTop + plot_h) + "\" stroke=\"#eee\"/>\n";
    svg += "<text x=\"" + number(px(t)) + "\" y=\"" + number(kTop + plot_h + 16) + "\" text-anchor=\"middle\">" +
           number(t) + "</text>\n";
  }
  for (double t : log_y ? log_ticks(std::pow(10.0, y0), std::pow(10.0, y1)) : ticks(y0, y1)) {
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
    const std::string colour = colour_of(i);
    std::string line;
    for (auto [x, y] : series[i].points)
      if (shown(x, y)) line += number(px(x)) + "," + number(py(y)) + " ";
    svg += "<polyline points=\"" + line + "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"1.5\"/>\n";
    for (auto [x, y] : series[i].points)
      if (shown(x, y))
        svg += "<circle cx=\"" + number(px(x)) + "\" cy=\"" + number(py(y)) + "\" r=\"3\" fill=\"" + colour + "\"/>\n";
    svg += legend_entry(i, series[i].name);
  }
  return svg + "</svg>\n";
}

std::string svg_stacked_bars(const std::string& title, const std::string& value_label,
                             const std::vector<std::string>& categories, const std::vector<BarSeries>& series) {
  constexpr double kRow = 26, kBar = 18, kNames = 150;
  auto value = [&](size_t s, size_t c) {
    const auto& v = series[s].values;
    return c < v.size() && std::isfinite(v[c]) && v[c] > 0 ? v[c] : 0.0;
  };
  double top = 0;
  for (size_t c = 0; c < categories.size(); ++c) {
    double sum = 0;
    for (size_t s = 0; s < series.size(); ++s) sum += value(s, c);
    top = std::max(top, sum);
  }
  if (top <= 0) top = 1;
  const std::vector<double> marks = ticks(0, top * 1.05);
  const double hi = std::max(top, marks.back());
  const double left = kLeft + kNames, plot_w = kWidth - left - kRight;
  const double plot_h = kRow * static_cast<double>(categories.size()) + 8;
  auto px = [&](double v) { return left + v / hi * plot_w; };

  std::string svg = begin_svg(title, kTop + plot_h + kBottom);
  for (double t : marks) {
    svg += "<line x1=\"" + number(px(t)) + "\" y1=\"" + number(kTop) + "\" x2=\"" + number(px(t)) + "\" y2=\"" +
           number(kTop + plot_h) + "\" stroke=\"#eee\"/>\n";
    svg += "<text x=\"" + number(px(t)) + "\" y=\"" + number(kTop + plot_h + 16) + "\" text-anchor=\"middle\">" +
           number(t) + "</text>\n";
  }
  for (size_t c = 0; c < categories.size(); ++c) {
    const double y = kTop + 4 + kRow * static_cast<double>(c);
    svg += "<text x=\"" + number(left - 8) + "\" y=\"" + number(y + kBar - 5) + "\" text-anchor=\"end\">" +
           escape(categories[c]) + "</text>\n";
    double at = 0;
    for (size_t s = 0; s < series.size(); ++s) {
      const double v = value(s, c);
      svg += "<rect x=\"" + number(px(at)) + "\" y=\"" + number(y) + "\" width=\"" + number(px(at + v) - px(at)) +
             "\" height=\"" + number(kBar) + "\" fill=\"" + colour_of(s) + "\"/>\n";
      at += v;
    }
  }
  svg += "<rect x=\"" + number(left) + "\" y=\"" + number(kTop) + "\" width=\"" + number(plot_w) + "\" height=\"" +
         number(plot_h) + "\" fill=\"none\" stroke=\"#333\"/>\n";
  svg += "<text x=\"" + number(left + plot_w / 2) + "\" y=\"" + number(kTop + plot_h + 40) +
         "\" text-anchor=\"middle\">" + escape(value_label) + "</text>\n";
  for (size_t s = 0; s < series.size(); ++s) svg += legend_entry(s, series[s].name);
  return svg + "</svg>\n";
}

}  // namespace rm
