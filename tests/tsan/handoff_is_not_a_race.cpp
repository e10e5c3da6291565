// Self-check of the ThreadSanitizer setup (tests/tsan/CMakeLists.txt): data written before
// each parallel_for and read by its bodies, results written by the bodies and read after it,
// task objects recycled by TBB's pool over many loops, with at least two threads running
// bodies in every loop. No race: TSan must stay silent, which it does only when TBB's
// hand-offs are visible to it (tbb_tsan_bridge.cpp).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdio>
#include <vector>

#include "two_threads.hpp"

int main() {
  std::vector<double> data(1 << 14, 1.0), out(data.size());
  double total = 0.0;
  constexpr int kLoops = 50;
  for (int loop = 0; loop < kLoops; ++loop) {
    for (double& d : data) d += 1.0;
    TwoThreads two;
    std::atomic<bool> met{true};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, data.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        if (!two.meet()) met = false;
                        for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = 2.0 * data[i];
                      });
    if (!met) return 2;
    for (const double x : out) total += x;
  }
  // Loop k (1-based) writes 2 (1 + k) into every element.
  const double expected = 2.0 * (kLoops + kLoops * (kLoops + 1) / 2.0) * data.size();
  std::printf("total %g, expected %g\n", total, expected);
  return total == expected ? 0 : 1;
}
