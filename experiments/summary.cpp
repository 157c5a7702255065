#include "summary.hpp"

#include "record_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace ccdlab {
namespace {

using nlohmann::json;

// One record as the summary reads it.
struct Cell {
  RecordContacts contacts;
  bool conservative = false;
  double cost = 0.0;  // seconds per simulated second
};

struct MethodRow {
  std::string method;
  std::map<double, Cell, std::greater<>> at;  // by dt, largest first
  double frontier_dt = 0.0;                   // 0: none
  double cheapest_cost = std::numeric_limits<double>::infinity();
  double cheapest_dt = 0.0;
  bool all_conservative() const {
    return std::all_of(at.begin(), at.end(), [](const auto& c) { return c.second.conservative; });
  }
  bool some_conservative() const {
    return std::any_of(at.begin(), at.end(), [](const auto& c) { return c.second.conservative; });
  }
};

struct Table {
  std::vector<double> dts;      // every dt of the records, largest first
  std::map<double, double> hz;  // dt -> the frequency the experiment gave for it (absent: seconds)
  bool in_hz = false;           // every dt given as a frequency: the table is in Hz, else in seconds
  std::vector<MethodRow> rows;
  RecordContacts first;                 // the contacts to detect (the same in every record)
  std::uint64_t initial = 0;            // events in progress at t = 0 (body-body and scenery)
  std::uint64_t undecided = 0;          // events (body-body and scenery) the truth could not decide
  bool scenery = false;                 // some record has body-scenery events
  std::set<std::uint64_t> to_detect;    // the distinct denominators over the records
};

std::string number(double x, const char* format) {
  char text[48];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

// A timestep in the table's one unit: the frequency (Hz) or seconds.
std::string dt_value(const Table& t, double dt) {
  return t.in_hz ? number(t.hz.at(dt), "%g") : number(dt, "%.3g");
}
std::string unit(const Table& t) { return t.in_hz ? "(Hz)" : "(s)"; }

// The zero-miss frontier (the largest dt at which the method missed nothing, nor at any
// smaller dt it ran) and its cheapest zero-miss point at or below it: the rule of
// `ccdlab report` (scripts/report.py, frontier()).
void find_frontier(MethodRow& row) {
  for (auto it = row.at.rbegin(); it != row.at.rend() && it->second.contacts.missed() == 0; ++it) {
    row.frontier_dt = it->first;
    if (it->second.cost < row.cheapest_cost) {
      row.cheapest_cost = it->second.cost;
      row.cheapest_dt = it->first;
    }
  }
}

Table build(const json& results) {
  Table t;
  std::set<double> given_hz;  // the experiment's "hz": those timesteps are labelled as frequencies
  if (const auto e = results.find("experiment"); e != results.end() && e->contains("hz"))
    for (const json& h : (*e)["hz"]) given_hz.insert(h.get<double>());
  std::set<double, std::greater<>> dts;
  std::vector<std::string> order;
  std::map<std::string, MethodRow> rows;
  bool first = true;
  for (const json& r : results.at("records")) {
    const std::string method = r.at("method").get<std::string>();
    const double dt = r.at("dt").get<double>();
    const double hz = r.value("hz", 0.0);
    dts.insert(dt);
    if (given_hz.count(hz)) t.hz[dt] = hz;
    auto it = rows.find(method);
    if (it == rows.end()) {
      order.push_back(method);
      it = rows.emplace(method, MethodRow{}).first;
      it->second.method = method;
    }
    const Cell cell{record_contacts(r), r.value("conservative", false), r.value("seconds_per_simulated_second", 0.0)};
    it->second.at[dt] = cell;
    t.to_detect.insert(cell.contacts.to_detect());
    t.scenery = t.scenery || r.value("static_events", std::uint64_t{0}) > 0;
    t.undecided = std::max(t.undecided, r.value("undecided", std::uint64_t{0}) + r.value("static_undecided", std::uint64_t{0}));
    if (first) {
      t.first = cell.contacts;
      t.initial = r.value("initial_contacts", std::uint64_t{0}) + r.value("static_initial_contacts", std::uint64_t{0});
      first = false;
    }
  }
  t.dts.assign(dts.begin(), dts.end());
  t.in_hz = !t.dts.empty() && t.hz.size() == t.dts.size();
  for (const std::string& m : order) {
    t.rows.push_back(rows[m]);
    find_frontier(t.rows.back());
  }
  return t;
}

// "311 (20.3 %)", "0"; with "of N" when the records do not all have the same contacts to detect.
std::string missed_cell(const Table& t, const RecordContacts& c) {
  if (c.missed() == 0) return "0";
  const std::string of = t.to_detect.size() > 1 ? " of " + std::to_string(c.to_detect()) : std::string();
  return std::to_string(c.missed()) + of + " (" + number(100.0 * c.missed_fraction(), "%.3g") + " %)";
}

using Cells = std::vector<std::vector<std::string>>;

// The answer: per method the zero-miss frontier and the cheapest zero-miss cost.
Cells answer_cells(const Table& t) {
  Cells out = {{"method", "largest dt, no miss " + unit(t), "cheapest zero-miss cost (s/s)", "at dt " + unit(t)}};
  for (const MethodRow& row : t.rows) {
    std::vector<std::string> line = {row.method + (row.all_conservative() ? " *" : "")};
    if (row.frontier_dt > 0.0) {
      line.push_back(dt_value(t, row.frontier_dt));
      line.push_back(number(row.cheapest_cost, "%.3g"));
      line.push_back(dt_value(t, row.cheapest_dt));
    } else {
      line.insert(line.end(), {"none", "-", "-"});
    }
    out.push_back(line);
  }
  return out;
}

// The missed contacts of every method at every dt (blank where it did not run).
Cells missed_cells(const Table& t) {
  Cells out = {{"method"}};
  for (double dt : t.dts) out[0].push_back("missed @ " + dt_value(t, dt) + (t.in_hz ? " Hz" : ""));
  for (const MethodRow& row : t.rows) {
    std::vector<std::string> line = {row.method + (row.all_conservative() ? " *" : "")};
    for (double dt : t.dts) {
      const auto it = row.at.find(dt);
      line.push_back(it == row.at.end() ? "" : missed_cell(t, it->second.contacts));
    }
    out.push_back(line);
  }
  return out;
}

std::string missed_title(const Table& t) {
  std::string title = "missed contacts";
  if (t.to_detect.size() == 1) title += " (of " + std::to_string(*t.to_detect.begin()) + ")";
  return title + " at each dt " + unit(t);
}

// What is counted: the contacts to detect, of each kind, and those counted apart.
std::string contacts_line(const Table& t) {
  if (t.to_detect.empty()) return "no records";
  std::string line = "contacts to detect: " + std::to_string(t.first.to_detect());
  if (t.scenery)
    line += " (" + std::to_string(t.first.body_to_detect) + " body-body, " +
            std::to_string(t.first.scenery_to_detect) + " body-scenery)";
  if (t.initial) line += "; " + std::to_string(t.initial) + " in progress at t = 0 apart";
  return line;
}

const char* kFootnote = "* conservative at every dt: a continuous method whose guarantee held as it ran (no miss expected)";

// Footnote lines: the star, the methods conservative at some dt only, the undecided events.
std::vector<std::string> notes(const Table& t) {
  std::vector<std::string> out = {kFootnote};
  for (const MethodRow& row : t.rows) {
    if (row.all_conservative() || !row.some_conservative()) continue;
    std::string yes, no;
    for (const auto& [dt, cell] : row.at) {
      std::string& list = cell.conservative ? yes : no;
      list += (list.empty() ? "" : ", ") + dt_value(t, dt);
    }
    out.push_back(row.method + ": no star: conservative as it ran at dt " + unit(t) + " " + yes + ", not at " + no);
  }
  if (t.undecided)
    out.push_back(std::to_string(t.undecided) +
                  " undecided events (the ground truth could certify neither a contact nor a separation) are counted "
                  "apart: neither detected nor missed");
  return out;
}

// Aligned plain text, the method left and numbers right; the columns after the first are
// split into blocks so that no line is wider than `width` (each block repeats the method).
std::string aligned(const Cells& c, std::size_t width) {
  std::vector<std::size_t> w(c.front().size(), 0);
  for (const auto& line : c)
    for (std::size_t k = 0; k < line.size(); ++k) w[k] = std::max(w[k], line[k].size());
  std::string out;
  for (std::size_t from = 1; from < w.size();) {
    std::size_t to = from, used = w[0];
    while (to < w.size() && (to == from || used + 2 + w[to] <= width)) used += 2 + w[to++];
    if (from > 1) out += "\n";
    for (const auto& line : c) {
      std::string text = line[0] + std::string(w[0] - line[0].size(), ' ');
      for (std::size_t k = from; k < to; ++k) text += "  " + std::string(w[k] - line[k].size(), ' ') + line[k];
      out += text.substr(0, text.find_last_not_of(' ') + 1) + "\n";  // no trailing blanks
    }
    from = to;
  }
  return out;
}

// `text` wrapped at spaces into lines of at most `width` columns (a longer word stays whole).
std::string wrapped(const std::string& text, std::size_t width) {
  std::string out, line;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t end = std::min(text.find(' ', i), text.size());
    const std::string word = text.substr(i, end - i);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line = "  " + word;  // continuation lines indented
    } else {
      line += (line.empty() ? "" : " ") + word;
    }
    i = end + 1;
  }
  return out + line + "\n";
}

std::string markdown_table(const Cells& c) {
  std::string out;
  for (std::size_t i = 0; i < c.size(); ++i) {
    out += "|";
    for (std::string cell : c[i]) {
      const bool starred = cell.size() >= 2 && cell.compare(cell.size() - 2, 2, " *") == 0;
      if (starred) cell = cell.substr(0, cell.size() - 1) + "\\*";  // a literal * in Markdown
      out += " " + cell + " |";
    }
    out += "\n";
    if (i == 0) {
      out += "|---|";
      for (std::size_t k = 1; k < c[i].size(); ++k) out += "---:|";
      out += "\n";
    }
  }
  return out;
}

}  // namespace

std::string summary_text(const json& results) {
  const Table t = build(results);
  std::string out = wrapped(contacts_line(t), kSummaryWidth) + "\n" + aligned(answer_cells(t), kSummaryWidth) + "\n" +
                    missed_title(t) + "\n" + aligned(missed_cells(t), kSummaryWidth);
  for (const std::string& n : notes(t)) out += wrapped(n, kSummaryWidth);
  return out;
}

std::string summary_markdown(const json& results) {
  const Table t = build(results);
  std::string out = "# Summary: " + results.at("experiment").value("name", std::string("experiment")) + "\n\n";
  const json& scene = results.at("scene");
  if (results.value("format", std::string()) == "ccdlab-cloth-results/1")  // a cloth experiment
    out += "A cloth of " + std::to_string(scene.value("triangles", 0)) + " triangles over " +
           number(scene.value("horizon", 0.0), "%g") + " s, " + std::to_string(results.at("truth").value("events", 0)) +
           " self-contact events. Methods are CULLER/MODE; dt is the check interval (k integrator steps). Missed: "
           "the contact events that the method did not detect; cost: seconds of computation per simulated "
           "second.\n\n";
  else
    out += std::to_string(scene.value("bodies", 0)) + " bodies over " + number(scene.value("horizon", 0.0), "%g") +
           " s. Missed: the contact events, body-body and body-scenery, that the method did not detect (those in "
           "progress at t = 0 apart); cost: seconds of computation per simulated second.\n\n";
  out += contacts_line(t) + ".\n\n" + markdown_table(answer_cells(t)) + "\n";
  std::string title = missed_title(t);
  title[0] = 'M';
  out += title + ":\n\n" + markdown_table(missed_cells(t)) + "\n";
  const auto n = notes(t);
  out += "\\" + n.front() + "\n";
  for (std::size_t i = 1; i < n.size(); ++i) out += "\n" + n[i] + ".\n";
  return out;
}

std::string summary_path(const std::string& results_path) {
  const std::string suffix = ".json";
  std::string stem = results_path;
  if (stem.size() > suffix.size() && stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
    stem.resize(stem.size() - suffix.size());
  return stem + ".summary.md";
}

}  // namespace ccdlab
