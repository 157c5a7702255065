// Every JSON example in the README and docs/ is valid JSON, and every scene or experiment
// among them is accepted by its reader (strict fields included), so that a newcomer can
// copy it. The shipped data files are checked the same way.
#include "../../experiments/cloth_experiment.hpp"
#include "../../experiments/experiment.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace docs_json_examples_test {

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> markdown_files() {
  const fs::path root = CCDLAB_SOURCE_DIR;
  std::vector<fs::path> files = {root / "README.md"};
  for (const auto& e : fs::recursive_directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") files.push_back(e.path());
  return files;
}

// Whether `doc` writes `name` with a command: some `-o PATH` whose PATH is `name` or ends in
// "/name" (an example experiment on a scene that the same page makes).
bool made_in(const std::string& doc, const std::string& name) {
  for (std::size_t at = doc.find("-o "); at != std::string::npos; at = doc.find("-o ", at + 3)) {
    const std::size_t from = at + 3, to = doc.find_first_of(" \n`", from);
    const std::string path = doc.substr(from, to == std::string::npos ? std::string::npos : to - from);
    if (path == name || (path.size() > name.size() && path.compare(path.size() - name.size() - 1, std::string::npos, "/" + name) == 0))
      return true;
  }
  return false;
}

// Checks one document: a scene or an experiment goes through its reader; an experiment's
// scene file is resolved against data/experiments/ (where the docs' examples live), or is
// one that the page `doc` makes with a command (`-o .../scene.json`).
void check_document(const nlohmann::json& j, const std::string& where, const std::string& doc) {
  INFO(where);
  if (!j.is_object() || !j.contains("format")) return;
  const std::string format = j["format"].get<std::string>();
  if (format == "ccdlab-scene/1" || format == "ccdlab-scene/2") {
    CHECK_NOTHROW(ccd::scene_from_json(j, where));
  } else if (format == "ccdlab-experiment/1") {
    ccdlab::Experiment e;
    REQUIRE_NOTHROW(e = ccdlab::experiment_from_json(j, where));
    if (!e.scene_path.empty()) {
      const fs::path scene = fs::path(CCDLAB_SOURCE_DIR) / "data" / "experiments" / e.scene_path;
      INFO(scene.string());
      if (fs::exists(scene) || !made_in(doc, e.scene_path)) CHECK_NOTHROW(ccd::load_scene(scene.lexically_normal().string()));
    }
  } else if (format == ccdlab::kClothExperimentFormat) {
    CHECK_NOTHROW(ccdlab::cloth_experiment_from_json(j, where));
  }
}

}  // namespace

TEST_CASE("every JSON block in the README and docs parses, scenes and experiments are accepted", "[docs]") {
  const std::regex block("```json\\n([\\s\\S]*?)```");
  int checked = 0;
  for (const fs::path& file : markdown_files()) {
    const std::string text = read(file);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), block); it != std::sregex_iterator(); ++it) {
      const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + it->position(), '\n'));
      const std::string where = file.filename().string() + ":" + std::to_string(line);
      nlohmann::json j;
      INFO(where);
      REQUIRE_NOTHROW(j = ccd::parse_json_text((*it)[1].str(), where));
      check_document(j, where, text);
      ++checked;
    }
  }
  CHECK(checked >= 9);  // README's experiment, docs/experiments.md's three, docs/formats.md's two scenes...
}

TEST_CASE("every JSON example in the README and docs is in a json block (so the test above reads it)", "[docs]") {
  // A fenced block without a language that opens like JSON would escape the check above.
  const std::regex block("```([A-Za-z]*)\n([\\s\\S]*?)```");
  for (const fs::path& file : markdown_files()) {
    const std::string text = read(file);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), block); it != std::sregex_iterator(); ++it) {
      const std::string lang = (*it)[1].str(), body = (*it)[2].str();
      const auto first = body.find_first_not_of(" \n");
      const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + it->position(), '\n'));
      INFO(file.filename().string() + ":" + std::to_string(line) + ": tag the block ```json");
      CHECK(!(lang.empty() && first != std::string::npos && (body[first] == '{' || body[first] == '[')));
    }
  }
}

TEST_CASE("the example experiment in docs/experiments.md is data/experiments/example.json", "[docs]") {
  const fs::path root = CCDLAB_SOURCE_DIR;
  const auto shipped = ccd::read_json_file((root / "data/experiments/example.json").string());
  const std::string doc = read(root / "docs/experiments.md");
  const auto at = doc.find("```json\n");
  REQUIRE(at != std::string::npos);
  const auto end = doc.find("```", at + 8);
  CHECK(ccd::parse_json_text(doc.substr(at + 8, end - at - 8), "docs/experiments.md") == shipped);
}

TEST_CASE("every shipped scene and experiment file is accepted", "[docs]") {
  const fs::path root = CCDLAB_SOURCE_DIR;
  int files = 0;
  for (const auto& e : fs::directory_iterator(root / "data/scenes")) {
    INFO(e.path().string());
    CHECK_NOTHROW(ccd::load_scene(e.path().string()));
    ++files;
  }
  int cloth = 0;
  for (const auto& e : fs::directory_iterator(root / "data/experiments")) {
    INFO(e.path().string());
    // Cloth experiments (the cloth study) have their own format and loader.
    if (ccd::read_json_file(e.path().string()).value("format", "") == "ccdlab-cloth-experiment/1") {
      const auto ex = ccdlab::load_cloth_experiment(e.path().string());
      CHECK_NOTHROW(ccdlab::load_cloth_experiment_scene(ex, e.path().string()));
      ++cloth;
    } else {
      CHECK_NOTHROW(ccdlab::load_experiment(e.path().string()));
    }
    ++files;
  }
  CHECK(cloth >= 2);
  CHECK(files >= 20);
}

}  // namespace docs_json_examples_test
