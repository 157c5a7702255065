// OutputDirectory: a folder appears whole at commit or not at all, and a folder the
// command did not write is never replaced.
#include <ccd/io/output_directory.hpp>
#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace ccd_io_output_directory_test {

namespace fs = std::filesystem;

namespace {

struct TempFolder {
  fs::path path;
  TempFolder() {
    std::string tmpl = (fs::temp_directory_path() / "ccdlab-outdir-test-XXXXXX").string();
    path = ::mkdtemp(tmpl.data());
  }
  ~TempFolder() { fs::remove_all(path); }
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST_CASE("OutputDirectory commits whole folders and refuses folders it did not write", "[io]") {
  TempFolder tmp;
  const std::string dest = (tmp.path / "out").string();
  const std::string temporary = dest + ".tmp." + std::to_string(::getpid());
  SECTION("new folder: nothing visible before commit, everything after") {
    ccd::OutputDirectory out(dest, "index.json");
    CHECK(fs::is_directory(temporary));
    out.write("index.json", "1");
    out.write("a.csv", "x");
    CHECK_FALSE(fs::exists(dest));
    out.commit();
    CHECK(slurp(fs::path(dest) / "index.json") == "1");
    CHECK(slurp(fs::path(dest) / "a.csv") == "x");
    CHECK_FALSE(fs::exists(temporary));
  }
  SECTION("a folder written before is replaced whole; no commit leaves it and no temporary") {
    {
      ccd::OutputDirectory out(dest, "index.json");
      out.write("index.json", "old");
      out.write("old.csv", "x");
      out.commit();
    }
    {
      ccd::OutputDirectory out(dest, "index.json");
      out.write("index.json", "abandoned");
    }  // an error before commit
    CHECK(slurp(fs::path(dest) / "index.json") == "old");
    CHECK_FALSE(fs::exists(temporary));
    ccd::OutputDirectory out(dest, "index.json");
    out.write("index.json", "new");
    out.commit();
    CHECK(slurp(fs::path(dest) / "index.json") == "new");
    CHECK_FALSE(fs::exists(fs::path(dest) / "old.csv"));
    CHECK(std::distance(fs::directory_iterator(tmp.path), fs::directory_iterator()) == 1);
  }
  SECTION("an empty folder is taken") {
    fs::create_directory(dest);
    ccd::OutputDirectory out(dest, "index.json");
    out.write("index.json", "1");
    out.commit();
    CHECK(slurp(fs::path(dest) / "index.json") == "1");
  }
  SECTION("refused: a folder without the marker, a file, a missing parent") {
    fs::create_directory(dest);
    std::ofstream(fs::path(dest) / "mine.txt") << "mine";
    CHECK_THROWS_AS(ccd::OutputDirectory(dest, "index.json"), ccd::InputError);
    CHECK(slurp(fs::path(dest) / "mine.txt") == "mine");
    const std::string file = (tmp.path / "file").string();
    std::ofstream(file) << "f";
    CHECK_THROWS_AS(ccd::OutputDirectory(file, "index.json"), ccd::InputError);
    CHECK_THROWS_AS(ccd::OutputDirectory((tmp.path / "no/out").string(), "index.json"), ccd::InputError);
    CHECK_FALSE(fs::exists(temporary));
  }
}

}  // namespace ccd_io_output_directory_test
