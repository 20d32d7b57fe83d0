// File identity: st_dev + st_ino where the file exists, the resolved path where it does not.
#include "core/file_identity.h"

#include "core/error.h"
#include "core/printable.h"

#include <filesystem>
#include <sys/stat.h>

namespace ob {

namespace {

// The absolute path with the links of its existing part resolved ("" when even that fails).
std::string resolvedPath(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    if (ec) return "";
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, ec);
    return (ec ? absolute.lexically_normal() : resolved).string();
}

std::string namedPathText(const NamedPath& p) { return p.what + " " + quotedValue(p.path); }

} // namespace

bool sameFile(const std::string& a, const std::string& b) {
    struct stat sa {}, sb {};
    const bool hasA = ::stat(a.c_str(), &sa) == 0, hasB = ::stat(b.c_str(), &sb) == 0;
    if (hasA && hasB) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    const std::string ra = resolvedPath(a);
    return !ra.empty() && ra == resolvedPath(b);
}

bool isInsideFolder(const std::string& path, const std::string& folder) {
    const std::filesystem::path p(resolvedPath(path)), f(resolvedPath(folder));
    if (p.empty() || f.empty()) return false;
    auto pi = p.begin();
    for (auto fi = f.begin(); fi != f.end(); ++fi, ++pi) {
        if (fi->empty()) continue;  // a trailing separator
        if (pi == p.end() || *pi != *fi) return false;
    }
    return true;
}

void checkOutputsApart(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
    for (size_t o = 0; o < outputs.size(); ++o) {
        const NamedPath& out = outputs[o];
        if (out.path.empty()) continue;
        for (const NamedPath& in : inputs)
            if (!in.path.empty() && sameFile(out.path, in.path))
                throw InputError(namedPathText(out) + " is " + namedPathText(in) +
                                 ": an output never replaces one of the run's inputs (choose another path)");
        for (size_t k = 0; k < o; ++k)
            if (!outputs[k].path.empty() && sameFile(out.path, outputs[k].path))
                throw InputError(namedPathText(out) + " and " + namedPathText(outputs[k]) +
                                 " name one file: one would be lost (give each output its own path)");
    }
}

} // namespace ob
