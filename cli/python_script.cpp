#include "python_script.hpp"

#include <unistd.h>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <vector>

namespace ccdlab {

int run_python_script(const std::string& command, const std::string& script,
                      std::span<const std::string> args) {
  const char* dir_env = std::getenv("CCDLAB_SCRIPTS_DIR");
  std::string dir = dir_env && *dir_env ? dir_env : CCDLAB_SCRIPTS_DIR;
  if (!dir_env || !*dir_env) {  // installed: PREFIX/bin/ccdlab and PREFIX/share/ccdlab/scripts
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    const auto installed = exe.parent_path().parent_path() / "share" / "ccdlab" / "scripts";
    if (!ec && std::filesystem::is_regular_file(installed / script, ec)) dir = installed.string();
  }
  const std::string path = dir + "/" + script;
  const char* python_env = std::getenv("CCDLAB_PYTHON3");
  const std::string python = python_env && *python_env ? python_env : "/usr/bin/python3";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    std::cerr << "ccdlab " << command << ": " << path
              << " not found (set CCDLAB_SCRIPTS_DIR to ccdlab's scripts folder)\n";
    return 1;
  }
#ifdef CCDLAB_PYTHON_MODULE_DIR
  const char* old = std::getenv("PYTHONPATH");
  std::string pythonpath = CCDLAB_PYTHON_MODULE_DIR;
  if (old && *old) {
    pythonpath += ':';
    pythonpath += old;
  }
  ::setenv("PYTHONPATH", pythonpath.c_str(), 1);
#endif
  std::vector<std::string> argv_text{python, path};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::cout.flush();
  ::execv(python.c_str(), argv.data());
  std::cerr << "ccdlab " << command << ": cannot run " << python << ": " << std::strerror(errno)
            << " (Debian's python3 and python3-matplotlib: scripts/install-deps.sh)\n";
  return 1;
}

}  // namespace ccdlab
