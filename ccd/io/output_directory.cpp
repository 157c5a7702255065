#include "output_directory.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace ccd {

namespace fs = std::filesystem;

OutputDirectory::OutputDirectory(std::string path, std::string marker) : path_(std::move(path)) {
  std::error_code ec;
  const fs::path dest(path_);
  if (path_.empty()) throw InputError(path_, "", "empty folder name");
  const fs::path parent = dest.has_parent_path() ? dest.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec)) throw InputError(path_, "", "its parent folder does not exist");
  const auto status = fs::symlink_status(dest, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) throw InputError(path_, "", "exists and is not a folder");
    if (!fs::is_empty(dest, ec) && !fs::is_regular_file(dest / marker, ec))
      throw InputError(path_, "", "folder exists and was not written by this command (no " + marker + " in it)");
  }
  temporary_ = (dest.has_filename() ? dest : dest.parent_path()).string() + ".tmp." + std::to_string(::getpid());
  fs::remove_all(temporary_, ec);
  slot_ = register_temporary_folder(temporary_);  // before it exists: a signal finds it
  if (!fs::create_directory(temporary_, ec) || ec) {
    release_temporary_folder(slot_);
    temporary_.clear();
    throw InputError(path_, "", "cannot create a folder beside it");
  }
}

OutputDirectory::~OutputDirectory() {
  if (!committed_ && !temporary_.empty()) {
    std::error_code ec;
    fs::remove_all(temporary_, ec);
  }
  release_temporary_folder(slot_);
}

std::string OutputDirectory::file(std::string_view name) const {
  std::string path = (fs::path(temporary_) / name).string();
  register_temporary_folder_file(slot_, path);
  return path;
}

void OutputDirectory::write(std::string_view name, std::string_view text) {
  const std::string f = file(name);
  auto fail = [&] { throw std::runtime_error(path_ + ": cannot write " + std::string(name) + ": " + std::strerror(errno)); };
  const int fd = ::open(f.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
  if (fd < 0) fail();
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      errno = err;
      fail();
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    errno = err;
    fail();
  }
  if (::close(fd) != 0) fail();
}

void OutputDirectory::commit() {
  if (committed_) return;
  std::error_code ec;
  const fs::path dest(path_);
  if (fs::exists(fs::symlink_status(dest, ec))) {
    // One atomic step: the new folder takes the name, the old one takes the temporary
    // name and is removed after; a reader (or a crash) sees the old folder or the new one.
    if (::renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, path_.c_str(), RENAME_EXCHANGE) == 0) {
      committed_ = true;
      fs::remove_all(temporary_, ec);
      return;
    }
    if (errno != EINVAL && errno != ENOSYS)
      throw std::runtime_error(path_ + ": cannot put the new folder in place: " + std::strerror(errno));
    // A file system without the exchange: move the old folder aside first.
    const std::string old =
        (dest.has_filename() ? dest : dest.parent_path()).string() + ".old." + std::to_string(::getpid());
    fs::remove_all(old, ec);
    fs::rename(dest, old, ec);
    if (ec) throw std::runtime_error(path_ + ": cannot move the previous folder aside: " + ec.message());
    fs::rename(temporary_, dest, ec);
    if (ec) {
      fs::rename(old, dest, ec);
      throw std::runtime_error(path_ + ": cannot rename the new folder into place");
    }
    committed_ = true;
    fs::remove_all(old, ec);
    return;
  }
  fs::rename(temporary_, dest, ec);
  if (ec) throw std::runtime_error(path_ + ": cannot rename the new folder into place: " + ec.message());
  committed_ = true;
}

}  // namespace ccd
