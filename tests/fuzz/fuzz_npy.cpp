// Fuzz target: the .npy reader (engine/core/npy.cpp: magic, version, header length, the
// header dict's parser, dtype, order, shape and the data's length). Every input must give an
// array whose data holds product(shape) floats, or throw ob::InputError naming the source;
// anything else is a finding.
#include "core/error.h"
#include "core/npy.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > (1u << 20)) return -1;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const ob::NpyArray a = ob::parseNpy(bytes, "fuzz.npy");
        size_t count = 1;
        for (size_t d : a.shape) count *= d;
        if (a.data.size() != count || count * sizeof(float) > size) {
            std::fprintf(stderr, "fuzz_npy: a loaded array breaks its contract: %zu values for shape of %zu\n", a.data.size(), count);
            std::abort();
        }
    } catch (const ob::InputError& e) {
        if (std::string(e.what()).rfind("fuzz.npy: ", 0) != 0) {
            std::fprintf(stderr, "fuzz_npy: InputError that does not name the source: %s\n", e.what());
            std::abort();
        }
    }
    return 0;
}
