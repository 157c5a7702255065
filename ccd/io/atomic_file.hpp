#pragma once
// Output files that are never left half written and never written where they must not be.
//
// A command names its destination before doing any work (OutputFile). The destination is
// checked then: it must not be one of the command's inputs (the same file under any name:
// same device and inode), it must be a regular file if it exists (a symbolic link is
// followed: the file it points to is replaced, the link stays), and its folder must exist
// (or be created, when asked) and take a new file: a temporary file FILE.tmp.PID.N is created beside the
// destination at once, so a read-only folder, a missing permission or a full inode table is
// found before the work, not after it. commit() writes the text to the temporary file,
// flushes it to disk and renames it over the destination: a reader sees the old file or the
// whole new one, never a part of it. Devices (/dev/null, /dev/full), folders and pipes are
// refused, since a rename would replace the node itself.
//
// Every other exit removes the temporary file: the destructor (errors, exceptions), and,
// once install_temporary_file_cleanup() has run, every signal that ends a process: SIGINT,
// SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGXFSZ, SIGVTALRM,
// SIGPROF (then the signal's previous action: the process ends as it would have) and
// SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL (then the previous handler, e.g. a sanitizer's).
// SIGKILL cannot be caught: a killed process may leave FILE.tmp.PID.N behind.
// "-" means standard output: nothing is checked or created, commit() writes the text.
#include <span>
#include <string>
#include <string_view>

namespace ccd {

class OutputFile {
 public:
  /// Checks the destination and creates the temporary file. Throws InputError naming
  /// `path` when the destination is refused or its folder cannot take a file.
  explicit OutputFile(std::string path, std::span<const std::string> inputs = {}, bool create_folder = false);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Writes `text` and renames it into place (once). Throws std::runtime_error naming the
  /// path when writing fails (e.g. a full disk); the temporary file is removed then.
  void commit(std::string_view text);
  const std::string& path() const { return path_; }
  bool is_stdout() const { return path_ == "-"; }

 private:
  void discard() noexcept;
  std::string path_;    // as given
  std::string target_;  // the file renamed over (symbolic links resolved)
  std::string temporary_;
  int fd_ = -1;
  int slot_ = -1;
  bool committed_ = false;
};

/// OutputFile(path).commit(text): one call for library users (ccd::save_scene, ...).
void write_file_atomically(const std::string& path, std::string_view text);

/// Installs the signal handlers described above (once, at program start). Signals that
/// are ignored (e.g. SIGHUP under nohup) stay ignored.
void install_temporary_file_cleanup();

/// Removes every temporary file still open. Async-signal-safe: a command's own signal
/// handler may call it before leaving with _exit.
void remove_pending_temporary_files() noexcept;

}  // namespace ccd
