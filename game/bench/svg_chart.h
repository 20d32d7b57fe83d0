// A small SVG chart writer for the benches: axes with ticks (linear or log10), a legend, one
// line with markers per series (dashed for a paper's numbers), or one bar per category.
#pragma once
#include <string>
#include <vector>

namespace ob::game {

/// One line of a chart: points (x, y); points with a non-finite or (on a log axis)
/// non-positive coordinate are left out.
struct ChartSeries {
    std::string label;
    std::vector<double> x, y;  ///< same length
    bool reference = false;    ///< a paper's numbers: dashed line, open markers
    int colour = -1;           ///< palette index (the paper's series takes its partner's); −1: by position
};

/// A line chart, or a bar chart when `categories` is set (one bar per category from the
/// first series' y, drawn as one path).
struct Chart {
    std::string title;
    std::string xLabel, yLabel;
    bool logX = false, logY = false;
    std::vector<ChartSeries> series;
    std::vector<std::string> categories;  ///< bar chart: one label per bar, top to bottom
};

/// The chart as an SVG document (starts with "<svg").
std::string chartSvg(const Chart& chart);

/// Writes chartSvg(chart) to path. Throws ob::RuntimeError when the file cannot be written.
void writeChart(const std::string& path, const Chart& chart);

} // namespace ob::game
