#include "command_line.hpp"

#include <ccd/util/integer_text.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>

namespace ccdlab {

std::string option_name(const std::string& names) { return names.substr(0, names.find(',')); }

CommandLine::CommandLine(const std::string& name, const std::string& description,
                         const std::string& help_name)
    : app_(description), name_(name), help_name_(help_name) {
  app_.name("ccdlab " + name_);  // the usage line: "Usage: ccdlab NAME [OPTIONS] ..."
  app_.allow_extras();  // reported by parse() in ccdlab's words ("unknown option '--x'")
  app_.get_formatter()->column_width(28);
  app_.get_formatter()->label("OPTIONS", "OPTIONS");
  app_.get_formatter()->label("REQUIRED", "");  // the usage line shows it: no brackets
  app_.set_help_flag("-h,--help", "print this help and exit");
}

void CommandLine::footer(const std::string& text) { app_.footer(text); }

CLI::Option* CommandLine::register_value(const std::string& names, const std::string& value_name,
                                         const std::string& help,
                                         std::function<void(const std::string&)> parse,
                                         const std::string& missing, bool once) {
  auto given = std::make_shared<bool>(false);
  const std::string shown = option_name(names);
  CLI::Option* o = app_.add_option(
      names,
      [this, parse, given, once, shown](const CLI::results_t& values) {
        if (once && *given) fail(shown + " given twice");
        *given = true;
        parse(values.empty() ? std::string() : values.back());
        return true;
      },
      help);
  o->type_name(value_name)
      ->expected(1)
      ->trigger_on_parse()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  missing_.push_back({o, missing.empty() ? shown + " needs " + value_name : missing});
  return o;
}

CLI::Option* CommandLine::text(const std::string& names, std::string& out, const std::string& value_name,
                               const std::string& help, const std::string& missing, bool once) {
  return register_value(
      names, value_name, help, [&out](const std::string& v) { out = v; }, missing, once);
}

CLI::Option* CommandLine::integer(const std::string& names, std::uint64_t lo, std::uint64_t hi,
                                  const std::string& value_name, const std::string& help,
                                  const std::function<void(std::uint64_t)>& set) {
  const std::string shown = option_name(names);
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return register_value(
      names, value_name, help,
      [this, set, lo, hi, shown, range](const std::string& v) {
        const auto n = ccd::parse_integer(v, lo, hi);
        if (!n) fail(shown + ": must be an integer in " + range + ", got '" + v + "'");
        set(*n);
      },
      shown + " needs an integer in " + range, false);
}

CLI::Option* CommandLine::number(const std::string& names, double lo, bool open,
                                 const std::string& value_name, const std::string& help,
                                 const std::function<void(double)>& set) {
  const std::string shown = option_name(names);
  char bound[32];
  std::snprintf(bound, sizeof bound, "%g", lo);
  const std::string rule = std::string("a finite number ") + (open ? "> " : ">= ") + bound;
  return register_value(
      names, value_name, help,
      [this, set, lo, open, shown, rule](const std::string& v) {
        char* end = nullptr;
        const double x = v.empty() ? 0.0 : std::strtod(v.c_str(), &end);
        if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(x) || (open ? !(x > lo) : !(x >= lo)))
          fail(shown + ": must be " + rule + ", got '" + v + "'");
        set(x);
      },
      shown + " needs " + rule, false);
}

CLI::Option* CommandLine::value(const std::string& names, const std::string& value_name,
                                const std::string& help, const std::function<void(const std::string&)>& parse,
                                const std::string& missing) {
  return register_value(names, value_name, help, parse, missing, false);
}

CLI::Option* CommandLine::flag(const std::string& names, bool& out, const std::string& help) {
  return app_.add_flag(names, out, help);
}

CLI::Option* CommandLine::positional(const std::string& name, std::string& out, const std::string& help,
                                     bool required) {
  return app_.add_option(name, out, help)->type_name("")->required(required);
}

CLI::Option* CommandLine::positionals(const std::string& name, std::vector<std::string>& out,
                                      const std::string& help, bool required) {
  return app_.add_option(name, out, help)->type_name("")->required(required);
}

bool CommandLine::parse(std::span<const std::string> args) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 reads from the back
  try {
    app_.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::cout << help();
    return false;
  } catch (const CLI::ArgumentMismatch& e) {  // an option's value is missing
    const std::string what = e.what();
    for (const Missing& m : missing_)
      if (what.rfind(m.option->get_name() + ":", 0) == 0) fail(m.message);
    fail(what);
  } catch (const CLI::RequiredError& e) {  // "NAME is required": a positional argument
    const std::string what = e.what(), tail = " is required";
    if (what.size() > tail.size() && what.ends_with(tail))
      fail("missing " + what.substr(0, what.size() - tail.size()));
    fail(what);
  } catch (const CLI::ParseError& e) {
    fail(e.what());
  }
  // What CLI11 left: unknown options, then extra positional arguments; after "--" (which
  // CLI11 leaves there too) every argument is positional.
  std::vector<std::string> extras;
  bool positional_only = false;
  for (const std::string& a : app_.remaining()) {
    if (a == "--" && !positional_only) {
      positional_only = true;
    } else {
      if (!positional_only && a.size() > 1 && a[0] == '-') fail("unknown option '" + a + "'");
      extras.push_back(a);
    }
  }
  if (!extras.empty()) fail("unexpected argument '" + extras.front() + "'");
  return true;
}

void CommandLine::fail(const std::string& what) const {
  throw UsageError(help_name_.empty() ? what : what + " (see ccdlab " + help_name_ + " --help)");
}

std::string CommandLine::help() const { return app_.help(); }

}  // namespace ccdlab
