// Compiled with -ffast-math by build_flags_test_fast_math_include: must stop at the #error of
// core/predicates/fp_environment.hpp, reached through a certified header.
#include "filters/cubic_filter.hpp"
