// Reading input files: open non-blocking, check the descriptor is a regular file, read it.
#include "core/file_read.h"

#include "core/error.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ob {

namespace {

// A file type that is not a regular file, in words ("" for a regular file).
const char* kindOf(mode_t mode) {
    if (S_ISREG(mode)) return "";
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a named pipe (FIFO)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// Why open() failed, in the user's words.
std::string openProblem(int err) {
    switch (err) {
    case ENOENT: return "no such file";
    case ELOOP: return "symlink loop";
    case EACCES: return "no read permission";
    case ENOTDIR: return "a part of the path is not a folder";
    default: return std::strerror(err);
    }
}

struct Fd {
    int fd;
    ~Fd() { ::close(fd); }
};

} // namespace

std::string notRegularFileKind(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return "";
    return kindOf(st.st_mode);
}

std::string readRegularFile(const std::string& path, uint64_t maxBytes) {
    // O_NONBLOCK: opening a FIFO with no writer returns at once instead of waiting for one.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        const int err = errno;
        // A folder opens read-only on Linux; other systems refuse it with EISDIR.
        if (err == EISDIR) throw InputError(path + ": is a folder, not a file");
        throw InputError(path + ": cannot open file (" + openProblem(err) + ")");
    }
    Fd guard{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw InputError(path + ": cannot open file (" + openProblem(errno) + ")");
    if (S_ISDIR(st.st_mode)) throw InputError(path + ": is a folder, not a file");
    if (!S_ISREG(st.st_mode)) throw InputError(path + ": is not a regular file (" + kindOf(st.st_mode) + "); give a file");
    if (uint64_t(st.st_size) > maxBytes)
        throw InputError(path + ": is larger than " + std::to_string(maxBytes) + " bytes");
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    std::string bytes;
    bytes.resize(size_t(st.st_size));
    size_t have = 0;
    for (;;) {
        if (have == bytes.size()) {
            // The file may have grown since fstat: read on, within the limit.
            if (bytes.size() >= maxBytes) {
                char probe;
                if (::read(fd, &probe, 1) > 0) throw InputError(path + ": is larger than " + std::to_string(maxBytes) + " bytes");
                break;
            }
            bytes.resize(size_t(std::min<uint64_t>(maxBytes, std::max<uint64_t>(4096, uint64_t(bytes.size()) * 2))));
        }
        const ssize_t n = ::read(fd, bytes.data() + have, bytes.size() - have);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw InputError(path + ": cannot read file (" + std::string(std::strerror(errno)) + ")");
        }
        if (n == 0) break;
        have += size_t(n);
    }
    bytes.resize(have);
    return bytes;
}

} // namespace ob
