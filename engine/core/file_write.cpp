#include "core/file_write.h"

#include "core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

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

} // namespace ob
