// Files embedded into the demo at build time (embed.cmake writes their
// definitions from the files CMakeLists.txt names).
#pragma once

#include <string_view>

namespace demo::embedded {

// viewer.html.in: the page --html writes, with the placeholders viewer_page
// fills in.
std::string_view viewer_template();

// three.js's classic build (build/three.min.js, which defines the global
// THREE) from node_modules, or an empty view when the build found none (npm ci
// was not run).
std::string_view three_js();

}  // namespace demo::embedded
