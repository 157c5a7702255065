// Faults, for every command that writes: a full disk (a 64 KiB tmpfs) and a read-only folder
// end with one line and leave the old output and no temporary file; SIGKILL at random
// points leaves the old output or the whole new one; two runs writing one output at once
// leave one whole file. Mounting needs root (CI runs as root): without it the disk cases
// are skipped with a message.
#include "cli_support.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <sys/mount.h>
#include <thread>
#include <vector>

namespace cli_hostile_faults_test {

namespace fs = std::filesystem;
using nlohmann::json;
using ccdlab::test::Folder;
using ccdlab::test::slurp;

namespace {

struct Run {
  int status;
  std::string err;
};

Run cli(const Folder& dir, const std::string& args) {
  Run r{};
  r.status = ccdlab::test::run_ccdlab(args, dir, nullptr, &r.err);
  return r;
}

int temporaries(const fs::path& folder) {
  int n = 0;
  for (const auto& f : fs::recursive_directory_iterator(folder))
    n += f.path().filename().string().find(".tmp.") != std::string::npos;
  return n;
}

// A tmpfs of `kib` KiB mounted on `path` (created), unmounted at the end; mounted() is false
// where mounting is not allowed.
class SmallDisk {
 public:
  SmallDisk(const fs::path& path, int kib) : path_(path) {
    fs::create_directories(path_);
    const std::string options = "size=" + std::to_string(kib) + "k";
    mounted_ = ::mount("tmpfs", path_.c_str(), "tmpfs", 0, options.c_str()) == 0;
  }
  ~SmallDisk() {
    if (mounted_) ::umount2(path_.c_str(), MNT_DETACH);
  }
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;
  bool mounted() const { return mounted_; }
  // Fills what is left of the disk (a file that takes every free block).
  void fill() const {
    std::ofstream f(path_ / "filler", std::ios::binary);
    const std::string block(4096, 'x');
    for (int i = 0; i < 100000 && f; ++i) f.write(block.data(), block.size()), f.flush();
  }
  void unfill() const { fs::remove(path_ / "filler"); }
  // Makes the file system read-only: even root cannot create a file in it.
  bool make_read_only() const {
    return ::mount(nullptr, path_.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr) == 0;
  }

 private:
  fs::path path_;
  bool mounted_ = false;
};

const char* kCloth = R"({"format": "ccdlab-cloth/1",
  "grid": {"nx": 3, "ny": 3, "origin": [0, 0, 0], "du": [0.5, 0, 0], "dv": [0, 0, 0.5]},
  "particle_mass": 0.1, "springs": {"structural": {"stiffness": 10, "damping": 0},
  "shear": {"stiffness": 1, "damping": 0}, "bend": {"stiffness": 1, "damping": 0}},
  "thickness": 0, "step": 0.01, "steps": 2})";

// The inputs of every writing command, outside the small disk.
struct Inputs {
  std::string scene, experiment, shard, csv, queries, cloth;
  explicit Inputs(const Folder& dir) {
    scene = dir / "s.json";
    std::ofstream(scene) << json{{"format", "ccdlab-scene/1"},
                                 {"horizon", 1.0},
                                 {"bodies",
                                  {{{"radius", 0.5}, {"position", {0, 0, 0}}, {"velocity", {1, 0, 0}}},
                                   {{"radius", 0.5}, {"position", {5, 0, 0}}, {"velocity", {-1, 0, 0}}}}}}
                                .dump();
    experiment = dir / "e.json";
    std::ofstream(experiment) << json{{"format", "ccdlab-experiment/1"}, {"scene", scene}, {"dt", {0.1, 0.01}},
                                      {"methods", {"aabb/grid"}}}
                                     .dump();
    shard = dir / "shard.json";
    csv = dir / "f.csv";
    std::ofstream(csv) << "body,t,x,y,z,radius\n0,0,0,0,0,0.5\n0,1,1,0,0,0.5\n1,0,3,0,0,0.5\n1,1,2,0,0,0.5\n";
    queries = dir / "q.csv";
    cloth = dir / "c.json";
    std::ofstream(cloth) << kCloth;
  }
};

struct Writer {
  std::string name;  // the output's name inside the disk
  std::string args;  // the command, with OUT for the output's path
  bool folder;       // the output is a folder (with `marker` in it)
  std::string marker;
};

std::vector<Writer> writers(const Inputs& in) {
  return {{"t.json", "truth " + in.scene + " -o OUT", false, ""},
          {"s.json", "scene gas bodies=200 -o OUT", false, ""},
          {"r.json", "run " + in.experiment + " --quiet -o OUT", false, ""},
          {"m.json", "merge " + in.shard + " -o OUT", false, ""},
          {"p.csv", "poses " + in.scene + " --times 0:1:0.001 -o OUT", false, ""},
          {"i.json", "import " + in.csv + " -o OUT", false, ""},
          {"v.html", "view " + in.scene + " -o OUT", false, ""},
          {"b.ccds", "pack " + in.scene + " -o OUT", false, ""},
          {"c.json", "ccd " + in.queries + " --kind vf -o OUT", false, ""},
          {"f.json", "cloth " + in.cloth + " -o OUT", false, ""},
          {"F", "cloth frames " + in.cloth + " -o OUT", true, "cloth.json"},
          {"Q", "cloth queries drape --n 4 --steps 0:1 -o OUT", true, "index.json"}};
}

std::string with_output(std::string args, const std::string& out) {
  args.replace(args.find("OUT"), 3, out);
  return args;
}

// Puts an old output at `out`: a file "old", or a folder holding the command's marker.
void put_old(const Writer& w, const fs::path& out) {
  if (w.folder) {
    fs::create_directories(out);
    std::ofstream(out / w.marker) << "old";
  } else {
    std::ofstream(out) << "old";
  }
}

bool old_intact(const Writer& w, const fs::path& out) {
  return w.folder ? slurp((out / w.marker).string()) == "old" : slurp(out.string()) == "old";
}

}  // namespace

TEST_CASE("a full disk and a read-only folder: one line, the old output kept, no temporary file",
          "[hostile][cli][faults]") {
  Folder dir;
  const Inputs in(dir);
  REQUIRE(cli(dir, "run " + in.experiment + " --quiet -o " + in.shard).status == 0);
  REQUIRE(cli(dir, "ccd --write-hard --kind vf -o " + in.queries).status == 0);
  const SmallDisk disk(dir.path / "disk", 64);
  if (!disk.mounted()) {
    WARN("skipped: cannot mount a tmpfs here (needs root)");
    return;
  }
  const fs::path root = dir.path / "disk";
  for (const Writer& w : writers(in)) put_old(w, root / w.name);
  SECTION("a full disk: exit 1") {
    disk.fill();
    for (const Writer& w : writers(in)) {
      INFO(w.args);
      const Run r = cli(dir, with_output(w.args, (root / w.name).string()));
      CHECK(r.status == 1);
      CHECK((!r.err.empty() && r.err.find('\n') == r.err.size() - 1));
      CHECK(old_intact(w, root / w.name));
      CHECK(temporaries(root) == 0);
    }
    CHECK_FALSE(fs::exists(root / "r.summary.md"));
    CHECK_FALSE(fs::exists(root / "m.summary.md"));
  }
  SECTION("a read-only folder (a read-only mount, which stops root too): exit 2 before the work") {
    REQUIRE(disk.make_read_only());
    for (const Writer& w : writers(in)) {
      INFO(w.args);
      const Run r = cli(dir, with_output(w.args, (root / w.name).string()));
      CHECK(r.status == 2);
      CHECK((!r.err.empty() && r.err.find('\n') == r.err.size() - 1));
      CHECK(old_intact(w, root / w.name));
    }
    CHECK(temporaries(root) == 0);
  }
}

TEST_CASE("SIGKILL at random points leaves the old output or the whole new one", "[hostile][cli][faults]") {
  Folder dir;
  const Inputs in(dir);
  REQUIRE(cli(dir, "run " + in.experiment + " --quiet -o " + in.shard).status == 0);
  REQUIRE(cli(dir, "ccd --write-hard --kind vf -o " + in.queries).status == 0);
  std::mt19937_64 rng(36);
  for (const Writer& w : writers(in)) {
    const fs::path out = dir.path / "out" / w.name;
    fs::create_directories(out.parent_path());
    // The whole new output, for comparison (timings differ run to run: JSON is parsed).
    REQUIRE(cli(dir, with_output(w.args, (dir.path / ("new-" + w.name)).string())).status == 0);
    const fs::path whole = dir.path / ("new-" + w.name);
    auto is_whole_new = [&] {
      const fs::path f = w.folder ? out / w.marker : out;
      const fs::path g = w.folder ? whole / w.marker : whole;
      const std::string text = slurp(f.string()), expected = slurp(g.string());
      if (text == expected) return true;
      if (f.extension() != ".json") return false;
      const json j = json::parse(text, nullptr, false);
      return !j.is_discarded() && j.size() == json::parse(expected).size();
    };
    for (int trial = 0; trial < 4; ++trial) {
      put_old(w, out);
      const int delay_us = std::uniform_int_distribution<int>(0, 60000)(rng);
      const std::string cmd = "sh -c '" + std::string(CCDLAB_BINARY) + " " + with_output(w.args, out.string()) +
                              " >/dev/null 2>&1 & p=$!; " +
                              "sleep " + std::to_string(delay_us / 1e6) + "; kill -KILL $p 2>/dev/null; wait $p' 2>/dev/null";
      (void)std::system(cmd.c_str());
      INFO(w.args << " killed after " << delay_us << " us");
      CHECK((old_intact(w, out) || is_whole_new()));
      fs::remove_all(out);
      for (const auto& f : fs::directory_iterator(out.parent_path())) fs::remove_all(f.path());  // SIGKILL's leftovers
    }
  }
}

TEST_CASE("two runs writing one output at once leave one whole file", "[hostile][cli][faults]") {
  Folder dir;
  const Inputs in(dir);
  for (const Writer& w : {Writer{"t.json", "truth " + in.scene + " -o OUT", false, ""},
                          Writer{"F", "cloth frames " + in.cloth + " -o OUT", true, "cloth.json"}}) {
    const fs::path out = dir.path / w.name;
    REQUIRE(cli(dir, with_output(w.args, (dir.path / ("one-" + w.name)).string())).status == 0);
    auto content = [&](const fs::path& p) { return slurp((w.folder ? p / w.marker : p).string()); };
    const std::string expected = content(dir.path / ("one-" + w.name));
    const std::string one = std::string(CCDLAB_BINARY) + " " + with_output(w.args, out.string()) + " >/dev/null 2>&1";
    for (int trial = 0; trial < 3; ++trial) {
      const int raw = std::system(("sh -c '" + one + " & " + one + " & wait'").c_str());
      CHECK(WIFEXITED(raw));
      INFO(w.args);
      CHECK(content(out) == expected);
      CHECK(temporaries(dir.path) == 0);
    }
  }
}

}  // namespace cli_hostile_faults_test
