#pragma once
// Write a result file atomically: the text goes to a temporary file in the same folder,
// which is renamed over the target only once it is complete, so a crash, an error or
// Ctrl-C never leaves a partial file behind. "-" writes to standard output.
#include <string>

namespace ccd {

/// Throws std::runtime_error naming the path when the folder cannot be written.
void write_file_atomically(const std::string& path, const std::string& text);

/// Removes any temporary file still being written (called from a signal handler path).
void remove_pending_temporary_files();

}  // namespace ccd
