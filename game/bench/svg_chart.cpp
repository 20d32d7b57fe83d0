// SVG charts for the benches: a fixed layout (plot, legend on the right), ticks at the data's
// x values on a log axis when there are few of them (bench sweeps), else at decades.
#include "bench/svg_chart.h"

#include "core/error.h"
#include "core/file_write.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

namespace ob::game {

namespace {

constexpr double WIDTH = 780, HEIGHT = 470;
constexpr double LEFT = 74, TOP = 46, RIGHT_GAP = 232, BOTTOM_GAP = 58;
constexpr int MAX_DATA_TICKS = 14;
const char* const PALETTE[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2",
                               "#7f7f7f", "#bcbd22"};

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

// Tick label: 1, 2.5, 30, 1k, 100k, 0.01.
std::string tickLabel(double v) {
    char buf[32];
    if (std::fabs(v) >= 1e6 && std::fmod(v, 1e6) == 0) std::snprintf(buf, sizeof buf, "%gM", v / 1e6);
    else if (std::fabs(v) >= 1000 && std::fmod(v, 1000) == 0) std::snprintf(buf, sizeof buf, "%gk", v / 1000);
    else std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// A step of 1, 2, 2.5 or 5 × 10^k giving about `count` intervals over span.
double niceStep(double span, int count) {
    const double raw = span / count;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (m * p >= raw) return m * p;
    return 10 * p;
}

// One axis: data range → pixels, and its ticks.
struct Axis {
    bool log = false;
    double lo = 0, hi = 1;        // in axis units (log10 when log)
    double p0 = 0, p1 = 1;        // pixels of lo and hi
    std::vector<double> ticks;    // data values
    double map(double v) const {
        const double u = log ? std::log10(v) : v;
        return p0 + (u - lo) / (hi - lo) * (p1 - p0);
    }
};

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

Axis makeAxis(const std::vector<double>& values, bool log, double p0, double p1, bool dataTicks) {
    Axis a;
    a.log = log;
    a.p0 = p0;
    a.p1 = p1;
    double mn = HUGE_VAL, mx = -HUGE_VAL;
    for (double v : values) {
        mn = std::min(mn, v);
        mx = std::max(mx, v);
    }
    if (!(mn <= mx)) mn = mx = log ? 1 : 0;
    if (log) {
        std::set<double> distinct(values.begin(), values.end());
        if (dataTicks && int(distinct.size()) <= MAX_DATA_TICKS && distinct.size() >= 2) {
            a.lo = std::log10(mn);
            a.hi = std::log10(mx);
            const double pad = 0.04 * (a.hi - a.lo);
            a.lo -= pad;
            a.hi += pad;
            a.ticks.assign(distinct.begin(), distinct.end());
        } else {
            a.lo = std::floor(std::log10(mn));
            a.hi = std::ceil(std::log10(mx));
            if (a.hi <= a.lo) a.hi = a.lo + 1;
            for (double e = a.lo; e <= a.hi + 1e-9; ++e) a.ticks.push_back(std::pow(10.0, e));
        }
        return a;
    }
    double lo = std::min(0.0, mn), hi = mx > lo ? mx : lo + 1;
    const double step = niceStep(hi - lo, 5);
    lo = std::floor(lo / step) * step;
    hi = std::ceil(hi * 1.02 / step) * step;
    a.lo = lo;
    a.hi = hi;
    for (double t = lo; t <= hi + step * 1e-6; t += step) a.ticks.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
    return a;
}

void header(std::ostringstream& s, double w, double h, const std::string& title) {
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(w) << "\" height=\"" << num(h)
      << "\" viewBox=\"0 0 " << num(w) << " " << num(h) << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s << "<text x=\"" << num(std::min(w, WIDTH) / 2) << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" << escape(title)
      << "</text>\n";
}

std::string lineChart(const Chart& c) {
    // The legend takes the right side, as wide as its longest label (about 7 px a character).
    size_t longest = 0;
    for (const ChartSeries& sr : c.series) longest = std::max(longest, sr.label.size());
    const double legend = std::max(RIGHT_GAP, 56.0 + 7.0 * double(longest));
    const double width = WIDTH - RIGHT_GAP + legend;
    const double x0 = LEFT, x1 = WIDTH - RIGHT_GAP, y0 = HEIGHT - BOTTOM_GAP, y1 = TOP;
    std::vector<double> xs, ys;
    for (const ChartSeries& s : c.series)
        for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
            if (usable(s.x[i], c.logX) && usable(s.y[i], c.logY)) {
                xs.push_back(s.x[i]);
                ys.push_back(s.y[i]);
            }
    const Axis ax = makeAxis(xs, c.logX, x0, x1, true), ay = makeAxis(ys, c.logY, y0, y1, false);

    std::ostringstream s;
    header(s, width, HEIGHT, c.title);
    // --- grid and ticks
    s << "<g stroke=\"#e4e4e4\">\n";
    for (double t : ay.ticks) s << "<line x1=\"" << num(x0) << "\" x2=\"" << num(x1) << "\" y1=\"" << num(ay.map(t)) << "\" y2=\"" << num(ay.map(t)) << "\"/>\n";
    for (double t : ax.ticks) s << "<line y1=\"" << num(y0) << "\" y2=\"" << num(y1) << "\" x1=\"" << num(ax.map(t)) << "\" x2=\"" << num(ax.map(t)) << "\"/>\n";
    s << "</g>\n<g fill=\"#333\">\n";
    for (double t : ay.ticks)
        s << "<text x=\"" << num(x0 - 6) << "\" y=\"" << num(ay.map(t) + 4) << "\" text-anchor=\"end\">" << tickLabel(t) << "</text>\n";
    for (double t : ax.ticks)
        s << "<text x=\"" << num(ax.map(t)) << "\" y=\"" << num(y0 + 16) << "\" text-anchor=\"middle\">" << tickLabel(t) << "</text>\n";
    s << "</g>\n";
    // --- axes and labels
    s << "<path d=\"M" << num(x0) << " " << num(y1) << " V" << num(y0) << " H" << num(x1) << "\" stroke=\"#333\" fill=\"none\"/>\n";
    s << "<text x=\"" << num((x0 + x1) / 2) << "\" y=\"" << num(HEIGHT - 16) << "\" text-anchor=\"middle\">"
      << escape(c.xLabel + (c.logX ? " (log)" : "")) << "</text>\n";
    s << "<text transform=\"translate(18 " << num((y0 + y1) / 2) << ") rotate(-90)\" text-anchor=\"middle\">"
      << escape(c.yLabel + (c.logY ? " (log)" : "")) << "</text>\n";
    // --- series: a polyline and markers each, legend entry on the right
    for (size_t k = 0; k < c.series.size(); ++k) {
        const ChartSeries& sr = c.series[k];
        const std::string colour = PALETTE[size_t(sr.colour >= 0 ? sr.colour : int(k)) % std::size(PALETTE)];
        std::string points;
        std::ostringstream markers;
        for (size_t i = 0; i < std::min(sr.x.size(), sr.y.size()); ++i) {
            if (!usable(sr.x[i], c.logX) || !usable(sr.y[i], c.logY)) continue;
            const double px = ax.map(sr.x[i]), py = ay.map(sr.y[i]);
            if (!points.empty()) points += ' ';
            points.append(num(px)).append(",").append(num(py));
            if (sr.reference)
                markers << "<rect x=\"" << num(px - 3.5) << "\" y=\"" << num(py - 3.5) << "\" width=\"7\" height=\"7\"/>\n";
            else
                markers << "<circle cx=\"" << num(px) << "\" cy=\"" << num(py) << "\" r=\"3.5\"/>\n";
        }
        s << "<g class=\"series\" stroke=\"" << colour << "\" fill=\"" << (sr.reference ? "white" : colour) << "\">\n";
        s << "<title>" << escape(sr.label) << "</title>\n";
        s << "<polyline fill=\"none\" stroke-width=\"2\"" << (sr.reference ? " stroke-dasharray=\"6 4\"" : "")
          << " points=\"" << points << "\"/>\n";
        s << markers.str() << "</g>\n";
        const double ly = TOP + 8 + 20.0 * double(k), lx = x1 + 16;
        s << "<line x1=\"" << num(lx) << "\" x2=\"" << num(lx + 26) << "\" y1=\"" << num(ly) << "\" y2=\"" << num(ly)
          << "\" stroke=\"" << colour << "\" stroke-width=\"2\"" << (sr.reference ? " stroke-dasharray=\"6 4\"" : "") << "/>\n";
        s << "<text x=\"" << num(lx + 32) << "\" y=\"" << num(ly + 4) << "\" fill=\"#333\">" << escape(sr.label) << "</text>\n";
    }
    s << "</svg>\n";
    return s.str();
}

std::string barChart(const Chart& c) {
    const std::vector<double> values = c.series.empty() ? std::vector<double>{} : c.series.front().y;
    const size_t n = c.categories.size();
    const double barH = 18, gap = 8, left = 190, right = 90;
    const double height = TOP + double(n) * (barH + gap) + BOTTOM_GAP;
    const double x0 = left, x1 = WIDTH - right, y0 = height - BOTTOM_GAP;
    std::vector<double> finite;
    for (size_t i = 0; i < std::min(n, values.size()); ++i)
        if (std::isfinite(values[i])) finite.push_back(std::max(0.0, values[i]));
    const Axis ax = makeAxis(finite, false, x0, x1, false);

    std::ostringstream s;
    header(s, WIDTH, height, c.title);
    s << "<g stroke=\"#e4e4e4\">\n";
    for (double t : ax.ticks) s << "<line y1=\"" << num(TOP) << "\" y2=\"" << num(y0) << "\" x1=\"" << num(ax.map(t)) << "\" x2=\"" << num(ax.map(t)) << "\"/>\n";
    s << "</g>\n<g fill=\"#333\">\n";
    for (double t : ax.ticks)
        s << "<text x=\"" << num(ax.map(t)) << "\" y=\"" << num(y0 + 16) << "\" text-anchor=\"middle\">" << tickLabel(t) << "</text>\n";
    s << "</g>\n";
    s << "<text x=\"" << num((x0 + x1) / 2) << "\" y=\"" << num(height - 16) << "\" text-anchor=\"middle\">" << escape(c.xLabel)
      << "</text>\n";
    std::string d;
    std::ostringstream labels;
    for (size_t i = 0; i < n; ++i) {
        const double y = TOP + double(i) * (barH + gap);
        const double v = i < values.size() && std::isfinite(values[i]) ? std::max(0.0, values[i]) : 0.0;
        const double w = ax.map(v) - x0;
        d.append("M").append(num(x0)).append(" ").append(num(y)).append(" h").append(num(w)).append(" v");
        d.append(num(barH)).append(" h").append(num(-w)).append(" Z ");
        labels << "<text x=\"" << num(x0 - 6) << "\" y=\"" << num(y + barH - 5) << "\" text-anchor=\"end\">"
               << escape(c.categories[i]) << "</text>\n";
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3g", v);
        labels << "<text x=\"" << num(x0 + w + 4) << "\" y=\"" << num(y + barH - 5) << "\">" << buf << "</text>\n";
    }
    const std::string label = c.series.empty() ? std::string() : c.series.front().label;
    s << "<g class=\"series\"><title>" << escape(label) << "</title><path d=\"" << d << "\" fill=\"" << PALETTE[0]
      << "\"/></g>\n";
    s << "<g fill=\"#333\">\n" << labels.str() << "</g>\n";
    s << "<path d=\"M" << num(x0) << " " << num(TOP) << " V" << num(y0) << " H" << num(x1) << "\" stroke=\"#333\" fill=\"none\"/>\n";
    s << "</svg>\n";
    return s.str();
}

} // namespace

std::string chartSvg(const Chart& chart) { return chart.categories.empty() ? lineChart(chart) : barChart(chart); }

void writeChart(const std::string& path, const Chart& chart) {
    writeFileWhole(path, "chart", [&](std::ostream& out) { out << chartSvg(chart); });
}

} // namespace ob::game
