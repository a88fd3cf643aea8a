// Snapshots: a world restored from world::save_snapshot steps on bit for bit
// as the uninterrupted world (the state hash after every step, which covers
// the warm-start impulses); files round-trip and are replaced whole; corrupt,
// truncated and fuzzed snapshots are invalid_input and leave the target world
// as it was. The truth is the saved world itself, stepped on.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/stat.h>  // mkfifo
#endif

#include "box_helpers.hpp"
#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

using bytes = std::vector<std::uint8_t>;

// The format's fixed places (snapshot.cpp): the header is the 8-byte magic,
// the u32 version, the u8 size of a real, the check real and the u64
// payload size; the payload opens with the settings (gravity, the two
// dampings, then the solver iterations); the checksum is the last 8 bytes.
constexpr std::size_t version_at = 8;
constexpr std::size_t real_size_at = 12;
constexpr std::size_t payload_at = 8 + 4 + 1 + sizeof(real) + 8;
constexpr std::size_t solver_iterations_at = payload_at + 5 * sizeof(real);

std::uint64_t fnv1a(const bytes& b, std::size_t size) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ b[i]) * 1099511628211ull;
  return hash;
}

// A fresh checksum over the (edited) bytes, as a fuzzer that knows the
// format would write: only the structural checks stand in its way.
void reseal(bytes& b) {
  if (b.size() < 8) return;
  const std::uint64_t sum = fnv1a(b, b.size() - 8);
  for (int i = 0; i < 8; ++i) b[b.size() - 8 + i] = std::uint8_t(sum >> (8 * i));
}

void put_u64(bytes& b, std::size_t at, std::uint64_t x) {
  for (int i = 0; i < 8; ++i) b[at + i] = std::uint8_t(x >> (8 * i));
}

// A real's bit pattern (binary64, or binary32 in a float engine).
using real_bits = std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>;
real_bits bits_of(real x) {
  real_bits bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

void put_real(bytes& b, std::size_t at, real x) {
  for (std::size_t i = 0; i < sizeof(real); ++i) b[at + i] = std::uint8_t(bits_of(x) >> (8 * i));
}

// The reals' bytes as the snapshot writes them (little-endian bit patterns).
bytes pattern_of(const std::vector<real>& values) {
  bytes pattern;
  for (real x : values) {
    for (std::size_t i = 0; i < sizeof(real); ++i) {
      pattern.push_back(std::uint8_t(bits_of(x) >> (8 * i)));
    }
  }
  return pattern;
}

// Where the reals appear in a row in the snapshot; the test needs them to
// be there once.
std::size_t find_reals(const bytes& b, const std::vector<real>& values) {
  const bytes pattern = pattern_of(values);
  const auto first = std::search(b.begin(), b.end(), pattern.begin(), pattern.end());
  if (first == b.end()) return b.size();
  const auto again = std::search(first + 1, b.end(), pattern.begin(), pattern.end());
  return again == b.end() ? std::size_t(first - b.begin()) : b.size();
}

// Every place the real `from` is written, made `to` (a sphere's radius and
// its body's bounding radius, a box's half extents in its polyhedron and
// its shape). Returns how many.
int replace_reals(bytes& b, real from, real to) {
  const bytes pattern = pattern_of({from});
  int count = 0;
  for (auto at = std::search(b.begin(), b.end(), pattern.begin(), pattern.end()); at != b.end();
       at = std::search(at + 1, b.end(), pattern.begin(), pattern.end())) {
    put_real(b, std::size_t(at - b.begin()), to);
    ++count;
  }
  return count;
}

bool same_polyhedron(const convex_polyhedron& a, const convex_polyhedron& b) {
  const auto same = [](const vector& u, const vector& v) {
    return bits_of(u.c[0]) == bits_of(v.c[0]) && bits_of(u.c[1]) == bits_of(v.c[1]) &&
           bits_of(u.c[2]) == bits_of(v.c[2]);
  };
  if (a.vertices.size() != b.vertices.size() || a.faces.size() != b.faces.size() ||
      a.vertex_indices != b.vertex_indices || a.edges.size() != b.edges.size() ||
      bits_of(a.bounding_radius) != bits_of(b.bounding_radius)) {
    return false;
  }
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    if (!same(a.vertices[i], b.vertices[i])) return false;
  }
  for (std::size_t f = 0; f < a.faces.size(); ++f) {
    const polyhedron_face &p = a.faces[f], &q = b.faces[f];
    if (!same(p.normal, q.normal) || bits_of(p.offset) != bits_of(q.offset) || p.first != q.first ||
        p.count != q.count) {
      return false;
    }
  }
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    const polyhedron_edge &p = a.edges[e], &q = b.edges[e];
    if (p.tail != q.tail || p.head != q.head || p.left != q.left || p.right != q.right) {
      return false;
    }
  }
  return true;
}

class snapshot_test : public engine_test {
 protected:
  struct scene {
    std::vector<body_id> ids;  // every live body, in creation order
    body_id pushed = 0;        // a force waits on it when the world is saved
    body_id gone = 0;          // removed: dead in the restored world too
  };

  static std::vector<vector> hull_points() {
    return {{0.2, 0, 0},     {-0.2, 0.05, 0},     {0, 0.2, 0.02},
            {0.03, -0.2, 0}, {0, 0, 0.25},        {0.02, 0.01, -0.2},
            {0.1, 0.1, 0.1}, {-0.12, -0.1, 0.08}, {0.11, -0.1, -0.1}};
  }

  // Every kind of state a snapshot holds: planes, spheres, boxes, a
  // capsule, a hull, a compound, a moving kinematic body, a sensor, filtered
  // shapes, ids with generations (a removed body, its slot reused, another
  // slot left free), per-body gravity scale and damping, bounces and
  // resting stacks (warm starts).
  static scene mixed(world& w) {
    scene s;
    s.ids.push_back(add_floor(w, 0, 0.2));
    const body_id removed_early = add_sphere(w, vector{9, 9, 1}, 0.3);
    s.ids.push_back(add_sphere(w, vector{0, 0, 0.5}, 0.5, 1, vector{0.3, 0, 0}, 0.6));
    w.remove_body(removed_early);  // its slot is reused below: generation 1
    body_definition rolling;
    rolling.position = vector{1.2, 0, 0.3};
    rolling.velocity = vector{-0.5, 0.2, 0};
    rolling.shape = shape::sphere(0.3).with_rolling_resistance(0.05).with_spinning_friction(0.1);
    rolling.gravity_scale = 0.5;
    s.ids.push_back(w.create_body(rolling));
    s.ids.push_back(add_box(w, vector{-1, 0, 0.25}, vector{0.25, 0.25, 0.25}));
    s.ids.push_back(add_box(w, vector{-1, 0.02, 0.76}, vector{0.25, 0.2, 0.25}));
    body_definition tilted;
    tilted.position = vector{0, 1.2, 0.6};
    tilted.attitude = rotor{0.9, 0.2, 0.1, 0.3};
    tilted.shape = shape::box(vector{0.3, 0.15, 0.1}).with_friction(0.8);
    tilted.linear_damping = 0.1;
    tilted.angular_damping = 0.3;
    s.ids.push_back(w.create_body(tilted));
    body_definition capsule;
    capsule.position = vector{1, 1, 0.3};
    capsule.attitude = rotor{0.8, 0, 0.6, 0};  // lying down
    capsule.shape = shape::capsule(0.3, 0.15);
    s.ids.push_back(w.create_body(capsule));
    body_definition hull;
    hull.position = vector{-0.3, -1, 0.4};
    hull.angular_velocity = bivector{1, 0.5, -0.3};
    hull.shape = shape::convex_hull(hull_points()).with_restitution(0.3);
    s.ids.push_back(w.create_body(hull));
    body_definition compound;
    compound.position = vector{1, -1, 0.6};
    compound.shapes = {
        attached_shape{shape::box(vector{0.2, 0.2, 0.05}), vector{0, 0, 0}, {1, 0, 0, 0}},
        attached_shape{shape::sphere(0.1), vector{0.15, 0, 0.15}, {1, 0, 0, 0}},
        attached_shape{shape::convex_hull(hull_points()), vector{-0.2, 0, 0.2}, {0.6, 0, 0, 0.8}}};
    s.ids.push_back(w.create_body(compound));
    s.pushed = s.ids.back();
    body_definition kinematic;
    kinematic.is_kinematic = true;
    kinematic.position = vector{-2, 0, 0.2};  // reaches the boxes after the save
    kinematic.velocity = vector{1.2, 0, 0};
    kinematic.angular_velocity = bivector{0.5, 0, 0};
    kinematic.shape = shape::box(vector{0.2, 0.2, 0.2});
    s.ids.push_back(w.create_body(kinematic));
    body_definition sensor;
    sensor.is_static = true;
    sensor.position = vector{0, 0, 0.5};
    sensor.shape = shape::box(vector{1.5, 1.5, 0.5}).as_sensor();
    s.ids.push_back(w.create_body(sensor));
    // Two filtered balls that pass through each other but land on the floor.
    for (real x : {real(0.45), real(0.55)}) {
      body_definition ghost;
      ghost.position = vector{x, -2, 0.6};
      ghost.shape = shape::sphere(0.2).with_filter(2, 1);
      s.ids.push_back(w.create_body(ghost));
    }
    s.gone = add_sphere(w, vector{-3, -3, 0.3}, 0.3);
    w.remove_body(s.gone);  // its slot stays free
    return s;
  }

  // What a user can observe of two worlds that must be the same.
  static void expect_same(const world& a, const world& b, const scene& s) {
    EXPECT_EQ(a.state_hash(), b.state_hash());
    EXPECT_EQ(a.time(), b.time());  // a double in either engine
    ASSERT_EQ(a.body_count(), b.body_count());
    for (std::size_t i = 0; i < a.body_count(); ++i) EXPECT_EQ(a.id_of(i), b.id_of(i));
    for (body_id id : s.ids) {
      ASSERT_TRUE(b.contains(id));
      EXPECT_EQ(&b.at(id) - b.bodies().data(), &a.at(id) - a.bodies().data());
    }
    EXPECT_FALSE(b.contains(s.gone));
    for (std::size_t i = 0; i < a.body_count(); ++i) {
      const body &p = a.bodies()[i], &q = b.bodies()[i];
      EXPECT_EQ(p.is_static(), q.is_static());
      EXPECT_EQ(p.is_kinematic(), q.is_kinematic());
      EXPECT_EQ(bits_of(p.gravity_scale()), bits_of(q.gravity_scale()));
      EXPECT_EQ(p.linear_damping(), q.linear_damping());
      EXPECT_EQ(p.angular_damping(), q.angular_damping());
      EXPECT_TRUE(near(p.accumulated_force(), q.accumulated_force(), 0));
      EXPECT_TRUE(near(p.accumulated_torque(), q.accumulated_torque(), 0));
      ASSERT_EQ(p.shapes().size(), q.shapes().size());
      for (std::size_t k = 0; k < p.shapes().size(); ++k) {
        const shape &u = p.shapes()[k].shape, &v = q.shapes()[k].shape;
        EXPECT_EQ(u.kind(), v.kind());
        EXPECT_EQ(u.is_sensor(), v.is_sensor());
        EXPECT_EQ(u.filter().category, v.filter().category);
        EXPECT_EQ(u.filter().mask, v.filter().mask);
        EXPECT_EQ(bits_of(u.friction()), bits_of(v.friction()));
        ASSERT_EQ(u.polyhedron() == nullptr, v.polyhedron() == nullptr);
        // Boxes' polyhedra are rebuilt, hulls' restored: both to the bit.
        if (u.polyhedron()) {
          EXPECT_TRUE(same_polyhedron(*u.polyhedron(), *v.polyhedron()));
        }
      }
    }
    ASSERT_EQ(a.contacts().size(), b.contacts().size());
    for (std::size_t k = 0; k < a.contacts().size(); ++k) {
      EXPECT_EQ(a.contacts()[k].body_a, b.contacts()[k].body_a);
      EXPECT_EQ(a.contacts()[k].feature, b.contacts()[k].feature);
    }
    const auto same_events = [](const std::vector<contact_event>& p,
                                const std::vector<contact_event>& q) {
      ASSERT_EQ(p.size(), q.size());
      for (std::size_t k = 0; k < p.size(); ++k) {
        EXPECT_EQ(p[k].body_a, q[k].body_a);
        EXPECT_EQ(p[k].body_b, q[k].body_b);
        EXPECT_EQ(bits_of(p[k].impulse), bits_of(q[k].impulse));
      }
    };
    same_events(a.events().began, b.events().began);
    same_events(a.events().persisted, b.events().persisted);
    same_events(a.events().ended, b.events().ended);
    ASSERT_EQ(a.sensor_overlaps().size(), b.sensor_overlaps().size());
    for (std::size_t k = 0; k < a.sensor_overlaps().size(); ++k) {
      EXPECT_EQ(a.sensor_overlaps()[k].sensor, b.sensor_overlaps()[k].sensor);
      EXPECT_EQ(a.sensor_overlaps()[k].other, b.sensor_overlaps()[k].other);
      EXPECT_EQ(a.sensor_overlaps()[k].other_shape, b.sensor_overlaps()[k].other_shape);
    }
    EXPECT_TRUE(near(a.settings().gravity, b.settings().gravity, 0));
    EXPECT_EQ(a.settings().broad_phase, b.settings().broad_phase);
  }

  // A world with bodies of its own, to restore over.
  static world busy_world() {
    world_settings settings;
    settings.gravity = vector{0, 0, -3};
    settings.broad_phase = broad_phase_kind::all_pairs;
    settings.solver_iterations = 7;
    world w(settings);
    add_floor(w, -1);
    for (int i = 0; i < 4; ++i) add_sphere(w, vector{real(i), 0, 0}, 0.4);
    simulate(w, 5);
    return w;
  }
};

TEST_F(snapshot_test, a_restored_world_steps_on_bit_for_bit) {
  world original = make_world();
  const scene s = mixed(original);
  simulate(original, 60);
  original.at(s.pushed).apply_force(vector{3, 0, 40}, vector{0.1, 0, 0});
  original.at(s.pushed).apply_torque(bivector{0, 0.5, 0});
  // The scene has what the snapshot must carry.
  ASSERT_FALSE(original.contacts().empty());
  ASSERT_FALSE(original.sensor_overlaps().empty());
  ASSERT_FALSE(original.events().persisted.empty());
  const bytes saved = original.save_snapshot();

  world fresh, busy = busy_world();
  fresh.restore_snapshot(saved);
  busy.restore_snapshot(saved);
  expect_same(original, fresh, s);
  expect_same(original, busy, s);
  EXPECT_EQ(fresh.save_snapshot(), saved);  // nothing lost on the way
  EXPECT_EQ(busy.save_snapshot(), saved);

  for (int i = 0; i < 120; ++i) {
    original.step(h);
    fresh.step(h);
    busy.step(h);
    ASSERT_EQ(fresh.state_hash(), original.state_hash()) << "step " << i;
    ASSERT_EQ(busy.state_hash(), original.state_hash()) << "step " << i;
  }
  expect_same(original, fresh, s);
  expect_same(original, busy, s);
  // New bodies get the same ids (the free slot, its generation).
  const body_id next = add_sphere(original, vector{5, 5, 1}, 0.2);
  EXPECT_EQ(add_sphere(fresh, vector{5, 5, 1}, 0.2), next);
  EXPECT_NE(next, s.gone);
  EXPECT_EQ(fresh.save_snapshot(), original.save_snapshot());
}

// Sleeping is on by default (world_settings::sleeping): the pile sleeps by
// the time it is saved, and a ball dropped on it after the restore wakes it
// in both worlds alike. The assertions are on state hashes only, so they
// hold whether or not the pile has fallen asleep.
TEST_F(snapshot_test, a_world_saved_asleep_wakes_and_steps_on_bit_for_bit) {
  world original;
  add_floor(original);
  add_box(original, vector{0, 0, 0.25}, vector{0.25, 0.25, 0.25});
  add_box(original, vector{0.05, 0, 0.75}, vector{0.25, 0.25, 0.25});
  const body_id ball = add_sphere(original, vector{1, 0, 0.2}, 0.2);
  simulate(original, 200);
  // A setter wakes the ball; the world wakes its island at the next step:
  // the snapshot carries that too.
  original.at(ball).set_velocity(vector{0.2, 0, 0});
  const bytes saved = original.save_snapshot();
  world restored = busy_world();
  restored.restore_snapshot(saved);
  ASSERT_EQ(restored.state_hash(), original.state_hash());
  for (int i = 0; i < 100; ++i) {
    if (i == 20) {
      const body_id dropped = add_sphere(original, vector{0, 0, 1.6}, 0.2, 2);
      EXPECT_EQ(add_sphere(restored, vector{0, 0, 1.6}, 0.2, 2), dropped);
    }
    original.step(h);
    restored.step(h);
    ASSERT_EQ(restored.state_hash(), original.state_hash()) << "step " << i;
  }
  EXPECT_EQ(restored.save_snapshot(), original.save_snapshot());
}

TEST_F(snapshot_test, files_round_trip_and_their_errors_name_the_path) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() /
                          ("gaphys_snapshot_test_" + std::to_string(std::random_device{}()));
  fs::create_directories(folder);
  world original = make_world();
  const scene s = mixed(original);
  simulate(original, 30);
  const std::string path = (folder / "world.snapshot").string();
  original.save_snapshot_file(path);
  simulate(original, 10);
  original.save_snapshot_file(path);  // replaces the first
  std::ifstream file(path, std::ios::binary);
  const bytes on_disk{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  EXPECT_EQ(on_disk, original.save_snapshot());
  // Only the snapshot is left in the folder: no temporary beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1);

  world restored = busy_world();
  restored.restore_snapshot_file(path);
  expect_same(original, restored, s);
  for (int i = 0; i < 30; ++i) {
    original.step(h);
    restored.step(h);
    ASSERT_EQ(restored.state_hash(), original.state_hash()) << "step " << i;
  }

  const std::uint64_t hash = restored.state_hash();
  const std::string missing = (folder / "missing.snapshot").string();
  EXPECT_TRUE(rejects([&] { restored.restore_snapshot_file(missing); }, missing));
  EXPECT_TRUE(rejects([&] { restored.restore_snapshot_file(folder.string()); }, folder.string()));
  EXPECT_TRUE(
      rejects([&] { restored.restore_snapshot_file(folder.string()); }, "is not a regular file"));
  EXPECT_TRUE(rejects([&] { restored.restore_snapshot_file(""); }, "path is empty"));
  // Only a regular file is read: a device without end (it filled memory
  // until std::bad_alloc) or a named pipe (opening it waited for a writer)
  // is refused at once.
  if (fs::exists("/dev/zero")) {
    EXPECT_TRUE(
        rejects([&] { restored.restore_snapshot_file("/dev/zero"); }, "is not a regular file"));
  }
#if defined(__unix__) || defined(__APPLE__)
  const std::string pipe = (folder / "a pipe").string();
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  EXPECT_TRUE(rejects([&] { restored.restore_snapshot_file(pipe); }, "is not a regular file"));
  fs::remove(pipe);
#endif
  const std::string unwritable = (folder / "no such folder" / "world.snapshot").string();
  EXPECT_TRUE(rejects([&] { original.save_snapshot_file(unwritable); }, unwritable));
  EXPECT_TRUE(rejects([&] { original.save_snapshot_file(""); }, "path is empty"));
  // Only a regular file is replaced (not a folder, a device or a pipe).
  const fs::path occupied = folder / "a folder";
  fs::create_directories(occupied);
  EXPECT_TRUE(
      rejects([&] { original.save_snapshot_file(occupied.string()); }, "is not a regular file"));
  EXPECT_TRUE(fs::is_directory(occupied));
  const std::string cut = (folder / "cut.snapshot").string();
  std::ofstream(cut, std::ios::binary)
      .write(reinterpret_cast<const char*>(on_disk.data()), std::streamsize(on_disk.size() / 2));
  EXPECT_TRUE(rejects([&] { restored.restore_snapshot_file(cut); }, cut));
  EXPECT_TRUE(rejects([&] { restored.restore_snapshot_file(cut); }, "truncated at byte"));
  EXPECT_EQ(restored.state_hash(), hash);
  fs::remove_all(folder);
}

// Saving replaces a file as an editor would: a private file stays private
// (a 600 file became 644), a symbolic link stays a link and the file it
// names is replaced (the link became a plain file), and a name of 255 bytes
// takes its temporary too (its name plus a suffix was too long).
TEST_F(snapshot_test, a_saved_file_keeps_its_permissions_its_link_and_a_long_name) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() /
                          ("gaphys_snapshot_test_" + std::to_string(std::random_device{}()));
  fs::create_directories(folder / "saves");
  world w = make_world();
  mixed(w);
  simulate(w, 5);
  const fs::path file = folder / "saves" / "game.snapshot";
  std::ofstream(file) << "old";
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
  const fs::path link = folder / "latest.snapshot";
  fs::create_symlink(fs::path("saves") / "game.snapshot", link);
  w.save_snapshot_file(link.string());
  EXPECT_TRUE(fs::is_symlink(link));
  std::ifstream in(file, std::ios::binary);
  EXPECT_EQ(bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()),
            w.save_snapshot());
  EXPECT_EQ(fs::status(file).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
  const fs::path long_name = folder / (std::string(246, 'n') + ".snapshot");
  w.save_snapshot_file(long_name.string());
  world restored = busy_world();
  restored.restore_snapshot_file(long_name.string());
  EXPECT_EQ(restored.state_hash(), w.state_hash());
  // Nothing else left beside them.
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 3);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder / "saves"), fs::directory_iterator()), 1);
  fs::remove_all(folder);
}

class corrupt_snapshot_test : public snapshot_test {
 protected:
  // A small world to save, and a target world that must come through every
  // failed restore as it was.
  void SetUp() override {
    add_floor(source);
    add_sphere(source, vector{0, 0, 0.5}, 0.2718281828);
    body_definition hull;
    hull.position = vector{1, 0, 0.3};
    hull.attitude = rotor{0.6, 0, 0.8, 0};
    hull.shape = shape::convex_hull(hull_points());
    hull.gravity_scale = 0.3141592653;
    source.create_body(hull);
    add_box(source, vector{-1, 0, 0.3}, vector{0.3, 0.3, 0.3});
    simulate(source, 20);
    good = source.save_snapshot();
    target = busy_world();
    hash = target.state_hash();
    time = target.time();
  }

  ::testing::AssertionResult rejected(const bytes& b, const std::string& what) {
    ::testing::AssertionResult r = rejects([&] { target.restore_snapshot(b); }, what);
    if (!r) return r;
    if (target.state_hash() != hash || target.body_count() != 5 || target.time() != time) {
      return ::testing::AssertionFailure() << "the target world changed";
    }
    return r;
  }

  world source, target;
  bytes good;
  std::uint64_t hash = 0;
  double time = 0;
};

TEST_F(corrupt_snapshot_test, damaged_bytes_are_rejected_and_change_nothing) {
  EXPECT_TRUE(rejected({}, "not a gaphys snapshot"));
  bytes b = good;
  b[0] ^= 1;
  EXPECT_TRUE(rejected(b, "not a gaphys snapshot"));
  EXPECT_TRUE(rejected(bytes{'h', 'e', 'l', 'l', 'o'}, "not a gaphys snapshot"));
  for (std::size_t size = 1; size < good.size(); ++size) {
    ASSERT_TRUE(rejected(bytes(good.begin(), good.begin() + std::ptrdiff_t(size)),
                         "truncated at byte " + std::to_string(size)))
        << size;
  }
  b = good;
  b.back() ^= 0x40;
  EXPECT_TRUE(rejected(b, "corrupt: checksum"));
  b = good;
  b[good.size() / 2] ^= 0x08;
  EXPECT_TRUE(rejected(b, "corrupt: checksum"));
  b = good;
  b.push_back(0);
  EXPECT_TRUE(rejected(b, "trailing bytes"));
  b = good;
  b[version_at] = 1;  // the format before approach speeds
  EXPECT_TRUE(rejected(b, "made by another build: format version 1"));
  b = good;
  const int other_size = sizeof(real) == 8 ? 4 : 8;  // the other engine scalar's
  b[real_size_at] = std::uint8_t(other_size);
  EXPECT_TRUE(
      rejected(b, "made by another build: reals of " + std::to_string(other_size) + " bytes"));
  b = good;
  b[real_size_at + 1] ^= 1;  // the byte order check
  EXPECT_TRUE(rejected(b, "made by another build"));
  // The good snapshot still restores into the target.
  target.restore_snapshot(good);
  EXPECT_EQ(target.state_hash(), source.state_hash());
}

// Snapshots with a valid checksum and a bad value: each names it.
TEST_F(corrupt_snapshot_test, resealed_bad_values_are_rejected_by_name) {
  const auto edited = [this](const auto& edit) {
    bytes b = good;
    edit(b);
    reseal(b);
    return b;
  };
  EXPECT_TRUE(rejected(edited([](bytes& b) { b[solver_iterations_at] = 0; }),
                       "solver iterations must be in [1, 1000000]"));
  // INT_MAX sweeps: the world's constructor refuses more than a million.
  EXPECT_TRUE(rejected(edited([](bytes& b) {
                         for (int i = 0; i < 4; ++i) b[solver_iterations_at + i] = 0xff;
                         b[solver_iterations_at + 3] = 0x7f;
                       }),
                       "solver iterations must be in [1, 1000000]"));
  // The first combine rule: after three i32 iteration counts and three reals.
  EXPECT_TRUE(
      rejected(edited([](bytes& b) { b[solver_iterations_at + 3 * 4 + 3 * sizeof(real)] = 7; }),
               "restitution combine rule is 7"));
  const std::size_t scale = find_reals(good, {0.3141592653});
  ASSERT_LT(scale, good.size());
  EXPECT_TRUE(rejected(edited([&](bytes& b) { put_real(b, scale, std::nan("")); }),
                       "gravity scale must be finite"));
  // The sphere's radius, then its (unused) normal and offset: the body's
  // bounding radius has the same bits, but not these after it.
  const std::size_t radius = find_reals(good, {0.2718281828, 0, 0, 0, 0});
  ASSERT_LT(radius, good.size());
  EXPECT_TRUE(rejected(edited([&](bytes& b) { put_real(b, radius, -0.5); }),
                       "a sphere's radius must be between"));
  // Sizes and speeds the API refuses (a static sphere of radius 1e300
  // restored moved a ball by 2e299 m; a capsule of radius 1e-300 made every
  // step throw; a speed whose square overflows, every step too).
  const real beyond = sizeof(real) == 8 ? real(1e300) : real(1e30);
  const real below = sizeof(real) == 8 ? real(1e-300) : real(1e-30);
  for (const real size : {beyond, below}) {
    EXPECT_TRUE(
        rejected(edited([&](bytes& b) { EXPECT_GE(replace_reals(b, 0.2718281828, size), 2); }),
                 "a sphere's radius must be between"));
    EXPECT_TRUE(rejected(edited([&](bytes& b) { EXPECT_GE(replace_reals(b, 0.3, size), 6); }),
                         "polyhedron 1: a box's half extents must be between"));
  }
  const real falling = source.bodies()[1].velocity().e3();
  const std::size_t velocity = find_reals(good, {0, 0, falling});
  ASSERT_LT(velocity, good.size());
  EXPECT_TRUE(rejected(edited([&](bytes& b) { put_real(b, velocity, beyond); }),
                       "velocity must be finite, its square too"));
  EXPECT_TRUE(rejected(edited([&](bytes& b) { b[radius - 1] = 9; }), "shape kind is 9"));
  const rotor& turn = source.bodies()[2].attitude();
  const std::size_t attitude = find_reals(good, {turn.c[0], turn.c[1], turn.c[2], turn.c[3]});
  ASSERT_LT(attitude, good.size());
  EXPECT_TRUE(rejected(edited([&](bytes& b) { put_real(b, attitude, 2 * turn.c[0]); }),
                       "attitude must be a unit rotor"));
  // A hull's vertex count, just before its first vertex: far more than the
  // bytes left, rejected before anything is allocated for it.
  const vector& corner = source.bodies()[2].shape()->polyhedron()->vertices[0];
  const std::size_t first_vertex = find_reals(good, {corner.c[0], corner.c[1], corner.c[2]});
  ASSERT_LT(first_vertex, good.size());
  EXPECT_TRUE(rejected(edited([&](bytes& b) { put_u64(b, first_vertex - 8, 1ull << 61); }),
                       "more than the"));
  // The inverse inertia follows the tensor's nine entries: one of them made
  // 1e245 (a resealed fuzzed snapshot restored so, and its step overflowed).
  const std::array<real, 9>& rows = source.bodies()[2].body_inertia().rows();
  const std::size_t tensor = find_reals(good, {rows[0], rows[1], rows[2], rows[3], rows[4]});
  ASSERT_LT(tensor, good.size());
  const real huge = sizeof(real) == 8 ? real(1e245) : real(1e35);
  EXPECT_TRUE(rejected(edited([&](bytes& b) { put_real(b, tensor + 10 * sizeof(real), huge); }),
                       "the inverse inertia is not the inertia tensor's inverse"));
  // A moment pushed up, its inverse left: it would turn the body by the
  // old inverse (a reviewer's resealed snapshot overflowed in its first step).
  EXPECT_TRUE(rejected(edited([&](bytes& b) { put_real(b, tensor, std::ldexp(rows[0], 10)); }),
                       "the inverse inertia is not the inertia tensor's inverse"));
  // A resting contact's impulses: the one the warm start gives back
  // pulling, or so large that its velocity change overflows (fuzzed
  // snapshots restored both, and their steps overflowed).
  const auto pushing = std::find_if(source.contacts().begin(), source.contacts().end(),
                                    [](const contact& c) { return c.resting.normal > 0; });
  ASSERT_NE(pushing, source.contacts().end());
  const contact_impulse& given = pushing->impulse;
  const std::size_t resting = find_reals(good, {given.angular.c[0], given.angular.c[1],
                                                given.angular.c[2], pushing->resting.normal}) +
                              3 * sizeof(real);
  ASSERT_LT(resting, good.size());
  EXPECT_TRUE(rejected(edited([&](bytes& b) { put_real(b, resting, -pushing->resting.normal); }),
                       "normal impulse must be finite and >= 0"));
  const real enormous = sizeof(real) == 8 ? real(1e306) : real(1e37);
  EXPECT_TRUE(
      rejected(edited([&](bytes& b) { put_real(b, resting, enormous); }), "is too large to step"));
  // A vertex moved far out: beyond the sizes hull() takes.
  const real far = sizeof(real) == 8 ? real(1e100) : real(1e15);
  EXPECT_TRUE(rejected(edited([&](bytes& b) {
                         for (int k = 0; k < 3; ++k) {
                           put_real(b, first_vertex + k * sizeof(real), far);
                         }
                       }),
                       "polyhedron 0: the hull's vertices must lie within"));
  // A vertex moved out: the hull is no longer convex.
  EXPECT_TRUE(
      rejected(edited([&](bytes& b) { put_real(b, first_vertex, real(1.01) * corner.c[0]); }),
               "polyhedron 0: face"));
}

// Values so large (beyond 1e30, 1e6 in float) that a world made through the
// API with them may overflow within a few steps (a body 1e200 m below a
// plane, a gravity scale of 1e77, a force of 6e144 N): world::step's
// numeric_overflow is then its documented answer, for a restored world as
// for a built one. In the world's settings (gravity, damping), and per body:
// its position, velocities, pending force and torque, mass and inertia,
// damping, gravity scale, shapes' offsets and sizes, and the warm-start
// impulses of its contacts.
struct absurd_values {
  bool in_settings = false;
  std::vector<char> in_body;  // by body index
};

absurd_values absurd_values_of(const world& w) {
  const real limit = sizeof(real) == 8 ? real(1e30) : real(1e6);
  const auto large = [limit](real x) { return !(std::fabs(x) <= limit); };
  const auto absurd = [&large](const auto& value) {
    return std::any_of(std::begin(value.c), std::end(value.c), large);
  };
  absurd_values found;
  found.in_settings = absurd(w.settings().gravity) || large(w.settings().linear_damping) ||
                      large(w.settings().angular_damping);
  found.in_body.assign(w.bodies().size(), 0);
  for (std::size_t i = 0; i < w.bodies().size(); ++i) {
    const body& b = w.bodies()[i];
    bool any = absurd(b.position()) || absurd(b.velocity()) || absurd(b.angular_velocity()) ||
               absurd(b.accumulated_force()) || absurd(b.accumulated_torque()) ||
               large(b.gravity_scale()) || large(b.linear_damping().value_or(0)) ||
               large(b.angular_damping().value_or(0));
    if (b.is_dynamic()) {
      const std::array<real, 9>& rows = b.body_inertia().rows();
      any = any || large(b.inverse_mass()) || large(1 / b.inverse_mass()) ||
            std::any_of(rows.begin(), rows.end(), large) ||
            absurd(b.world_inverse_inertia(bivector{1, 0, 0})) ||
            absurd(b.world_inverse_inertia(bivector{0, 1, 0})) ||
            absurd(b.world_inverse_inertia(bivector{0, 0, 1}));
    }
    for (const attached_shape& s : b.shapes()) {
      const bool plane = s.shape.kind() == shape_kind::plane;
      any = any || absurd(s.offset) || (!plane && large(s.shape.bounding_radius()));
    }
    found.in_body[i] = any;
  }
  for (const contact& c : w.contacts()) {
    const real masses = w.bodies()[c.body_a].inverse_mass() + w.bodies()[c.body_b].inverse_mass();
    if (large(c.resting.normal * masses)) found.in_body[c.body_a] = found.in_body[c.body_b] = 1;
  }
  return found;
}

// Whether a numeric_overflow `message` from stepping `w` (restored holding
// `found`) is the documented answer to absurd values: in the settings, or
// in the body it names ("the motion of body N") or one joined to it by
// contacts, before or after the step (an absurd body may push others).
bool excused_by(const absurd_values& found, const world& restored, const world& w,
                const std::string& message) {
  if (found.in_settings) return true;
  const std::string prefix = "the motion of body ";
  const std::size_t at = message.find(prefix);
  if (at == std::string::npos) return false;
  const body_id named = std::stoull(message.substr(at + prefix.size()));
  // The bodies joined by contacts (indices are the same in both worlds).
  std::vector<std::size_t> root(found.in_body.size());
  for (std::size_t i = 0; i < root.size(); ++i) root[i] = i;
  const auto find = [&root](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (const world* each : {&restored, &w}) {
    for (const contact& c : each->contacts()) root[find(c.body_a)] = find(c.body_b);
  }
  for (std::size_t i = 0; i < root.size(); ++i) {
    if (w.id_of(i) != named) continue;
    for (std::size_t j = 0; j < root.size(); ++j) {
      if (found.in_body[j] && find(j) == find(i)) return true;
    }
  }
  return false;
}

// Mutations of real snapshots (flipped bits, overwritten bytes, runs of
// 0x00 or 0xff, truncations, insertions, duplicated ranges), every other
// one resealed: each is rejected with the target unchanged, or restores a
// world that steps (GAPHYS_SNAPSHOT_FUZZ_COUNT raises the count), throwing
// at most invalid_input, or numeric_overflow where the settings or the
// bodies it reaches hold absurd values (excused_by). The snapshots: the mixed scene with a force
// pending, and a pile asleep.
TEST_F(corrupt_snapshot_test, fuzzed_snapshots_are_rejected_or_step_safely) {
  int count = 2000;
  if (const char* env = std::getenv("GAPHYS_SNAPSHOT_FUZZ_COUNT")) count = std::atoi(env);
  world rich = make_world();
  const scene s = mixed(rich);
  simulate(rich, 40);
  rich.at(s.pushed).apply_force(vector{3, 0, 40}, vector{0.1, 0, 0});
  world pile;
  add_floor(pile);
  add_box(pile, vector{0, 0, 0.25}, vector{0.25, 0.25, 0.25});
  add_box(pile, vector{0.05, 0, 0.75}, vector{0.25, 0.25, 0.25});
  simulate(pile, 200);
  const bytes sources[] = {rich.save_snapshot(), pile.save_snapshot()};
  std::mt19937_64 rng(0x5eed5a7e);
  const auto below = [&rng](std::size_t n) {
    return std::size_t(std::uniform_int_distribution<std::uint64_t>(0, n - 1)(rng));
  };
  const world untouched = target;
  int accepted = 0, refused = 0, absurd = 0, overflowed = 0;
  for (int i = 0; i < count; ++i) {
    bytes b = sources[i / 2 % 2];
    switch (below(6)) {
      case 0:
        for (std::size_t k = 1 + below(4); k > 0; --k) {
          b[below(b.size())] ^= std::uint8_t(1 << below(8));
        }
        break;
      case 1:
        for (std::size_t k = 1 + below(4); k > 0; --k) {
          b[below(b.size())] = std::uint8_t(below(256));
        }
        break;
      case 2: {
        const std::size_t at = below(b.size()), n = std::min(1 + below(16), b.size() - at);
        std::fill_n(b.begin() + std::ptrdiff_t(at), n, below(2) ? 0xff : 0x00);
        break;
      }
      case 3:
        b.resize(below(b.size()));
        break;
      case 4: {
        bytes inserted(1 + below(16));
        for (std::uint8_t& x : inserted) x = std::uint8_t(below(256));
        b.insert(b.begin() + std::ptrdiff_t(below(b.size() + 1)), inserted.begin(), inserted.end());
        break;
      }
      default: {
        const std::size_t at = below(b.size()), n = std::min(1 + below(64), b.size() - at);
        const bytes copy(b.begin() + std::ptrdiff_t(at), b.begin() + std::ptrdiff_t(at + n));
        b.insert(b.begin() + std::ptrdiff_t(below(b.size() + 1)), copy.begin(), copy.end());
        break;
      }
    }
    if (i % 2 == 1) reseal(b);
    try {
      target.restore_snapshot(b);
    } catch (const invalid_input&) {
      ++refused;
      ASSERT_EQ(target.state_hash(), hash) << "mutation " << i;
      ASSERT_EQ(target.body_count(), 5u) << "mutation " << i;
      continue;
    }
    ++accepted;
    const absurd_values found = absurd_values_of(target);
    if (found.in_settings ||
        std::any_of(found.in_body.begin(), found.in_body.end(), [](char x) { return x != 0; })) {
      ++absurd;
    }
    const world restored = target;
    for (int k = 0; k < 3; ++k) {
      try {
        target.step(h);
      } catch (const invalid_input&) {
      } catch (const numeric_overflow& e) {
        ASSERT_TRUE(excused_by(found, restored, target, e.what()))
            << "mutation " << i << ": " << e.what();
        ++overflowed;
        break;
      }
    }
    (void)target.state_hash();
    (void)target.ray_cast(vector{0, 0, 5}, vector{0, 0, -1}, 10);
    target = untouched;
  }
  RecordProperty("accepted", accepted);
  RecordProperty("refused", refused);
  RecordProperty("absurd", absurd);
  RecordProperty("overflowed", overflowed);
  EXPECT_EQ(accepted + refused, count);
  EXPECT_GT(refused, count / 2);
  EXPECT_GT(accepted, 0);  // some mutations leave a valid world: those must step
}

}  // namespace
}  // namespace gaphys::testing
