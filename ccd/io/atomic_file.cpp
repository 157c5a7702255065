#include <ccd/io/atomic_file.hpp>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <unistd.h>

namespace ccd {
namespace {

std::mutex pending_mutex;
std::set<std::string>& pending() {
  static std::set<std::string> files;
  return files;
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    std::cout.flush();
    return;
  }
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::lock_guard<std::mutex> lock(pending_mutex);
    pending().insert(tmp);
  }
  auto fail = [&](const char* what) {
    const std::string reason = std::strerror(errno);
    ::unlink(tmp.c_str());
    std::lock_guard<std::mutex> lock(pending_mutex);
    pending().erase(tmp);
    throw std::runtime_error(path + ": " + what + ": " + reason);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) fail("cannot create");
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      ::close(fd);
      fail("cannot write");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) fail("cannot write");
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail("cannot rename into place");
  std::lock_guard<std::mutex> lock(pending_mutex);
  pending().erase(tmp);
}

void remove_pending_temporary_files() {
  // Called on SIGINT/SIGTERM: unlink is async-signal-safe; the set is not modified here.
  for (const std::string& f : pending()) ::unlink(f.c_str());
}

}  // namespace ccd
