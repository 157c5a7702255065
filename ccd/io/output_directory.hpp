#pragma once
// Output folders that appear whole or not at all (the folder counterpart of OutputFile).
//
// The destination is checked when the object is made: its parent folder must exist, and
// if the destination exists it must be a folder that is empty or holds `marker` (a file
// that a previous run of the same command wrote); anything else is refused, so a command
// never replaces a folder it did not write. The files are written into a temporary folder
// DIR.tmp.PID beside the destination, each flushed to disk; commit() renames it to DIR. An
// existing DIR is exchanged with it in one step (renameat2 RENAME_EXCHANGE) and removed
// after: a reader, or a process killed at any point, sees the old folder or the whole new
// one, never a part of one (a file system without the exchange: the old folder is renamed
// to DIR.old.PID first, so for an instant there is none).
// Every exit without commit() (errors, exceptions) removes the temporary folder, and so do
// the signal handlers of ccd::install_temporary_file_cleanup (the folder and the files
// named through file() and write()); only SIGKILL may leave DIR.tmp.PID behind.
#include <string>
#include <string_view>

namespace ccd {

class OutputDirectory {
 public:
  /// Checks the destination and creates the temporary folder. Throws InputError naming
  /// `path` when it is refused.
  OutputDirectory(std::string path, std::string marker);
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  /// The path of file `name` inside the temporary folder (for callers that stream).
  std::string file(std::string_view name) const;
  /// Writes `text` to file `name` of the temporary folder. Throws std::runtime_error on failure.
  void write(std::string_view name, std::string_view text);
  /// Renames the temporary folder into place (once). Throws std::runtime_error on failure.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temporary_;
  int slot_ = -1;  // the signal handlers' registration of the temporary folder
  bool committed_ = false;
};

}  // namespace ccd
