// NumPy .npy files: little-endian float32, C order, any rank (docs/references.md#contracts field files).
// Format: numpy.lib.format, version 1.0 (2.0 is also read: same, with a 4-byte header length).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace ob {

/// A float32 array read from a .npy file; data is C order (last index fastest).
struct NpyArray {
    std::vector<size_t> shape;  ///< extent per axis; empty for a 0-D (scalar) array
    std::vector<float> data;    ///< product(shape) values, row-major
};

/// Reads a .npy file holding '<f4' data in C order. Throws ob::InputError naming the file
/// for a missing file or one that is not a regular file (a named pipe, device, folder), bad magic, unsupported version, bad header, other dtype,
/// fortran_order True or truncated data.
NpyArray readNpy(const std::string& path);

/// As readNpy, from the bytes of a .npy file; `sourceName` names it in messages.
NpyArray parseNpy(const std::string& bytes, const std::string& sourceName);

/// Writes a version 1.0 .npy file ('<f4', C order) holding product(shape) values from data.
/// Written whole or not at all (writeFileWhole: a temporary beside it, renamed over it).
/// Throws ob::InputError if the path cannot be created (the user's choice: exit 2),
/// ob::RuntimeError if writing fails part way (disk full).
void writeNpy(const std::string& path, const std::vector<size_t>& shape, const float* data);

} // namespace ob
