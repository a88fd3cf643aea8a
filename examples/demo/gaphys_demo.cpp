// gaphys_demo: runs one of the shared scenes (gaphys::scenes) at its time step
// and writes the trajectory of its dynamic bodies as CSV or JSON.
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <csignal>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "atomic_file.hpp"
#include "gaphys/error.hpp"
#include "gaphys/scenes.hpp"
#include "trajectory_writer.hpp"

namespace {

constexpr const char* usage =
    R"(usage: gaphys_demo [--scene NAME] [--spheres N] [--steps N] [--every K] [--out FILE]
       gaphys_demo --list | --help

Runs a scene at h = 1/240 s and writes, at step 0 and every K-th step, each
dynamic body's position (x y z) and attitude rotor (scalar e12 e13 e23).

  --scene NAME  a scene from --list (default falling_spheres)
  --spheres N   falling_spheres only: how many spheres (default 100, at most 10000)
  --steps N     steps to run (default 2400: 10 s)
  --every K     record every K-th step (default 10)
  --out FILE    FILE.csv or FILE.json, replaced only once complete
                (default: CSV on standard output)
  --list        print the scenes and exit
  --help        print this help and exit
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
  std::string out;  // empty: standard output
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
        option != "--every" && option != "--out") {
      throw usage_error("unknown option '" + option + "'");
    }
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
    } else {
      o.out = value;
    }
  }
  o.scene = &find_scene(scene);
  if (o.spheres && o.scene->name != "falling_spheres") {
    throw usage_error("--spheres applies only to falling_spheres, not " + scene);
  }
  if (!o.out.empty()) {
    const auto format = demo::format_of(o.out);
    if (!format) throw usage_error("--out needs a .csv or .json file, not '" + o.out + "'");
    o.format = *format;
  }
  return o;
}

void list_scenes() {
  for (const gaphys::scenes::entry& entry : gaphys::scenes::catalogue()) {
    std::cout << std::left << std::setw(20) << entry.name << entry.description << '\n';
  }
}

// Percent done on stderr: rewritten in place on a terminal; elsewhere (a log,
// a CI run) one line per 10%, so the log stays short.
class progress {
 public:
  explicit progress(long long total) : total_(total), in_place_(isatty(STDERR_FILENO) == 1) {}

  void update(long long done) {
    const int percent = static_cast<int>(100.0 * double(done) / double(total_));
    const int shown = in_place_ ? percent : percent / 10 * 10;
    if (shown == shown_) return;
    shown_ = shown;
    std::cerr << (in_place_ ? "\r" : "") << shown << '%' << (in_place_ ? "" : "\n") << std::flush;
    line_open_ = in_place_;
  }

  // Clears the in-place line, so what follows (the summary, or an error while
  // unwinding) starts on a clean line.
  void finish() {
    if (line_open_) std::cerr << "\r    \r";
    line_open_ = false;
  }
  ~progress() { finish(); }

 private:
  long long total_;
  bool in_place_;
  bool line_open_ = false;
  int shown_ = 0;  // 0% is not worth a line
};

// Set by Ctrl-C or a kill: the run stops between steps and unwinds, so the
// output's temporary file is removed instead of left behind.
volatile std::sig_atomic_t stop_signal = 0;
extern "C" void request_stop(int signal) { stop_signal = signal; }

int run(const options& o) {
  std::signal(SIGINT, request_stop);
  std::signal(SIGTERM, request_stop);
  const gaphys::real h = gaphys::scenes::time_step;
  gaphys::world world =
      o.spheres ? gaphys::scenes::falling_spheres_in_box(*o.spheres) : o.scene->build();

  // The file is opened before the run, so a bad path fails at once.
  std::optional<demo::atomic_file> file;
  std::ostream& out = o.out.empty() ? std::cout : file.emplace(o.out).stream();
  demo::trajectory_writer writer(out, o.format, o.scene->name, h);
  writer.write_frame(world);

  // Only world::step is timed: ms/step is the engine's cost, not the writer's.
  progress bar(o.steps);
  std::chrono::steady_clock::duration stepping{};
  for (long long step = 1; step <= o.steps; ++step) {
    if (stop_signal) throw std::runtime_error("interrupted at step " + std::to_string(step));
    const auto start = std::chrono::steady_clock::now();
    world.step(h);
    stepping += std::chrono::steady_clock::now() - start;
    if (step % o.every == 0) writer.write_frame(world);
    bar.update(step);
  }
  writer.finish();
  if (file) {
    file->commit();
  } else if (!std::cout.flush()) {
    throw std::runtime_error("cannot write to standard output");
  }
  bar.finish();

  const double seconds = std::chrono::duration<double>(stepping).count();
  std::cerr << o.scene->name << ": " << o.steps << " steps, " << world.time() << " s simulated, "
            << std::fixed << std::setprecision(3) << seconds << " s wall, "
            << 1000 * seconds / double(o.steps) << " ms/step, " << world.contacts().size()
            << " contacts in the last step\n";
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
