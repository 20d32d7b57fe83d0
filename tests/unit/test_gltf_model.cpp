// glTF loading: hand-written files whose every number is known (a unit right tetrahedron
// moved by its node), each kind of corrupt file, and the committed models' geometry against
// the dimensions they are documented with (closed, outward, Archimedes' sphere volume).
#include "assets/model.h"
#include "core/error.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <map>
#include <random>
#include <sys/stat.h>
#include <tuple>

using ob::InputError;
using ob::assets::loadGltfModel;
using ob::assets::ModelData;
using ob::test::tempPath;
using ob::test::writeFile;

namespace {

constexpr double PI = 3.14159265358979323846;

std::string base64(const std::string& bytes) {
    static const char* ALPHABET = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
        for (int k = 3; k >= 0; --k) out += ALPHABET[(v >> (6 * k)) & 63];
    }
    if (i + 1 == bytes.size()) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        out += ALPHABET[(v >> 18) & 63];
        out += ALPHABET[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == bytes.size()) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8;
        out += ALPHABET[(v >> 18) & 63];
        out += ALPHABET[(v >> 12) & 63];
        out += ALPHABET[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

template <class T> void append(std::string& bytes, std::initializer_list<T> values) {
    for (T v : values) bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// The unit right tetrahedron O, X, Y, Z; faces counter-clockwise seen from outside.
const std::vector<glm::vec3> TETRA = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<uint32_t> TETRA_FACES = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

// Buffer: 4 float positions (48 bytes), 12 indices (24 bytes of u16), then 4 float normals
// (48 bytes) pointing away from the centroid.
std::string tetraBytes() {
    std::string b;
    for (const glm::vec3& p : TETRA) append<float>(b, {p.x, p.y, p.z});
    for (uint32_t i : TETRA_FACES) append<uint16_t>(b, {uint16_t(i)});
    for (const glm::vec3& p : TETRA) {
        glm::vec3 n = glm::normalize(p - glm::vec3(0.25f));
        append<float>(b, {n.x, n.y, n.z});
    }
    return b;
}

struct TetraOptions {
    bool normals = true;
    std::string node = R"("translation": [1, 2, 3], "scale": [2, 2, 2])";
    std::string uri;               // "" = embedded base64 of `bytes`
    std::string bytes = tetraBytes();
    size_t byteLength = 0;         // 0 = bytes.size()
    int positionCount = 4;
    int mode = 4;
    std::string extraAttributes;   // appended inside "attributes"
    std::string extraJson;         // appended at the top level
};

std::string tetraJson(const TetraOptions& o) {
    const std::string uri = o.uri.empty() ? "data:application/octet-stream;base64," + base64(o.bytes) : o.uri;
    const size_t length = o.byteLength ? o.byteLength : o.bytes.size();
    return R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0, )" + o.node + R"(}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0)" +
           std::string(o.normals ? R"(, "NORMAL": 2)" : "") + o.extraAttributes + R"(}, "indices": 1, "material": 0, "mode": )" +
           std::to_string(o.mode) + R"(}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1.0]}}],
  "buffers": [{"byteLength": )" + std::to_string(length) + R"(, "uri": ")" + uri + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 48, "byteLength": 24},
                  {"buffer": 0, "byteOffset": 72, "byteLength": 48}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" + std::to_string(o.positionCount) +
           R"(, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]},
                {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"},
                {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC3"}])" +
           o.extraJson + "\n}\n";
}

std::string writeTetra(const TetraOptions& o, const std::string& name = "tetra.gltf") {
    return writeFile(tempPath(name), tetraJson(o));
}

// A .glb: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with zeros.
std::string glb(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out = "glTF";
    append<uint32_t>(out, {2u, uint32_t(12 + 8 + json.size() + 8 + bin.size())});
    append<uint32_t>(out, {uint32_t(json.size()), 0x4E4F534Au});
    out += json;
    append<uint32_t>(out, {uint32_t(bin.size()), 0x004E4942u});
    out += bin;
    return out;
}

// `text` with the one occurrence of `from` replaced (the test fails if there is none).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

// The InputError message of loading `path` ("" if it loaded).
std::string loadError(const std::string& path) {
    try {
        loadGltfModel(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

double signedVolume(const ModelData& m) {
    double v = 0.0;
    for (size_t k = 0; k + 2 < m.indices.size(); k += 3) {
        glm::dvec3 a = m.positions[m.indices[k]], b = m.positions[m.indices[k + 1]], c = m.positions[m.indices[k + 2]];
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

glm::dvec3 faceNormal(const ModelData& m, size_t k) {
    glm::dvec3 a = m.positions[m.indices[k]], b = m.positions[m.indices[k + 1]], c = m.positions[m.indices[k + 2]];
    return glm::cross(b - a, c - a);
}

} // namespace

// --- hand-written files ------------------------------------------------------------------

TEST_CASE("a hand-written glTF tetrahedron loads with its node's translation and scale, exact indices and colour", "[gltf]") {
    ModelData m = loadGltfModel(writeTetra({}));
    REQUIRE(m.positions.size() == 4);
    for (size_t i = 0; i < 4; ++i) CHECK(m.positions[i] == 2.0f * TETRA[i] + glm::vec3(1, 2, 3));  // exact in binary
    CHECK(m.indices == TETRA_FACES);
    REQUIRE(m.colors.size() == 4);
    for (const glm::vec3& c : m.colors) CHECK(c == glm::vec3(0.2f, 0.4f, 0.6f));
    REQUIRE(m.normals.size() == 4);
    for (size_t i = 0; i < 4; ++i) {  // a uniform scale keeps directions
        glm::vec3 expected = glm::normalize(TETRA[i] - glm::vec3(0.25f));
        CHECK(glm::length(m.normals[i] - expected) < 1e-6f);
    }
    CHECK(m.boundsMin == glm::vec3(1, 2, 3));
    CHECK(m.boundsMax == glm::vec3(3, 4, 5));
    CHECK(signedVolume(m) == Approx(8.0 / 6.0));  // scale 2 → 2³ × 1/6
}

TEST_CASE("without NORMAL every triangle gets its own flat face normal", "[gltf]") {
    TetraOptions o;
    o.normals = false;
    ModelData m = loadGltfModel(writeTetra(o));
    REQUIRE(m.indices.size() == 12);
    REQUIRE(m.positions.size() == 12);
    const glm::vec3 expected[4] = {{0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, glm::vec3(1.0f) / std::sqrt(3.0f)};
    for (size_t f = 0; f < 4; ++f)
        for (size_t j = 0; j < 3; ++j) {
            uint32_t v = m.indices[3 * f + j];
            CHECK(m.positions[v] == 2.0f * TETRA[TETRA_FACES[3 * f + j]] + glm::vec3(1, 2, 3));
            CHECK(glm::length(m.normals[v] - expected[f]) < 1e-6f);
        }
}

TEST_CASE("node hierarchies compose parent matrix and child rotation and a mirror keeps faces outward", "[gltf]") {
    TetraOptions o;
    // Parent: a translation by (10, 0, 0) as a column-major matrix; child: 90° about +y,
    // which takes +x to −z and +z to +x.
    o.node = R"("rotation": [0, 0.7071067811865476, 0, 0.7071067811865476]}, {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 10,0,0,1], "children": [0])";
    std::string json = tetraJson(o);
    json = replaced(json, R"("nodes": [0])", R"("nodes": [1])");
    ModelData m = loadGltfModel(writeFile(tempPath("tree.gltf"), json));
    REQUIRE(m.positions.size() == 4);
    const glm::vec3 expected[4] = {{10, 0, 0}, {10, 0, -1}, {10, 1, 0}, {11, 0, 0}};
    for (size_t i = 0; i < 4; ++i) CHECK(glm::length(m.positions[i] - expected[i]) < 1e-6f);
    CHECK(glm::length(m.normals[1] - glm::normalize(glm::vec3(-0.25f, -0.25f, -0.75f))) < 1e-5f);

    o = TetraOptions();
    o.node = R"("scale": [-1, 1, 1])";
    m = loadGltfModel(writeTetra(o, "mirror.gltf"));
    CHECK(m.positions[1] == glm::vec3(-1, 0, 0));
    CHECK(signedVolume(m) == Approx(1.0 / 6.0));  // winding flipped with the mirror
    for (size_t k = 0; k < m.indices.size(); k += 3) {
        glm::dvec3 n = m.normals[m.indices[k]] + m.normals[m.indices[k + 1]] + m.normals[m.indices[k + 2]];
        CHECK(glm::dot(faceNormal(m, k), n) > 0.0);
    }
}

TEST_CASE("COLOR_0 multiplies the material's baseColorFactor and normalized bytes read as c/255", "[gltf]") {
    TetraOptions o;
    append<uint8_t>(o.bytes, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 51, 102, 255, 255});
    o.extraAttributes = R"(, "COLOR_0": 3)";
    std::string json = tetraJson(o);
    json = replaced(json, R"({"buffer": 0, "byteOffset": 72, "byteLength": 48})", R"({"buffer": 0, "byteOffset": 72, "byteLength": 48}, {"buffer": 0, "byteOffset": 120, "byteLength": 16})");
    json = replaced(json, R"("count": 4, "type": "VEC3"}])", R"("count": 4, "type": "VEC3"}, {"bufferView": 3, "componentType": 5121, "normalized": true, "count": 4, "type": "VEC4"}])");
    ModelData m = loadGltfModel(writeFile(tempPath("colors.gltf"), json));
    REQUIRE(m.colors.size() == 4);
    CHECK(glm::length(m.colors[0] - glm::vec3(0.2f, 0.0f, 0.0f)) < 1e-6f);
    CHECK(glm::length(m.colors[1] - glm::vec3(0.0f, 0.4f, 0.0f)) < 1e-6f);
    CHECK(glm::length(m.colors[2] - glm::vec3(0.0f, 0.0f, 0.6f)) < 1e-6f);
    CHECK(glm::length(m.colors[3] - glm::vec3(0.2f * 0.2f, 0.4f * 0.4f, 0.6f)) < 1e-6f);
}

TEST_CASE("u8 and u32 indices and non-indexed triangles give the same triangles as u16", "[gltf]") {
    const std::vector<glm::vec3> expected = {{1, 2, 3}, {3, 2, 3}, {1, 4, 3}, {1, 2, 5}};
    auto check = [&](const ModelData& m) {
        REQUIRE(m.indices.size() == 12);
        for (size_t k = 0; k < 12; ++k) CHECK(m.positions[m.indices[k]] == expected[TETRA_FACES[k]]);
    };
    for (int componentType : {5121, 5125}) {
        TetraOptions o;
        o.bytes.resize(48);
        for (uint32_t i : TETRA_FACES) {
            if (componentType == 5121) append<uint8_t>(o.bytes, {uint8_t(i)});
            else append<uint32_t>(o.bytes, {i});
        }
        const size_t indexBytes = o.bytes.size() - 48;
        o.normals = false;
        std::string json = tetraJson(o);
        json = replaced(json, R"("byteOffset": 48, "byteLength": 24)", R"("byteOffset": 48, "byteLength": )" + std::to_string(indexBytes));
        json = replaced(json, R"("componentType": 5123)", R"("componentType": )" + std::to_string(componentType));
        json = replaced(json, R"({"buffer": 0, "byteOffset": 72, "byteLength": 48})", R"({"buffer": 0, "byteLength": 4})");
        INFO("componentType " << componentType);
        check(loadGltfModel(writeFile(tempPath("indices.gltf"), json)));
    }
    // Non-indexed: the 12 corners written out in order.
    TetraOptions o;
    o.bytes.clear();
    for (uint32_t i : TETRA_FACES) append<float>(o.bytes, {TETRA[i].x, TETRA[i].y, TETRA[i].z});
    o.normals = false;
    o.positionCount = 12;
    std::string json = tetraJson(o);
    json = replaced(json, R"("indices": 1, )", "");
    json = replaced(json, R"("byteOffset": 0, "byteLength": 48)", R"("byteOffset": 0, "byteLength": 144)");
    json = replaced(json, R"("byteOffset": 48, "byteLength": 24)", R"("byteOffset": 0, "byteLength": 24)");
    json = replaced(json, R"("byteOffset": 72, "byteLength": 48)", R"("byteOffset": 0, "byteLength": 48)");
    ModelData m = loadGltfModel(writeFile(tempPath("soup.gltf"), json));
    REQUIRE(m.indices.size() == 12);
    for (size_t k = 0; k < 12; ++k) CHECK(m.positions[m.indices[k]] == expected[TETRA_FACES[k]]);
}

TEST_CASE("a sparse accessor without a buffer view reads as zeros with its substitutions applied", "[gltf]") {
    const ModelData reference = loadGltfModel(writeTetra({}));
    TetraOptions o;
    append<uint8_t>(o.bytes, {3, 1, 2, 0});  // substitution targets (the fourth byte is padding)
    std::string json = tetraJson(o);
    json = replaced(json, R"({"buffer": 0, "byteOffset": 72, "byteLength": 48})",
                    R"({"buffer": 0, "byteOffset": 72, "byteLength": 48}, {"buffer": 0, "byteOffset": 120, "byteLength": 4})");
    // Positions: no buffer view (zeros); 3 substitutions put the first three values of
    // bufferView 0 (corners O, X, Y) at elements 3, 1, 2.
    json = replaced(json, R"({"bufferView": 0, "componentType": 5126, "count": 4,)",
                    R"({"componentType": 5126, "sparse": {"count": 3, "indices": {"bufferView": 3, "componentType": 5121},
                        "values": {"bufferView": 0}}, "count": 4,)");
    ModelData m = loadGltfModel(writeFile(tempPath("sparse.gltf"), json));
    // Targets 3, 1, 2 take values TETRA[0], TETRA[1], TETRA[2]; element 0 stays zero.
    const glm::vec3 corners[4] = {{0, 0, 0}, TETRA[1], TETRA[2], TETRA[0]};
    for (size_t i = 0; i < 4; ++i) CHECK(m.positions[i] == 2.0f * corners[i] + glm::vec3(1, 2, 3));
    CHECK(m.indices == reference.indices);
}

TEST_CASE("a .glb and a .gltf with an external .bin load the same as the embedded .gltf", "[gltf]") {
    const ModelData reference = loadGltfModel(writeTetra({}));

    std::string json = tetraJson({});
    const size_t uri = json.find(", \"uri\"");
    json.erase(uri, json.find('}', uri) - uri);  // buffer 0 without uri: the BIN chunk
    const std::string path = tempPath("tetra.glb");
    writeFile(path, glb(json, tetraBytes()));
    ModelData m = loadGltfModel(path);
    CHECK(m.positions == reference.positions);
    CHECK(m.indices == reference.indices);
    CHECK(m.normals == reference.normals);
    CHECK(m.colors == reference.colors);

    const std::string bin = tempPath("tetra.bin");
    writeFile(bin, tetraBytes());
    TetraOptions o;
    o.uri = std::filesystem::path(bin).filename().string();
    m = loadGltfModel(writeTetra(o, "external.gltf"));
    CHECK(m.positions == reference.positions);
    CHECK(m.indices == reference.indices);
}

TEST_CASE("missing, truncated, short, out-of-range and non-triangle files each raise InputError naming the path", "[gltf]") {
    auto expectError = [](const std::string& path, const std::string& part) {
        std::string e = loadError(path);
        INFO(e);
        CHECK(e.rfind(path + ": ", 0) == 0);
        CHECK(e.find(part) != std::string::npos);
        CHECK(e.find('\n') == std::string::npos);
    };
    expectError(tempPath("nowhere.gltf"), "cannot open file (no such file)");
    expectError(writeFile(tempPath("empty.gltf"), ""), "empty");

    const std::string text = tetraJson({});
    expectError(writeFile(tempPath("truncated.gltf"), text.substr(0, text.size() / 2)), "glTF");

    TetraOptions shortBuffer;  // the buffer holds 40 bytes, the positions' view claims 48
    shortBuffer.bytes = tetraBytes().substr(0, 40);
    shortBuffer.normals = false;
    expectError(writeTetra(shortBuffer, "short.gltf"), "buffer");

    TetraOptions tooMany;  // 5 positions of 12 bytes in a 48-byte view
    tooMany.positionCount = 5;
    expectError(writeTetra(tooMany, "count.gltf"), "do not fit in bufferView 0");

    TetraOptions badIndex;
    badIndex.bytes = tetraBytes();
    uint16_t seven = 7;
    std::memcpy(&badIndex.bytes[48 + 2 * 5], &seven, 2);
    expectError(writeTetra(badIndex, "index.gltf"), "index 7 (element 5) is out of range");

    TetraOptions lines;
    lines.mode = 1;
    expectError(writeTetra(lines, "lines.gltf"), "no triangles");

    TetraOptions cycle;
    cycle.node = R"("children": [0])";
    expectError(writeTetra(cycle, "cycle.gltf"), "appears twice");

    expectError(writeFile(tempPath("not.glb"), glb("{", "")), "glTF");
    std::string glbBytes = glb(tetraJson({}), tetraBytes());
    expectError(writeFile(tempPath("cut.glb"), glbBytes.substr(0, glbBytes.size() - 30)), "glTF");
}

TEST_CASE("a buffer uri that leaves the model's folder is refused: plain, percent-encoded, absolute or through a symlink",
          "[gltf][hostile]") {
    namespace fs = std::filesystem;
    const std::string root = tempPath("confined");
    fs::create_directories(root + "/models/sub");
    // A valid buffer outside the model's folder: loading it would succeed, so a model that
    // loads has read outside.
    writeFile(root + "/secret.bin", tetraBytes());
    writeFile(root + "/models/sub/tetra.bin", tetraBytes());
    fs::create_symlink(root + "/secret.bin", root + "/models/link.bin");
    auto model = [&](const std::string& uri, const std::string& name) {
        TetraOptions o;
        o.uri = uri;
        return writeFile(root + "/models/" + name, tetraJson(o));
    };
    CHECK(loadError(model("sub/tetra.bin", "below.gltf")).empty());
    CHECK(loadError(model("sub/%74etra.bin", "encoded_below.gltf")).empty());
    const std::pair<std::string, std::string> escapes[] = {
        {"../secret.bin", "up.gltf"},           {"%2E%2E/secret.bin", "encoded.gltf"}, {"%2e%2e%2fsecret.bin", "slash.gltf"},
        {root + "/secret.bin", "absolute.gltf"}, {"link.bin", "symlink.gltf"},      {"sub/../../secret.bin", "round.gltf"},
        {"../../../../../../../../etc/passwd", "passwd.gltf"}};
    for (const auto& [uri, name] : escapes) {
        const std::string path = model(uri, name);
        const std::string e = loadError(path);
        INFO(uri << ": " << e);
        CHECK(e.rfind(path + ": external file uri '", 0) == 0);
        CHECK(e.find("leads outside the model's folder " + fs::canonical(root + "/models").string()) != std::string::npos);
    }
}

TEST_CASE("a buffer that is a named pipe or a folder is refused at once", "[gltf][hostile]") {
    namespace fs = std::filesystem;
    const std::string folder = tempPath("pipe_model");
    fs::create_directories(folder + "/dir.bin");
    REQUIRE(::mkfifo((folder + "/pipe.bin").c_str(), 0644) == 0);
    TetraOptions o;
    o.uri = "pipe.bin";
    const std::string piped = writeFile(folder + "/piped.gltf", tetraJson(o));
    const std::optional<std::string> e = ob::test::inputErrorWithin(5.0, [&] { loadGltfModel(piped); });
    REQUIRE(e.has_value());  // no hang
    CHECK(e->find(piped + ": external file uri 'pipe.bin': ") == 0);
    CHECK(e->find("is not a regular file (a named pipe (FIFO))") != std::string::npos);
    o.uri = "dir.bin";
    CHECK(loadError(writeFile(folder + "/dir.gltf", tetraJson(o))).find("is a folder") != std::string::npos);
    // The model itself.
    CHECK(loadError(folder + "/pipe.bin") == folder + "/pipe.bin: is not a regular file (a named pipe (FIFO)); give a file");
}

TEST_CASE("a required extension, a glTF 1.x asset and a version 1 GLB are refused (glTF 2.0 §3.12, §4.4)", "[gltf][hostile]") {
    TetraOptions required;
    required.extraJson = R"(, "extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"])";
    CHECK(loadError(writeTetra(required, "required.gltf"))
              .find("requires the extension \"KHR_draco_mesh_compression\", which oceanbox does not implement") != std::string::npos);
    TetraOptions used;  // used but not required: ignored, the file loads
    used.extraJson = R"(, "extensionsUsed": ["KHR_materials_unlit"])";
    CHECK(loadError(writeTetra(used, "used.gltf")).empty());

    const std::string old = replaced(tetraJson({}), R"("version": "2.0")", R"("version": "1.0")");
    CHECK(loadError(writeFile(tempPath("old.gltf"), old)).find("asset.version \"1.0\" is not 2.x") != std::string::npos);

    TetraOptions embeddedBin;
    embeddedBin.uri = "x";
    std::string json = replaced(tetraJson(embeddedBin), R"(, "uri": "x")", "");
    std::string v1 = glb(json, tetraBytes());
    v1[4] = 1;
    CHECK(loadError(writeFile(tempPath("v1.glb"), v1)).find("GLB container version 1 (only version 2 is read)") != std::string::npos);
    CHECK(loadError(writeFile(tempPath("v2.glb"), glb(json, tetraBytes()))).empty());
}

TEST_CASE("ten thousand corrupted copies of a valid file load or raise InputError, never anything else", "[gltf]") {
    std::string json = tetraJson({});
    const size_t uri = json.find(", \"uri\"");
    std::string glbJson = json;
    glbJson.erase(uri, glbJson.find('}', uri) - uri);
    const std::string originals[2] = {json, glb(glbJson, tetraBytes())};
    std::mt19937 rng(12345);
    const std::string path = "fuzz.gltf";
    int loaded = 0, rejected = 0;
    for (int round = 0; round < 5000; ++round)
        for (const std::string& original : originals) {
            std::string bytes = original;
            const int edits = 1 + int(rng() % 4);
            for (int e = 0; e < edits; ++e) {
                size_t at = rng() % bytes.size();
                switch (rng() % 4) {
                case 0: bytes[at] = char(rng()); break;                            // any byte
                case 1: bytes[at] = "0123456789-.e"[rng() % 13]; break;            // a number's characters
                case 2: bytes.erase(at, 1 + rng() % 8); break;                     // a gap
                default: bytes.insert(at, std::string(1 + rng() % 3, char('0' + rng() % 10))); break;
                }
                if (bytes.empty()) bytes.push_back('x');
            }
            try {
                ModelData m = ob::assets::parseGltfModel(std::vector<unsigned char>(bytes.begin(), bytes.end()), path);
                for (uint32_t i : m.indices) REQUIRE(i < m.positions.size());
                REQUIRE(m.normals.size() == m.positions.size());
                REQUIRE(m.colors.size() == m.positions.size());
                ++loaded;
            } catch (const InputError& e) {
                REQUIRE(std::string(e.what()).rfind(path + ": ", 0) == 0);
                ++rejected;
            }
        }
    CHECK(loaded > 0);
    CHECK(rejected > 0);
}

// --- the committed models --------------------------------------------------------------

namespace {

std::string modelPath(const char* name) { return std::string(OCEANBOX_SOURCE_DIR) + "/assets/models/" + name + ".gltf"; }

// Indices in range and by threes, unit normals, every triangle wound so that its face
// normal agrees with its corners' normals, and every edge met once in each direction once
// corners are welded by position (closed, consistently oriented surfaces).
void checkWellFormed(const ModelData& m) {
    REQUIRE(!m.indices.empty());
    REQUIRE(m.indices.size() % 3 == 0);
    REQUIRE(m.normals.size() == m.positions.size());
    for (uint32_t i : m.indices) REQUIRE(i < m.positions.size());
    for (const glm::vec3& n : m.normals) REQUIRE(std::abs(glm::length(n) - 1.0f) < 1e-4f);

    int against = 0;
    for (size_t k = 0; k < m.indices.size(); k += 3) {
        glm::dvec3 n = glm::dvec3(m.normals[m.indices[k]]) + glm::dvec3(m.normals[m.indices[k + 1]]) +
                       glm::dvec3(m.normals[m.indices[k + 2]]);
        if (glm::dot(faceNormal(m, k), n) <= 0.0) ++against;
    }
    CHECK(against == 0);

    using Key = std::tuple<long, long, long>;
    std::map<Key, int> welded;
    std::vector<int> id(m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec3& p = m.positions[i];
        Key key{std::lround(p.x * 1e5), std::lround(p.y * 1e5), std::lround(p.z * 1e5)};
        id[i] = welded.emplace(key, int(welded.size())).first->second;
    }
    std::map<std::pair<int, int>, int> edges;
    for (size_t k = 0; k < m.indices.size(); k += 3)
        for (int j = 0; j < 3; ++j) edges[{id[m.indices[k + j]], id[m.indices[k + (j + 1) % 3]]}]++;
    int open = 0;
    for (const auto& [edge, count] : edges) {
        auto back = edges.find({edge.second, edge.first});
        if (back == edges.end() || back->second != count) ++open;
    }
    CHECK(open == 0);
    CHECK(signedVolume(m) > 0.0);

    glm::vec3 lo = m.positions.front(), hi = lo;
    for (const glm::vec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    CHECK(m.boundsMin == lo);
    CHECK(m.boundsMax == hi);
}

// Area of each distinct colour among the triangles that pass `where` (by centroid).
template <class Pred> std::map<std::tuple<float, float, float>, double> colourAreas(const ModelData& m, Pred where) {
    std::map<std::tuple<float, float, float>, double> areas;
    for (size_t k = 0; k < m.indices.size(); k += 3) {
        glm::vec3 centroid = (m.positions[m.indices[k]] + m.positions[m.indices[k + 1]] + m.positions[m.indices[k + 2]]) / 3.0f;
        if (!where(centroid)) continue;
        const glm::vec3& c = m.colors[m.indices[k]];
        areas[{c.x, c.y, c.z}] += 0.5 * glm::length(faceNormal(m, k));
    }
    return areas;
}

glm::vec3 dominant(const std::map<std::tuple<float, float, float>, double>& areas) {
    double best = -1.0;
    glm::vec3 colour(0.0f);
    for (const auto& [c, a] : areas)
        if (a > best) {
            best = a;
            colour = glm::vec3(std::get<0>(c), std::get<1>(c), std::get<2>(c));
        }
    return colour;
}

} // namespace

TEST_CASE("ship.gltf: closed and outward, hull 3 × 1.5 × 10 m about the origin with the bow at +z, rig up to about 7 m, brown hull and off-white sail", "[gltf][models]") {
    ModelData m = loadGltfModel(modelPath("ship"));
    checkWellFormed(m);
    CHECK(m.boundsMin.x == Approx(-1.5f).margin(1e-4));
    CHECK(m.boundsMax.x == Approx(1.5f).margin(1e-4));
    CHECK(m.boundsMin.z == Approx(-5.0f).margin(1e-4));
    CHECK(m.boundsMax.z == Approx(5.0f).margin(1e-4));
    CHECK(m.boundsMin.y == Approx(-0.75f).margin(1e-4));
    CHECK(m.boundsMax.y > 6.0f);
    CHECK(m.boundsMax.y < 7.5f);
    // Everything at or below the deck is inside the documented hull box.
    for (const glm::vec3& p : m.positions)
        if (p.y <= 0.75f) CHECK((std::abs(p.x) <= 1.5001f && std::abs(p.z) <= 5.0001f && p.y >= -0.7501f));
    // Pointed bow: near z = 5 the hull is narrow; near z = −5 (round stern) too, wide mid-ships.
    float bowWidth = 0.0f, midWidth = 0.0f;
    for (const glm::vec3& p : m.positions) {
        if (p.z > 4.7f) bowWidth = std::max(bowWidth, std::abs(p.x));
        if (std::abs(p.z) < 0.5f && p.y <= 0.75f) midWidth = std::max(midWidth, std::abs(p.x));
    }
    CHECK(bowWidth < 0.5f);
    CHECK(midWidth == Approx(1.5f).margin(1e-3));

    // Hull below the deck: brown dominates (red > green > blue, dark).
    glm::vec3 hull = dominant(colourAreas(m, [](glm::vec3 c) { return c.y < 0.7f; }));
    CHECK(hull.x > hull.y);
    CHECK(hull.y > hull.z);
    CHECK(hull.x < 0.6f);
    // High up, away from the mast, the sail dominates: off-white.
    glm::vec3 sail = dominant(colourAreas(m, [](glm::vec3 c) { return c.y > 2.5f && std::abs(c.x) > 0.3f; }));
    CHECK(std::min({sail.x, sail.y, sail.z}) > 0.7f);
}

TEST_CASE("fish.gltf: closed and outward, 1 m long along z with the nose at +z and the tail fin at -z, silver-blue", "[gltf][models]") {
    ModelData m = loadGltfModel(modelPath("fish"));
    checkWellFormed(m);
    CHECK(m.boundsMax.z == Approx(0.5f).margin(1e-3));
    CHECK(m.boundsMin.z == Approx(-0.5f).margin(1e-3));
    CHECK(std::max(-m.boundsMin.x, m.boundsMax.x) < 0.15f);
    CHECK(std::max(-m.boundsMin.y, m.boundsMax.y) < 0.3f);
    float noseHeight = 0.0f, tailHeight = 0.0f;
    for (const glm::vec3& p : m.positions) {
        if (p.z > 0.45f) noseHeight = std::max(noseHeight, std::abs(p.y));
        if (p.z < -0.45f) tailHeight = std::max(tailHeight, std::abs(p.y));
    }
    CHECK(noseHeight < 0.1f);   // a rounded nose, not a fin
    CHECK(tailHeight > 0.12f);  // the tail fin spreads at −z
    glm::vec3 body = dominant(colourAreas(m, [](glm::vec3) { return true; }));
    CHECK(body.z > body.x);
    CHECK(body.x > 0.3f);
}

TEST_CASE("cannonball.gltf: a closed unit sphere, radial normals, volume 4/3 pi within 2%", "[gltf][models]") {
    ModelData m = loadGltfModel(modelPath("cannonball"));
    checkWellFormed(m);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const float r = glm::length(m.positions[i]);
        REQUIRE(r == Approx(1.0f).margin(1e-5));
        REQUIRE(glm::dot(m.normals[i], m.positions[i] / r) > 0.9999f);
    }
    CHECK(signedVolume(m) == Approx(4.0 / 3.0 * PI).epsilon(0.02));
    CHECK(glm::length(m.boundsMax - glm::vec3(1.0f)) < 1e-4f);
    CHECK(glm::length(m.boundsMin + glm::vec3(1.0f)) < 1e-4f);
    for (const glm::vec3& c : m.colors) CHECK(std::max({c.x, c.y, c.z}) < 0.2f);  // dark iron
}

TEST_CASE("cannon.gltf: closed and outward, barrel on the z axis with the muzzle at z = 1.5 and the pivot at the origin, on a carriage below", "[gltf][models]") {
    ModelData m = loadGltfModel(modelPath("cannon"));
    checkWellFormed(m);
    CHECK(m.boundsMax.z == Approx(1.5f).margin(1e-3));
    glm::dvec2 muzzleCentre(0.0);
    int muzzle = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec3& p = m.positions[i];
        if (p.z < 1.0f) continue;
        muzzleCentre += glm::dvec2(p.x, p.y);
        ++muzzle;
        CHECK(std::hypot(p.x, p.y) < 0.25f);                  // only the barrel reaches forward
        CHECK(std::max({m.colors[i].x, m.colors[i].y, m.colors[i].z}) < 0.2f);  // dark iron
    }
    REQUIRE(muzzle > 0);
    CHECK(glm::length(muzzleCentre / double(muzzle)) < 1e-4);  // the barrel's axis is the z axis
    CHECK(m.boundsMin.y < -0.5f);                             // carriage and wheels under the pivot
    CHECK(m.boundsMax.y < 0.3f);
}
