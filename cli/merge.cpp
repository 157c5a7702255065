// `ccdlab merge SHARD.json... -o RESULTS.json`
#include "command.hpp"
#include "command_line.hpp"

#include "../experiments/results_file.hpp"
#include "../experiments/summary.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>

#include <iostream>
#include <new>
#include <optional>
#include <string_view>

namespace ccdlab {
namespace {

int run_merge(std::span<const std::string> args) {
  std::vector<std::string> inputs;
  std::string out;
  CommandLine cli("merge",
                  "Checks every input as a ccdlab-results/2 file (every field with its type, job indices\n"
                  "within the experiment and owned by the shard), that all are shards of the same\n"
                  "experiment, scene (contents, by digest) and ground truth, that no shard appears twice\n"
                  "and none is missing, and writes one results file ordered by job ('-' = standard\n"
                  "output; never over an input). Prints the summary table of `ccdlab run` and writes it\n"
                  "beside the results (RESULTS.summary.md).\n",
                  "merge");
  cli.footer("Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).");
  cli.positionals("SHARD.json", inputs, "the shard results (ccdlab run --shard K/N), any order");
  cli.text("-o,--output", out, "RESULTS.json", "the merged results", "-o needs a file name");
  try {
    if (!cli.parse(args)) return 0;
    if (inputs.empty() || out.empty()) cli.fail("need at least one shard file and -o RESULTS.json");
  } catch (...) {
    return command_failed("merge");
  }
  try {
    // The results and their summary side-file: both checked against every shard now, and
    // written as one after the merge (neither is left without the other).
    ccd::OutputFile output(out, inputs);
    std::optional<ccd::OutputFile> summary;
    if (out != "-") summary.emplace(summary_path(out), inputs);
    std::vector<ResultsShard> shards;
    for (const std::string& f : inputs) shards.push_back({f, ccd::read_json_file(f)});
    const nlohmann::json merged = merge_results(shards);
    const std::string text = merged.dump(1) + "\n";
    if (summary) {
      const std::string markdown = summary_markdown(merged);
      ccd::OutputFile* files[] = {&output, &*summary};
      const std::string_view texts[] = {text, markdown};
      ccd::commit_together(files, texts);
    } else {
      output.commit(text);
    }
    (out == "-" ? std::cerr : std::cout) << "\n" << summary_text(merged) << "\n";
  } catch (...) {
    return command_failed("merge", "reading " + std::to_string(inputs.size()) + " shard files");
  }
  if (out != "-") std::cout << "results: " << out << "\nsummary: " << summary_path(out) << "\n";
  return 0;
}

}  // namespace

extern const Command kMergeCommand = {
    "merge", "join the shard results of one experiment (ccdlab run --shard K/N)", run_merge};

}  // namespace ccdlab
