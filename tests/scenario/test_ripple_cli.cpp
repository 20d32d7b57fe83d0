// `oceanbox ripple` end to end (docs/references.md#contracts): eq. 1–2 with the fixed boundary on .npy files,
// checked against a naive double-precision reference; bad input exits 2 with a clear message.
#include "core/npy.h"
#include "support/ripple_reference.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// Eq. 1–2, plainly, in double: 8 neighbours at 1/4, interior cells only, new ring 0.
std::vector<double> naiveRipple(int n, int m, std::vector<double> cur, std::vector<double> prev, int steps, double df) {
    for (int k = 0; k < steps; ++k) ob::test::naiveRippleStep(n, m, cur, prev, df);
    return cur;
}

} // namespace

TEST_CASE("ripple CLI: 3 steps at DF 0.9 on a random field match eq. 1-2 computed naively", "[scenario][ripple]") {
    const int n = 24, m = 17;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> dist(-1.0f, 1.0f);
    std::vector<float> h(n * m);
    for (float& v : h) v = dist(rng);
    const std::string in = ob::test::tempPath("cli_in.npy"), out = ob::test::tempPath("cli_out.npy");
    ob::writeNpy(in, {size_t(n), size_t(m)}, h.data());

    auto r = ob::test::runOceanbox("ripple --in " + quoted(in) + " --steps 3 --damping 0.9 --out " + quoted(out));
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    const ob::NpyArray a = ob::readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{size_t(n), size_t(m)});
    const std::vector<double> hd(h.begin(), h.end());
    const std::vector<double> ref = naiveRipple(n, m, hd, hd, 3, 0.9);  // --prev defaults to --in
    for (int i = 0; i < n * m; ++i) REQUIRE(a.data[size_t(i)] == Approx(ref[size_t(i)]).margin(1e-6));
    // The fixed boundary: the output's ring is 0.
    for (int x = 0; x < m; ++x) REQUIRE(a.data[size_t(x)] == 0.0f);
}

TEST_CASE("ripple CLI: --damping 1.5 exits 2 naming the flag", "[scenario][ripple]") {
    const std::string in = ob::test::tempPath("cli_in2.npy"), out = ob::test::tempPath("cli_out2.npy");
    const std::vector<float> h(16, 1.0f);
    ob::writeNpy(in, {4, 4}, h.data());
    auto r = ob::test::runOceanbox("ripple --in " + quoted(in) + " --steps 3 --damping 1.5 --out " + quoted(out));
    INFO(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("--damping") != std::string::npos);
    CHECK(r.output.find("1.5") != std::string::npos);
}

TEST_CASE("ripple CLI: a missing --in file exits 2 naming the file", "[scenario][ripple]") {
    const std::string in = ob::test::tempPath("cli_missing.npy"), out = ob::test::tempPath("cli_out3.npy");
    auto r = ob::test::runOceanbox("ripple --in " + quoted(in) + " --steps 3 --damping 0.9 --out " + quoted(out));
    INFO(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(in) != std::string::npos);
}

TEST_CASE("ripple CLI: a float64 .npy exits 2 naming the file and its dtype", "[scenario][ripple]") {
    // np.save of a float64 [2, 2] array: header padded so 10 + 118 = 128, then 4 doubles.
    std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }";
    header += std::string(128 - 10 - 1 - header.size(), ' ') + "\n";
    std::string bytes = std::string("\x93NUMPY\x01\x00", 8) + char(header.size()) + '\0' + header;
    const double values[4] = {1.0, 2.0, 3.0, 4.0};
    bytes.append(reinterpret_cast<const char*>(values), sizeof values);
    const std::string in = ob::test::writeFile(ob::test::tempPath("cli_f8.npy"), bytes);
    const std::string out = ob::test::tempPath("cli_out4.npy");
    auto r = ob::test::runOceanbox("ripple --in " + quoted(in) + " --steps 1 --damping 0.9 --out " + quoted(out));
    INFO(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(in) != std::string::npos);
    CHECK(r.output.find("<f8") != std::string::npos);
}
