// Which files a run reads and writes, compared by identity: an output never replaces one of
// the run's inputs, nor another output (docs/reliability.md#hostile-input).
#pragma once
#include <string>
#include <vector>

namespace ob {

/// A file the run reads or writes, and what names it in messages ("--stats", "the scene
/// file", "events[2].file").
struct NamedPath {
    std::string what;  ///< the flag or key that names it
    std::string path;  ///< as given (relative to the current folder)
};

/// Whether `a` and `b` name one file: the same device and inode where both exist (a hard
/// link or a symbolic link to it counts), else the same absolute path once the links of its
/// existing part are resolved (std::filesystem::weakly_canonical).
bool sameFile(const std::string& a, const std::string& b);

/// Whether `path`, resolved (links included), is `folder` or lies below it (both resolved).
bool isInsideFolder(const std::string& path, const std::string& folder);

/// Throws ob::InputError, before the run, when an output names one of the inputs ("--stats
/// 'S.toml' is the scene file 'S.toml': an output never replaces an input") or two outputs
/// name one file (one of them would be lost). Empty paths are skipped.
void checkOutputsApart(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

} // namespace ob
