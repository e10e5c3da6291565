// For the ThreadSanitizer self-checks: makes the first two bodies of a parallel loop run at the
// same time, hence on two threads (the first one waits for the second), so that a check cannot
// pass because one thread happened to run every body. Relaxed atomics: TSan orders nothing by
// them, so the wait hides no race. Gives up after 10 s (a single-core machine) and returns false.
#pragma once

#include <atomic>
#include <chrono>
#include <thread>

class TwoThreads {
 public:
  /// Call at the start of every body; returns false when no second body came within 10 s.
  bool meet() {
    if (arrived_.fetch_add(1, std::memory_order_relaxed) >= 2) return true;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (arrived_.load(std::memory_order_relaxed) < 2)
      if (std::chrono::steady_clock::now() > give_up) return false;
      else std::this_thread::yield();
    return true;
  }

 private:
  std::atomic<int> arrived_{0};
};
