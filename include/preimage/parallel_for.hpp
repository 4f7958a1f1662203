// SPDX-License-Identifier: Apache-2.0
// A strided parallel loop over indices 0..n-1 on short-lived threads: the per-vertex and
// per-level passes of the shortest path map, the visibility graph and the wave-front
// decomposition. (compute_many has its own persistent pool: its batches are too short for
// thread start-up.)
#pragma once
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace preimage {

/// Runs body(k) for every k in [0, n), thread t taking k = t, t + threads, ...; with
/// threads <= 1 on the calling thread. The first exception a thread throws is rethrown
/// once all have joined.
template <class Body>
void parallel_for(std::size_t n, unsigned threads, Body&& body) {
  if (threads <= 1) {
    for (std::size_t k = 0; k < n; ++k) body(k);
    return;
  }
  std::vector<std::thread> pool;
  std::exception_ptr error;
  std::mutex guard;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      try {
        for (std::size_t k = t; k < n; k += threads) body(k);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(guard);
        if (!error) error = std::current_exception();
      }
    });
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace preimage
