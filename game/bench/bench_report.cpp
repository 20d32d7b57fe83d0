// Bench output: CSV with comment lines, Markdown on stdout, terminal progress, machine info.
#include "bench/bench_report.h"

#include "core/error.h"
#include "core/file_write.h"
#include "gfx/gl.h"
#include "platform/platform.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <thread>
#include <unistd.h>

namespace ob::game {

MachineInfo machineInfo(bool hasContext) {
    MachineInfo m;
    m.cpu = "unknown";
    std::ifstream info("/proc/cpuinfo");
    for (std::string line; std::getline(info, line);) {
        if (line.rfind("model name", 0) != 0) continue;
        const size_t colon = line.find(':');
        if (colon != std::string::npos) m.cpu = line.substr(line.find_first_not_of(" \t", colon + 1));
        break;
    }
    m.cores = int(std::max(1u, std::thread::hardware_concurrency()));
    if (hasContext) {
        m.renderer = gfx::glRendererName();
    } else {
        try {
            auto probe = platform::createHeadlessPlatform({16, 16});
            m.renderer = gfx::glRendererName();
        } catch (const std::exception&) {
            m.renderer = "none";
        }
    }
    return m;
}

double medianOf(std::vector<double> samples) {
    if (samples.empty()) return 0.0;
    const size_t mid = samples.size() / 2;
    std::nth_element(samples.begin(), samples.begin() + long(mid), samples.end());
    const double hi = samples[mid];
    if (samples.size() % 2) return hi;
    return 0.5 * (*std::max_element(samples.begin(), samples.begin() + long(mid)) + hi);
}

BenchTable::BenchTable(std::string command, std::vector<std::string> columns)
    : m_command(std::move(command)), m_columns(std::move(columns)) {}

void BenchTable::setting(const std::string& key, const std::string& value) { m_settings.emplace_back(key, value); }

void BenchTable::addRow(std::vector<std::string> cells) {
    cells.resize(m_columns.size());
    m_rows.push_back(std::move(cells));
}

void BenchTable::writeCsv(const std::string& path, const MachineInfo& machine) const {
    writeFileWhole(path, "CSV", [&](std::ostream& out) {
        out << "# " << m_command << "\n";
        out << "# machine: cpu " << machine.cpu << "; cores " << machine.cores << "; gl " << machine.renderer << "\n";
        for (const auto& [key, value] : m_settings) out << "# " << key << ": " << value << "\n";
        for (size_t c = 0; c < m_columns.size(); ++c) out << (c ? "," : "") << m_columns[c];
        out << "\n";
        for (const auto& row : m_rows) {
            for (size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << row[c];
            out << "\n";
        }
    });
}

void BenchTable::printMarkdown(std::FILE* out) const {
    const auto printRow = [out](const std::vector<std::string>& cells) {
        std::fputc('|', out);
        for (const auto& c : cells) std::fprintf(out, " %s |", c.c_str());
        std::fputc('\n', out);
    };
    printRow(m_columns);
    std::fputc('|', out);
    for (size_t c = 0; c < m_columns.size(); ++c) std::fputs("---|", out);
    std::fputc('\n', out);
    for (const auto& row : m_rows) printRow(row);
    std::fflush(out);
}

std::string cell(double v) {
    if (!std::isfinite(v)) return "";
    char buf[32];
    const double a = std::fabs(v);
    if (a >= 1000.0 || a == 0.0) std::snprintf(buf, sizeof buf, "%.0f", v);
    else if (a >= 100.0) std::snprintf(buf, sizeof buf, "%.1f", v);
    else if (a >= 10.0) std::snprintf(buf, sizeof buf, "%.2f", v);
    else if (a >= 1.0) std::snprintf(buf, sizeof buf, "%.3f", v);
    else std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

Progress::Progress(std::string bench) : m_bench(std::move(bench)), m_tty(isatty(STDERR_FILENO) != 0) {}

void Progress::show(const std::string& what, int point, int points) {
    if (!m_tty) return;
    const std::string line = "oceanbox bench " + m_bench + ": " + what + " (" + std::to_string(point) + "/" +
                             std::to_string(points) + ")";
    std::fprintf(stderr, "\r%s%*s", line.c_str(), int(m_width > line.size() ? m_width - line.size() : 0), "");
    std::fflush(stderr);
    m_width = line.size();
}

void Progress::done() {
    if (!m_tty || m_width == 0) return;
    std::fprintf(stderr, "\r%*s\r", int(m_width), "");
    std::fflush(stderr);
    m_width = 0;
}

} // namespace ob::game
