// Hostile and extreme input to the ccdlab command, end to end: every case exits with one
// line naming the file and the field (status 2 for bad input, 1 for runtime failures),
// writes no file, leaves no temporary file, and never crashes. One TEST_CASE per defect
// family; the reproducer of each is its first SECTION.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_hostile_input_test {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Run {
  int status;       // exit status; 128 + N when ended by signal N
  std::string out;  // standard output
  std::string err;  // standard error
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class Scratch {
 public:
  Scratch() {
    std::string tmpl = (fs::temp_directory_path() / "ccdlab-hostile-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
  }
  ~Scratch() { fs::remove_all(dir_); }
  std::string operator/(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return *this / name;
  }
  std::string write(const std::string& name, const json& j) const { return write(name, j.dump()); }
  // Files left in the folder whose name contains ".tmp." (temporary files of an output).
  int temporaries() const {
    int n = 0;
    for (const auto& f : fs::directory_iterator(dir_)) n += f.path().filename().string().find(".tmp.") != std::string::npos;
    return n;
  }
  const fs::path& path() const { return dir_; }

 private:
  fs::path dir_;
};

// Runs `ccdlab ARGS` through the shell (ARGS may carry redirections and `ulimit`).
Run ccdlab(const Scratch& dir, const std::string& args, const std::string& prefix = "") {
  const std::string cmd = prefix + std::string(CCDLAB_BINARY) + " " + args + " >" + (dir / "stdout.txt") + " 2>" +
                          (dir / "stderr.txt");
  const int raw = std::system(("sh -c '" + cmd + "'").c_str());
  const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return {status, slurp(dir / "stdout.txt"), slurp(dir / "stderr.txt")};
}

bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == s.size() - 1; }

json two_bodies(double speed = 1.0) {
  return {{"format", "ccdlab-scene/1"},
          {"horizon", 1.0},
          {"bodies",
           {{{"radius", 0.5}, {"position", {0, 0, 0}}, {"velocity", {speed, 0, 0}}},
            {{"radius", 0.5}, {"position", {5, 0, 0}}, {"velocity", {-speed, 0, 0}}}}}};
}

json experiment(const std::string& scene, const json& methods = {"aabb/grid", "capsule/grid"},
                const json& dt = {0.1, 0.01}) {
  return {{"format", "ccdlab-experiment/1"}, {"scene", scene}, {"dt", dt}, {"methods", methods}};
}

}  // namespace

TEST_CASE("magnitudes whose products overflow are rejected with the field and the limit", "[hostile][cli]") {
  const Scratch dir;
  const std::string out = dir / "out.json";
  SECTION("|velocity| 1e300 with no walls: once a SIGSEGV in the grid broad phase") {
    const std::string scene = dir.write("fast.json", two_bodies(1e300));
    const Run r = ccdlab(dir, "run " + dir.write("e.json", experiment(scene)) + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab run: " + scene + ": bodies[0].velocity[0]: magnitude above the limit 1e+30\n");
  }
  SECTION("acceleration 1e308 inside a box: once a body left the box with a bogus event at t = 0") {
    json s = two_bodies(0.0);
    s["box"] = {{"min", {-1, -1, -1}}, {"max", {6, 1, 1}}};
    s["bodies"][0]["acceleration"] = {1e308, 0, 0};
    const Run r = ccdlab(dir, "truth " + dir.write("s.json", s) + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab truth: " + (dir / "s.json") + ": bodies[0].acceleration[0]: magnitude above the limit 1e+30\n");
  }
  SECTION("each number within the limit, but the distance travelled beyond it") {
    json s = two_bodies(1e25);
    s["horizon"] = 1e6;
    const Run r = ccdlab(dir, "truth " + dir.write("s.json", s));
    CHECK(r.status == 2);
    CHECK(r.err.find("bodies[0].velocity: |velocity| * horizon is 1e+31 m, above the limit 1e+30 m") != std::string::npos);
    s = two_bodies(0.0);
    s["horizon"] = 1e15;
    s["gravity"] = {0, 0, 1e1};
    const Run g = ccdlab(dir, "truth " + dir.write("s.json", s));
    CHECK(g.status == 2);
    CHECK(g.err.find("bodies[0].acceleration: |acceleration + gravity| * horizon^2 / 2") != std::string::npos);
  }
  SECTION("a body as wide as the box, moving across it: once it left the box at t = 0 (found by fuzz_scene)") {
    json s = two_bodies(0.0);
    s["box"] = {{"min", {-1, -1, -1}}, {"max", {6, 0.5, 1}}};
    s["bodies"][1]["position"] = {5, -0.25, 0};
    s["bodies"][1]["radius"] = 0.75;  // y in [-1, 0.5]: no room on axis 1
    s["bodies"][1]["velocity"] = {0, 7, 0};
    const std::string file = dir.write("s.json", s);
    const Run r = ccdlab(dir, "truth " + file + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab truth: " + file +
                       ": bodies[1].velocity[1]: must be 0: the body fills the box on this axis (no room to move "
                       "between the walls)\n");
    s["bodies"][1]["velocity"] = {-3, 0, 0};  // along an axis with room it moves and bounces
    CHECK(ccdlab(dir, "truth " + dir.write("s.json", s)).status == 0);
  }
  SECTION("an acceleration bound of 1e308 for the horn bounds") {
    json e = experiment(dir.write("s.json", two_bodies()), {"horn:4/grid"});
    e["acceleration_bound"] = 1e308;
    const Run r = ccdlab(dir, "run " + dir.write("e.json", e) + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err.find("acceleration_bound: must be a number in [0, 1e+30]") != std::string::npos);
  }
  SECTION("at the limit every method of every broad phase runs, and no conservative one misses") {
    // Speeds 1e29 m/s over 10 s and an acceleration bound of 1e28: lengths up to 1e30.
    json s = two_bodies(1e29);
    s["horizon"] = 10.0;
    s["bodies"].push_back({{"radius", 1e20}, {"position", {-1e29, 1e29, 0}}, {"acceleration", {0, -2e28, 0}}});
    json methods = json::array();
    for (const char* bound : {"sphere", "aabb", "swept_aabb", "capsule", "horn:2", "horn_sat:2", "enclosing_sphere"})
      for (const char* broad : {"brute", "sap", "sweep", "grid", "hgrid", "rtree"})
        methods.push_back(std::string(bound) + "/" + broad);
    const Run r = ccdlab(dir, "run " + dir.write("e.json", experiment(dir.write("s.json", s), methods, {1.0, 0.1})) +
                                  " --quiet -o " + out);
    REQUIRE(r.status == 0);
    std::ifstream in(out);
    const json results = json::parse(in);
    REQUIRE(results["truth"]["events"].get<int>() >= 1);
    for (const json& rec : results["records"])
      if (rec["continuous"].get<bool>() && rec["conservative"].get<bool>()) CHECK(rec["missed"] == 0);
  }
  CHECK(dir.temporaries() == 0);
}

TEST_CASE("a dt the horizon cannot resolve is rejected, past the work limit a run needs --force", "[hostile][cli]") {
  const Scratch dir;
  const std::string out = dir / "out.json";
  const std::string scene = dir.write("s.json", two_bodies());
  SECTION("dt = 1e-300: once 0 steps, exit 0, and a conservative method missing every event") {
    const Run r = ccdlab(dir, "run " + dir.write("e.json", experiment(scene, {"capsule/grid"}, {0.1, 1e-300})) +
                                  " -o " + out);
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK(r.err.find("dt: timestep 1e-300 is below what the horizon 1.0 can resolve") != std::string::npos);
  }
  SECTION("dt = 1e-12: 1e12 steps per job, refused before the run with the estimate") {
    const std::string e = dir.write("e.json", experiment(scene, {"capsule/grid"}, {1e-12}));
    const Run r = ccdlab(dir, "run " + e + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab run: " + e + ": dt: the run needs 2e+12 body-steps (2 bodies, up to 1e+12 steps per job "
                                        "at dt = 1e-12), above the limit 1e+11 without --force\n");
    // --force passes the estimate: the next check (the destination) is what stops it here.
    const Run forced = ccdlab(dir, "run " + e + " --force -o /dev/null");
    CHECK(forced.status == 2);
    CHECK(forced.err.find("/dev/null: is not a regular file") != std::string::npos);
  }
  SECTION("the estimate is printed before the run") {
    const Run r = ccdlab(dir, "run " + dir.write("e.json", experiment(scene)) + " -o " + out);
    CHECK(r.status == 0);
    CHECK(r.err.find("ccdlab: work: 448 body-steps (2 bodies, up to 101 steps per job)") != std::string::npos);
  }
}

TEST_CASE("outputs: never over an input, only regular files, checked before the work, no temporaries", "[hostile][cli]") {
  const Scratch dir;
  const std::string scene = dir.write("s.json", two_bodies());
  const std::string scene_text = slurp(scene);
  const std::string e = dir.write("e.json", experiment(scene));
  const std::string e_text = slurp(e);
  SECTION("-o onto the input file") {
    Run r = ccdlab(dir, "run " + e + " -o " + e);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab run: " + e + ": is an input of this command (" + e + "); choose another output file\n");
    r = ccdlab(dir, "run " + e + " -o " + scene);
    CHECK(r.status == 2);
    r = ccdlab(dir, "truth " + scene + " -o " + scene);
    CHECK(r.status == 2);
    // The same file under another name.
    fs::create_hard_link(scene, dir / "link.json");
    r = ccdlab(dir, "truth " + scene + " -o " + (dir / "link.json"));
    CHECK(r.status == 2);
    CHECK(r.err.find("is an input of this command") != std::string::npos);
    CHECK(slurp(e) == e_text);
    CHECK(slurp(scene) == scene_text);
  }
  SECTION("-o /dev/null and /dev/full: refused, the device stays a device") {
    for (const char* device : {"/dev/null", "/dev/full"}) {
      for (const std::string& cmd : {"run " + e, "truth " + scene, std::string("scene gas bodies=3")}) {
        const Run r = ccdlab(dir, cmd + " -o " + device);
        CHECK(r.status == 2);
        CHECK(r.err.find(std::string(device) + ": is not a regular file") != std::string::npos);
      }
      struct stat st {};
      REQUIRE(::stat(device, &st) == 0);
      CHECK(S_ISCHR(st.st_mode));
    }
  }
  SECTION("a symbolic link is followed: the file it points to is replaced, the link stays") {
    const std::string target = dir.write("target.json", std::string("old"));
    fs::create_symlink(target, dir / "link.json");
    REQUIRE(ccdlab(dir, "truth " + scene + " -o " + (dir / "link.json")).status == 0);
    CHECK(fs::is_symlink(dir / "link.json"));
    CHECK(slurp(target).find("ccdlab-truth/2") != std::string::npos);
  }
  SECTION("an experiment named ../../escape does not choose where the results go") {
    json bad = experiment(scene);
    bad["name"] = "../../escape";
    const Run r = ccdlab(dir, "run " + dir.write("bad.json", bad));
    CHECK(r.status == 2);
    CHECK(r.err.find("bad.json: name: '../../escape' is not a plain file name") != std::string::npos);
  }
  SECTION("a folder that cannot take a file is found before the run, not after it") {
    // /proc refuses new files for every user, root included.
    const Run r = ccdlab(dir, "run " + e + " -o /proc/ccdlab-results.json");
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK(r.err.find("cannot write to the folder '/proc'") != std::string::npos);
    const Run t = ccdlab(dir, "truth " + scene + " -o /proc/ccdlab-truth.json");
    CHECK(t.status == 2);
    const Run s = ccdlab(dir, "scene gas bodies=3 -o /proc/ccdlab-scene.json");
    CHECK(s.status == 2);
  }
  SECTION("truth interrupted while it works leaves no FILE.tmp.*") {
    // The scene is a pipe nobody writes: truth has created its temporary output and waits
    // in the read, where SIGTERM reaches it.
    const std::string fifo = dir / "scene.fifo";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const std::string out = dir / "truth.json";
    const std::string cmd = "sh -c '" + std::string(CCDLAB_BINARY) + " truth " + fifo + " -o " + out +
                            " 2>/dev/null & p=$!; while ! ls " + out + ".tmp.* >/dev/null 2>&1; do sleep 0.01; done; "
                            "kill -TERM $p; wait $p'";
    const int raw = std::system(cmd.c_str());
    CHECK(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 128 + SIGTERM);
    CHECK_FALSE(fs::exists(out));
  }
  SECTION("run -o - prints the JSON and nothing else on standard output") {
    const Run r = ccdlab(dir, "run " + e + " --quiet -o -");
    REQUIRE(r.status == 0);
    CHECK(json::parse(r.out)["format"] == "ccdlab-results/2");
  }
  CHECK(dir.temporaries() == 0);
}

TEST_CASE("out of memory and absurd sizes: one line, exit 1 or 2, no file", "[hostile][cli]") {
  const Scratch dir;
  const std::string out = dir / "out.json";
  SECTION("truth --windows 999999999: bounded up front") {
    const Run r = ccdlab(dir, "truth " + dir.write("s.json", two_bodies()) + " --windows 999999999 -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab truth: --windows must be at most 1000000, got 999999999 (see ccdlab truth --help)\n");
  }
  SECTION("an experiment reading /dev/zero: fails at the first byte, not after all memory") {
    const Run r = ccdlab(dir, "run " + dir.write("e.json", experiment("/dev/zero")) + " -o " + out);
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK(r.err.find("/dev/zero: malformed JSON") != std::string::npos);
  }
  SECTION("a folder as the scene") {
    const Run r = ccdlab(dir, "truth " + dir.path().string());
    CHECK(r.status == 2);
    CHECK(r.err.find("cannot open file: is a folder") != std::string::npos);
  }
#ifndef CCDLAB_SANITIZED  // the sanitizers' allocator aborts instead of throwing std::bad_alloc
  SECTION("a huge generator count under a memory limit: std::bad_alloc caught and named") {
    // 1e8 bodies need about 10 GB; the shell limits the address space to 2 GB.
    const Run r = ccdlab(dir, "scene gas bodies=100000000 -o " + out, "ulimit -v 2000000; ");
    CHECK(r.status == 1);
    CHECK(r.err == "ccdlab scene: out of memory generating gas with bodies=100000000\n");
    json e = experiment("x");
    e["scene"] = {{"generator", "gas"}, {"bodies", 100000000}};
    const Run run = ccdlab(dir, "run " + dir.write("e.json", e) + " -o " + out, "ulimit -v 2000000; ");
    CHECK(run.status == 1);
    CHECK(run.err.find("ccdlab run: out of memory generating the scene") != std::string::npos);
  }
#endif
  CHECK_FALSE(fs::exists(out));
  CHECK(dir.temporaries() == 0);
}

TEST_CASE("silent oddities are errors or are normalised", "[hostile][cli]") {
  const Scratch dir;
  const std::string out = dir / "out.json";
  SECTION("a duplicate key: radius -1 then 0.5 is not read as 0.5") {
    const std::string s = dir.write("s.json", std::string(R"({"format": "ccdlab-scene/1", "horizon": 1,
      "bodies": [{"radius": 0.5, "position": [0, 0, 0]}, {"radius": -1, "radius": 0.5, "position": [3, 0, 0]}]})"));
    const Run r = ccdlab(dir, "truth " + s);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab truth: " + s + ": bodies[1].radius: key given twice in one object\n");
  }
  SECTION("the same method spelled three ways") {
    const std::string s = dir.write("s.json", two_bodies());
    const Run r = ccdlab(dir, "run " + dir.write("e.json", experiment(s, {"horn/grid", "horn:4/grid", "horn:04/grid"})) +
                                  " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err.find("methods[1]: method 'horn:4/grid' is the same method as methods[0] ('horn/grid')") !=
          std::string::npos);
    const Run z = ccdlab(dir, "run " + dir.write("e.json", experiment(s, {"horn:4/grid", "horn:04/grid"})) + " -o " + out);
    CHECK(z.status == 2);
    CHECK(z.err.find("methods[1]: method 'horn:04/grid' is the same method as methods[0]") != std::string::npos);
  }
  SECTION("a seed beyond 2^53 on the command line") {
    Run r = ccdlab(dir, "scene gas bodies=3 seed=9007199254740993 -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab scene: gas: parameter 'seed': integer 9007199254740993 is too large to be exact (|x| > 2^53)\n");
    r = ccdlab(dir, "scene gas bodies=3 seed=9007199254740992 -o " + out);  // 2^53 itself is exact
    CHECK(r.status == 0);
    fs::remove(out);
  }
  SECTION("too many wall reflections name the body") {
    json s = two_bodies(0.0);
    s["box"] = {{"min", {-1, -1, -1}}, {"max", {6, 1, 1}}};
    s["bodies"][1]["velocity"] = {1e7, 0, 0};  // 1e7 m/s across a 1 m gap: millions of bounces
    const std::string file = dir.write("s.json", s);
    Run r = ccdlab(dir, "truth " + file);
    CHECK(r.status == 2);
    CHECK(r.err.find("ccdlab truth: " + file + ": bodies[1]: needs more than 1000000 trajectory pieces") == 0);
    r = ccdlab(dir, "run " + dir.write("e.json", experiment(file)) + " --quiet -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err.find("ccdlab run: " + file + ": bodies[1]: needs more than 1000000 trajectory pieces") == 0);
  }
  CHECK_FALSE(fs::exists(out));
  CHECK(dir.temporaries() == 0);
}

}  // namespace cli_hostile_input_test
