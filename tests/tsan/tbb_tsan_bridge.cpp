// Makes Debian's libtbb (not built with ThreadSanitizer) visible to ThreadSanitizer, so that a
// TSan report in a TBB program is a race in our code, not TBB's hidden synchronisation.
//
// libtbb hands a task to another thread, and a pooled task object's memory to the next task,
// through its own atomics, which TSan cannot see: it then reports our data written before a
// parallel_for and read by its bodies (and TBB's task objects) as races. This library supplies
// the two edges TSan misses, as release/acquire on the object's address:
//  - as an ITT collector (INTEL_LIBITTNOTIFY64=<this library>, INTEL_ITTNOTIFY_GROUPS=sync):
//    libtbb and TBB's headers compiled with TBB_USE_PROFILING_TOOLS=2 (cmake/Sanitizers.cmake)
//    announce every hand-off as __itt_sync_releasing / __itt_sync_acquired, the annotations
//    TBB carries for Intel's race detector;
//  - preloaded (LD_PRELOAD=<this library>), it wraps libtbb's small-object pool: deallocate
//    releases the block, allocate acquires it, as a malloc does for TSan.
// Bodies stay unordered among themselves: a race between two of them is still reported.
// .ci/sanitizers.sh sets the three variables. In a process without TSan (a shell started by a
// test) the TSan entry points are absent and this library only forwards.
#include <dlfcn.h>

#include <cstddef>

namespace tbb::detail {
namespace d1 {
class small_object_pool;
struct execution_data;
}  // namespace d1
}  // namespace tbb::detail

extern "C" {
void __tsan_acquire(void* address) __attribute__((weak));
void __tsan_release(void* address) __attribute__((weak));

void __itt_sync_acquired(void* address) {
  if (__tsan_acquire) __tsan_acquire(address);
}
void __itt_sync_releasing(void* address) {
  if (__tsan_release) __tsan_release(address);
}
// Marks this library as an ITT collector whose functions are looked up one by one.
const char* __itt_api_version() { return "exactccd tbb_tsan_bridge"; }
}

namespace {

template <typename Function>
Function next(const char* mangled_name) {
  return reinterpret_cast<Function>(dlsym(RTLD_NEXT, mangled_name));
}

}  // namespace

namespace tbb::detail::r1 {

using d1::execution_data;
using d1::small_object_pool;

void* allocate(small_object_pool*& pool, std::size_t bytes, const execution_data& ed) {
  static const auto real = next<void* (*)(small_object_pool*&, std::size_t, const execution_data&)>(
      "_ZN3tbb6detail2r18allocateERPNS0_2d117small_object_poolEmRKNS2_14execution_dataE");
  void* block = real(pool, bytes, ed);
  __itt_sync_acquired(block);
  return block;
}

void* allocate(small_object_pool*& pool, std::size_t bytes) {
  static const auto real = next<void* (*)(small_object_pool*&, std::size_t)>(
      "_ZN3tbb6detail2r18allocateERPNS0_2d117small_object_poolEm");
  void* block = real(pool, bytes);
  __itt_sync_acquired(block);
  return block;
}

void deallocate(small_object_pool& pool, void* block, std::size_t bytes, const execution_data& ed) {
  static const auto real =
      next<void (*)(small_object_pool&, void*, std::size_t, const execution_data&)>(
          "_ZN3tbb6detail2r110deallocateERNS0_2d117small_object_poolEPvmRKNS2_14execution_dataE");
  __itt_sync_releasing(block);
  real(pool, block, bytes, ed);
}

void deallocate(small_object_pool& pool, void* block, std::size_t bytes) {
  static const auto real = next<void (*)(small_object_pool&, void*, std::size_t)>(
      "_ZN3tbb6detail2r110deallocateERNS0_2d117small_object_poolEPvm");
  __itt_sync_releasing(block);
  real(pool, block, bytes);
}

}  // namespace tbb::detail::r1
