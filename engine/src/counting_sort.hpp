// A stable counting sort on the threads: the order is the one thread's
// (items of one key in index order), whatever the number of threads, so
// what is built from it is the same on any number (docs/engine.md,
// "Threads").
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include <omp.h>

#include "thread_count.hpp"

#ifndef _OPENMP
#error "counting_sort.hpp needs OpenMP (without it the threads' shares would be skipped)"
#endif

namespace gaphys::detail {

// Calls place(i, at) once for every item i in [0, count), `at` being its
// place in the order by key(i) (in [0, keys)); sets starts[k] (keys + 1
// entries) to where key k's items begin. On threads_for(threads, count,
// per_thread) threads, each counting and placing a contiguous share of the
// items, and adding up the counts of a share of the keys; or, where there
// are more keys than items, each counting and placing the items of a share
// of the keys. `offsets` is scratch. key(i) is asked twice per item and
// thread.
template <class Key, class Place>
void counting_sort(int threads, std::size_t per_thread, std::size_t count, std::size_t keys,
                   const Key& key, std::vector<std::size_t>& starts,
                   std::vector<std::size_t>& offsets, const Place& place) {
  const int parts = threads_for(threads, count, per_thread);
  if (parts == 1) {
    starts.assign(keys + 1, 0);
    for (std::size_t i = 0; i < count; ++i) ++starts[key(i) + 1];
    for (std::size_t k = 0; k < keys; ++k) starts[k + 1] += starts[k];
    offsets.assign(starts.begin(), starts.end() - 1);
    for (std::size_t i = 0; i < count; ++i) place(i, offsets[key(i)]++);
    return;
  }
  const auto most = static_cast<std::size_t>(parts);
  if (keys > count) {
    // More keys than items (the grid's cells, up to 8 per bound): each
    // thread takes a share of the keys, reads every item's key, and counts
    // and places those in its share; its part of the order is its own.
    // (Split by items, each thread cleared and added up the counts of every
    // key, and read the other's from its core: at 10,000 spheres the grid's
    // sort took as long on two threads as on one.)
    starts.resize(keys + 1);
    offsets.resize(keys + most + 1);
    std::size_t* share_totals = &offsets[keys];
#pragma omp parallel num_threads(parts)
    {
      const auto shares = static_cast<std::size_t>(omp_get_num_threads());
      const auto part = static_cast<std::size_t>(omp_get_thread_num());
      const std::size_t first_key = keys * part / shares, end_key = keys * (part + 1) / shares;
      std::fill(&starts[first_key], &starts[first_key] + (end_key - first_key), std::size_t{0});
      for (std::size_t i = 0; i < count; ++i) {
        const std::size_t k = key(i);
        if (k >= first_key && k < end_key) ++starts[k];
      }
      std::size_t total = 0;
      for (std::size_t k = first_key; k < end_key; ++k) total += starts[k];
      share_totals[part + 1] = total;
#pragma omp barrier
#pragma omp single
      {
        share_totals[0] = 0;
        for (std::size_t p = 0; p < shares; ++p) share_totals[p + 1] += share_totals[p];
      }
      // (single's barrier)
      std::size_t at = share_totals[part];
      for (std::size_t k = first_key; k < end_key; ++k) {
        const std::size_t items = starts[k];
        starts[k] = offsets[k] = at;
        at += items;
      }
      for (std::size_t i = 0; i < count; ++i) {
        const std::size_t k = key(i);
        if (k >= first_key && k < end_key) place(i, offsets[k]++);
      }
    }
    starts[keys] = count;
    return;
  }
  // Part p's count of key k at p * stride + k, each part's counts followed
  // by 128 bytes that no one writes (cache_padded.hpp's reason: with the
  // solver's three keys, the parts' counts shared a line, and every count
  // took it from the other core: 10,000 bodies' sort 113 us on one thread,
  // 104 on two); then, for each thread's share of the keys, how many items
  // they have. (Each thread clears its own counts, on the threads: the
  // grid's sort has up to 8 keys per item.)
  constexpr std::size_t line_gap = 128 / sizeof(std::size_t);
  const std::size_t stride = keys + line_gap;
  starts.resize(keys + 1);
  offsets.resize(most * stride + most + 1);
  std::size_t* key_share_totals = &offsets[most * stride];
#pragma omp parallel num_threads(parts)
  {
    // (As many parts as the threads OpenMP gives: inside an application's
    // own parallel region, one.)
    const auto shares = static_cast<std::size_t>(omp_get_num_threads());
    const auto part = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t first = count * part / shares, end = count * (part + 1) / shares;
    std::size_t* counts = &offsets[part * stride];
    std::fill(counts, counts + keys, std::size_t{0});
    for (std::size_t i = first; i < end; ++i) ++counts[key(i)];
#pragma omp barrier
    // This thread's share of the keys: their items over all parts...
    const std::size_t first_key = keys * part / shares, end_key = keys * (part + 1) / shares;
    std::size_t total = 0;
    for (std::size_t k = first_key; k < end_key; ++k) {
      for (std::size_t p = 0; p < shares; ++p) total += offsets[p * stride + k];
    }
    key_share_totals[part + 1] = total;
#pragma omp barrier
#pragma omp single
    {
      key_share_totals[0] = 0;
      for (std::size_t p = 0; p < shares; ++p) key_share_totals[p + 1] += key_share_totals[p];
    }
    // (single's barrier) ...then where each key, and each part's items of
    // it, begin.
    std::size_t at = key_share_totals[part];
    for (std::size_t k = first_key; k < end_key; ++k) {
      starts[k] = at;
      for (std::size_t p = 0; p < shares; ++p) {
        const std::size_t items = offsets[p * stride + k];
        offsets[p * stride + k] = at;
        at += items;
      }
    }
#pragma omp barrier
    for (std::size_t i = first; i < end; ++i) place(i, counts[key(i)]++);
  }
  starts[keys] = count;
}

}  // namespace gaphys::detail
