// gaphys_demo: runs one of the shared scenes (gaphys::scenes) at its time step
// and writes the trajectory of its dynamic bodies as CSV or JSON, and as a
// page that plays it in 3-D in a browser (viewer_page.hpp).
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "atomic_file.hpp"
#include "gaphys/error.hpp"
#include "gaphys/scenes.hpp"
#include "trajectory_writer.hpp"
#include "viewer_page.hpp"

namespace {

constexpr const char* usage =
    R"(usage: gaphys_demo [--scene NAME] [--spheres N] [--steps N] [--every K]
                   [--remove-at S] [--out FILE] [--html FILE]
       gaphys_demo --list | --help

Runs a scene at h = 1/240 s and writes, at step 0 and every K-th step, each
dynamic body's position (x y z) and attitude rotor (scalar e12 e13 e23).
JSON also lists every body first (static ones too): its shapes (sphere,
plane, point, box, capsule, convex hull), each with its position and
attitude in the body's frame, and the body's starting pose.
Progress goes to standard error: percent done and the time left (ETA).

  --scene NAME  a scene from --list (default falling_spheres)
  --spheres N   falling_spheres only: how many spheres (default 100, at most 10000)
  --steps N     steps to run (default 2400: 10 s)
  --every K     record every K-th step (default 10)
  --remove-at S after step S, cast a ray down the z axis from 100 m and
                remove the dynamic body it hits first (say, the top box of
                a tower): the rest go on without it, and it leaves the
                output from then on
  --out FILE    FILE.csv or FILE.json, replaced only once complete
                (default: CSV on standard output, unless --html is given)
  --html FILE   also (without --out: only) write a web page that plays the
                run in 3-D, replaced only once complete: every body with its
                shape, play/pause, a time slider and a speed control. It holds
                three.js and the data, so it opens from disk, offline. Drag:
                orbit; wheel: zoom; right-drag: pan; double-click: reset view.
                The address's #fragment sets the state, e.g. FILE#t=1.25&paused:
                  t=SECONDS  paused  speed=FACTOR
                  eye=X,Y,Z  target=X,Y,Z  fov=DEGREES   (a fixed camera, z up;
                             default: fitted to the scene, 45 degrees)
  --list        print the scenes and exit
  --help, -h    print this help and exit
Each option may be given once.
)";

// A bad command line: reported with the usage, exit code 2.
class usage_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct options {
  bool help = false;
  bool list = false;
  const gaphys::scenes::entry* scene = nullptr;
  std::optional<int> spheres;
  long long steps = 2400;
  long long every = 10;
  std::optional<long long> remove_at;  // the step after which the ray's body goes
  std::string out;   // empty: standard output, unless html is given
  std::string html;  // empty: no page
  demo::trajectory_format format = demo::trajectory_format::csv;
};

// Contacts are found among all pairs, so the cost of a step grows with the
// square of the count: 10000 spheres already take seconds per step.
constexpr long long max_spheres = 10000;
// Keeps percentages and step counts far from overflow; a billion steps is
// already 48 days of simulated time.
constexpr long long max_steps = 1'000'000'000;

// Plain decimal digits only: std::stoll would accept " 12", "12abc" or "1e3".
long long positive_count(const std::string& option, const std::string& text, long long max) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  const bool whole = error == std::errc() && stop == end;
  if (error == std::errc::result_out_of_range || (whole && value > max)) {
    throw usage_error(option + " must be at most " + std::to_string(max) + ", not " + text);
  }
  if (!whole || value <= 0) {
    throw usage_error(option + " needs a positive whole number, not '" + text + "'");
  }
  return value;
}

const gaphys::scenes::entry& find_scene(const std::string& name) {
  for (const gaphys::scenes::entry& entry : gaphys::scenes::catalogue()) {
    if (entry.name == name) return entry;
  }
  throw usage_error("unknown scene '" + name + "' (see --list)");
}

options parse(int argc, char** argv) {
  options o;
  std::string scene = "falling_spheres";
  std::set<std::string> given;  // the run's options seen so far
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h") {
      o.help = true;
      continue;
    }
    if (option == "--list") {
      o.list = true;
      continue;
    }
    if (option != "--scene" && option != "--spheres" && option != "--steps" &&
        option != "--every" && option != "--remove-at" && option != "--out" &&
        option != "--html") {
      throw usage_error("unknown option '" + option + "'");
    }
    // "--steps 10 ... --steps 1000" is a slip more often than a wish.
    if (!given.insert(option).second) throw usage_error(option + " is given twice");
    // "--out --steps 5" means a forgotten value, not a file named --steps.
    if (i + 1 == argc || std::string(argv[i + 1]).rfind("--", 0) == 0) {
      throw usage_error(option + " needs a value");
    }
    const std::string value = argv[++i];
    if (option == "--scene") {
      scene = value;
    } else if (option == "--spheres") {
      o.spheres = static_cast<int>(positive_count(option, value, max_spheres));
    } else if (option == "--steps") {
      o.steps = positive_count(option, value, max_steps);
    } else if (option == "--every") {
      o.every = positive_count(option, value, max_steps);
    } else if (option == "--remove-at") {
      o.remove_at = positive_count(option, value, max_steps);
    } else if (value.empty()) {
      throw usage_error(option + " needs a file name, not an empty one");
    } else if (option == "--out") {
      o.out = value;
    } else {
      o.html = value;
    }
  }
  // "--list --out scenes.json" would write nothing: say so.
  if (o.list && !o.help && !given.empty()) {
    throw usage_error("--list takes no other options, not " + *given.begin());
  }
  o.scene = &find_scene(scene);
  if (o.remove_at && *o.remove_at > o.steps) {
    throw usage_error("--remove-at " + std::to_string(*o.remove_at) + " is after the last step, " +
                      std::to_string(o.steps));
  }
  if (o.spheres && o.scene->name != "falling_spheres") {
    throw usage_error("--spheres applies only to falling_spheres, not " + scene);
  }
  if (!o.out.empty()) {
    const auto format = demo::format_of(o.out);
    if (!format) throw usage_error("--out needs a .csv or .json file, not '" + o.out + "'");
    o.format = *format;
  }
  if (!o.html.empty() && !o.out.empty() && demo::atomic_file::same_target(o.html, o.out)) {
    throw usage_error("--out and --html need two different files, not both '" + o.out + "'");
  }
  return o;
}

void list_scenes() {
  for (const gaphys::scenes::entry& entry : gaphys::scenes::catalogue()) {
    std::cout << std::left << std::setw(20) << entry.name << entry.description << '\n';
  }
}

// "< 1 s", "12 s", "3 min 05 s" or "2 h 07 min": whole seconds, rounded up.
std::string duration_text(double seconds) {
  if (seconds < 1) return "< 1 s";
  const long long whole = static_cast<long long>(std::ceil(seconds));
  char text[48];
  if (whole < 60) {
    std::snprintf(text, sizeof text, "%lld s", whole);
  } else if (whole < 3600) {
    std::snprintf(text, sizeof text, "%lld min %02lld s", whole / 60, whole % 60);
  } else {
    std::snprintf(text, sizeof text, "%lld h %02lld min", whole / 3600, whole / 60 % 60);
  }
  return text;
}

// Percent done on stderr, with the time left at the rate so far ("42% (ETA
// 12 s)"): rewritten in place on a terminal; elsewhere (a log, a CI run) one
// line per 10%, so the log stays short.
class progress {
 public:
  using clock = std::chrono::steady_clock;

  explicit progress(long long total)
      : total_(total), in_place_(isatty(STDERR_FILENO) == 1), start_(clock::now()) {}

  void update(long long done) {
    const int percent = static_cast<int>(100.0 * double(done) / double(total_));
    const int shown = in_place_ ? percent : percent / 10 * 10;
    if (shown == shown_) return;
    shown_ = shown;
    std::string line = std::to_string(shown) + '%';
    if (done < total_) {
      const double elapsed = std::chrono::duration<double>(clock::now() - start_).count();
      line += " (ETA " + duration_text(elapsed * double(total_ - done) / double(done)) + ")";
    }
    if (in_place_) {
      // Blanks over what is left of a longer line before.
      const std::size_t length = line.size();
      if (length < width_) line.append(width_ - length, ' ');
      width_ = length;
      std::cerr << '\r' << line << std::flush;
    } else {
      std::cerr << line << '\n' << std::flush;
    }
    line_open_ = in_place_;
  }

  // Clears the in-place line, so what follows (the summary, or an error while
  // unwinding) starts on a clean line.
  void finish() {
    if (line_open_) std::cerr << '\r' << std::string(width_, ' ') << '\r' << std::flush;
    line_open_ = false;
  }
  ~progress() { finish(); }

 private:
  long long total_;
  bool in_place_;
  clock::time_point start_;
  bool line_open_ = false;
  std::size_t width_ = 0;  // of the line on screen
  int shown_ = 0;          // 0% is not worth a line
};

std::size_t asleep(const gaphys::world& world) {
  std::size_t count = 0;
  for (const gaphys::body& b : world.bodies()) count += b.is_sleeping();
  return count;
}

// What a ray straight down the middle of the scene meets first.
std::optional<gaphys::ray_hit> ray_down_the_middle(const gaphys::world& world) {
  return world.ray_cast(gaphys::vector{0, 0, 100}, gaphys::vector{0, 0, -1}, 200);
}

// Removes the dynamic body the ray down the middle hits, if any.
void remove_what_the_ray_hits(gaphys::world& world) {
  const std::optional<gaphys::ray_hit> hit = ray_down_the_middle(world);
  if (!hit || !world.at(hit->body).is_dynamic()) {
    std::cerr << "--remove-at: the ray down the z axis hits no dynamic body at t = "
              << world.time() << " s\n";
    return;
  }
  world.remove_body(hit->body);
  std::cerr << "removed body " << hit->body << ", hit by the ray down the z axis at z = "
            << hit->point.e3() << " m, t = " << world.time() << " s\n";
}

// Set by Ctrl-C, a kill or a closed terminal: the run stops between steps and
// unwinds, so the output's temporary file is removed instead of left behind.
volatile std::sig_atomic_t stop_signal = 0;
extern "C" void request_stop(int signal) { stop_signal = signal; }

// Catches `signal` unless the demo was started with it ignored (a
// background job ignores Ctrl-C; nohup, a closed terminal).
void stop_on(int signal) {
  if (std::signal(signal, request_stop) == SIG_IGN) std::signal(signal, SIG_IGN);
}

int run(const options& o) {
  if (!o.html.empty()) demo::require_viewer();  // before any file is made
  stop_on(SIGINT);
  stop_on(SIGTERM);
  stop_on(SIGHUP);
  const gaphys::real h = gaphys::scenes::time_step;
  gaphys::world world =
      o.spheres ? gaphys::scenes::falling_spheres_in_box(*o.spheres) : o.scene->build();

  // Files are opened before the run, so a bad path fails at once.
  std::optional<demo::atomic_file> file;
  std::optional<demo::trajectory_writer> writer;
  if (!o.out.empty() || o.html.empty()) {
    std::ostream& out = o.out.empty() ? std::cout : file.emplace(o.out).stream();
    writer.emplace(out, o.format, o.scene->name, h, &world);
  }
  // The page holds the same trajectory as a JSON --out; its scene holds the
  // bodies' shapes.
  std::optional<demo::atomic_file> page_file;
  std::optional<demo::viewer_page> page;
  std::optional<demo::trajectory_writer> page_writer;
  if (!o.html.empty()) {
    const std::string description = o.spheres
                                        ? std::to_string(*o.spheres) + " spheres falling into a box"
                                        : o.scene->description;
    page.emplace(page_file.emplace(o.html).stream(), world, o.scene->name, description);
    page_writer.emplace(page->trajectory(), demo::trajectory_format::json, o.scene->name, h);
  }
  const auto record = [&] {
    if (writer) writer->write_frame(world);
    if (page_writer) page_writer->write_frame(world);
    // A write that failed (a full disk) stops the run now.
    if (file) file->check();
    if (page_file) page_file->check();
  };
  record();

  // Only world::step is timed: ms/step is the engine's cost, not the writer's.
  progress bar(o.steps);
  std::chrono::steady_clock::duration stepping{};
  long long touches_began = 0;  // pairs that began touching, from the contact events
  for (long long step = 1; step <= o.steps; ++step) {
    if (stop_signal) throw std::runtime_error("interrupted at step " + std::to_string(step));
    const auto start = std::chrono::steady_clock::now();
    world.step(h);
    stepping += std::chrono::steady_clock::now() - start;
    touches_began += static_cast<long long>(world.events().began.size());
    if (o.remove_at && step == *o.remove_at) remove_what_the_ray_hits(world);
    if (step % o.every == 0) record();
    bar.update(step);
  }
  if (writer) writer->finish();
  if (page) {
    page_writer->finish();
    page->finish();
  }
  if (file) {
    file->commit();
  } else if (writer && !std::cout.flush()) {
    throw std::runtime_error("cannot write to standard output");
  }
  if (page_file) page_file->commit();
  bar.finish();

  const double seconds = std::chrono::duration<double>(stepping).count();
  std::cerr << o.scene->name << ": " << o.steps << " steps, " << world.time() << " s simulated, "
            << std::fixed << std::setprecision(3) << seconds << " s wall, "
            << 1000 * seconds / double(o.steps) << " ms/step, " << world.contacts().size()
            << " contacts in the last step, " << touches_began << " touches began, "
            << asleep(world) << " of " << world.body_count() << " bodies asleep\n";
  if (const std::optional<gaphys::ray_hit> hit = ray_down_the_middle(world)) {
    std::cerr << "a ray down the z axis from 100 m meets body " << hit->body << " at z = "
              << std::setprecision(4) << hit->point.e3() << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const options o = parse(argc, argv);
    if (o.help) {
      std::cout << usage;
    } else if (o.list) {
      list_scenes();
    } else {
      return run(o);
    }
    if (!std::cout.flush()) throw std::runtime_error("cannot write to standard output");
    return 0;
  } catch (const usage_error& e) {
    std::cerr << "gaphys_demo: " << e.what() << "\n\n" << usage;
    return 2;
  } catch (const gaphys::invalid_input& e) {
    std::cerr << "gaphys_demo: invalid input: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "gaphys_demo: " << e.what() << '\n';
    return 1;
  }
}
