// The --html output: one self-contained page that plays a run in 3-D in a
// browser, opened from disk with no server or network. It is viewer.html.in
// with three.js, the scene (every body's shapes and starting pose, static
// bodies included) and the trajectory (trajectory_writer's JSON document)
// put in place of its placeholders. The page is written as the run goes: the
// constructor writes everything before the trajectory, the caller streams the
// trajectory, and finish() writes the rest.
#pragma once

#include <ostream>
#include <string>

#include "gaphys/world.hpp"

namespace demo {

// Throws std::runtime_error, saying how to get three.js, when the demo was
// built without it (npm ci not run in the gaphys tree): then no page can be
// made.
void require_viewer();

class viewer_page {
 public:
  // Writes the page up to its trajectory. The world gives each body's shape
  // and pose; scene and description name it on the page. Throws as
  // require_viewer() does.
  viewer_page(std::ostream& out, const gaphys::world& world, const std::string& scene,
              const std::string& description);

  // Where the trajectory's JSON document goes (a trajectory_writer in JSON).
  std::ostream& trajectory() { return out_; }

  // Writes the rest of the page.
  void finish();

 private:
  std::ostream& out_;
  std::string rest_;  // the template after the trajectory's placeholder
};

}  // namespace demo
