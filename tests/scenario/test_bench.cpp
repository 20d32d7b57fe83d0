// `oceanbox bench` end to end on tiny sweeps (docs/references.md#paper-experiments, docs/references.md#contracts): each bench writes a CSV of the
// papers' table form (its header, one row per point, machine and settings in # lines), prints
// the Markdown table, and draws an SVG chart with one line per series; bad flags exit 2.
// Timings are never checked: benchmarks are not tests.
#include "support/test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using ob::test::runOceanbox;
using ob::test::tempPath;

namespace {

struct Csv {
    std::vector<std::string> comments;
    std::string header;
    std::vector<std::vector<std::string>> rows;
};

Csv readCsv(const std::string& path) {
    Csv csv;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("#", 0) == 0) {
            csv.comments.push_back(line);
        } else if (csv.header.empty()) {
            csv.header = line;
        } else {
            std::vector<std::string> cells;
            std::stringstream ss(line);
            for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
            if (!line.empty() && line.back() == ',') cells.emplace_back();
            csv.rows.push_back(cells);
        }
    }
    return csv;
}

std::string readText(const std::string& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

size_t countOf(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// The CSV has the header, `rows` rows of as many cells, the machine line and a settings line.
void checkCsv(const std::string& path, const std::string& header, size_t rows) {
    const Csv csv = readCsv(path);
    CHECK(csv.header == header);
    REQUIRE(csv.rows.size() == rows);
    const size_t columns = size_t(countOf(header, ",") + 1);
    for (const auto& row : csv.rows) CHECK(row.size() == columns);
    REQUIRE(csv.comments.size() >= 3);
    CHECK(csv.comments[0].find("# oceanbox bench") == 0);
    CHECK(csv.comments[1].find("# machine: cpu ") == 0);
    CHECK(csv.comments[1].find("; cores ") != std::string::npos);
    CHECK(csv.comments[1].find("; gl ") != std::string::npos);
}

// Well-formed enough: an <svg> document with at least `series` polylines or paths in series groups.
void checkSvg(const std::string& path, size_t series) {
    const std::string svg = readText(path);
    CHECK(svg.rfind("<svg", 0) == 0);
    CHECK(svg.find("</svg>") != std::string::npos);
    CHECK(countOf(svg, "<g class=\"series\"") >= series);
    CHECK(countOf(svg, "<polyline") + countOf(svg, "<path d=\"M") >= series);
}

} // namespace

TEST_CASE("bench spheres: one row per fish count, the Table 5 columns, our curve and the paper's", "[bench]") {
    const std::string csv = tempPath("spheres.csv"), svg = tempPath("spheres.svg");
    auto r = runOceanbox("bench spheres --counts 1,50 --frames 3 --warmup 1 --out " + csv + " --chart " + svg);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK(r.output.find("| count | fps | ms_frame | ms_stamp | ms_step |") != std::string::npos);
    checkCsv(csv, "count,fps,ms_frame,ms_stamp,ms_step", 2);
    CHECK(readCsv(csv).rows[1][0] == "50");
    checkSvg(svg, 2);
    // The reference path (stepSphere per fish) runs the same sweep.
    r = runOceanbox("bench spheres --counts 1,20 --frames 2 --warmup 0 --stamping sequential --out " + csv);
    CHECK(r.exitCode == 0);
    checkCsv(csv, "count,fps,ms_frame,ms_stamp,ms_step", 2);
}

TEST_CASE("bench spheres --render draws the ripple field and adds the render time", "[bench]") {
    const std::string csv = tempPath("spheres_render.csv");
    auto r = runOceanbox("bench spheres --counts 1,10 --render --size 64x48 --field 32 --radius-cells 4 --frames 2 "
                         "--warmup 1 --out " + csv);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    checkCsv(csv, "count,fps,ms_frame,ms_stamp,ms_step,ms_render", 2);
}

TEST_CASE("bench fields: scene x size x (full, spheres only) rows in Table 3's form", "[bench]") {
    const std::string csv = tempPath("fields.csv"), svg = tempPath("fields.svg");
    auto r = runOceanbox("bench fields --sizes 16,32 --scenes default --frames 2 --warmup 1 --size 64x48 "
                         "--set ocean.resolution=32 --out " + csv + " --chart " + svg);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    checkCsv(csv, "scene,size,render,fps,ms_frame", 4);
    const Csv table = readCsv(csv);
    CHECK(table.rows[0][2] == "full");
    CHECK(table.rows[1][2] == "spheres_only");
    checkSvg(svg, 3);  // ours full and spheres only, the paper's
    r = runOceanbox("bench fields --sizes 16,32 --scenes config/scenes/default.toml --no-render --frames 2 --warmup 0 "
                    "--set ocean.resolution=32 --out " + csv);
    CHECK(r.exitCode == 0);
    checkCsv(csv, "scene,size,render,fps,ms_frame", 2);
}

TEST_CASE("bench ocean: size x backend rows with the [Lee2007] columns and FFTW alone", "[bench]") {
    const std::string csv = tempPath("ocean.csv"), svg = tempPath("ocean.svg");
    auto r = runOceanbox("bench ocean --sizes 16,32 --backend cpu,gpu --frames 2 --warmup 1 --size 64x48 --out " + csv +
                         " --chart " + svg);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    checkCsv(csv, "size,backend,fps_sim_render,fps_sim,ms_fft,ms_fftw", 4);
    CHECK(readCsv(csv).rows[1][1] == "gpu");
    checkSvg(svg, 7);  // sim + render, sim, FFT per backend, FFTW alone; then the paper's
}

TEST_CASE("bench frame: one row per phase and timed span, as a bar chart", "[bench]") {
    const std::string csv = tempPath("frame.csv"), svg = tempPath("frame.svg");
    auto r = runOceanbox("bench frame default --size 64x48 --frames 3 --warmup 1 --set ocean.resolution=32 --out " + csv +
                         " --chart " + svg);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    const Csv table = readCsv(csv);
    CHECK(table.header == "pass,ms");
    std::vector<std::string> names;
    for (const auto& row : table.rows) names.push_back(row.at(0));
    for (const char* want : {"frame", "input", "script", "physics", "interaction", "ocean", "render"})
        CHECK(std::find(names.begin(), names.end(), want) != names.end());
    checkSvg(svg, 1);
}

TEST_CASE("bench sea: one row per run and their median, the change's frame and phase times", "[bench][sea_live]") {
    const std::string csv = tempPath("sea.csv");
    auto r = runOceanbox("bench sea default --size 64x48 --runs 2 --warmup 1 --before 3 --after 4 --preset calm "
                         "--set ocean.resolution=32 --out " + csv);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    const Csv table = readCsv(csv);
    CHECK(table.header == "run,median_ms,max_before_ms,max_change_ms,change_frame_ms,max_over_median,script_change_ms,"
                          "ocean_median_ms,ocean_max_change_ms");
    REQUIRE(table.rows.size() == 3);
    CHECK(table.rows.back().at(0) == "median");
}

TEST_CASE("bench: bad flags exit 2 with a message naming the flag", "[bench]") {
    const struct {
        const char* args;
        const char* message;
    } cases[] = {
        {"bench spheres --counts 0,10", "--counts"},
        {"bench spheres --counts 1,ten", "--counts"},
        {"bench spheres --frobnicate", "--frobnicate"},
        {"bench spheres --stamping magic", "--stamping"},
        {"bench spheres --render --size 3x3", "--size"},
        {"bench spheres --out /no/such/dir/x.csv", "/no/such/dir/x.csv"},
        {"bench fields --scenes no_such_scene", "no_such_scene"},
        {"bench fields --sizes 100", "--sizes"},
        {"bench ocean --sizes 48", "--sizes"},
        {"bench ocean --backend vulkan", "--backend"},
        {"bench frame", "scene"},
        {"bench frame default --frames 0", "--frames"},
        {"bench sea --preset hurricane", "--preset"},
        {"bench sea --runs 0", "--runs"},
        {"bench warp", "warp"},
        {"bench", "bench"},
    };
    for (const auto& c : cases) {
        auto r = runOceanbox(c.args);
        INFO(c.args << ": " << r.output);
        CHECK(r.exitCode == 2);
        CHECK(r.output.find(c.message) != std::string::npos);
    }
}
