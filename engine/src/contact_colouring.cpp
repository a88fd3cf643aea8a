#include "contact_colouring.hpp"

#include <algorithm>

#include "counting_sort.hpp"
#include "thread_count.hpp"

namespace gaphys::detail {

namespace {

// Each coloured run's block (contact_colouring.hpp): the thread whose slab
// of space holds its moving body; 0 for the sequential group's.
void assign_blocks(const std::vector<vector>& positions, int colours, int blocks,
                   contact_colouring& out);

}  // namespace

std::size_t contact_colouring::slab_cut::bin_of(const vector& p) const {
  if (!(span > 0)) return 0;
  // (Written so that a NaN or an infinity, from a world that has blown up,
  // lands in a bin instead of an undefined conversion.)
  const real x = (p.c[axis] - start) / span * real(bins - 1);
  if (!(x < real(bins - 1))) return x > 0 ? bins - 1 : 0;
  return x > 0 ? static_cast<std::size_t>(x) : 0;
}

void colour_contacts(const std::vector<vector>& positions, contact_colouring& out, int threads,
                     int blocks) {
  const std::size_t bodies = out.moves.size();
  constexpr int sequential = contact_colouring::most_colours;
  const std::size_t contacts = out.pairs.size();
  // The runs, in contact order.
  std::vector<std::size_t>& begins = out.run_begins;
  begins.clear();
  for (std::size_t i = 0; i < contacts; ++i) {
    if (i == 0 || out.pairs[i] != out.pairs[i - 1]) begins.push_back(i);
  }
  const std::size_t runs = begins.size();
  begins.push_back(contacts);

  // Greedy colours: the lowest one neither dynamic body has yet.
  out.body_colours.assign(bodies, 0);
  out.run_colours.resize(runs);
  out.colour_counts.assign(sequential + 1, 0);
  for (std::size_t r = 0; r < runs; ++r) {
    const auto [body_a, body_b] = out.pairs[begins[r]];
    // The bodies the solver changes (impulse_row::apply): those with mass.
    const bool moves_a = out.moves[body_a], moves_b = out.moves[body_b];
    const std::uint32_t taken =
        (moves_a ? out.body_colours[body_a] : 0) | (moves_b ? out.body_colours[body_b] : 0);
    int colour = sequential;
    if (taken != ~std::uint32_t{0}) {
      colour = __builtin_ctz(~taken);  // the lowest free colour
      const std::uint32_t bit = std::uint32_t{1} << colour;
      if (moves_a) out.body_colours[body_a] |= bit;
      if (moves_b) out.body_colours[body_b] |= bit;
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
  for (int& colour : out.run_colours) colour = std::min(renamed[colour], kept);

  // Each run's block (0 on one), then one stable counting sort of the runs
  // by (colour, block): runs stay in contact order within a block, and the
  // sequential group (colour `kept`, one block) keeps contact order.
  if (blocks > 1) {
    assign_blocks(positions, kept, blocks, out);
  } else {
    out.run_blocks.assign(runs, 0);
  }
  const std::size_t stride = static_cast<std::size_t>(blocks) + 1;
  const auto key_of = [&](std::size_t r) {
    return static_cast<std::size_t>(out.run_colours[r]) * blocks + out.run_blocks[r];
  };
  std::vector<std::size_t>& key_starts = out.colour_counts;
  out.sorted_runs.resize(runs);
  counting_sort(threads, 8192, runs, static_cast<std::size_t>(kept + 1) * blocks, key_of,
                key_starts, out.sort_scratch,
                [&](std::size_t r, std::size_t at) { out.sorted_runs[at] = r; });
  out.colour_starts.resize(static_cast<std::size_t>(kept) + 1);
  for (int colour = 0; colour <= kept; ++colour) {
    out.colour_starts[colour] = key_starts[static_cast<std::size_t>(colour) * blocks];
  }
  out.thread_starts.assign(blocks > 1 ? static_cast<std::size_t>(kept) * stride : 0, 0);
  for (std::size_t colour = 0; blocks > 1 && colour < static_cast<std::size_t>(kept); ++colour) {
    for (std::size_t b = 0; b <= static_cast<std::size_t>(blocks); ++b) {
      out.thread_starts[colour * stride + b] = key_starts[colour * blocks + b];
    }
  }
  const std::vector<std::size_t>& sorted_runs = out.sorted_runs;

  // Where each run starts in the order, then the order itself (on the
  // threads: each run's contacts are written to their own places).
  out.run_starts.resize(runs + 1);
  out.run_starts[0] = 0;
  for (std::size_t at = 0; at < runs; ++at) {
    const std::size_t r = sorted_runs[at];
    out.run_starts[at + 1] = out.run_starts[at] + (begins[r + 1] - begins[r]);
  }
  out.order.resize(contacts);
  parallel_for(threads, runs, 4096, [&](std::size_t at) {
    const std::size_t r = sorted_runs[at];
    std::size_t to = out.run_starts[at];
    for (std::size_t i = begins[r]; i < begins[r + 1]; ++i) out.order[to++] = i;
  });
}

namespace {

void assign_blocks(const std::vector<vector>& positions, int colours, int blocks,
                   contact_colouring& out) {
  const std::size_t runs = out.run_colours.size();
  const auto coloured = [&](std::size_t r) { return out.run_colours[r] < colours; };
  // Each coloured run's moving body, and the box around those bodies. (Kept
  // in six scalars: as two vectors GCC kept them in memory, and the pass
  // took a tenth of the colouring. Each run's position was copied aside
  // before, 24 bytes a run written and read twice by the one thread that
  // colours while the others prepare: at 10,000 spheres on two threads its
  // task took 0.53-0.54 ms instead of 0.60-0.64.)
  out.movers.resize(runs);
  bool first = true;
  real low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
  for (std::size_t r = 0; r < runs; ++r) {
    if (!coloured(r)) continue;
    const auto [body_a, body_b] = out.pairs[out.run_begins[r]];
    const std::size_t mover = out.moves[body_a] ? body_a : body_b;
    out.movers[r] = static_cast<std::uint32_t>(mover);
    const vector& p = positions[mover];
    for (int k = 0; k < 3; ++k) {
      low[k] = first ? p.c[k] : std::min(low[k], p.c[k]);
      high[k] = first ? p.c[k] : std::max(high[k], p.c[k]);
    }
    first = false;
  }
  const vector extent{high[0] - low[0], high[1] - low[1], high[2] - low[2]};
  const int axis = extent.e1() >= extent.e2() && extent.e1() >= extent.e3() ? 0
                   : extent.e2() >= extent.e3()                             ? 1
                                                                            : 2;
  // The contacts in each of the slices (bins) of the axis, then each run's
  // block: the share its slice falls in.
  contact_colouring::slab_cut& cut = out.slabs;
  cut.axis = axis;
  cut.start = low[axis];
  cut.span = extent.c[axis];
  std::vector<std::size_t>& weight = out.bin_weights;
  weight.assign(contact_colouring::bins + 1, 0);
  out.run_bins.resize(runs);
  for (std::size_t r = 0; r < runs; ++r) {
    if (!coloured(r)) continue;
    const std::size_t bin = cut.bin_of(positions[out.movers[r]]);
    out.run_bins[r] = bin;
    weight[bin + 1] += out.run_begins[r + 1] - out.run_begins[r];
  }
  for (std::size_t b = 1; b <= contact_colouring::bins; ++b) weight[b] += weight[b - 1];
  const std::size_t total = weight.back();
  cut.any = total > 0;
  // Each bin's block: the share of the contacts before it (a division per
  // bin, not per run).
  std::vector<std::uint32_t>& bin_blocks = cut.bin_blocks;
  bin_blocks.resize(contact_colouring::bins);
  for (std::size_t b = 0; b < contact_colouring::bins && total > 0; ++b) {
    const std::size_t share = weight[b] * static_cast<std::size_t>(blocks) / total;
    bin_blocks[b] = static_cast<std::uint32_t>(std::min<std::size_t>(share, blocks - 1));
  }
  // (The sequential group is one block.)
  out.run_blocks.resize(runs);
  for (std::size_t r = 0; r < runs; ++r) {
    out.run_blocks[r] = coloured(r) && total > 0 ? bin_blocks[out.run_bins[r]] : 0;
  }
}

}  // namespace

}  // namespace gaphys::detail
