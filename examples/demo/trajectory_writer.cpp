#include "trajectory_writer.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "shape_json.hpp"

namespace demo {

namespace {

// Whether `text` ends with `suffix` (lower case) in any case: "run.CSV" too.
bool ends_with(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  const std::size_t start = text.size() - suffix.size();
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[start + i])) != suffix[i]) return false;
  }
  return true;
}

// Nine significant digits: nanometres on a metre-sized scene, and far below
// what the engine's 1/240 s steps resolve.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace

// A blown-up simulation still gives a document that parses.
std::string json_number(double value) { return std::isfinite(value) ? number(value) : "null"; }

std::optional<trajectory_format> format_of(const std::string& path) {
  if (ends_with(path, ".csv")) return trajectory_format::csv;
  if (ends_with(path, ".json")) return trajectory_format::json;
  return std::nullopt;
}

// The scene names come from gaphys::scenes::catalogue() (lower case and
// underscores), so the JSON string needs no escaping.
trajectory_writer::trajectory_writer(std::ostream& out, trajectory_format format,
                                     const std::string& scene, gaphys::real time_step,
                                     const gaphys::world* bodies_of)
    : out_(out), format_(format) {
  if (format_ == trajectory_format::csv) {
    out_ << "time,body,x,y,z,r_scalar,r_e12,r_e13,r_e23\n";
    return;
  }
  out_ << "{\"scene\": \"" << scene << "\", \"time_step\": " << json_number(time_step);
  if (bodies_of) {
    out_ << ", \"bodies\": [";
    for (std::size_t i = 0; i < bodies_of->body_count(); ++i) {
      out_ << (i == 0 ? "\n" : ",\n") << json_body(bodies_of->bodies()[i], bodies_of->id_of(i));
    }
    out_ << "\n]";
  }
  out_ << ", \"frames\": [";
}

void trajectory_writer::write_frame(const gaphys::world& world) {
  if (format_ == trajectory_format::csv) {
    write_csv_frame(world);
  } else {
    write_json_frame(world);
  }
  first_frame_ = false;
}

void trajectory_writer::write_csv_frame(const gaphys::world& world) {
  const std::string time = number(world.time());
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const gaphys::body& b = world.bodies()[i];
    if (b.is_static()) continue;
    const gaphys::vector& x = b.position();
    const gaphys::rotor& r = b.attitude();
    out_ << time << ',' << world.id_of(i) << ',' << number(x.e1()) << ',' << number(x.e2()) << ','
         << number(x.e3()) << ',' << number(r.scalar()) << ',' << number(r.e12()) << ','
         << number(r.e13()) << ',' << number(r.e23()) << '\n';
  }
}

// One frame per line, so the file stays readable and diffable.
void trajectory_writer::write_json_frame(const gaphys::world& world) {
  out_ << (first_frame_ ? "\n" : ",\n") << "{\"time\": " << json_number(world.time())
       << ", \"bodies\": [";
  bool first_body = true;
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const gaphys::body& b = world.bodies()[i];
    if (b.is_static()) continue;
    const gaphys::vector& x = b.position();
    const gaphys::rotor& r = b.attitude();
    out_ << (first_body ? "" : ", ") << "{\"id\": " << world.id_of(i) << ", \"position\": ["
         << json_number(x.e1()) << ", " << json_number(x.e2()) << ", " << json_number(x.e3())
         << "], \"attitude\": [" << json_number(r.scalar()) << ", " << json_number(r.e12()) << ", "
         << json_number(r.e13()) << ", " << json_number(r.e23()) << "]}";
    first_body = false;
  }
  out_ << "]}";
}

void trajectory_writer::finish() {
  if (format_ == trajectory_format::json) out_ << "\n]}\n";
}

}  // namespace demo
