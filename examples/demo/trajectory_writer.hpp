// The demo's output: at each recorded step, the time and every dynamic body's
// position and attitude rotor, as CSV rows or as one JSON document. The JSON
// document can also start with every body's shapes (shape_json.hpp), so that
// it holds all a reader needs to draw the run. Frames are written as the
// simulation goes, so a long run does not keep them in memory.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "gaphys/world.hpp"

namespace demo {

enum class trajectory_format { csv, json };

// From the file name's extension, .csv or .json; nothing for any other.
std::optional<trajectory_format> format_of(const std::string& path);

// A number as the JSON output writes it: nine significant digits, or null
// when it is not finite (JSON has no NaN or infinity).
std::string json_number(double value);

class trajectory_writer {
 public:
  // Writes the CSV header or the opening of the JSON document. With a world
  // (JSON only), the opening lists its bodies, static ones included, with
  // their shapes and starting poses ("bodies", one a line); the viewer page
  // passes none, as its scene holds them already.
  trajectory_writer(std::ostream& out, trajectory_format format, const std::string& scene,
                    gaphys::real time_step, const gaphys::world* bodies_of = nullptr);

  // One frame: the world's time and the pose of each non-static body, named
  // by its body id (a removed body is in no later frame).
  void write_frame(const gaphys::world& world);

  // Closes the JSON document (CSV needs nothing).
  void finish();

 private:
  void write_csv_frame(const gaphys::world& world);
  void write_json_frame(const gaphys::world& world);

  std::ostream& out_;
  trajectory_format format_;
  bool first_frame_ = true;
};

}  // namespace demo
