#include "case_file.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gaphys_oracle {

namespace {

constexpr int kFormatVersion = 2;

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw std::runtime_error("cannot open oracle case file '" + path + "'");
  }

  // Next non-comment line split into words; false at end of file.
  bool next(std::vector<std::string>& words) {
    std::string text;
    while (std::getline(in_, text)) {
      ++line_;
      if (text.empty() || text[0] == '#') continue;
      std::istringstream split(text);
      words.clear();
      for (std::string w; split >> w;) words.push_back(w);
      if (!words.empty()) return true;
    }
    return false;
  }

  std::vector<std::string> expect(const std::string& tag) {
    std::vector<std::string> words;
    if (!next(words)) fail("unexpected end of file, wanted '" + tag + "'");
    if (words[0] != tag) fail("wanted '" + tag + "', found '" + words[0] + "'");
    return words;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(path_ + ":" + std::to_string(line_) + ": " + what);
  }

  double number(const std::string& word) const {
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if (word.empty() || *end != '\0') fail("not a number: '" + word + "'");
    return x;
  }

  int integer(const std::string& word) const {
    const double x = number(word);
    if (x != static_cast<int>(x)) fail("not an integer: '" + word + "'");
    return static_cast<int>(x);
  }

 private:
  std::string path_;
  std::ifstream in_;
  int line_ = 0;
};

std::string second(Reader& r, const std::string& tag) {
  const auto words = r.expect(tag);
  if (words.size() != 2) r.fail("'" + tag + "' takes one value");
  return words[1];
}

}  // namespace

const std::vector<double>& OracleCase::at(const std::string& key) const {
  const auto it = values.find(key);
  if (it == values.end()) throw std::runtime_error(label() + " has no '" + key + "' line");
  return it->second;
}

std::string OracleCase::label() const {
  return "case " + std::to_string(index) + " (" + kind_a + ", " + kind_b + ", " + kind_v + ")";
}

CaseFile read_case_file(const std::string& path) {
  Reader r(path);
  CaseFile file;
  const int version = r.integer(second(r, "format"));
  if (version != kFormatVersion)
    r.fail("format version " + std::to_string(version) + ", this reader reads version " +
           std::to_string(kFormatVersion) + " (regenerate the case file)");
  file.algebra = second(r, "algebra");
  file.representation = second(r, "representation");
  file.ganja_version = second(r, "ganja");
  r.expect("seed");
  const auto blades = r.expect("blades");
  const auto size = static_cast<std::size_t>(r.integer(blades.at(1)));
  file.blade_names.assign(blades.begin() + 2, blades.end());
  if (file.blade_names.size() != size) r.fail("blade name count differs from blade count");
  const int count = r.integer(second(r, "cases"));

  for (int i = 0; i < count; ++i) {
    const auto head = r.expect("case");
    if (head.size() != 5 || r.integer(head[1]) != i) r.fail("malformed case header");
    OracleCase c;
    c.index = i;
    c.kind_a = head[2];
    c.kind_b = head[3];
    c.kind_v = head[4];
    std::vector<std::string> words;
    while (r.next(words) && words[0] != "end") {
      std::vector<double> xs;
      for (std::size_t k = 1; k < words.size(); ++k) xs.push_back(r.number(words[k]));
      const std::size_t want = words[0] == "scp" ? 1 : size;
      if (xs.size() != want) r.fail("'" + words[0] + "' needs " + std::to_string(want) + " values");
      c.values[words[0]] = xs;
    }
    if (words.empty() || words[0] != "end")
      r.fail("case " + std::to_string(i) + " is not closed by 'end'");
    file.cases.push_back(std::move(c));
  }
  std::vector<std::string> extra;
  if (r.next(extra)) r.fail("trailing content after the last case");
  return file;
}

}  // namespace gaphys_oracle
