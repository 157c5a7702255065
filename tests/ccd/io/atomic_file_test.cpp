// OutputFile: checked before the work, only regular files, never an input, no temporary
// file left on any exit path; SHA-256 against the FIPS 180-4 examples.
#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <csignal>
#include <string_view>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ccd_io_atomic_file_test {

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

TEST_CASE("commit_together: when one output cannot be written, none appears", "[io][output]") {
  const Folder dir;
  const fs::path a = dir.path / "r.json", b = dir.path / "r.summary.md";
  std::ofstream(a) << "old results";
  std::ofstream(b) << "old summary";
  SECTION("both written") {
    ccd::OutputFile fa(a.string()), fb(b.string());
    ccd::OutputFile* files[] = {&fa, &fb};
    const std::string_view texts[] = {"new results", "new summary"};
    ccd::commit_together(files, texts);
    CHECK(slurp(a) == "new results");
    CHECK(slurp(b) == "new summary");
  }
  SECTION("the second one fails (a file size limit stands in for a full disk)") {
    ccd::OutputFile fa(a.string()), fb(b.string());
    // Writes past 1000 bytes fail with EFBIG (SIGXFSZ ignored meanwhile).
    struct rlimit saved {};
    REQUIRE(::getrlimit(RLIMIT_FSIZE, &saved) == 0);
    const auto previous = std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit small = saved;
    small.rlim_cur = 1000;
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &small) == 0);
    ccd::OutputFile* files[] = {&fa, &fb};
    const std::string big(5000, 'x');
    const std::string_view texts[] = {"new results", big};
    CHECK_THROWS_WITH(ccd::commit_together(files, texts), Catch::Matchers::Contains("r.summary.md: cannot write"));
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous);
    CHECK(slurp(a) == "old results");
    CHECK(slurp(b) == "old summary");
  }
  CHECK(dir.files() == 2);  // no temporary file left
}

TEST_CASE("remove_pending_temporary_files removes a registered temporary folder and its files", "[io][output]") {
  const Folder dir;
  const fs::path folder = dir.path / "DIR.tmp.1";
  const int slot = ccd::register_temporary_folder(folder.string());
  REQUIRE(slot >= 0);
  fs::create_directory(folder);
  std::ofstream(folder / "a.csv") << "x";
  ccd::register_temporary_folder_file(slot, (folder / "a.csv").string());
  ccd::remove_pending_temporary_files();
  CHECK_FALSE(fs::exists(folder));
  ccd::release_temporary_folder(slot);
}

}  // namespace ccd_io_atomic_file_test
