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
  // The vertex-face query of issue 9 (normal coordinates around 2^-338).
  exactccd::VertexFaceQuery q;
  q.p_t0 = {0x1.aab1c61f7f9dap-338, -0x1.e1ef9284f41ep-339, -0x1.5a51f81272d58p-339};
  q.a_t0 = {0x1.4269e20b15724p-338, 0x1.5568922adc9fp-338, 0x1.90b88adca3faap-338};
  q.b_t0 = {0x1.82f749d8bc38cp-339, -0x1.a9afa9c8e98aep-339, -0x1.727a774581258p-338};
  q.c_t0 = {0x1.dc481382d3bcap-338, 0x1.4ad954f0592f8p-339, -0x1.6447c14db359ep-338};
  q.p_t1 = {-0x1.3727506d293aep-338, 0x1.7a5b5f1061c02p-338, -0x1.4adf27a799287p-338};
  q.a_t1 = {-0x1.225c59ded729ep-338, -0x1.e642c24349be8p-341, 0x1.94af9e2f5d798p-339};
  q.b_t1 = {0x1.3e922784f5e96p-338, -0x1.329379daddddcp-340, 0x1.95f907fcff02p-339};
  q.c_t1 = {0x1.44dbef531e216p-338, -0x1.74cb96014ae58p-338, 0x1.82ddfef46fe5ep-338};
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
