// The instrumented variant's recorder: counts, per library call, which
// coefficients of the arguments and of the result were really nonzero.
//
// A coefficient counts as nonzero when |c| > 8 eps max|c| of its multivector:
// a coefficient left by cancellation (1e-17 after a rotation) counts as zero.
// At exit, or on flush(), the counts are written as a gaphys profile (see
// generator/gaphys_gen/profile.py) to $GAPHYS_PROFILE_DIR/<namespace>.json,
// added to the counts already in that file, in whatever layout it is (as
// gaphys-gen merge, a formatter or this recorder left it). The file is
// replaced atomically (written beside it, then renamed), under a lock on the
// folder, so processes recording at once (ctest -j) add up instead of one
// replacing another's counts. An existing file that is not a profile of the
// same algebra and spec, or holds what the recorder cannot carry over
// exactly (a count over 2^64 - 1), is left alone, with a message on stderr.
#pragma once

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "json_reader.hpp"
#include "mv_algorithms.hpp"

namespace gaphys::ga {

// Bit i set when coefficient i is nonzero beyond rounding (see above).
template <class MV>
std::uint32_t nonzero_bits(const MV& x) {
  using T = typename MV::scalar_type;
  const T floor = T(8) * std::numeric_limits<T>::epsilon() * max_abs(x);
  std::uint32_t bits = 0;
  for (int i = 0; i < MV::size; ++i)
    if (std::abs(x.c[i]) > floor) bits |= std::uint32_t(1) << i;
  return bits;
}
inline std::uint32_t nonzero_bits(float x) { return x != 0 ? 1u : 0u; }
inline std::uint32_t nonzero_bits(double x) { return x != 0 ? 1u : 0u; }

class profile_recorder {
 public:
  // function, argument bitmaps (unused ones 0), result bitmap
  using key = std::tuple<int, std::uint32_t, std::uint32_t, std::uint32_t>;

  profile_recorder(std::string algebra, std::string file_stem, std::string spec_hash, std::string generator_version,
                   std::vector<std::pair<std::string, int>> functions)
      : algebra_(std::move(algebra)),
        file_stem_(std::move(file_stem)),
        spec_hash_(std::move(spec_hash)),
        generator_version_(std::move(generator_version)),
        functions_(std::move(functions)) {}

  ~profile_recorder() { flush(); }
  profile_recorder(const profile_recorder&) = delete;
  profile_recorder& operator=(const profile_recorder&) = delete;

  void record(int function, std::uint32_t a, std::uint32_t b, std::uint32_t result) {
    const std::lock_guard<std::mutex> lock(mutex_);
    counts_.add(key{function, a, b, result});
  }

  // Adds the counts so far to the profile file and starts counting afresh.
  // Returns false (with a message on stderr) when nothing could be written.
  bool flush() {
    const std::lock_guard<std::mutex> lock(mutex_);
    const char* folder = std::getenv("GAPHYS_PROFILE_DIR");
    if (folder == nullptr || *folder == '\0' || counts_.empty()) return true;
    const std::string path = std::string(folder) + "/" + file_stem_ + ".json";
    const folder_lock held(folder);
    if (!held) {
      std::cerr << "gaphys: cannot use the profile folder " << folder << " ("
                << std::strerror(held.error) << "); profile " << path << " not written\n";
      return false;
    }
    counts merged;
    if (!read_existing(path, merged)) return false;
    bool overflow = false;
    counts_.for_each([&](const key& k, unsigned long long count) {
      const auto& [function, a, b, result] = k;
      overflow = !add(merged[{functions_[function].first, a, b, result}], count) || overflow;
    });
    if (overflow) {
      std::cerr << "gaphys: " << path << ": a count would pass 2^64 - 1; profile not updated\n";
      return false;
    }
    const std::string temporary = path + ".tmp" + std::to_string(::getpid());
    {
      std::ofstream out(temporary, std::ios::trunc);
      write(out, merged);
      out.flush();
      if (!out) {
        const int error = errno;
        std::cerr << "gaphys: cannot write profile " << path << " (" << std::strerror(error)
                  << ")\n";
        std::remove(temporary.c_str());
        return false;
      }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
      const int error = errno;
      std::cerr << "gaphys: cannot replace profile " << path << " (" << std::strerror(error)
                << ")\n";
      std::remove(temporary.c_str());
      return false;
    }
    counts_.clear();
    return true;
  }

 private:
  // function name, argument bitmaps (unused ones 0), result bitmap -> calls
  using counts = std::map<std::tuple<std::string, std::uint32_t, std::uint32_t, std::uint32_t>,
                          unsigned long long>;

  // An exclusive lock on the profile folder for as long as it lives
  // (flock: released when its descriptor closes, the process's end too).
  struct folder_lock {
    explicit folder_lock(const char* folder)
        : descriptor(::open(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
      if (descriptor >= 0) {
        while (::flock(descriptor, LOCK_EX) != 0 && errno == EINTR) {
        }
      }
      error = descriptor < 0 ? errno : 0;
    }
    ~folder_lock() {
      if (descriptor >= 0) ::close(descriptor);
    }
    folder_lock(const folder_lock&) = delete;
    folder_lock& operator=(const folder_lock&) = delete;
    explicit operator bool() const { return descriptor >= 0; }
    int descriptor;
    int error = 0;
  };

  // total += count, false where it would pass 2^64 - 1.
  static bool add(unsigned long long& total, unsigned long long count) {
    if (count > std::numeric_limits<unsigned long long>::max() - total) return false;
    total += count;
    return true;
  }

  int arity(const std::string& name) const {
    for (const auto& [f, n] : functions_)
      if (f == name) return n;
    return -1;
  }

  void write(std::ostream& out, const counts& merged) const {
    out << "{\n  \"format\": \"gaphys-profile\",\n  \"version\": 1,\n  \"algebra\": \"" << algebra_
        << "\",\n  \"spec_hash\": \"" << spec_hash_ << "\",\n  \"generator_version\": \"" << generator_version_
        << "\",\n  \"entries\": [";
    const char* separator = "\n";
    for (const auto& [k, count] : merged) {
      const auto& [function, a, b, result] = k;
      out << separator << "    {\"function\": \"" << function << "\", \"arguments\": [" << a;
      if (arity(function) == 2) out << ", " << b;
      out << "], \"result\": " << result << ", \"count\": " << count << "}";
      separator = ",\n";
    }
    out << (merged.empty() ? "]\n}\n" : "\n  ]\n}\n");
  }

  // Adds the counts of the profile at `path` to `merged`: a missing file is
  // an empty profile. It is read as gaphys-gen reads one (profile.py: the
  // same keys and types, an integer version 1, this algebra and spec), in
  // any layout; a bitmap must fit 32 bits and a count 64 (gaphys-gen allows
  // 128). Anything else leaves the file alone, with a message.
  bool read_existing(const std::string& path, counts& merged) const {
    auto fail = [&](const std::string& why) {
      std::cerr << "gaphys: " << path << ": " << why << "; profile not updated\n";
      return false;
    };
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      if (errno == ENOENT) return true;
      return fail(std::string("cannot read (") + std::strerror(errno) + ")");
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    json::value profile;
    std::string error;
    if (!json::parse(buffer.str(), profile, error)) return fail("malformed JSON at " + error);
    using kind = json::value::kind;
    const auto is_string = [](const json::value* v) {
      return v != nullptr && v->type == kind::string;
    };
    if (profile.type != kind::object) return fail("not a gaphys profile (not a JSON object)");
    const json::value* format = profile.member("format");
    if (!is_string(format) || format->text != "gaphys-profile") return fail("not a gaphys profile");
    const json::value* version = profile.member("version");
    if (version == nullptr || !version->is_unsigned_integer() || version->magnitude != 1) {
      return fail("profile format version not supported (expected 1)");
    }
    for (const auto& [name, unused] : profile.members) {
      (void)unused;
      if (name != "format" && name != "version" && name != "algebra" && name != "spec_hash" &&
          name != "generator_version" && name != "entries") {
        return fail("unknown key \"" + name + "\"");
      }
    }
    if (!is_string(profile.member("generator_version")))
      return fail("\"generator_version\" must be a string");
    const json::value* algebra = profile.member("algebra");
    if (!is_string(algebra) || algebra->text != algebra_) return fail("profile of another algebra");
    const json::value* spec_hash = profile.member("spec_hash");
    if (!is_string(spec_hash) || spec_hash->text != spec_hash_) {
      return fail("profile of another version of the spec");
    }
    const json::value* entries = profile.member("entries");
    if (entries == nullptr || entries->type != kind::array)
      return fail("\"entries\" must be a list");
    for (std::size_t number = 0; number < entries->items.size(); ++number) {
      const json::value& entry = entries->items[number];
      const std::string where = "entry " + std::to_string(number) + ": ";
      if (entry.type != kind::object || entry.members.size() != 4) {
        return fail(where + "needs exactly the keys function, arguments, result, count");
      }
      const json::value* function = entry.member("function");
      const json::value* arguments = entry.member("arguments");
      const json::value* result = entry.member("result");
      const json::value* count = entry.member("count");
      if (!function || !arguments || !result || !count) {
        return fail(where + "needs exactly the keys function, arguments, result, count");
      }
      const int n = is_string(function) ? arity(function->text) : -1;
      if (n < 0) return fail(where + "unknown function");
      if (arguments->type != kind::array || arguments->items.size() != std::size_t(n)) {
        return fail(where + function->text + " takes " + std::to_string(n) + " bitmap argument(s)");
      }
      std::uint32_t bitmaps[3] = {0, 0, 0};  // arguments, then the result
      for (int k = 0; k <= n; ++k) {
        const json::value& bitmap = k < n ? arguments->items[std::size_t(k)] : *result;
        if (!bitmap.is_unsigned_integer() || bitmap.magnitude > 0xFFFFFFFFu) {
          return fail(where + "a bitmap that is not an integer in [0, 2^32)");
        }
        bitmaps[k] = std::uint32_t(bitmap.magnitude);
      }
      if (count->type != kind::integer || count->negative) {
        return fail(where + "count must be a non-negative integer");
      }
      if (count->too_large)
        return fail(where + "a count over 2^64 - 1, more than the recorder can add to");
      const std::uint32_t b = n == 2 ? bitmaps[1] : 0;
      if (!add(merged[{function->text, bitmaps[0], b, bitmaps[n]}], count->magnitude)) {
        return fail("a count would pass 2^64 - 1");
      }
    }
    return true;
  }

  std::string algebra_, file_stem_, spec_hash_, generator_version_;
  std::vector<std::pair<std::string, int>> functions_;  // name, number of mv arguments
  // The counts so far: an open-addressing hash table, as every library call
  // of the instrumented variant adds one (with a std::map, its look-up took
  // a third of an instrumented engine's time). flush() writes them in order,
  // through a std::map.
  class count_table {
   public:
    void add(const key& k) {
      if (2 * (used_ + 1) > slots_.size()) grow();
      ++slots_[find(k)].count;
    }
    bool empty() const { return used_ == 0; }
    void clear() {
      slots_.clear();
      used_ = 0;
    }
    template <class F>
    void for_each(F&& f) const {
      for (const slot& s : slots_)
        if (s.count) f(s.k, s.count);
    }

   private:
    struct slot {
      key k{};
      unsigned long long count = 0;  // 0: empty
    };
    static std::size_t hash(const key& k) {
      const auto& [function, a, b, result] = k;
      std::uint64_t h = (std::uint64_t(std::uint32_t(function)) << 32 | a) * 0x9E3779B97F4A7C15ull;
      h ^= (std::uint64_t(b) << 32 | result) * 0xC2B2AE3D27D4EB4Full;
      return std::size_t(h ^ (h >> 31));
    }
    // The slot holding k, or the empty one where it goes (then taken).
    std::size_t find(const key& k) {
      const std::size_t mask = slots_.size() - 1;
      for (std::size_t i = hash(k) & mask;; i = (i + 1) & mask) {
        if (slots_[i].count == 0) {
          slots_[i].k = k;
          ++used_;
          return i;
        }
        if (slots_[i].k == k) return i;
      }
    }
    void grow() {
      std::vector<slot> old = std::move(slots_);
      slots_.assign(old.empty() ? 256 : 2 * old.size(), slot{});
      used_ = 0;
      for (const slot& s : old)
        if (s.count) slots_[find(s.k)].count = s.count;
    }
    std::vector<slot> slots_;  // a power of two long, at most half full
    std::size_t used_ = 0;
  };
  std::mutex mutex_;
  count_table counts_;
};

}  // namespace gaphys::ga
