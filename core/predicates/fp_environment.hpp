// The floating-point environment every certified computation of exactccd assumes, and the guard
// that sets it on entry to the library and gives the caller's back on every return.
//
// What the proofs assume (PROOF: proofs/filters.md#fp-environment): IEEE 754 binary64 arithmetic
// with the rounding the code asks for (to nearest, or towards +infinity for interval
// arithmetic), gradual underflow (no flush-to-zero of results, no denormals-are-zero on
// operands), and no trap on any exception (overflow to infinity and invalid operations are
// values the filters detect). A host process may run with any of these changed: builds with
// -ffast-math / -Ofast set flush-to-zero and denormals-are-zero at start-up (crtfastmath.o),
// some simulators unmask exceptions to catch NaNs. The guard saves the whole control and
// status register, sets exactly the state above, and restores the saved register on
// destruction, so the caller's modes and its sticky exception flags are both left untouched.
//
// Every header holding certified floating-point code includes this one: it also refuses to be
// compiled with -ffast-math, under which no bound of proofs/ holds.
#pragma once

#if defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)
#error "exactccd: certified code needs -ffp-contract=off -frounding-math -fno-fast-math, \
not -ffast-math or -ffinite-math-only (proofs/filters.md#fp-environment)"
#endif

#include <cstdint>

#if defined(__x86_64__) || defined(_M_X64) || (defined(__i386__) && defined(__SSE2_MATH__))
#include <xmmintrin.h>
#define EXACTCCD_FP_MXCSR 1
#elif defined(__aarch64__)
#define EXACTCCD_FP_AARCH64 1
#else
#include <cfenv>
#define EXACTCCD_FP_FENV 1
#endif

/// The linkage of every free function holding certified floating-point code: internal, so that
/// no copy of it compiled elsewhere without the FP flags (a weak inline symbol of another
/// translation unit) can replace this one at link time.
#define EXACTCCD_CERTIFIED static inline

namespace exactccd::predicates {

enum class Rounding : std::uint8_t { to_nearest, upward };

#if defined(EXACTCCD_FP_MXCSR)

namespace mxcsr {
constexpr unsigned kRoundToNearest = 0x0000;
constexpr unsigned kRoundUpward = 0x4000;
constexpr unsigned kAllExceptionsMasked = 0x1f80;  // IM DM ZM OM UM PM; FTZ (0x8000), DAZ (0x40)
                                                   // and the sticky flags (0x3f) all clear
constexpr unsigned kStickyFlags = 0x3f;            // IE DE ZE OE UE PE
}  // namespace mxcsr

/// Holds the environment the proofs assume for its lifetime (one thread: MXCSR is per thread).
class FpEnvironmentGuard {
 public:
  /// Writes the register only when its control bits differ from those asked for (an ldmxcsr
  /// costs about as much as a filtered query's arithmetic); the caller's sticky flags are kept,
  /// the library never reads them.
  explicit FpEnvironmentGuard(Rounding rounding) noexcept : saved_(_mm_getcsr()) {
    const unsigned wanted =
        mxcsr::kAllExceptionsMasked |
        (rounding == Rounding::upward ? mxcsr::kRoundUpward : mxcsr::kRoundToNearest) |
        (saved_ & mxcsr::kStickyFlags);
    if (wanted != saved_) _mm_setcsr(wanted);
  }
  /// The caller's register back, bit for bit (flags raised inside the library included). An
  /// unconditional write: reading the register first to skip it would wait for every floating-
  /// point operation in flight (the flags), which costs more than the write.
  ~FpEnvironmentGuard() { _mm_setcsr(saved_); }
  FpEnvironmentGuard(const FpEnvironmentGuard&) = delete;
  FpEnvironmentGuard& operator=(const FpEnvironmentGuard&) = delete;

 private:
  unsigned saved_;
};

/// The SSE control and status register as the hardware holds it (tests read it directly:
/// glibc's fegetround reads the x87 control word on x86-64 and cannot see an MXCSR mode).
inline unsigned raw_fp_control() noexcept { return _mm_getcsr(); }
inline void set_raw_fp_control(unsigned value) noexcept { _mm_setcsr(value); }

#elif defined(EXACTCCD_FP_AARCH64)

// FPCR: RMode bits 22-23 (00 nearest, 01 towards +infinity), FZ bit 24, FZ16 bit 19, trap
// enables bits 8-12 and 15, AH/FIZ bits 0-1 (FEAT_AFP): all cleared but the rounding.
namespace fpcr {
constexpr std::uint64_t kRoundUpward = std::uint64_t{1} << 22;
constexpr std::uint64_t kControlled = (std::uint64_t{3} << 22) | (std::uint64_t{1} << 24) |
                                      (std::uint64_t{1} << 19) | (std::uint64_t{0x1f} << 8) |
                                      (std::uint64_t{1} << 15) | std::uint64_t{3};
}  // namespace fpcr

class FpEnvironmentGuard {
 public:
  explicit FpEnvironmentGuard(Rounding rounding) noexcept {
    asm volatile("mrs %0, fpcr" : "=r"(saved_fpcr_));
    asm volatile("mrs %0, fpsr" : "=r"(saved_fpsr_));
    const std::uint64_t fpcr = (saved_fpcr_ & ~fpcr::kControlled) |
                               (rounding == Rounding::upward ? fpcr::kRoundUpward : 0);
    asm volatile("msr fpcr, %0" : : "r"(fpcr));
  }
  ~FpEnvironmentGuard() {
    asm volatile("msr fpcr, %0" : : "r"(saved_fpcr_));
    asm volatile("msr fpsr, %0" : : "r"(saved_fpsr_));
  }
  FpEnvironmentGuard(const FpEnvironmentGuard&) = delete;
  FpEnvironmentGuard& operator=(const FpEnvironmentGuard&) = delete;

 private:
  std::uint64_t saved_fpcr_ = 0, saved_fpsr_ = 0;
};

inline unsigned raw_fp_control() noexcept {
  std::uint64_t v;
  asm volatile("mrs %0, fpcr" : "=r"(v));
  return static_cast<unsigned>(v);
}
inline void set_raw_fp_control(unsigned value) noexcept {
  const std::uint64_t v = value;
  asm volatile("msr fpcr, %0" : : "r"(v));
}

#else

// Portable fallback: the rounding mode and the exception state through <cfenv>. It cannot clear
// a flush-to-zero mode it does not know of; the README names the supported targets.
class FpEnvironmentGuard {
 public:
  explicit FpEnvironmentGuard(Rounding rounding) noexcept {
    std::feholdexcept(&saved_);  // saves the environment, clears flags, non-stop mode
    std::fesetround(rounding == Rounding::upward ? FE_UPWARD : FE_TONEAREST);
  }
  ~FpEnvironmentGuard() { std::fesetenv(&saved_); }
  FpEnvironmentGuard(const FpEnvironmentGuard&) = delete;
  FpEnvironmentGuard& operator=(const FpEnvironmentGuard&) = delete;

 private:
  std::fenv_t saved_;
};

#endif

/// Round to nearest, no flush-to-zero, no denormals-are-zero, exceptions masked: what every entry
/// point of the library and every parallel body it runs computes under (a TBB worker may run
/// with the host's FP state); the caller's whole FP state is restored on every return,
/// exceptions included. PROOF: proofs/filters.md#fp-environment
class RoundToNearestGuard : FpEnvironmentGuard {
 public:
  RoundToNearestGuard() noexcept : FpEnvironmentGuard(Rounding::to_nearest) {}
};

#if defined(__i386__) || defined(__x86_64__)
/// The x87 unit (long double): the wide-range interval filter of the exact stage
/// (exact/arithmetic/wide_interval.hpp) computes its bounds in extended precision, rounding upward.
/// A caller's unmasked x87 exception would trap there, and its precision or rounding control would
/// break the bounds: all masked, 64-bit precision, the requested rounding (to nearest by
/// default); the caller's control word and sticky flags are restored on return.
class X87EnvironmentGuard {
 public:
  explicit X87EnvironmentGuard(Rounding rounding = Rounding::to_nearest) noexcept {
    asm volatile("fnstenv %0" : "=m"(saved_) : : "memory");  // also masks all x87 exceptions
    // Exceptions masked (0x3f), 64-bit precision (0x300), rounding control 00 or 10 (up).
    const std::uint16_t wanted = rounding == Rounding::upward ? 0x0b7f : 0x037f;
    asm volatile("fldcw %0" : : "m"(wanted) : "memory");
  }
  /// Restores the caller's control word and status flags, but not the tag word nor the stack
  /// top: those describe the register stack as it is now (the compiler may keep long doubles
  /// in x87 registers across this point; an old tag word would mark them empty, and the next
  /// push would then overflow the stack into the indefinite NaN).
  ~X87EnvironmentGuard() {
    Environment now;
    asm volatile("fnstenv %0" : "=m"(now) : : "memory");
    now.words[0] = saved_.words[0];                                    // control word
    now.words[1] = (saved_.words[1] & ~kTop) | (now.words[1] & kTop);  // flags, current top
    asm volatile("fldenv %0" : : "m"(now) : "memory");
  }
  X87EnvironmentGuard(const X87EnvironmentGuard&) = delete;
  X87EnvironmentGuard& operator=(const X87EnvironmentGuard&) = delete;

 private:
  static constexpr std::uint32_t kTop = 0x3800;  // status word bits 11-13
  struct Environment {
    std::uint32_t words[7];  // the 28-byte protected-mode x87 environment
  };
  Environment saved_{};
};
#else
struct X87EnvironmentGuard {
  explicit X87EnvironmentGuard(Rounding = Rounding::to_nearest) noexcept {}
};
#endif

}  // namespace exactccd::predicates
