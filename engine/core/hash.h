// FNV-1a 64-bit hashing of simulation state (determinism checks).
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace ob {

/// Incremental FNV-1a 64 hash; feed values explicitly (never raw structs: padding).
class StateHasher {
public:
    /// Hashes `size` bytes.
    void bytes(const void* data, size_t size) {
        auto p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) m_hash = (m_hash ^ p[i]) * 1099511628211ull;
    }
    /// Hashes a float's bit pattern (−0 and +0 differ: states must match bit for bit).
    void f32(float v) { bytes(&v, sizeof v); }
    void f64(double v) { bytes(&v, sizeof v); }
    void u64(uint64_t v) { bytes(&v, sizeof v); }
    /// Hashes an array of floats.
    void f32s(const float* v, size_t n) { bytes(v, n * sizeof(float)); }
    uint64_t value() const { return m_hash; }

private:
    uint64_t m_hash = 1469598103934665603ull;
};

} // namespace ob
