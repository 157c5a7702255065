#pragma once
// The bytes of an input file that must be a regular file (mesh frames are read whole, so a
// folder, a device such as /dev/zero or a pipe is refused before anything is read).
#include <string>

namespace ccd::cloth {

/// The whole content of the regular file at `path`. Throws InputError naming `path` when it
/// cannot be opened, is not a regular file, or a read fails.
std::string read_regular_file(const std::string& path);

}  // namespace ccd::cloth
