// Upstream TinyAD has no TinyAD::ScalarBase (ipc-toolkit pins a fork that adds it, for its
// smooth-contact code only, which the offline build leaves out). This header, found before
// TinyAD's own, adds an empty stand-in so that ipc/utils/autodiff_types.hpp compiles.
#pragma once
#include_next <TinyAD/Scalar.hh>

namespace TinyAD {
struct ScalarBase {};
}  // namespace TinyAD
