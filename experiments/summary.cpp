#include "summary.hpp"

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

struct MethodRow {
  std::string method;
  bool conservative = false;
  std::map<double, double, std::greater<>> missed_fraction;  // by dt, largest first
  double largest_zero_miss_dt = 0.0;                          // 0: none
  double cheapest_zero_miss_cost = std::numeric_limits<double>::infinity();
  double cheapest_zero_miss_dt = 0.0;
};

struct Table {
  std::vector<double> dts;  // every dt of the records, largest first
  std::vector<double> hz;   // parallel: the frequency when the experiment gave it so, else 0
  std::vector<MethodRow> rows;
  std::uint64_t undecided = 0;  // events (body-body and static) the truth could not decide
};

std::string number(double x, const char* format) {
  char text[48];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

// A timestep as the experiment gave it: "60 Hz" for a frequency (hz > 0), else seconds.
std::string dt_label(double dt, double hz) { return hz > 0.0 ? number(hz, "%g") + " Hz" : number(dt, "%.3g"); }

Table build(const json& results) {
  Table t;
  std::map<double, double, std::greater<>> hz_of;
  std::vector<std::string> order;
  std::map<std::string, MethodRow> rows;
  std::set<double> given_hz;  // the experiment's "hz": those timesteps are labelled as frequencies
  if (const auto e = results.find("experiment"); e != results.end() && e->contains("hz"))
    for (const json& h : (*e)["hz"]) given_hz.insert(h.get<double>());
  for (const json& r : results.at("records")) {
    const std::string method = r.at("method").get<std::string>();
    const double dt = r.at("dt").get<double>();
    const double hz = r.contains("hz") ? r.at("hz").get<double>() : 0.0;
    hz_of.emplace(dt, given_hz.count(hz) ? hz : 0.0);
    auto it = rows.find(method);
    if (it == rows.end()) {
      order.push_back(method);
      it = rows.emplace(method, MethodRow{}).first;
      it->second.method = method;
    }
    MethodRow& row = it->second;
    row.conservative = r.value("conservative", false);
    t.undecided = std::max(t.undecided, r.value("undecided", std::uint64_t{0}) + r.value("static_undecided", std::uint64_t{0}));
    row.missed_fraction[dt] = r.at("missed_fraction").get<double>();
    if (r.at("missed").get<std::uint64_t>() == 0) {
      row.largest_zero_miss_dt = std::max(row.largest_zero_miss_dt, dt);
      const double cost = r.at("seconds_per_simulated_second").get<double>();
      if (cost < row.cheapest_zero_miss_cost) {
        row.cheapest_zero_miss_cost = cost;
        row.cheapest_zero_miss_dt = dt;
      }
    }
  }
  for (const auto& [dt, hz] : hz_of) {
    t.dts.push_back(dt);
    t.hz.push_back(hz);
  }
  for (const std::string& m : order) t.rows.push_back(rows[m]);
  return t;
}

// The table's cells, as strings: a header row then one row per method.
std::vector<std::vector<std::string>> cells(const Table& t) {
  std::vector<std::vector<std::string>> out;
  std::vector<std::string> header = {"method", "largest dt, no miss", "cost at zero misses (s/s)"};
  for (std::size_t i = 0; i < t.dts.size(); ++i) header.push_back("missed @ " + dt_label(t.dts[i], t.hz[i]));
  out.push_back(header);
  for (const MethodRow& row : t.rows) {
    std::vector<std::string> line = {row.method + (row.conservative ? " *" : "")};
    if (row.largest_zero_miss_dt > 0.0) {
      const auto at = std::find(t.dts.begin(), t.dts.end(), row.largest_zero_miss_dt) - t.dts.begin();
      line.push_back(dt_label(row.largest_zero_miss_dt, t.hz[static_cast<std::size_t>(at)]));
      const auto cheap = std::find(t.dts.begin(), t.dts.end(), row.cheapest_zero_miss_dt) - t.dts.begin();
      line.push_back(number(row.cheapest_zero_miss_cost, "%.3g") + " (dt " +
                     dt_label(row.cheapest_zero_miss_dt, t.hz[static_cast<std::size_t>(cheap)]) + ")");
    } else {
      line.push_back("none");
      line.push_back("-");
    }
    for (double dt : t.dts) {
      const auto it = row.missed_fraction.find(dt);
      line.push_back(it == row.missed_fraction.end() ? "" : it->second == 0.0 ? "0" : number(100.0 * it->second, "%.3g%%"));
    }
    out.push_back(line);
  }
  return out;
}

const char* kFootnote = "* conservative as it ran (a continuous method whose guarantee held: zero misses expected)";

// The line on the events the truth could not decide, or nothing when there are none.
std::string undecided_line(const Table& t) {
  if (t.undecided == 0) return std::string();
  return std::to_string(t.undecided) +
         " undecided events (the ground truth could certify neither a contact nor a separation) are counted apart: "
         "neither detected nor missed";
}

}  // namespace

std::string summary_text(const json& results) {
  const Table t = build(results);
  const auto c = cells(t);
  std::vector<std::size_t> width(c.front().size(), 0);
  for (const auto& line : c)
    for (std::size_t k = 0; k < line.size(); ++k) width[k] = std::max(width[k], line[k].size());
  std::string out;
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (std::size_t k = 0; k < c[i].size(); ++k) {
      const std::string& cell = c[i][k];
      const std::string pad(width[k] - cell.size(), ' ');
      out += k == 0 ? cell + pad : "  " + pad + cell;  // method left, numbers right
    }
    out += "\n";
  }
  out += std::string(kFootnote) + "\n";
  if (const std::string u = undecided_line(t); !u.empty()) out += u + "\n";
  return out;
}

std::string summary_markdown(const json& results) {
  const Table t = build(results);
  const auto c = cells(t);
  std::string out = "# Summary: " + results.at("experiment").value("name", std::string("experiment")) + "\n\n";
  const json& scene = results.at("scene");
  if (results.value("format", std::string()) == "ccdlab-cloth-results/1")  // a cloth experiment
    out += "A cloth of " + std::to_string(scene.value("triangles", 0)) + " triangles over " +
           number(scene.value("horizon", 0.0), "%g") + " s, " + std::to_string(results.at("truth").value("events", 0)) +
           " self-contact events. Methods are CULLER/MODE; dt is the check interval (k integrator steps). Missed: "
           "percentage of the contact events that the method did not detect; cost: seconds of computation per "
           "simulated second.\n\n";
  else
    out += std::to_string(scene.value("bodies", 0)) + " bodies over " + number(scene.value("horizon", 0.0), "%g") +
           " s, " + std::to_string(results.at("truth").value("events", 0)) +
           " contact events. Missed: percentage of the contact events (not in progress at t = 0) that the "
           "method did not detect; cost: seconds of computation per simulated second.\n\n";
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
  out += "\n\\" + std::string(kFootnote) + "\n";
  if (const std::string u = undecided_line(t); !u.empty()) out += "\n" + u + ".\n";
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
