#include "command.hpp"
#include "command_line.hpp"

#include <ccd/io/input_error.hpp>
#include <ccdlab_git_hash.hpp>

#include <exception>
#include <iostream>
#include <new>

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
extern const Command kMeshFramesCommand;

std::span<const Command> commands() {
  static const Command table[] = {kRunCommand,   kTruthCommand,   kSceneCommand, kMethodsCommand, kMergeCommand,
                                  kCcdCommand,   kClothCommand,   kReportCommand, kAnimateCommand,
                                  kViewCommand,  kPosesCommand,   kImportCommand, kPackCommand,
                                  kMeshFramesCommand};
  return table;
}

std::string version_string() { return std::string(CCDLAB_VERSION) + " (git " + CCDLAB_GIT_HASH + ")"; }

int command_failed(std::string_view name, const std::string& out_of_memory_detail) {
  try {
    throw;
  } catch (const UsageError& e) {
    std::cerr << "ccdlab " << name << ": " << e.what() << "\n";
    return kExitBadInput;
  } catch (const ccd::InputError& e) {
    std::cerr << "ccdlab " << name << ": " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "ccdlab " << name << ": out of memory" << (out_of_memory_detail.empty() ? "" : " ")
              << out_of_memory_detail << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "ccdlab " << name << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace ccdlab
