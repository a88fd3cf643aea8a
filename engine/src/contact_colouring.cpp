#include "contact_colouring.hpp"

#include <algorithm>

#include "counting_sort.hpp"
#include "thread_count.hpp"

namespace gaphys::detail {

namespace {

constexpr std::uint16_t no_bin = 0xffff;

// Each coloured run's block (contact_colouring.hpp): the thread whose slab
// of space holds its moving body; 0 for the sequential group's.
void assign_blocks(const std::vector<vector>& positions, int colours, int blocks,
                   contact_colouring& out);

}  // namespace

std::size_t contact_colouring::slab_cut::bin_of(const vector& p) const {
  if (!(span > 0)) return 0;
  // (Written so that a NaN or an infinity, from a world that has blown up,
  // lands in a bin instead of an undefined conversion.)
  const real x = (p.c[axis] - start) * scale;
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

  // Each run's block and part (0 on one), then one stable counting sort of
  // the runs by (colour, block, part): runs stay in contact order within a
  // part, and the sequential group (colour `kept`, one block) keeps contact
  // order.
  const std::size_t parts = blocks > 1 ? 2 : 1;
  if (blocks > 1) {
    assign_blocks(positions, kept, blocks, out);
  } else {
    out.run_blocks.assign(runs, 0);
  }
  const std::size_t stride = static_cast<std::size_t>(blocks) + 1;
  const std::size_t per_colour = static_cast<std::size_t>(blocks) * parts;
  const auto key_of = [&](std::size_t r) {
    return static_cast<std::size_t>(out.run_colours[r]) * per_colour + out.run_blocks[r];
  };
  std::vector<std::size_t>& key_starts = out.colour_counts;
  out.sorted_runs.resize(runs);
  counting_sort(threads, 8192, runs, static_cast<std::size_t>(kept + 1) * per_colour, key_of,
                key_starts, out.sort_scratch,
                [&](std::size_t r, std::size_t at) { out.sorted_runs[at] = r; });
  out.colour_starts.resize(static_cast<std::size_t>(kept) + 1);
  for (int colour = 0; colour <= kept; ++colour) {
    out.colour_starts[colour] = key_starts[static_cast<std::size_t>(colour) * per_colour];
  }
  const std::size_t coloured_blocks = blocks > 1 ? static_cast<std::size_t>(kept) : 0;
  out.thread_starts.assign(coloured_blocks * stride, 0);
  out.shared_ends.assign(coloured_blocks * blocks, 0);
  for (std::size_t colour = 0; colour < coloured_blocks; ++colour) {
    for (std::size_t b = 0; b <= static_cast<std::size_t>(blocks); ++b) {
      const std::size_t key = (colour * blocks + b) * parts;
      out.thread_starts[colour * stride + b] = key_starts[key];
      if (b < static_cast<std::size_t>(blocks))
        out.shared_ends[colour * blocks + b] = key_starts[key + 1];
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
  // Also its other body, where that has mass (else `bodies`, a slot no
  // body has).
  const std::size_t bodies = out.moves.size();
  out.movers.resize(runs);
  out.partners.resize(runs);
  bool first = true;
  real low[3] = {0, 0, 0}, high[3] = {0, 0, 0};
  for (std::size_t r = 0; r < runs; ++r) {
    if (!coloured(r)) continue;
    const auto [body_a, body_b] = out.pairs[out.run_begins[r]];
    const std::size_t mover = out.moves[body_a] ? body_a : body_b;
    out.movers[r] = static_cast<std::uint32_t>(mover);
    out.partners[r] =
        static_cast<std::uint32_t>(mover == body_a && out.moves[body_b] ? body_b : bodies);
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
  // block: the share its slice falls in. Also, for each body, the lowest
  // and the highest bin of the runs that move it as their partner.
  contact_colouring::slab_cut& cut = out.slabs;
  cut.axis = axis;
  cut.start = low[axis];
  cut.span = extent.c[axis];
  // (A product per run, not a quotient: a sixth of this pass.)
  cut.scale = cut.span > 0 ? real(contact_colouring::bins - 1) / cut.span : real(0);
  std::vector<std::size_t>& weight = out.bin_weights;
  weight.assign(contact_colouring::bins + 1, 0);
  out.run_bins.resize(runs);
  // (A run's mover, often the same from run to run, would chain each
  // update of its lowest and highest bin to the last through memory: its
  // bin is only stored. The partners differ from run to run.)
  std::vector<std::uint16_t>& own = out.own_bins;
  std::vector<std::uint16_t>& lowest = out.lowest_bins;
  std::vector<std::uint16_t>& highest = out.highest_bins;
  static_assert(contact_colouring::bins < 65536);
  own.assign(bodies + 1, no_bin);
  lowest.assign(bodies + 1, contact_colouring::bins - 1);
  highest.assign(bodies + 1, 0);
  // (Runs in a row mostly share a bin, their movers being neighbours: the
  // contacts of a row of runs of one bin are added up here and added to
  // its weight once, not each to the last through memory.)
  std::size_t row_bin = 0, row_weight = 0;
  for (std::size_t r = 0; r < runs; ++r) {
    if (!coloured(r)) continue;
    const auto bin = static_cast<std::uint16_t>(cut.bin_of(positions[out.movers[r]]));
    out.run_bins[r] = bin;
    if (bin != row_bin) {
      weight[row_bin + 1] += row_weight;
      row_bin = bin;
      row_weight = 0;
    }
    row_weight += out.run_begins[r + 1] - out.run_begins[r];
    own[out.movers[r]] = bin;
    const std::size_t partner = out.partners[r];
    lowest[partner] = std::min(lowest[partner], bin);
    highest[partner] = std::max(highest[partner], bin);
  }
  weight[row_bin + 1] += row_weight;
  lowest[bodies] = highest[bodies] = 0;  // (no body: one bin)
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
  // Whether runs of two blocks move each body: the blocks of its bins as
  // mover and as partner differ (the blocks follow the bins in order).
  // Then each run's block and part (the sequential group is one block):
  // shared where one of its moving bodies is moved by two.
  std::vector<char>& spans_blocks = out.spans_blocks;
  spans_blocks.resize(bodies + 1);
  for (std::size_t x = 0; x <= bodies; ++x) {
    const std::uint16_t first = own[x] == no_bin ? lowest[x] : std::min(own[x], lowest[x]);
    const std::uint16_t last = own[x] == no_bin ? highest[x] : std::max(own[x], highest[x]);
    spans_blocks[x] = first <= last && bin_blocks[first] != bin_blocks[last];
  }
  out.run_blocks.resize(runs);
  for (std::size_t r = 0; r < runs; ++r) {
    if (!coloured(r) || total == 0) {
      out.run_blocks[r] = contact_colouring::own_runs;  // (block 0)
      continue;
    }
    const bool shared = spans_blocks[out.movers[r]] | spans_blocks[out.partners[r]];
    out.run_blocks[r] = 2 * bin_blocks[out.run_bins[r]] +
                        (shared ? contact_colouring::shared_runs : contact_colouring::own_runs);
  }
}

}  // namespace

}  // namespace gaphys::detail
