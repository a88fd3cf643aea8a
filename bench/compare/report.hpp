// The results as a terminal table, a CSV file and a JSON file. The table
// shows one row per scene and quantity with a column per engine; the files
// hold every number, details included, and the settings that produced them.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "engine_adapter.hpp"
#include "options.hpp"
#include "result.hpp"

namespace gaphys_compare {

void print_parameters(std::ostream& out, const std::vector<engine>& engines);
void print_table(std::ostream& out, const std::vector<engine>& engines,
                 const std::vector<result>& results);
void write_csv(const std::string& path, const std::vector<result>& results);
void write_json(const std::string& path, const options& o, const std::vector<engine>& engines,
                const std::vector<result>& results);

}  // namespace gaphys_compare
