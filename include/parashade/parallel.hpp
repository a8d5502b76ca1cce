#pragma once
// Host parallelism for the software stages (vertex stage, setup, binning, reference). Workers block
// on a condition variable between jobs: PoCL runs its kernels on the same cores, and spinning host
// threads (OpenMP's default) measurably slowed the kernels they wait for. A short spin before blocking
// (PARASHADE_HOST_SPIN_US, default 0) did not pay either (parallel.cpp); parallel_rest() ends it at
// once, for a caller about to hand the cores to the device.
#include <algorithm>
#include <cstddef>
#include <functional>

namespace parashade {

// Number of host threads: set_host_threads() if called, else PARASHADE_HOST_THREADS if set (1..1024; any
// other value is a UsageError naming it, environment.hpp),
// else the hardware's.
unsigned host_threads();
// Changes the number of host threads (not while a parallel_for runs).
void set_host_threads(unsigned threads);

// Calls body(i) for every i in [0, count), spread over host_threads() threads (the caller is one of
// them), and returns when all are done. Items are taken in increasing order from a shared counter;
// results must not depend on which thread runs an item. Exceptions from body are rethrown (the first).
void parallel_for(std::size_t count, const std::function<void(std::size_t)>& body);

// parallel_for when `worth_waking`, else the same calls in order on the calling thread: a job of a
// tenth of a millisecond or less finishes sooner without waking a worker and waiting for it.
inline void parallel_for_if(bool worth_waking, std::size_t count, const std::function<void(std::size_t)>& body) {
  if (worth_waking) return parallel_for(count, body);
  for (std::size_t i = 0; i < count; ++i) body(i);
}

// Idle workers stop spinning and block until the next parallel_for.
void parallel_rest();

// A range size for parallel_for_ranges: about four ranges per thread (dynamic balance on cores shared
// with other work), each of at least min_chunk items (a range is worth a wake-up: fewer than 2 ranges
// run on the calling thread alone) and at most max_chunk; equal ranges, so none is a small remainder.
inline std::size_t balanced_chunk(std::size_t count, std::size_t min_chunk, std::size_t max_chunk) {
  if (count == 0) return std::max<std::size_t>(1, min_chunk);
  const std::size_t at_most_min = std::max<std::size_t>(1, count / std::max<std::size_t>(1, min_chunk));
  const std::size_t at_least_max = (count + max_chunk - 1) / std::max<std::size_t>(1, max_chunk);
  const std::size_t ranges = std::max(std::min(4 * std::size_t(host_threads()), at_most_min), at_least_max);
  return (count + ranges - 1) / ranges;
}

// Calls body(begin, end) on consecutive ranges of at most `chunk` items covering [0, count).
inline void parallel_for_ranges(std::size_t count, std::size_t chunk,
                                const std::function<void(std::size_t, std::size_t)>& body) {
  const std::size_t ranges = (count + chunk - 1) / chunk;
  parallel_for(ranges, [&](std::size_t r) { body(r * chunk, std::min(count, (r + 1) * chunk)); });
}

}  // namespace parashade
