// OutputFile: checked before the work, only regular files, never an input, no temporary
// file left on any exit path; SHA-256 against the FIPS 180-4 examples.
#include <ccd/io/atomic_file.hpp>
#include <ccd/scene/input_error.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct Folder {
  fs::path path;
  Folder() {
    std::string tmpl = (fs::temp_directory_path() / "ccdlab-output-XXXXXX").string();
    path = ::mkdtemp(tmpl.data());
  }
  ~Folder() { fs::remove_all(path); }
  std::size_t files() const {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& f : fs::directory_iterator(path)) ++n;
    return n;
  }
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("OutputFile creates its temporary file at once and renames it on commit", "[io][output]") {
  const Folder dir;
  const std::string target = (dir.path / "out.json").string();
  {
    ccd::OutputFile out(target);
    CHECK(dir.files() == 1);  // the temporary file: the folder takes a file
    CHECK_FALSE(fs::exists(target));
    out.commit("text\n");
  }
  CHECK(slurp(target) == "text\n");
  CHECK(dir.files() == 1);
  SECTION("not committed (an error, an exception): nothing changes, nothing is left") {
    { ccd::OutputFile out(target); }
    CHECK(slurp(target) == "text\n");
    CHECK(dir.files() == 1);
  }
  SECTION("an existing regular file is replaced whole") {
    ccd::write_file_atomically(target, "new");
    CHECK(slurp(target) == "new");
  }
}

TEST_CASE("OutputFile refuses what a rename would destroy", "[io][output]") {
  const Folder dir;
  SECTION("devices, folders and pipes") {
    CHECK_THROWS_WITH(ccd::OutputFile("/dev/null"), Catch::Matchers::StartsWith("/dev/null: is not a regular file"));
    CHECK_THROWS_WITH(ccd::OutputFile("/dev/full"), Catch::Matchers::StartsWith("/dev/full: is not a regular file"));
    CHECK_THROWS_WITH(ccd::OutputFile(dir.path.string()), Catch::Matchers::EndsWith("is a folder; the output must be a file"));
    const std::string fifo = (dir.path / "fifo").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK_THROWS_AS(ccd::OutputFile(fifo), ccd::InputError);
    struct stat st {};
    REQUIRE(::stat("/dev/null", &st) == 0);
    CHECK(S_ISCHR(st.st_mode));
  }
  SECTION("an input, under its own name or another") {
    const std::string input = (dir.path / "in.json").string();
    std::ofstream(input) << "input";
    const std::string inputs[] = {"-", input};
    CHECK_THROWS_WITH(ccd::OutputFile(input, inputs),
                      input + ": is an input of this command (" + input + "); choose another output file");
    fs::create_symlink(input, dir.path / "sym.json");
    CHECK_THROWS_AS(ccd::OutputFile((dir.path / "sym.json").string(), inputs), ccd::InputError);
    fs::create_hard_link(input, dir.path / "hard.json");
    CHECK_THROWS_AS(ccd::OutputFile((dir.path / "hard.json").string(), inputs), ccd::InputError);
    CHECK(slurp(input) == "input");
  }
  SECTION("a folder that takes no file, before any work") {
    CHECK_THROWS_WITH(ccd::OutputFile("/proc/ccdlab.json"),
                      Catch::Matchers::StartsWith("/proc/ccdlab.json: cannot write to the folder '/proc'"));
    CHECK_THROWS_WITH(ccd::OutputFile((dir.path / "missing" / "x.json").string()),
                      Catch::Matchers::Contains("cannot write to the folder"));
    ccd::OutputFile created((dir.path / "made" / "x.json").string(), {}, /*create_folder=*/true);
    CHECK(fs::is_directory(dir.path / "made"));
  }
  SECTION("an empty name") { CHECK_THROWS_AS(ccd::OutputFile(""), ccd::InputError); }
  CHECK(std::none_of(fs::directory_iterator(dir.path), fs::directory_iterator(), [](const fs::directory_entry& f) {
    return f.path().filename().string().find(".tmp.") != std::string::npos;
  }));
}

TEST_CASE("a symbolic link as the output: its target is replaced, the link stays", "[io][output]") {
  const Folder dir;
  const fs::path target = dir.path / "target.json";
  std::ofstream(target) << "old";
  fs::create_symlink(target, dir.path / "link.json");
  ccd::write_file_atomically((dir.path / "link.json").string(), "new");
  CHECK(fs::is_symlink(dir.path / "link.json"));
  CHECK(slurp(target) == "new");
}

TEST_CASE("remove_pending_temporary_files removes what a signal would leave", "[io][output]") {
  const Folder dir;
  ccd::OutputFile out((dir.path / "x.json").string());
  CHECK(dir.files() == 1);
  ccd::remove_pending_temporary_files();  // what the signal handlers call
  CHECK(dir.files() == 0);
}
