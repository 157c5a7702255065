#include "command.hpp"

#include <ccdlab_git_hash.hpp>

#include <algorithm>

namespace ccdlab {

// Each command's entry point and texts live in its own file.
extern const Command kRunCommand;
extern const Command kTruthCommand;
extern const Command kSceneCommand;
extern const Command kMethodsCommand;
extern const Command kMergeCommand;
extern const Command kReportCommand;
extern const Command kAnimateCommand;
extern const Command kCcdCommand;
extern const Command kClothCommand;
extern const Command kViewCommand;
extern const Command kPosesCommand;
extern const Command kImportCommand;
extern const Command kPackCommand;

std::span<const Command> commands() {
  static const Command table[] = {kRunCommand,   kTruthCommand,   kSceneCommand, kMethodsCommand, kMergeCommand,
                                  kCcdCommand,   kClothCommand,   kReportCommand, kAnimateCommand,
                                  kViewCommand,  kPosesCommand,   kImportCommand, kPackCommand};
  return table;
}

std::string version_string() { return std::string(CCDLAB_VERSION) + " (git " + CCDLAB_GIT_HASH + ")"; }

bool wants_help(std::span<const std::string> args) {
  return std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "-h" || a == "--help"; });
}

}  // namespace ccdlab
