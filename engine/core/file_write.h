// Writing an output file whole or not at all.
#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace ob {

/// Writes `path` through `write` into `path + ".tmp"`, then renames it over `path`, so a
/// failed write never leaves half a file there and an older file stays whole. `what` names
/// the output in messages ("screenshot", "stats"). Throws ob::InputError when the file
/// cannot be created or renamed into place (the user's path: exit 2), ob::RuntimeError when
/// writing fails part way (disk full); the temporary is removed either way.
void writeFileWhole(const std::string& path, const std::string& what, const std::function<void(std::ostream&)>& write);

/// writeFileWhole of a text.
void writeTextFile(const std::string& path, const std::string& text, const char* what);

/// Throws ob::InputError unless `path` can be created (its folder exists and is writable, it
/// is not a folder), naming `what` and what to do: checked before a run, so a bad output path
/// fails at once, not after the work.
void checkWritable(const std::string& path, const char* what);

} // namespace ob
