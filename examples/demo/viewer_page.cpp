#include "viewer_page.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

#include "embedded.hpp"
#include "shape_json.hpp"
#include "trajectory_writer.hpp"

namespace demo {

namespace {

// The template's placeholders, in the order they appear in it.
constexpr std::string_view three_js_slot = "@GAPHYS_THREE_JS@";
constexpr std::string_view scene_slot = "@GAPHYS_SCENE@";
constexpr std::string_view trajectory_slot = "@GAPHYS_TRAJECTORY@";

// The template from `from` on, cut at the next placeholder: what comes
// before it, and `from` moved past it. A template without it is a build bug.
std::string_view up_to(std::string_view page, std::size_t& from, std::string_view slot) {
  const std::size_t at = page.find(slot, from);
  if (at == std::string_view::npos) {
    throw std::logic_error("viewer.html.in lacks " + std::string(slot) + " after byte " +
                           std::to_string(from));
  }
  const std::string_view before = page.substr(from, at - from);
  from = at + slot.size();
  return before;
}

// Inside <script>, the HTML parser ends the script at the first "</script"
// in any case, even within a JavaScript string. "<\/" is the same string, the
// same regular expression or the same comment to JavaScript, and no such end.
void write_script(std::ostream& out, std::string_view script) {
  std::size_t from = 0;
  for (std::size_t at = script.find("</"); at != std::string_view::npos;
       at = script.find("</", at + 2)) {
    std::string_view tag = script.substr(at + 2, 6);
    bool closes = tag.size() == 6;
    for (std::size_t i = 0; closes && i < 6; ++i) {
      closes = (tag[i] | 0x20) == "script"[i];
    }
    if (!closes) continue;
    out << script.substr(from, at + 1 - from) << '\\';
    from = at + 1;
  }
  out << script.substr(from);
}

// A JSON string. "<" is escaped too, so that no text can end the page's
// <script> element that holds the JSON.
std::string json_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == '<') {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
      quoted += escape;
    } else {
      quoted += c;
    }
  }
  return quoted + '"';
}

// The scene: its names and every body, one a line, with its shapes and its
// pose at the start (a static body keeps it; the trajectory moves the others).
void write_scene(std::ostream& out, const gaphys::world& world, const std::string& scene,
                 const std::string& description) {
  out << "{\"scene\": " << json_string(scene) << ", \"description\": " << json_string(description)
      << ", \"gravity\": " << json_vector(world.settings().gravity) << ", \"bodies\": [";
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    out << (i == 0 ? "\n" : ",\n") << json_body(world.bodies()[i], world.id_of(i));
  }
  out << "\n]}";
}

}  // namespace

void require_viewer() {
  if (embedded::three_js().empty()) {
    throw std::runtime_error(
        "--html: built without three.js: run npm ci in the gaphys source tree, then configure "
        "and build the demo again");
  }
}

viewer_page::viewer_page(std::ostream& out, const gaphys::world& world, const std::string& scene,
                         const std::string& description)
    : out_(out) {
  require_viewer();
  const std::string_view page = embedded::viewer_template();
  std::size_t from = 0;
  out_ << up_to(page, from, three_js_slot);
  write_script(out_, embedded::three_js());
  out_ << up_to(page, from, scene_slot);
  write_scene(out_, world, scene, description);
  out_ << up_to(page, from, trajectory_slot);
  rest_ = std::string(page.substr(from));
}

void viewer_page::finish() { out_ << rest_; }

}  // namespace demo
