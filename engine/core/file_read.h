// Reading an input file (scene, .npy, glTF and its buffers, --input script): only a regular
// file is read, so a named pipe cannot hang a load nor a device feed it without end.
#pragma once
#include <cstdint>
#include <string>

namespace ob {

/// The largest input file read whole, bytes (1 GiB: far beyond any scene, model or field here).
constexpr uint64_t MAX_INPUT_FILE_BYTES = uint64_t(1) << 30;

/// The whole content of `path` if it is a regular file of at most `maxBytes`. Throws
/// ob::InputError "<path>: <why>" otherwise: "cannot open file (no such file)", "(symlink
/// loop)", "(no read permission)", "is a folder, not a file", "is not a regular file (a named
/// pipe)" (device, socket), "is larger than N bytes". The file is opened non-blocking and
/// checked on the open descriptor (fstat), so nothing can swap it for a pipe in between.
std::string readRegularFile(const std::string& path, uint64_t maxBytes = MAX_INPUT_FILE_BYTES);

/// What `path` is when it is not a regular file ("a folder", "a named pipe (FIFO)", "a
/// character device", "a block device", "a socket"); "" for a regular file or no file.
/// Follows symlinks.
std::string notRegularFileKind(const std::string& path);

} // namespace ob
