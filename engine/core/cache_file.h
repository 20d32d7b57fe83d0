// Files oceanbox keeps between runs on one machine (the FFTW wisdom, the measured thread
// counts): where they live, and the lock that lets processes share them.
#pragma once
#include <string>

namespace ob {

/// $XDG_CACHE_HOME/oceanbox/<name>, else ~/.cache/oceanbox/<name>; "" with neither set.
std::string cachePath(const std::string& name);

/// An exclusive flock on path + ".lock" for the object's lifetime (the folder is made if
/// missing); held() is false where it cannot be had (no path, read-only folder).
class FileLock {
public:
    explicit FileLock(const std::string& path);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
    bool held() const { return m_fd >= 0; }

private:
    int m_fd = -1;
};

} // namespace ob
