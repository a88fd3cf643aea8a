#include "contact_colouring.hpp"

#include <algorithm>

#include "thread_count.hpp"

namespace gaphys::detail {

void colour_contacts(const std::vector<body>& bodies, const std::vector<contact>& contacts,
                     contact_colouring& out, int threads) {
  constexpr int sequential = contact_colouring::most_colours;
  // Each contact's bodies, and which bodies have mass, read in one pass
  // each on the threads (contacts and bodies are large objects, and the
  // greedy colouring below cannot be shared out).
  out.pairs.resize(contacts.size());
  parallel_for(threads, contacts.size(), 4096, [&](std::size_t i) {
    out.pairs[i] = {contacts[i].body_a, contacts[i].body_b};
  });
  out.moves.resize(bodies.size());
  parallel_for(threads, bodies.size(), 4096,
               [&](std::size_t i) { out.moves[i] = bodies[i].inverse_mass() > 0; });
  // The runs, in contact order.
  std::vector<std::size_t>& begins = out.run_begins;
  begins.clear();
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    if (i == 0 || out.pairs[i] != out.pairs[i - 1]) begins.push_back(i);
  }
  const std::size_t runs = begins.size();
  begins.push_back(contacts.size());

  // Greedy colours: the lowest one neither dynamic body has yet.
  out.body_colours.assign(bodies.size(), 0);
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

void split_colours(const std::vector<body>& bodies, int threads, contact_colouring& out) {
  const std::size_t coloured_runs = out.colour_starts.back();
  // Each run's moving body's position (colour_contacts left out.moves), on
  // the threads: a look-up in the contacts and one in the bodies per run.
  out.positions.resize(coloured_runs);
  parallel_for(threads, coloured_runs, 2048, [&](std::size_t run) {
    const auto [body_a, body_b] = out.pairs[out.order[out.run_starts[run]]];
    out.positions[run] = bodies[out.moves[body_a] ? body_a : body_b].position();
  });
  const auto position_of = [&](std::size_t run) { return out.positions[run]; };
  // The axis along which the runs' bodies spread most.
  vector low = coloured_runs > 0 ? position_of(0) : vector{};
  vector high = low;
  for (std::size_t run = 0; run < coloured_runs; ++run) {
    const vector p = position_of(run);
    low = vector{std::min(low.e1(), p.e1()), std::min(low.e2(), p.e2()), std::min(low.e3(), p.e3())};
    high = vector{std::max(high.e1(), p.e1()), std::max(high.e2(), p.e2()), std::max(high.e3(), p.e3())};
  }
  const vector extent = high - low;
  const int axis = extent.e1() >= extent.e2() && extent.e1() >= extent.e3() ? 0
                   : extent.e2() >= extent.e3()                             ? 1
                                                                            : 2;
  const auto along = [axis](const vector& v) {
    return axis == 0 ? v.e1() : axis == 1 ? v.e2() : v.e3();
  };
  // The contacts in each of `bins` slices of the axis, then each run's
  // thread: the share its slice falls in.
  constexpr std::size_t bins = 1024;
  const real start = along(low), span = along(extent);
  std::vector<std::size_t>& weight = out.bin_weights;
  weight.assign(bins + 1, 0);
  out.run_bins.resize(coloured_runs);
  for (std::size_t run = 0; run < coloured_runs; ++run) {
    std::size_t bin = 0;
    if (span > 0) {
      // (Written so that a NaN or an infinity, from a world that has blown
      // up, lands in a bin instead of an undefined conversion.)
      const real x = (along(position_of(run)) - start) / span * real(bins - 1);
      if (!(x < real(bins - 1))) {
        bin = x > 0 ? bins - 1 : 0;
      } else if (x > 0) {
        bin = static_cast<std::size_t>(x);
      }
    }
    out.run_bins[run] = bin;
    weight[bin + 1] += out.run_starts[run + 1] - out.run_starts[run];
  }
  for (std::size_t b = 1; b <= bins; ++b) weight[b] += weight[b - 1];
  const std::size_t total = weight.back();
  const auto thread_of = [&](std::size_t run) {
    const std::size_t share = total == 0 ? 0 : weight[out.run_bins[run]] * threads / total;
    return std::min<std::size_t>(share, threads - 1);
  };

  // Each colour's runs by thread (a stable counting sort), in contact order
  // within a thread; the sequential group as it was.
  out.run_threads.resize(coloured_runs);
  for (std::size_t run = 0; run < coloured_runs; ++run) out.run_threads[run] = thread_of(run);
  const std::size_t stride = static_cast<std::size_t>(threads) + 1;
  out.thread_starts.assign(out.colours() * stride, 0);
  out.sorted_runs.resize(coloured_runs);
  for (std::size_t colour = 0; colour < out.colours(); ++colour) {
    const std::size_t first = out.colour_starts[colour], end = out.colour_starts[colour + 1];
    std::size_t* starts = &out.thread_starts[colour * stride];
    for (std::size_t run = first; run < end; ++run) ++starts[out.run_threads[run] + 1];
    starts[0] = first;
    for (int t = 0; t < threads; ++t) starts[t + 1] += starts[t];
    weight.assign(starts, starts + threads);  // each thread's next place
    for (std::size_t run = first; run < end; ++run) {
      out.sorted_runs[weight[out.run_threads[run]]++] = run;
    }
  }
  out.split_order.clear();
  out.split_run_starts.clear();
  const auto append = [&](std::size_t run) {
    out.split_run_starts.push_back(out.split_order.size());
    for (std::size_t i = out.run_starts[run]; i < out.run_starts[run + 1]; ++i) {
      out.split_order.push_back(out.order[i]);
    }
  };
  for (std::size_t at = 0; at < coloured_runs; ++at) append(out.sorted_runs[at]);
  for (std::size_t run = coloured_runs; run < out.runs(); ++run) append(run);
  out.split_run_starts.push_back(out.split_order.size());
  out.order.swap(out.split_order);
  out.run_starts.swap(out.split_run_starts);
}

}  // namespace gaphys::detail
