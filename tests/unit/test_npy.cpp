// NumPy .npy I/O (docs/references.md#contracts field files): byte layout as numpy writes it, round trips, bad files.
#include "core/error.h"
#include "core/npy.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string floatBytes(const std::vector<float>& v) {
    std::string s(v.size() * sizeof(float), '\0');
    std::memcpy(s.data(), v.data(), s.size());
    return s;
}

// The file numpy 1.14+ writes for np.save(p, np.arange(6, dtype='<f4').reshape(2, 3) * 0.5):
// magic, version 1.0, header length 118 (0x76, little-endian), the dict padded with spaces
// so that 10 + 118 = 128 is a multiple of 64, a final '\n', then 6 float32 values.
std::string numpyFile2x3() {
    std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }";
    REQUIRE(dict.size() == 59);
    std::string header = dict + std::string(58, ' ') + "\n";
    REQUIRE(header.size() == 118);
    return std::string("\x93NUMPY\x01\x00\x76\x00", 10) + header + floatBytes({0.0f, 0.5f, 1.0f, 1.5f, 2.0f, 2.5f});
}

// A file whose header dict is `dict`, padded like numpy, followed by `data`.
std::string npyWithDict(const std::string& dict, const std::string& data, char major = 1) {
    std::string header = dict;
    while ((10 + header.size() + 1) % 64 != 0) header += ' ';
    header += '\n';
    std::string pre = std::string("\x93NUMPY", 6) + major + '\0' + char(header.size() & 0xFF) + char(header.size() >> 8);
    return pre + header + data;
}

std::string writeTemp(const std::string& name, const std::string& bytes) {
    return ob::test::writeFile(ob::test::tempPath(name), bytes);
}

} // namespace

TEST_CASE("npy: a file in numpy's exact v1.0 byte layout is read with its shape and values", "[npy]") {
    const std::string path = writeTemp("numpy_2x3.npy", numpyFile2x3());
    ob::NpyArray a = ob::readNpy(path);
    REQUIRE(a.shape == std::vector<size_t>{2, 3});
    REQUIRE(a.data == std::vector<float>{0.0f, 0.5f, 1.0f, 1.5f, 2.0f, 2.5f});
}

TEST_CASE("npy: writeNpy produces numpy's bytes exactly (header padded to 64, ending in newline)", "[npy]") {
    const std::string path = ob::test::tempPath("written_2x3.npy");
    const float values[6] = {0.0f, 0.5f, 1.0f, 1.5f, 2.0f, 2.5f};
    ob::writeNpy(path, {2, 3}, values);
    REQUIRE(readBytes(path) == numpyFile2x3());
    REQUIRE_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST_CASE("npy: round trips keep shape and every bit for rank 0, 1, 3 and empty arrays", "[npy]") {
    for (const auto& shape : {std::vector<size_t>{}, std::vector<size_t>{5}, std::vector<size_t>{2, 3, 4},
                              std::vector<size_t>{0, 3}, std::vector<size_t>{1, 1}}) {
        size_t n = 1;
        for (size_t d : shape) n *= d;
        std::vector<float> data(n);
        for (size_t i = 0; i < n; ++i) data[i] = float(i) * -0.37f + 1e-30f * float(i);
        const std::string path = ob::test::tempPath("roundtrip.npy");
        ob::writeNpy(path, shape, data.data());
        const std::string bytes = readBytes(path);
        const size_t headerLen = size_t(uint8_t(bytes[8])) | size_t(uint8_t(bytes[9])) << 8;
        CHECK((10 + headerLen) % 64 == 0);
        CHECK(bytes[10 + headerLen - 1] == '\n');
        CHECK(bytes.size() == 10 + headerLen + 4 * n);
        ob::NpyArray a = ob::readNpy(path);
        CHECK(a.shape == shape);
        CHECK((n == 0 || std::memcmp(a.data.data(), data.data(), n * sizeof(float)) == 0));  // no null pointers to memcmp
    }
}

TEST_CASE("npy: the 1-D shape is written as numpy's one-element tuple '(5,)'", "[npy]") {
    const std::string path = ob::test::tempPath("shape1d.npy");
    const float v[5] = {};
    ob::writeNpy(path, {5}, v);
    REQUIRE(readBytes(path).find("'shape': (5,), }") != std::string::npos);
}

TEST_CASE("npy: a version 2.0 file (4-byte header length) is read", "[npy]") {
    std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (2,), }";
    while ((12 + header.size() + 1) % 64 != 0) header += ' ';
    header += '\n';
    std::string bytes = std::string("\x93NUMPY\x02\x00", 8) + char(header.size()) + std::string(3, '\0') + header +
                        floatBytes({3.0f, -4.0f});
    ob::NpyArray a = ob::readNpy(writeTemp("v2.npy", bytes));
    REQUIRE(a.shape == std::vector<size_t>{2});
    REQUIRE(a.data == std::vector<float>{3.0f, -4.0f});
}

TEST_CASE("npy: bad files throw InputError naming the file and the problem", "[npy]") {
    const std::string good = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 2), }";
    const std::string four = floatBytes({1, 2, 3, 4});
    struct Bad { const char* name; std::string bytes; const char* problem; };
    const Bad cases[] = {
        {"magic.npy", "PK\x03\x04 this is a zip file, not npy", "bad magic"},
        {"short.npy", std::string("\x93NUM", 4), "bad magic"},
        {"version.npy", npyWithDict(good, four, 3), "unsupported .npy version 3.0"},
        {"f8.npy", npyWithDict("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }", four + four), "'<f8'"},
        {"bigendian.npy", npyWithDict("{'descr': '>f4', 'fortran_order': False, 'shape': (2, 2), }", four), "'>f4'"},
        {"int.npy", npyWithDict("{'descr': '<i4', 'fortran_order': False, 'shape': (2, 2), }", four), "'<i4'"},
        {"fortran.npy", npyWithDict("{'descr': '<f4', 'fortran_order': True, 'shape': (2, 2), }", four), "fortran_order"},
        {"truncated.npy", npyWithDict(good, four.substr(0, 12)), "truncated data"},
        {"noshape.npy", npyWithDict("{'descr': '<f4', 'fortran_order': False, }", four), "'shape'"},
        {"badshape.npy", npyWithDict("{'descr': '<f4', 'fortran_order': False, 'shape': (2, x), }", four), "'shape'"},
        {"header.npy", std::string("\x93NUMPY\x01\x00\xff\x00", 10) + "{'descr'", "truncated .npy header"},
    };
    for (const Bad& c : cases) {
        INFO(c.name);
        const std::string path = writeTemp(c.name, c.bytes);
        try {
            ob::readNpy(path);
            FAIL("no exception for " << c.name);
        } catch (const ob::InputError& e) {
            const std::string msg = e.what();
            CHECK(msg.find(path) != std::string::npos);
            CHECK(msg.find(c.problem) != std::string::npos);
        }
    }
}

TEST_CASE("npy: a missing file throws InputError naming it", "[npy]") {
    const std::string path = ob::test::tempPath("does_not_exist.npy");
    REQUIRE_THROWS_AS(ob::readNpy(path), ob::InputError);
    REQUIRE_THROWS_WITH(ob::readNpy(path), Catch::Contains(path) && Catch::Contains("cannot open"));
}

TEST_CASE("npy: writing into a missing folder throws InputError (the path is the user's) and leaves no file", "[npy]") {
    const std::string path = ob::test::tempPath("no_such_dir") + "/out.npy";
    const float v[1] = {1.0f};
    REQUIRE_THROWS_WITH(ob::writeNpy(path, {1}, v), Catch::Contains("cannot write output '" + path + "'") &&
                                                         Catch::Contains("choose another path"));
    REQUIRE_THROWS_AS(ob::writeNpy(path, {1}, v), ob::InputError);
    REQUIRE_FALSE(std::filesystem::exists(path));
    REQUIRE_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST_CASE("npy: rewriting a file replaces it whole", "[npy]") {
    const std::string path = ob::test::tempPath("rewrite.npy");
    std::vector<float> big(1000, 1.0f), small{2.0f, 3.0f};
    ob::writeNpy(path, {1000}, big.data());
    ob::writeNpy(path, {2}, small.data());
    ob::NpyArray a = ob::readNpy(path);
    REQUIRE(a.shape == std::vector<size_t>{2});
    REQUIRE(a.data == small);
}
