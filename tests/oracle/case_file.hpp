// Reader for the plain-text case files written by ganja_oracle.mjs
// (format described in README.md next to this file).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace gaphys_oracle {

struct OracleCase {
  int index = 0;
  std::string kind_a, kind_b, kind_v;  // how the inputs were made
  // Keyed by line tag: inputs "a", "b", "v" and results "gp", "op", ...
  // Multivectors hold blade_count coefficients in canonical order.
  std::map<std::string, std::vector<double>> values;

  const std::vector<double>& at(const std::string& key) const;
  std::string label() const;  // "case 12 (mv, blade2, rotor)"
};

struct CaseFile {
  std::string algebra;
  std::string representation;  // "direct" or "dual" (the spec's)
  std::string ganja_version;
  std::vector<std::string> blade_names;
  std::vector<OracleCase> cases;
};

// Throws std::runtime_error naming the file and line on malformed input.
CaseFile read_case_file(const std::string& path);

}  // namespace gaphys_oracle
