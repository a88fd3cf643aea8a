#include "contact_colouring.hpp"

#include <algorithm>

namespace gaphys::detail {

void colour_contacts(const std::vector<body>& bodies, const std::vector<contact>& contacts,
                     contact_colouring& out) {
  constexpr int sequential = contact_colouring::most_colours;
  // The runs, in contact order.
  std::vector<std::size_t>& begins = out.run_begins;
  begins.clear();
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const bool same_pair = i > 0 && contacts[i].body_a == contacts[i - 1].body_a &&
                           contacts[i].body_b == contacts[i - 1].body_b;
    if (!same_pair) begins.push_back(i);
  }
  const std::size_t runs = begins.size();
  begins.push_back(contacts.size());

  // Greedy colours: the lowest one neither dynamic body has yet.
  out.body_colours.assign(bodies.size(), 0);
  out.run_colours.resize(runs);
  out.colour_counts.assign(sequential + 1, 0);
  for (std::size_t r = 0; r < runs; ++r) {
    const contact& c = contacts[begins[r]];
    // The bodies the solver changes (impulse_row::apply): those with mass.
    const bool moves_a = bodies[c.body_a].inverse_mass() > 0;
    const bool moves_b = bodies[c.body_b].inverse_mass() > 0;
    const std::uint32_t taken = (moves_a ? out.body_colours[c.body_a] : 0) |
                                (moves_b ? out.body_colours[c.body_b] : 0);
    int colour = sequential;
    if (taken != ~std::uint32_t{0}) {
      colour = __builtin_ctz(~taken);  // the lowest free colour
      const std::uint32_t bit = std::uint32_t{1} << colour;
      if (moves_a) out.body_colours[c.body_a] |= bit;
      if (moves_b) out.body_colours[c.body_b] |= bit;
    }
    out.run_colours[r] = colour;
    ++out.colour_counts[colour];
  }
  // Small colours join the sequential group; the others keep their order.
  std::vector<int> renamed(sequential + 1, sequential);
  int kept = 0;
  for (int colour = 0; colour < sequential; ++colour) {
    if (out.colour_counts[colour] >= contact_colouring::fewest_runs) renamed[colour] = kept++;
  }
  for (int& colour : out.run_colours) colour = renamed[colour];

  // Counting sort of the runs by colour, stable.
  std::vector<std::size_t>& counts = out.colour_counts;
  counts.assign(kept + 2, 0);
  for (const int colour : out.run_colours) {
    ++counts[std::min(colour, kept) + 1];
  }
  for (int colour = 0; colour <= kept; ++colour) counts[colour + 1] += counts[colour];
  out.colour_starts.assign(counts.begin(), counts.begin() + kept + 1);
  std::vector<std::size_t>& sorted_runs = out.sorted_runs;
  sorted_runs.resize(runs);
  for (std::size_t r = 0; r < runs; ++r) {
    sorted_runs[counts[std::min(out.run_colours[r], kept)]++] = r;
  }
  out.order.clear();
  out.run_starts.clear();
  for (const std::size_t r : sorted_runs) {
    out.run_starts.push_back(out.order.size());
    for (std::size_t i = begins[r]; i < begins[r + 1]; ++i) out.order.push_back(i);
  }
  out.run_starts.push_back(out.order.size());
}

}  // namespace gaphys::detail
