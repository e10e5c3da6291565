// Self-check of the ThreadSanitizer setup (tests/tsan/CMakeLists.txt): two parallel_for bodies,
// on two threads at once, add to one double without synchronisation. TSan must report the race,
// in this file: with TBB's synchronisation made visible (tbb_tsan_bridge.cpp), races between
// bodies must still be seen.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdio>

#include "two_threads.hpp"

int main() {
  double sum = 0.0;
  TwoThreads two;
  std::atomic<bool> met{true};
  tbb::parallel_for(tbb::blocked_range<int>(0, 2, 1), [&](const tbb::blocked_range<int>& r) {
    sum += r.size();  // the race
    if (!two.meet()) met = false;
  });
  std::printf("sum %g\n", sum);
  return met ? 0 : 2;
}
