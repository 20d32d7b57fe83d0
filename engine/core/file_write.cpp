// Output files: a unique temporary beside the target (O_EXCL | O_NOFOLLOW), the target's
// mode, fsync, rename; only a regular file (or nothing) at the target is replaced.
#include "core/file_write.h"

#include "core/error.h"
#include "core/printable.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <filesystem>
#include <climits>
#include <fstream>
#include <random>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>

namespace ob {

namespace {

// When this process started (near enough): a temporary older than it whose writer is gone
// was left by a killed run.
const auto PROCESS_START = std::filesystem::file_time_type::clock::now();

// What sits at a path, in words, when it is not a regular file.
std::string fileKindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISLNK(mode)) return "a symbolic link";
    if (S_ISFIFO(mode)) return "a named pipe (FIFO)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// The process's umask, read without changing it (umask(2) would race other threads).
mode_t currentUmask() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("Umask:", 0) == 0) return mode_t(std::strtoul(line.c_str() + 6, nullptr, 8));
    return 022;
}

std::string folderOf(const std::string& path) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? "." : parent.string();
}

// Removes the temporaries in `folder` that a run of ours left when it was killed: the name
// pattern, a regular file of our user, older than this process, its writer's pid gone.
void removeStaleTemporaries(const std::string& folder) {
    DIR* dir = ::opendir(folder.c_str());
    if (!dir) return;
    while (const dirent* entry = ::readdir(dir)) {
        const std::string name = entry->d_name;
        const size_t mark = name.rfind(TEMPORARY_MARK);
        if (name.empty() || name[0] != '.' || mark == std::string::npos) continue;
        // ".NAME.oceanbox-PID-XXXXXX"
        const std::string tail = name.substr(mark + std::strlen(TEMPORARY_MARK));
        const size_t dash = tail.find('-');
        if (dash == std::string::npos || dash == 0 || tail.size() != dash + 7) continue;
        char* end = nullptr;
        const long pid = std::strtol(tail.c_str(), &end, 10);
        if (end != tail.c_str() + dash || pid <= 0 || pid == long(::getpid())) continue;
        if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;  // the writer may still run
        const std::string path = folder + "/" + name;
        struct stat st {};
        if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid()) continue;
        std::error_code ec;
        if (std::filesystem::last_write_time(path, ec) >= PROCESS_START || ec) continue;
        ::unlink(path.c_str());
    }
    ::closedir(dir);
}

// A stream buffer over a file descriptor that remembers the first write error.
class FdBuffer : public std::streambuf {
public:
    explicit FdBuffer(int fd) : m_fd(fd) { setp(m_buffer, m_buffer + sizeof m_buffer); }
    int error() const { return m_error; }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        if (n <= epptr() - pptr()) {
            std::memcpy(pptr(), s, size_t(n));
            pbump(int(n));
            return n;
        }
        return drain() && writeAll(s, size_t(n)) ? n : 0;
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    bool drain() {
        const bool ok = writeAll(pbase(), size_t(pptr() - pbase()));
        setp(m_buffer, m_buffer + sizeof m_buffer);
        return ok;
    }
    bool writeAll(const char* p, size_t n) {
        while (n > 0 && m_error == 0) {
            const ssize_t w = ::write(m_fd, p, n);
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) m_error = w < 0 ? errno : EIO;
            else p += w, n -= size_t(w);
        }
        return m_error == 0;
    }
    int m_fd;
    int m_error = 0;
    char m_buffer[1 << 16];
};

// The random characters that end a temporary's name.
constexpr int TEMPORARY_RANDOM_CHARS = 6;

// A temporary's name beside `path` up to its random characters: ".NAME.oceanbox-PID-".
std::string temporaryStem(const std::string& path) {
    return "." + std::filesystem::path(path).filename().string() + TEMPORARY_MARK + std::to_string(::getpid()) + "-";
}

// A new temporary beside `path`, created with O_EXCL | O_NOFOLLOW under a fresh name; its
// name in `tmp`. -1 and errno when none can be made.
int createTemporary(const std::string& path, std::string& tmp) {
    const std::string stem = folderOf(path) + "/" + temporaryStem(path);
    static const char LETTERS[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    std::random_device device;
    std::mt19937_64 random((uint64_t(device()) << 32) ^ device() ^ uint64_t(std::chrono::steady_clock::now().time_since_epoch().count()));
    for (int attempt = 0; attempt < 100; ++attempt) {
        tmp = stem;
        for (int i = 0; i < TEMPORARY_RANDOM_CHARS; ++i) tmp += LETTERS[random() % (sizeof LETTERS - 1)];
        const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    errno = EEXIST;
    return -1;
}

} // namespace

void checkWritable(const std::string& path, const char* what) {
    const std::string head = std::string("cannot write ") + what + " " + quotedValue(path) + ": ";
    if (path.empty()) throw InputError(std::string("cannot write ") + what + ": the path is empty (give a file name)");
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) throw InputError(head + "it is a folder (give a file name)");
        if (S_ISLNK(st.st_mode)) {
            std::error_code ec;
            const std::string to = std::filesystem::read_symlink(path, ec).string();
            throw InputError(head + "it is a symbolic link to '" + to +
                             "', which oceanbox neither follows nor replaces (give the path of a regular file: choose another path)");
        }
        if (!S_ISREG(st.st_mode))
            throw InputError(head + "it is " + fileKindOf(st.st_mode) +
                             ", not a regular file; oceanbox replaces regular files only (choose another path)");
    } else if (errno != ENOENT) {
        const int err = errno;
        throw InputError(head + (err == ELOOP ? std::string("symlink loop") : std::strerror(err)) + " (choose another path)");
    }
    const std::string dir = folderOf(path);
    if (!std::filesystem::is_directory(dir))
        throw InputError(head + "folder " + quotedValue(dir) + " does not exist (create it or choose another path)");
    if (::access(dir.c_str(), W_OK) != 0)
        throw InputError(head + "folder " + quotedValue(dir) + " is not writable (choose another path)");
    // The temporary's name is longer than the output's: a name near the folder's limit
    // would fail only after the run.
    const long nameMax = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    const size_t limit = nameMax > 0 ? size_t(nameMax) : size_t(NAME_MAX);
    const size_t temporary = temporaryStem(path).size() + TEMPORARY_RANDOM_CHARS;
    if (temporary > limit) {
        const size_t name = std::filesystem::path(path).filename().string().size();
        throw InputError(head + "its name has " + std::to_string(name) + " characters and the temporary written beside it "
                         "first (.NAME" + TEMPORARY_MARK + "PID-XXXXXX) would have " + std::to_string(temporary) +
                         ", over the folder's limit of " + std::to_string(limit) + " (give a name of at most " +
                         std::to_string(name - (temporary - limit)) + " characters)");
    }
}

void writeFileWhole(const std::string& path, const std::string& what, const std::function<void(std::ostream&)>& write) {
    checkWritable(path, what.c_str());
    const std::string head = "cannot write " + what + " '" + path + "': ";
    const std::string folder = folderOf(path);
    removeStaleTemporaries(folder);

    // The old file's mode and owner carry over; a new file gets 0666 less the umask.
    struct stat old {};
    const bool replacing = ::lstat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode);
    std::string tmp;
    const int fd = createTemporary(path, tmp);
    if (fd < 0) throw InputError(head + std::strerror(errno) + " (choose another path)");  // nothing made
    struct Guard {
        int fd;
        std::string tmp;
        bool done = false;
        ~Guard() {
            if (fd >= 0) ::close(fd);
            if (!done) ::unlink(tmp.c_str());
        }
    } guard{fd, tmp};
    ::fchmod(fd, replacing ? (old.st_mode & 07777) : (0666 & ~currentUmask()));
    if (replacing && (old.st_uid != ::geteuid() || old.st_gid != ::getegid())) (void)::fchown(fd, old.st_uid, old.st_gid);

    FdBuffer buffer(fd);
    {
        std::ostream out(&buffer);
        write(out);
        out.flush();
        if (!out || buffer.error() != 0)
            throw RuntimeError(head + "writing " + tmp + " failed: " + std::strerror(buffer.error() ? buffer.error() : EIO) +
                               " (disk full?)");
    }
    int err = ::fsync(fd) == 0 ? 0 : errno;
    guard.fd = -1;
    if (::close(fd) != 0 && err == 0) err = errno;
    if (err != 0) throw RuntimeError(head + "writing " + tmp + " failed: " + std::strerror(err) + " (disk full?)");
    // The path may have changed since the check (another process): never rename over what is
    // not a regular file.
    checkWritable(path, what.c_str());
    if (::rename(tmp.c_str(), path.c_str()) != 0) throw InputError(head + std::strerror(errno) + " (choose another path)");
    guard.done = true;
    // The rename itself lasts once the folder is synced.
    if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

void writeTextFile(const std::string& path, const std::string& text, const char* what) {
    writeFileWhole(path, what, [&](std::ostream& out) { out << text; });
}

} // namespace ob
