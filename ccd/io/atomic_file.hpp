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
// SIGKILL cannot be caught: a killed process may leave FILE.tmp.PID.N behind. The same
// handlers remove the temporary folders of ccd::OutputDirectory (register_temporary_folder).
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
  /// Equivalent to stage(text) then publish().
  void commit(std::string_view text);
  /// The first half of commit(): writes `text` to the temporary file and flushes it to
  /// disk (standard output: writes the text). Nothing is visible at the destination yet.
  void stage(std::string_view text);
  /// The second half: renames the staged temporary file into place.
  void publish();
  const std::string& path() const { return path_; }
  bool is_stdout() const { return path_ == "-"; }

 private:
  void discard() noexcept;
  std::string path_;    // as given
  std::string target_;  // the file renamed over (symbolic links resolved)
  std::string temporary_;
  int fd_ = -1;
  int slot_ = -1;
  bool staged_ = false;
  bool committed_ = false;
};

/// Writes several outputs of one command as one: every text is staged (written and
/// flushed) first, and only when all of them are on disk are they renamed into place, so
/// a failure to write one (a full disk, a folder of that name) leaves none of them behind
/// and every destination as it was. `files` and `texts` are parallel.
void commit_together(std::span<OutputFile* const> files, std::span<const std::string_view> texts);

/// OutputFile(path).commit(text): one call for library users (ccd::save_scene, ...).
void write_file_atomically(const std::string& path, std::string_view text);

/// Installs the signal handlers described above (once, at program start). Signals that
/// are ignored (e.g. SIGHUP under nohup) stay ignored.
void install_temporary_file_cleanup();

/// Removes every temporary file still open, and every temporary folder registered below
/// with the files registered in it. Async-signal-safe: a command's own signal handler may
/// call it before leaving with _exit.
void remove_pending_temporary_files() noexcept;

/// A temporary folder (ccd::OutputDirectory's DIR.tmp.PID) that the signal handlers remove:
/// register_temporary_folder gives a slot (-1 when all are taken: the folder is then not
/// removed by a signal), each file written in it is added with its full path (at most 16;
/// more are not removed by a signal), release_temporary_folder ends the registration.
int register_temporary_folder(const std::string& folder) noexcept;
void register_temporary_folder_file(int slot, const std::string& path) noexcept;
void release_temporary_folder(int slot) noexcept;

}  // namespace ccd
