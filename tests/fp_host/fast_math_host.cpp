// A host process built the way many simulators are: this file is compiled and linked with
// -Ofast, so crtfastmath.o sets flush-to-zero and denormals-are-zero in MXCSR at start-up. It
// includes only the public headers and calls the library as such a host would. The library must
// still give the exact answer (its entry points set the state the proofs assume) and leave the
// host's state as it found it. Exit 0 on success, 1 on a wrong answer, 2 when the host state is
// not what this test needs (so the test cannot pass without exercising anything).
#include <cstdio>
#include <cstring>

#include <xmmintrin.h>

#include "exactccd/ccd.hpp"
#include "issue9_query.hpp"

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

int main() {
  const unsigned at_start = _mm_getcsr();
  if ((at_start & 0x8040u) != 0x8040u) {
    std::printf("fast_math_host: FTZ|DAZ not set at start-up (MXCSR %#x): not an -Ofast host\n",
                at_start);
    return 2;
  }
  const exactccd::VertexFaceQuery q = exactccd::test::issue9_query();
  int failures = 0;
  for (exactccd::Mode mode : {exactccd::Mode::filtered, exactccd::Mode::exact}) {
    exactccd::CcdOptions options;
    options.mode = mode;
    const unsigned before = _mm_getcsr();
    const exactccd::CcdResult r = exactccd::vertex_face_ccd(q, options);
    const unsigned after = _mm_getcsr();
    // The exact first contact lies strictly between these consecutive doubles (the exact path,
    // checked in fp_environment_test).
    const bool right = r.collides && same_bits(r.toi_lo, 0x1.b48d9299e2cf1p-3) &&
                       same_bits(r.toi_hi, 0x1.b48d9299e2cf2p-3);
    std::printf("fast_math_host: %s: collides %d, toi [%a, %a], MXCSR %#x -> %#x: %s\n",
                exactccd::to_string(mode), r.collides, r.toi_lo, r.toi_hi, before, after,
                right && after == before ? "ok" : "WRONG");
    if (!right || after != before) ++failures;
  }
  return failures == 0 ? 0 : 1;
}
