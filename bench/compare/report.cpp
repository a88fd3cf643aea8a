#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "metrics.hpp"
#include "number.hpp"

namespace gaphys_compare {

namespace {

std::ofstream open(const std::string& path) {
  std::ofstream file(path);
  if (!file) throw std::runtime_error("cannot write " + path);
  return file;
}

std::string cell(const result& r) { return std::isnan(r.value) ? r.note : number(r.value, 4); }

std::string padded(const std::string& text, std::size_t width) {
  return text + std::string(width > text.size() ? width - text.size() : 0, ' ');
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string json_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      quoted += ' ';
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

// JSON has no NaN: a missing number is null.
std::string json_number(double value) { return std::isnan(value) ? "null" : number(value, 17); }

}  // namespace

void print_parameters(std::ostream& out, const std::vector<engine>& engines) {
  for (const engine& e : engines) {
    out << e.name << " " << e.version << ", " << e.precision << "\n";
    for (const parameter& p : e.parameters) {
      out << "  " << p.name << ": " << p.value << "  [" << p.why << "]\n";
    }
  }
  out << "time step h = 1/" << number(1 / time_step)
      << " s, every engine; Bullet and ODE on one thread, gaphys on its threads above\n";
}

void print_table(std::ostream& out, const std::vector<engine>& engines,
                 const std::vector<result>& results) {
  for (const metric& m : all_metrics()) {
    // Rows in the order they were first measured; a cell per engine.
    std::vector<std::pair<std::string, std::string>> rows;
    for (const result& r : results) {
      if (r.metric != m.label || r.detail) continue;
      const std::pair<std::string, std::string> key{r.scenario, r.quantity};
      if (std::find(rows.begin(), rows.end(), key) == rows.end()) rows.push_back(key);
    }
    if (rows.empty()) continue;
    std::vector<std::vector<std::string>> table;
    for (const auto& [scenario, quantity] : rows) {
      std::vector<std::string> line{scenario, quantity};
      for (const engine& e : engines) {
        std::string text = "-";
        for (const result& r : results) {
          if (r.metric == m.label && !r.detail && r.scenario == scenario &&
              r.quantity == quantity && r.engine == e.name) {
            text = cell(r);
          }
        }
        line.push_back(text);
      }
      table.push_back(line);
    }
    std::vector<std::string> header{"scene", "quantity"};
    for (const engine& e : engines) header.push_back(e.name);
    std::vector<std::size_t> widths(header.size());
    for (std::size_t c = 0; c < header.size(); ++c) {
      widths[c] = header[c].size();
      for (const auto& line : table) widths[c] = std::max(widths[c], line[c].size());
    }
    out << "\n" << m.label << "  " << m.title << "\n";
    const auto print_line = [&](const std::vector<std::string>& line) {
      out << " ";
      for (std::size_t c = 0; c < line.size(); ++c) out << " " << padded(line[c], widths[c] + 1);
      out << "\n";
    };
    print_line(header);
    std::string previous;
    for (auto line : table) {
      // Each scene's name on its first row only.
      if (line[0] == previous) {
        line[0] = "";
      } else {
        previous = line[0];
      }
      print_line(line);
    }
  }
}

void write_csv(const std::string& path, const std::vector<result>& results) {
  std::ofstream file = open(path);
  file << "metric,scenario,parameter,quantity,engine,value,note,detail\n";
  for (const result& r : results) {
    file << r.metric << "," << csv_field(r.scenario) << ","
         << (std::isnan(r.parameter) ? "" : number(r.parameter, 17)) << "," << csv_field(r.quantity)
         << "," << r.engine << "," << (std::isnan(r.value) ? "" : number(r.value, 17)) << ","
         << csv_field(r.note) << "," << (r.detail ? 1 : 0) << "\n";
  }
}

void write_json(const std::string& path, const options& o, const std::vector<engine>& engines,
                const std::vector<result>& results) {
  std::ofstream file = open(path);
  file << "{\n  \"time_step\": " << json_number(time_step) << ",\n";
  file << "  \"options\": {\"m1_steps\": " << o.m1_steps << ", \"m6_warmup\": " << o.m6_warmup
       << ", \"m6_steps\": " << o.m6_steps
       << ", \"m6_step_budget\": " << json_number(o.m6_step_budget)
       << ", \"m6_size_budget\": " << json_number(o.m6_size_budget)
       << ", \"stack_seconds\": " << json_number(o.stack_seconds)
       << ", \"b5_warmup\": " << o.b5_warmup << ", \"b5_steps\": " << o.b5_steps
       << ", \"box_budget\": " << json_number(o.box_budget) << "},\n";
  file << "  \"engines\": [";
  for (std::size_t i = 0; i < engines.size(); ++i) {
    const engine& e = engines[i];
    file << (i ? ",\n" : "\n") << "    {\"name\": " << json_string(e.name)
         << ", \"version\": " << json_string(e.version)
         << ", \"precision\": " << json_string(e.precision) << ", \"parameters\": [";
    for (std::size_t j = 0; j < e.parameters.size(); ++j) {
      const parameter& p = e.parameters[j];
      file << (j ? ",\n" : "\n") << "      {\"name\": " << json_string(p.name)
           << ", \"value\": " << json_string(p.value) << ", \"why\": " << json_string(p.why) << "}";
    }
    file << "]}";
  }
  file << "\n  ],\n  \"results\": [";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const result& r = results[i];
    file << (i ? ",\n" : "\n") << "    {\"metric\": " << json_string(r.metric)
         << ", \"scenario\": " << json_string(r.scenario)
         << ", \"parameter\": " << json_number(r.parameter)
         << ", \"quantity\": " << json_string(r.quantity)
         << ", \"engine\": " << json_string(r.engine) << ", \"value\": " << json_number(r.value)
         << ", \"note\": " << json_string(r.note)
         << ", \"detail\": " << (r.detail ? "true" : "false") << "}";
  }
  file << "\n  ]\n}\n";
}

}  // namespace gaphys_compare
