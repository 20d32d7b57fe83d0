#include "core/file_write.h"

#include "core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace ob {

void writeFileWhole(const std::string& path, const std::string& what, const std::function<void(std::ostream&)>& write) {
    const std::string head = "cannot write " + what + " '" + path + "': ";
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw InputError(head + std::strerror(errno) + " (choose another path)");  // nothing made
        write(out);
        out.close();
        if (!out) {
            std::remove(tmp.c_str());
            throw RuntimeError(head + "writing " + tmp + " failed (disk full?)");
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        std::remove(tmp.c_str());
        throw InputError(head + std::strerror(err) + " (choose another path)");
    }
}

void checkWritable(const std::string& path, const char* what) {
    std::filesystem::path p(path);
    std::filesystem::path dir = p.parent_path().empty() ? "." : p.parent_path();
    const std::string head = std::string("cannot write ") + what + " '" + path + "': ";
    if (std::filesystem::is_directory(p)) throw InputError(head + "it is a folder (give a file name)");
    if (!std::filesystem::is_directory(dir))
        throw InputError(head + "folder '" + dir.string() + "' does not exist (create it or choose another path)");
    if (access(dir.c_str(), W_OK) != 0)
        throw InputError(head + "folder '" + dir.string() + "' is not writable (choose another path)");
}

void writeTextFile(const std::string& path, const std::string& text, const char* what) {
    writeFileWhole(path, what, [&](std::ostream& out) { out << text; });
}

} // namespace ob
