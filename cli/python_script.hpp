#pragma once
// Subcommands written in Python (`ccdlab report`, `ccdlab animate`): the command replaces
// itself with /usr/bin/python3 running scripts/NAME.py with the same arguments, so the
// script's output and exit status are the command's. Charts and pictures are matplotlib's
// job (Debian's python3-matplotlib), and `animate` needs the ccdlab Python module: this
// build's python/ folder is put first on PYTHONPATH.
//
// The scripts folder is the one named by the environment variable CCDLAB_SCRIPTS_DIR, else
// PREFIX/share/ccdlab/scripts when the program is installed as PREFIX/bin/ccdlab, else this
// source tree's scripts/ (set at build time); the interpreter is /usr/bin/python3 unless
// CCDLAB_PYTHON3 names another.
#include <span>
#include <string>

namespace ccdlab {

/// Runs scripts/`script` with `args`; returns only on failure (exit status 1, message on
/// stderr naming `command`).
int run_python_script(const std::string& command, const std::string& script,
                      std::span<const std::string> args);

}  // namespace ccdlab
