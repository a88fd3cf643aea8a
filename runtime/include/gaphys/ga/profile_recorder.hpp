// The instrumented variant's recorder: counts, per library call, which
// coefficients of the arguments and of the result were really nonzero.
//
// A coefficient counts as nonzero when |c| > 8 eps max|c| of its multivector:
// a coefficient left by cancellation (1e-17 after a rotation) counts as zero.
// At exit, or on flush(), the counts are written as a gaphys profile (see
// generator/gaphys_gen/profile.py) to $GAPHYS_PROFILE_DIR/<namespace>.json,
// added to the counts already in that file. The file is replaced atomically
// (written beside it, then renamed); an existing file that is not a profile of
// the same algebra and spec is left alone, with a message on stderr.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

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
    std::map<std::tuple<std::string, std::uint32_t, std::uint32_t, std::uint32_t>, unsigned long long> merged;
    if (!read_existing(path, merged)) return false;
    counts_.for_each([&](const key& k, unsigned long long count) {
      const auto& [function, a, b, result] = k;
      merged[{functions_[function].first, a, b, result}] += count;
    });
    const std::string temporary = path + ".tmp" + std::to_string(::getpid());
    {
      std::ofstream out(temporary, std::ios::trunc);
      write(out, merged);
      if (!out) {
        std::cerr << "gaphys: cannot write profile " << temporary << "\n";
        std::remove(temporary.c_str());
        return false;
      }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
      std::cerr << "gaphys: cannot replace profile " << path << "\n";
      std::remove(temporary.c_str());
      return false;
    }
    counts_.clear();
    return true;
  }

 private:
  int arity(const std::string& name) const {
    for (const auto& [f, n] : functions_)
      if (f == name) return n;
    return -1;
  }

  void write(std::ostream& out,
             const std::map<std::tuple<std::string, std::uint32_t, std::uint32_t, std::uint32_t>,
                            unsigned long long>& merged) const {
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

  // Reads a profile this recorder (or gaphys-gen merge) wrote. A missing file
  // is an empty profile; anything else unexpected is an error.
  bool read_existing(const std::string& path,
                     std::map<std::tuple<std::string, std::uint32_t, std::uint32_t, std::uint32_t>,
                              unsigned long long>& merged) const {
    std::ifstream in(path);
    if (!in) return true;
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    auto fail = [&](const std::string& why) {
      std::cerr << "gaphys: " << path << ": " << why << "; profile not updated\n";
      return false;
    };
    auto string_field = [&](const std::string& name) -> std::string {
      const std::string tag = "\"" + name + "\": \"";
      const auto at = text.find(tag);
      if (at == std::string::npos) return {};
      const auto end = text.find('"', at + tag.size());
      return end == std::string::npos ? std::string{} : text.substr(at + tag.size(), end - at - tag.size());
    };
    if (text.find("\"format\": \"gaphys-profile\"") == std::string::npos) return fail("not a gaphys profile");
    if (string_field("algebra") != algebra_) return fail("profile of another algebra");
    if (string_field("spec_hash") != spec_hash_) return fail("profile of another version of the spec");
    // Entries: {"function": "gp", "arguments": [a, b], "result": r, "count": n}
    std::size_t at = text.find("\"entries\"");
    while ((at = text.find("{\"function\": \"", at)) != std::string::npos) {
      at += 14;
      const auto name_end = text.find('"', at);
      const std::string function = text.substr(at, name_end - at);
      const int n = arity(function);
      if (n < 0) return fail("unknown function " + function);
      unsigned long long values[4] = {0, 0, 0, 0};
      const char* labels[] = {"\"arguments\": [", "\"result\": ", "\"count\": "};
      std::size_t pos = name_end;
      int read = 0;
      for (int field = 0; field < 3; ++field) {
        pos = text.find(labels[field], pos);
        if (pos == std::string::npos) return fail("malformed entry");
        pos += std::string(labels[field]).size();
        for (int k = 0; k < (field == 0 ? n : 1); ++k) {
          char* end = nullptr;
          values[read++] = std::strtoull(text.c_str() + pos, &end, 10);
          if (end == text.c_str() + pos) return fail("malformed number");
          pos = static_cast<std::size_t>(end - text.c_str());
          if (field == 0 && k + 1 < n) pos = text.find(',', pos) + 1;
        }
      }
      const std::uint32_t a = std::uint32_t(values[0]), b = n == 2 ? std::uint32_t(values[1]) : 0;
      merged[{function, a, b, std::uint32_t(values[n])}] += values[n + 1];
      at = pos;
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
