// Loading a scene file end to end, JSON against the binary companion format
// (ccd/scene/scene_binary.hpp), and the parts of a load: parsing the JSON into a document
// only (read_json_file), validating a scene in memory (validate_scene) and its digest
// (scene_digest, which `ccdlab truth` and `ccdlab run` compute). The scenes are made here, in
// a temporary folder removed at exit: a gas of N spheres (radii uniform in [0.5, 1.5],
// speeds in [0, 10] m/s, uniform in a cube of 10% volume fraction with elastic walls,
// horizon 0.01 s), written as `ccdlab scene` writes it (indented JSON) and with
// ccd::save_binary_scene. N = 100,000 and 1,000,000 (about 28 and 280 MB of JSON);
// --sizes=N,... changes them. Each benchmark is one load per iteration; quote medians:
//   ./build/scene_io_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//   ./build/scene_io_bench --benchmark_filter='binary|digest' --benchmark_repetitions=5
#include <ccd/io/json_reader.hpp>
#include <ccd/scene/scene_binary.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <benchmarks/support/size_option.hpp>

#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

ccd::Scene gas(std::size_t n) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> radius(0.5, 1.5), unit(0.0, 1.0), normal_ish(-1.0, 1.0);
  // Mean ball volume (4/3) pi E[r^3], E[r^3] = (1.5^4 - 0.5^4) / 4 for r uniform in [0.5, 1.5].
  const double ball = 4.0 / 3.0 * M_PI * (std::pow(1.5, 4) - std::pow(0.5, 4)) / 4.0;
  const double side = std::cbrt(static_cast<double>(n) * ball / 0.1);
  ccd::Scene s;
  s.horizon = 0.01;
  s.box = ccd::WallBox{};
  s.box->max = ccd::Vec3::Constant(side);
  s.bodies.resize(n);
  for (ccd::Body& b : s.bodies) {
    b.radius = radius(rng);
    for (int k = 0; k < 3; ++k) b.position[k] = b.radius + unit(rng) * (side - 2.0 * b.radius);
    ccd::Vec3 d(normal_ish(rng), normal_ish(rng), normal_ish(rng));
    if (d.norm() == 0.0) d = ccd::Vec3::UnitX();
    b.velocity = d.normalized() * (10.0 * unit(rng));
  }
  return s;
}

struct Files {
  std::filesystem::path folder;
  std::map<std::size_t, std::pair<std::string, std::string>> by_size;  // N -> (json, binary)
  ~Files() {
    if (!folder.empty()) std::filesystem::remove_all(folder);
  }
};

Files& files() {
  static Files f;
  return f;
}

void load_json(benchmark::State& state, std::size_t n) {
  const std::string& path = files().by_size.at(n).first;
  for (auto _ : state) benchmark::DoNotOptimize(ccd::load_scene(path));
}

void load_binary(benchmark::State& state, std::size_t n) {
  const std::string& path = files().by_size.at(n).second;
  for (auto _ : state) benchmark::DoNotOptimize(ccd::load_scene(path));
}

void parse_json_only(benchmark::State& state, std::size_t n) {
  const std::string& path = files().by_size.at(n).first;
  for (auto _ : state) benchmark::DoNotOptimize(ccd::read_json_file(path));
}

void validate(benchmark::State& state, std::size_t n) {
  const ccd::Scene scene = ccd::load_scene(files().by_size.at(n).second);
  for (auto _ : state) ccd::validate_scene(scene, "bench");
}

void digest(benchmark::State& state, std::size_t n) {
  const ccd::Scene scene = ccd::load_scene(files().by_size.at(n).second);
  for (auto _ : state) benchmark::DoNotOptimize(ccd::scene_digest(scene));
}

}  // namespace

int main(int argc, char** argv) {
  auto args = ccdlab::bench::take_sizes(argc, argv, {100000, 1000000}, "scene_io_bench", 10000000, "1e7");
  if (!args) return 2;
  const std::vector<std::size_t>& sizes = args->sizes;
  std::vector<char*>& rest = args->rest;
  std::string tmpl = (std::filesystem::temp_directory_path() / "scene_io_bench-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) {
    std::perror("scene_io_bench: mkdtemp");
    return 1;
  }
  files().folder = tmpl;
  for (std::size_t n : sizes) {
    const ccd::Scene scene = gas(n);
    const std::string base = (files().folder / ("gas" + std::to_string(n))).string();
    ccd::save_scene(scene, base + ".json");
    ccd::save_binary_scene(scene, base + ".ccds");
    files().by_size[n] = {base + ".json", base + ".ccds"};
    std::fprintf(stderr, "gas %zu: %ju bytes of JSON, %ju bytes binary\n", n,
                 static_cast<std::uintmax_t>(std::filesystem::file_size(base + ".json")),
                 static_cast<std::uintmax_t>(std::filesystem::file_size(base + ".ccds")));
    auto name = [n](const char* what) {
      std::string s(what);
      s += '/';
      s += std::to_string(n);
      return s;
    };
    benchmark::RegisterBenchmark(name("load_scene/json").c_str(), load_json, n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(name("load_scene/binary").c_str(), load_binary, n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(name("read_json_file").c_str(), parse_json_only, n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(name("validate_scene").c_str(), validate, n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(name("scene_digest").c_str(), digest, n)->Unit(benchmark::kMillisecond);
  }
  int rest_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
