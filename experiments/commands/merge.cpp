// `ccdlab merge SHARD.json... -o RESULTS.json`
#include "command.hpp"

#include "../run_experiment.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/scene/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <iostream>

namespace ccdlab {
namespace {

int run_merge(std::span<const std::string> args) {
  std::vector<std::string> inputs;
  std::string out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-o" || args[i] == "--output") {
      if (i + 1 >= args.size()) {
        std::cerr << "ccdlab merge: -o needs a file name\n";
        return kExitBadInput;
      }
      out = args[++i];
    } else {
      inputs.push_back(args[i]);
    }
  }
  if (inputs.empty() || out.empty()) {
    std::cerr << "ccdlab merge: need at least one shard file and -o RESULTS.json (see ccdlab merge --help)\n";
    return kExitBadInput;
  }
  try {
    std::vector<nlohmann::json> shards;
    for (const std::string& f : inputs) shards.push_back(ccd::read_json_file(f));
    ccd::write_file_atomically(out, merge_results(shards, inputs).dump(1) + "\n");
  } catch (const std::exception& e) {
    std::cerr << "ccdlab merge: " << e.what() << "\n";
    return kExitBadInput;
  }
  std::cout << "results: " << out << "\n";
  return 0;
}

}  // namespace

extern const Command kMergeCommand = {
    "merge", "join the shard results of one experiment (ccdlab run --shard K/N)",
    "usage: ccdlab merge SHARD.json... -o RESULTS.json\n"
    "\n"
    "Checks that every input is a shard of the same experiment and scene, that no job\n"
    "appears twice and none is missing, and writes one results file ordered by job.\n",
    run_merge};

}  // namespace ccdlab
