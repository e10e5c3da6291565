// The vertex-face query of issue 9: normal coordinates around 2^-338, whose cubic's coefficients
// (~2^-1014) and their products underflow into the subnormal range. Under FTZ|DAZ a library that
// does not own its FP state reports toi [0x1.b439p-3, 0x1.b439p-3], before the exact first
// contact, which lies strictly between 0x1.b48d9299e2cf1p-3 and 0x1.b48d9299e2cf2p-3.
// Public headers only: the -Ofast host (fast_math_host.cpp) includes it too.
#pragma once

#include "exactccd/types.hpp"

namespace exactccd::test {

inline VertexFaceQuery issue9_query() {
  VertexFaceQuery q;
  q.p_t0 = {0x1.aab1c61f7f9dap-338, -0x1.e1ef9284f41ep-339, -0x1.5a51f81272d58p-339};
  q.a_t0 = {0x1.4269e20b15724p-338, 0x1.5568922adc9fp-338, 0x1.90b88adca3faap-338};
  q.b_t0 = {0x1.82f749d8bc38cp-339, -0x1.a9afa9c8e98aep-339, -0x1.727a774581258p-338};
  q.c_t0 = {0x1.dc481382d3bcap-338, 0x1.4ad954f0592f8p-339, -0x1.6447c14db359ep-338};
  q.p_t1 = {-0x1.3727506d293aep-338, 0x1.7a5b5f1061c02p-338, -0x1.4adf27a799287p-338};
  q.a_t1 = {-0x1.225c59ded729ep-338, -0x1.e642c24349be8p-341, 0x1.94af9e2f5d798p-339};
  q.b_t1 = {0x1.3e922784f5e96p-338, -0x1.329379daddddcp-340, 0x1.95f907fcff02p-339};
  q.c_t1 = {0x1.44dbef531e216p-338, -0x1.74cb96014ae58p-338, 0x1.82ddfef46fe5ep-338};
  return q;
}

}  // namespace exactccd::test
