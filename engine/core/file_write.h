// Writing an output file whole or not at all, and only where a regular file may be.
#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace ob {

/// The temporaries' names: ".NAME.oceanbox-PID-XXXXXX" beside the output NAME (hidden, the
/// writer's process id, six random characters), so a killed run's are recognisable.
constexpr const char* TEMPORARY_MARK = ".oceanbox-";

/// Writes `path` through `write`: into a new temporary file beside it (created with
/// O_CREAT | O_EXCL | O_NOFOLLOW under a unique name, so no link, other file or other writer
/// is ever written through), given the old file's mode (new: 0666 less the umask), synced,
/// then renamed over `path`: a failed or killed write never leaves half a file there, and an
/// older file stays whole. Temporaries a killed run of ours left in that folder are removed.
/// `what` names the output in messages ("screenshot", "stats"). Throws ob::InputError when
/// checkWritable refuses the path or the temporary cannot be made (exit 2), ob::RuntimeError
/// when writing fails part way (disk full); the temporary is removed either way.
void writeFileWhole(const std::string& path, const std::string& what, const std::function<void(std::ostream&)>& write);

/// writeFileWhole of a text.
void writeTextFile(const std::string& path, const std::string& text, const char* what);

/// Throws ob::InputError unless `path` can be written: not empty, its folder exists and is
/// writable, and nothing is at the path but a regular file. A folder, a device (/dev/null), a
/// named pipe, a socket or a symbolic link (/dev/stdout) at the path is refused, never
/// replaced nor written through. The message names `what`, the path, what is there and what
/// to do. Called before a run, so a bad output path fails at once, not after the work.
void checkWritable(const std::string& path, const char* what);

} // namespace ob
