// Fuzz target: the glTF 2.0 loader (tinygltf's parse, then every index and byte range
// checked by engine/assets/model.cpp). Every input must give a model whose indices and
// arrays agree, or throw ob::InputError; anything else is a finding. External buffers are
// looked for in the corpus folder only.
#include "assets/model.h"
#include "core/error.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

void check(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "fuzz_gltf: a loaded model breaks its contract: %s\n", what);
    std::abort();
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > (1u << 20)) return -1;
    const std::vector<unsigned char> bytes(data, data + size);
    try {
        ob::assets::ModelData m = ob::assets::parseGltfModel(bytes, "fuzz.gltf", OCEANBOX_FUZZ_BASE_DIR);
        check(!m.indices.empty() && m.indices.size() % 3 == 0, "triangle list");
        check(m.normals.size() == m.positions.size() && m.colors.size() == m.positions.size(), "one normal and colour per position");
        for (uint32_t i : m.indices) check(i < m.positions.size(), "index in range");
        for (const glm::vec3& p : m.positions) check(finite(p), "finite positions");
        for (const glm::vec3& n : m.normals) check(finite(n), "finite normals");
    } catch (const ob::InputError&) {
    }
    return 0;
}
