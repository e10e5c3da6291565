// libFuzzer harness: the public CCD API (vertex_face_ccd / edge_edge_ccd) on raw bytes.
//
// Input layout (shorter inputs are padded with zero bytes, longer ones cut):
//   byte 0        flags: bit 0 the query type (0 vertex-face, 1 edge-edge); bit 1 t_max from
//                 the bytes below (else 1); bit 2 toi_width from the bytes below (else 0)
//   bytes 1-192   24 doubles, native byte order: the 8 points in the benchmark's row order
//   bytes 193-200 t_max, a double
//   bytes 201-208 toi_width, a double
//
// Properties (ccd.hpp, types.hpp): non-finite coordinates, t_max outside [0, 1] and a negative
// or non-finite toi_width throw std::invalid_argument in every mode; otherwise the default
// path equals the exact path (fuzz_support.hpp, check_default_equals_exact).
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz_support.hpp"

using namespace exactccd;

namespace {

constexpr std::size_t kPoints = 1, kTmax = kPoints + 24 * sizeof(double);
constexpr std::size_t kWidth = kTmax + sizeof(double), kSize = kWidth + sizeof(double);

double double_at(const std::uint8_t* bytes, std::size_t offset) {
  double x;
  std::memcpy(&x, bytes + offset, sizeof x);
  return x;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::uint8_t bytes[kSize] = {};
  std::memcpy(bytes, data, size < kSize ? size : kSize);
  const QueryType type = bytes[0] & 1 ? QueryType::edge_edge : QueryType::vertex_face;
  fuzz::Points v;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) v[i][k] = double_at(bytes, kPoints + (3 * i + k) * sizeof(double));
  CcdOptions options;
  if (bytes[0] & 2) options.t_max = double_at(bytes, kTmax);
  if (bytes[0] & 4) options.toi_width = double_at(bytes, kWidth);
  if (fuzz::invalid_input(v, options))
    fuzz::check_rejected(type, v, options);
  else
    fuzz::check_default_equals_exact(type, v, options);
  return 0;
}
