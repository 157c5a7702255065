#pragma once
// Running the ccdlab program from a test: a temporary folder removed afterwards, and the
// program's exit status with what it printed.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace ccdlab::test {

struct Folder {
  std::filesystem::path path;
  Folder() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "ccdlab-cli-test-XXXXXX").string();
    path = ::mkdtemp(tmpl.data());
  }
  ~Folder() { std::filesystem::remove_all(path); }
  Folder(const Folder&) = delete;
  Folder& operator=(const Folder&) = delete;
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Runs `ccdlab ARGS` (stdout and stderr into files of `dir`); returns the exit status (-1
/// if it did not exit) and, when asked, what it printed.
inline int run_ccdlab(const std::string& args, const Folder& dir, std::string* out = nullptr,
                      std::string* err = nullptr) {
  const std::string o = dir / "stdout.txt", e = dir / "stderr.txt";
  const int rc = std::system((std::string(CCDLAB_BINARY) + " " + args + " >" + o + " 2>" + e).c_str());
  if (out) *out = slurp(o);
  if (err) *err = slurp(e);
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace ccdlab::test
