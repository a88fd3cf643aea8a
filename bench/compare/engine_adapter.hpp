// What the metrics need from a physics engine, and nothing more: build a
// neutral scene, step it, read each body's state back as doubles. Energies
// and momenta are not asked of the engine; the harness computes them from
// these states (mechanics.hpp), the same way for every engine.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene.hpp"
#include "vec3.hpp"

namespace gaphys_compare {

struct body_state {
  vec3 position;
  vec3 velocity;
  vec3 angular_velocity;  // world frame, rad/s
  quat attitude;          // body to world, as the engine keeps it (not renormalized)
};

class engine_adapter {
 public:
  virtual ~engine_adapter() = default;
  // Replaces whatever was built before.
  virtual void build(const scene& s) = 0;
  virtual void step(double h) = 0;
  // Body i of the scene's `bodies` (planes are not bodies).
  virtual body_state state(std::size_t i) const = 0;
};

// A setting chosen to match the other engines, and why: printed with the
// results so that every number can be traced to the configuration that made it.
struct parameter {
  std::string name;
  std::string value;
  std::string why;
};

struct engine {
  std::string name;
  std::string version;
  std::string precision;
  std::vector<parameter> parameters;
  std::function<std::unique_ptr<engine_adapter>()> make;
};

}  // namespace gaphys_compare
