#include <ccd/io/atomic_file.hpp>

#include <ccd/io/input_error.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace ccd {
namespace {

namespace fs = std::filesystem;

// Temporary files being written, in slots a signal handler may read: a slot's path is
// written while its state is Claimed and read only once it is Named (lock-free atomics
// and unlink are async-signal-safe; a std::set under a mutex is not). A slot is Named
// before the file is created, so a signal that arrives just after the creation still
// finds its name; unlinking a name whose file does not exist yet is harmless, and a file
// that already has the name (O_EXCL refused it) is a leftover of a process with our pid.
enum SlotState : int { Free = 0, Claimed = 1, Named = 2 };
struct Slot {
  std::atomic<int> state{Free};
  char path[4096];
};
std::array<Slot, 16> g_slots;
static_assert(std::atomic<int>::is_always_lock_free);

int claim_slot(const std::string& path) {
  if (path.size() >= sizeof(Slot::path)) throw InputError(path, "", "file name too long");
  for (std::size_t i = 0; i < g_slots.size(); ++i) {
    int expected = Free;
    if (g_slots[i].state.compare_exchange_strong(expected, Claimed)) {
      std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
      g_slots[i].state.store(Named);
      return static_cast<int>(i);
    }
  }
  throw std::runtime_error(path + ": more than " + std::to_string(g_slots.size()) + " output files open at once");
}

// Temporary folders and the files written in them, for the signal handlers (same states).
struct FolderSlot {
  std::atomic<int> state{Free};
  std::atomic<int> files{0};
  char folder[4096];
  char file[16][4096];
};
std::array<FolderSlot, 4> g_folders;

void release_slot(int slot) {
  if (slot >= 0) g_slots[static_cast<std::size_t>(slot)].state.store(Free);
}

std::string reason() { return std::strerror(errno); }

bool same_file(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

// Signals after which the process ends anyway: remove the temporary files, then restore
// the previous action and deliver the signal to it.
constexpr int kEndingSignals[] = {SIGINT,  SIGTERM, SIGHUP,  SIGQUIT,   SIGPIPE, SIGALRM,
                                   SIGUSR1, SIGUSR2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF};
constexpr int kFaultSignals[] = {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL};
struct sigaction g_previous[NSIG];

extern "C" void on_ending_signal(int sig) {
  remove_pending_temporary_files();
  ::sigaction(sig, &g_previous[sig], nullptr);
  ::raise(sig);  // blocked while this handler runs: delivered to the previous action on return
}

extern "C" void on_fault_signal(int sig) {
  remove_pending_temporary_files();
  // A fault repeats when the faulting instruction runs again, now with the previous
  // handler (the default action, or a sanitizer's report with the original address);
  // abort() raises SIGABRT again itself.
  ::sigaction(sig, &g_previous[sig], nullptr);
}

}  // namespace

OutputFile::OutputFile(std::string path, std::span<const std::string> inputs, bool create_folder)
    : path_(std::move(path)) {
  if (path_ == "-") return;
  if (path_.empty()) throw InputError("-o", "", "the output file name is empty");
  target_ = path_;
  struct stat st {};
  if (::lstat(path_.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(path_, ec);
    if (ec) throw InputError(path_, "", "cannot follow the symbolic link: " + ec.message());
    target_ = resolved.string();
  }
  const bool exists = ::stat(target_.c_str(), &st) == 0;
  if (exists && !S_ISREG(st.st_mode))
    throw InputError(path_, "", S_ISDIR(st.st_mode) ? "is a folder; the output must be a file"
                                                     : "is not a regular file (a device or a pipe); ccdlab writes only "
                                                       "regular files (use -o - for standard output)");
  if (exists) {
    for (const std::string& input : inputs) {
      struct stat in {};
      if (input != "-" && ::stat(input.c_str(), &in) == 0 && same_file(st, in))
        throw InputError(path_, "", "is an input of this command (" + input + "); choose another output file");
    }
  }
  const fs::path folder = fs::path(target_).parent_path();
  if (create_folder && !folder.empty()) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw InputError(path_, "", "cannot create the folder '" + folder.string() + "': " + ec.message());
  }
  // Unique temporary name beside the target (O_EXCL: never opens what is already there).
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name = target_ + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    slot_ = claim_slot(name);
    fd_ = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd_ >= 0) {
      temporary_ = name;
      return;
    }
    const int err = errno;
    release_slot(slot_);
    slot_ = -1;
    if (err != EEXIST) {
      errno = err;
      throw InputError(path_, "", "cannot write to the folder '" + (folder.empty() ? std::string(".") : folder.string()) +
                                      "': " + reason());
    }
  }
  throw InputError(path_, "", "cannot create a temporary file beside it");
}

OutputFile::~OutputFile() {
  if (!committed_) discard();
}

void OutputFile::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  release_slot(slot_);
  slot_ = -1;
}

void OutputFile::commit(std::string_view text) {
  stage(text);
  publish();
}

void OutputFile::stage(std::string_view text) {
  if (committed_ || staged_) throw std::logic_error(path_ + ": written twice");
  if (is_stdout()) {
    std::cout << text;
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("standard output: cannot write");
    staged_ = true;
    return;
  }
  auto fail = [&](const char* what) {
    const std::string why = reason();
    discard();
    throw std::runtime_error(path_ + ": " + what + ": " + why);
  };
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd_) != 0) fail("cannot write");
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("cannot write");
  staged_ = true;
}

void OutputFile::publish() {
  if (!staged_ || committed_) throw std::logic_error(path_ + ": published before it was written, or twice");
  committed_ = true;
  if (is_stdout()) return;
  auto fail = [&](const char* what) {
    const std::string why = reason();
    committed_ = false;
    discard();
    throw std::runtime_error(path_ + ": " + what + ": " + why);
  };
  // The destination may have changed since it was checked: still never rename over
  // anything but a regular file.
  struct stat st {};
  if (::stat(target_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    errno = EEXIST;
    fail("is no longer a regular file");
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail("cannot rename into place");
  temporary_.clear();
  release_slot(slot_);
  slot_ = -1;
  // Make the rename itself durable (best effort: some file systems refuse a folder fsync).
  const fs::path folder = fs::path(target_).parent_path();
  const int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void commit_together(std::span<OutputFile* const> files, std::span<const std::string_view> texts) {
  if (files.size() != texts.size()) throw std::logic_error("commit_together: one text per file");
  for (std::size_t i = 0; i < files.size(); ++i) files[i]->stage(texts[i]);
  for (OutputFile* f : files) f->publish();
}

void write_file_atomically(const std::string& path, std::string_view text) { OutputFile(path).commit(text); }

void install_temporary_file_cleanup() {
  auto install = [](int sig, void (*handler)(int)) {
    struct sigaction current {};
    if (::sigaction(sig, nullptr, &current) != 0 || current.sa_handler == SIG_IGN) return;
    g_previous[sig] = current;
    struct sigaction action {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    ::sigaction(sig, &action, nullptr);
  };
  for (int sig : kEndingSignals) install(sig, on_ending_signal);
  for (int sig : kFaultSignals) install(sig, on_fault_signal);
}

void remove_pending_temporary_files() noexcept {
  for (Slot& s : g_slots)
    if (s.state.load() == Named) ::unlink(s.path);
  for (FolderSlot& f : g_folders) {
    if (f.state.load() != Named) continue;
    const int n = std::min(f.files.load(), static_cast<int>(std::size(f.file)));
    for (int k = 0; k < n; ++k) ::unlink(f.file[k]);
    ::rmdir(f.folder);
  }
}

int register_temporary_folder(const std::string& folder) noexcept {
  if (folder.size() >= sizeof(FolderSlot::folder)) return -1;
  for (std::size_t i = 0; i < g_folders.size(); ++i) {
    int expected = Free;
    if (g_folders[i].state.compare_exchange_strong(expected, Claimed)) {
      std::memcpy(g_folders[i].folder, folder.c_str(), folder.size() + 1);
      g_folders[i].files.store(0);
      g_folders[i].state.store(Named);
      return static_cast<int>(i);
    }
  }
  return -1;
}

void register_temporary_folder_file(int slot, const std::string& path) noexcept {
  if (slot < 0 || path.size() >= sizeof(FolderSlot::file[0])) return;
  FolderSlot& f = g_folders[static_cast<std::size_t>(slot)];
  const int n = f.files.load();
  for (int k = 0; k < std::min(n, static_cast<int>(std::size(f.file))); ++k)
    if (path == f.file[k]) return;
  if (n >= static_cast<int>(std::size(f.file))) return;
  std::memcpy(f.file[n], path.c_str(), path.size() + 1);
  f.files.store(n + 1);  // the name is complete before a handler may read it
}

void release_temporary_folder(int slot) noexcept {
  if (slot >= 0) g_folders[static_cast<std::size_t>(slot)].state.store(Free);
}

}  // namespace ccd
