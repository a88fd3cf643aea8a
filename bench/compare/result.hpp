// One number the comparison measured: which metric, scene and quantity, on
// which engine. The reports (table, CSV, JSON, plots) are views of a list of these.
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace gaphys_compare {

inline constexpr double no_number = std::numeric_limits<double>::quiet_NaN();

// A scene as the results name it, with the parameter that varies along a
// metric (e in M3, N in M6), which the plots put on their x axis.
struct scene_label {
  // Implicit: a plain name is a scene without a parameter.
  scene_label(std::string name, double parameter = no_number)
      : name(std::move(name)), parameter(parameter) {}
  std::string name;
  double parameter;
};

struct result {
  std::string metric;    // "M1" .. "M6"
  std::string scenario;  // the scene, e.g. "oblique 0.3"
  double parameter;      // see scene_label; NaN when none
  std::string quantity;  // what was measured, with its unit
  std::string engine;
  double value;      // NaN: no number, see note
  std::string note;  // why there is no number (e.g. "skipped (too slow)")
  bool detail;       // in the CSV and JSON only, not in the terminal table
};

// Adds the results of one metric on one engine.
class recorder {
 public:
  recorder(std::string metric, std::string engine, std::vector<result>& out)
      : metric_(std::move(metric)), engine_(std::move(engine)), out_(out) {}

  void add(const scene_label& s, const std::string& quantity, double value) {
    out_.push_back({metric_, s.name, s.parameter, quantity, engine_, value, "", false});
  }
  // A quantity without a number, and why.
  void add_missing(const scene_label& s, const std::string& quantity, const std::string& note) {
    out_.push_back({metric_, s.name, s.parameter, quantity, engine_, no_number, note, false});
  }
  void add_detail(const scene_label& s, const std::string& quantity, double value) {
    out_.push_back({metric_, s.name, s.parameter, quantity, engine_, value, "", true});
  }

 private:
  std::string metric_;
  std::string engine_;
  std::vector<result>& out_;
};

}  // namespace gaphys_compare
