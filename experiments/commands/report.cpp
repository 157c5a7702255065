// `ccdlab report RESULTS.json... -o DIR`: scripts/report.py (see python_script.hpp).
#include "command.hpp"
#include "python_script.hpp"

namespace ccdlab {
namespace {

int run_report(std::span<const std::string> args) { return run_python_script("report", "report.py", args); }

}  // namespace

extern const Command kReportCommand = {
    "report", "write report.md and a self-contained report.html of one or more results files",
    "usage: ccdlab report RESULTS.json... -o DIR [--title TEXT]\n"
    "\n"
    "Writes DIR/report.md and DIR/report.html (charts embedded; opens in a browser without a\n"
    "server), and the charts DIR/missed.png and DIR/cost.png: per method the zero-miss frontier\n"
    "(the largest dt at and below which it missed nothing), the missed fraction per dt and the\n"
    "cost; several results files (other scenes, other machines, another dt range) are overlaid\n"
    "on one chart and one table. Runs scripts/report.py with /usr/bin/python3 (matplotlib).\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input (one line naming the file and the field).\n",
    run_report};

}  // namespace ccdlab
