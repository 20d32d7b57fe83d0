// What every `oceanbox bench` prints and writes: a table of points as Markdown on stdout and
// CSV with the machine and settings in `#` lines, progress on a terminal, medians of samples.
#pragma once
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace ob::game {

/// The machine a bench ran on, for the CSV's comment lines.
struct MachineInfo {
    std::string cpu;       ///< /proc/cpuinfo "model name" ("unknown" if absent)
    int cores = 1;         ///< hardware threads
    std::string renderer;  ///< GL_RENDERER of the current context, or of a probe OSMesa context
};

/// Describes this machine. Uses the current GL context's renderer string when one is
/// current (hasContext), else opens a small headless context to read it ("none" if that fails).
MachineInfo machineInfo(bool hasContext);

/// Median of samples (0 when empty).
double medianOf(std::vector<double> samples);

/// A bench's result table: named columns, one row per point, cells as text.
class BenchTable {
public:
    /// `command`: the bench as typed (first comment line); columns: the CSV header.
    BenchTable(std::string command, std::vector<std::string> columns);
    /// Adds a `# key: value` settings line to the CSV.
    void setting(const std::string& key, const std::string& value);
    /// Appends a row (one cell per column).
    void addRow(std::vector<std::string> cells);
    /// Writes the CSV: comment lines (command, machine, settings), header, rows. Throws
    /// ob::RuntimeError when the file cannot be written.
    void writeCsv(const std::string& path, const MachineInfo& machine) const;
    /// Prints the rows as a Markdown table.
    void printMarkdown(std::FILE* out) const;
    size_t rowCount() const { return m_rows.size(); }

private:
    std::string m_command;
    std::vector<std::string> m_columns;
    std::vector<std::pair<std::string, std::string>> m_settings;
    std::vector<std::vector<std::string>> m_rows;
};

/// A number for a table cell: 4 significant digits for CSV-friendly text without exponents
/// in the usual range (e.g. 1234, 56.78, 0.1234, 0.0001234).
std::string cell(double v);

/// A progress line on stderr, drawn only when stderr is a terminal.
class Progress {
public:
    explicit Progress(std::string bench);
    /// Shows "<bench>: <what> (point/points)".
    void show(const std::string& what, int point, int points);
    /// Clears the line.
    void done();

private:
    std::string m_bench;
    bool m_tty;
    size_t m_width = 0;
};

} // namespace ob::game
