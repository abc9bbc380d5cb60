// Draws columns of a CSV as an SVG line chart with the project's own chart
// (headless/svg_chart), for the reports in docs/.
// Usage: csv_chart [--bars | --log-y] TITLE Y_LABEL COLUMN... < table.csv > chart.svg
// The first column is x and names the x axis; each COLUMN becomes a curve,
// on a y axis of powers of ten with --log-y. An empty cell is a point the
// curve does not have (a series shorter than the others).
// With --bars the first column names the rows instead, and each row is a bar
// of the COLUMNs stacked (Y_LABEL then labels the values).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "headless/svg_chart.h"

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();  // getline drops a last empty cell
  return cells;
}

// A cell's number; NaN (a point left out) for an empty cell.
double value_of(const std::string& cell) { return cell.empty() ? std::nan("") : std::stod(cell); }

}  // namespace

int main(int argc, char** argv) {
  const bool bars = argc > 1 && std::string(argv[1]) == "--bars";
  const bool log_y = argc > 1 && std::string(argv[1]) == "--log-y";
  if (bars || log_y) --argc, ++argv;
  if (argc < 4) {
    std::cerr << "usage: csv_chart [--bars | --log-y] TITLE Y_LABEL COLUMN... < table.csv > chart.svg\n";
    return 2;
  }
  std::string line;
  std::getline(std::cin, line);
  const std::vector<std::string> header = split(line);
  std::vector<rm::ChartSeries> series;
  std::vector<size_t> columns;
  for (int i = 3; i < argc; ++i) {
    const auto it = std::find(header.begin(), header.end(), argv[i]);
    if (it == header.end() || it == header.begin()) {
      std::cerr << "csv_chart: no column '" << argv[i] << "' besides x\n";
      return 2;
    }
    columns.push_back(static_cast<size_t>(it - header.begin()));
    series.push_back({argv[i], {}});
  }
  std::vector<std::string> rows;
  while (std::getline(std::cin, line)) {
    const std::vector<std::string> cells = split(line);
    if (cells.size() != header.size()) continue;
    rows.push_back(cells[0]);
    for (size_t s = 0; s < columns.size(); ++s)
      series[s].points.emplace_back(bars ? 0.0 : value_of(cells[0]), value_of(cells[columns[s]]));
  }
  if (!bars) {
    std::cout << rm::svg_chart(argv[1], header[0], argv[2], series, log_y ? rm::YAxis::Log : rm::YAxis::Linear);
    return 0;
  }
  std::vector<rm::BarSeries> stacked;
  for (const rm::ChartSeries& s : series) {
    stacked.push_back({s.name, {}});
    for (auto [unused, value] : s.points) stacked.back().values.push_back(value);
  }
  std::cout << rm::svg_stacked_bars(argv[1], argv[2], rows, stacked);
  return 0;
}
