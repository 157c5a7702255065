#include "output_directory.hpp"

#include <ccd/scene/input_error.hpp>

#include <filesystem>
#include <fstream>
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
  if (!fs::create_directory(temporary_, ec) || ec) {
    temporary_.clear();
    throw InputError(path_, "", "cannot create a folder beside it");
  }
}

OutputDirectory::~OutputDirectory() {
  if (!committed_ && !temporary_.empty()) {
    std::error_code ec;
    fs::remove_all(temporary_, ec);
  }
}

std::string OutputDirectory::file(std::string_view name) const { return (fs::path(temporary_) / name).string(); }

void OutputDirectory::write(std::string_view name, std::string_view text) {
  const std::string f = file(name);
  std::ofstream out(f, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error(path_ + ": cannot write " + std::string(name));
}

void OutputDirectory::commit() {
  if (committed_) return;
  std::error_code ec;
  const fs::path dest(path_);
  std::string old;
  if (fs::exists(fs::symlink_status(dest, ec))) {
    old = (dest.has_filename() ? dest : dest.parent_path()).string() + ".old." + std::to_string(::getpid());
    fs::remove_all(old, ec);
    fs::rename(dest, old, ec);
    if (ec) throw std::runtime_error(path_ + ": cannot move the previous folder aside: " + ec.message());
  }
  fs::rename(temporary_, dest, ec);
  if (ec) {
    if (!old.empty()) fs::rename(old, dest, ec);
    throw std::runtime_error(path_ + ": cannot rename the new folder into place");
  }
  committed_ = true;
  if (!old.empty()) fs::remove_all(old, ec);
}

}  // namespace ccd
