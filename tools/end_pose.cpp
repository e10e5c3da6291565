#include "end_pose.hpp"

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <string>

#include "corpus/rigid_exact_pose.hpp"
#include "exact/arithmetic/rational.hpp"
#include "exactccd/query_file.hpp"

namespace exactccd::cli {

Positions rounded_end_pose(const Positions& start, const RigidMotion& m, double* rounding,
                           const std::string& what) {
  Positions end(start.rows(), 3);
  mpq_class largest(0);
  for (Eigen::Index v = 0; v < start.rows(); ++v) {
    const rigid_pose::RationalPosition at_end =
        rigid_pose::exact_position(m, start.row(v).transpose(), mpq_class(1));
    for (int i = 0; i < 3; ++i) {
      const mpq_class& exact = at_end[i];
      const double rounded = exact::round_nearest(exact);
      if (!std::isfinite(rounded))
        throw InputError(what, 0,
                         "the pose at the end of a step is beyond the doubles (vertex " +
                             std::to_string(v) + ")");
      end(v, i) = rounded;
      const mpq_class error = abs(mpq_class(rounded) - exact);
      if (error > largest) largest = error;
    }
  }
  // An upper bound as a double: get_d truncates, the next double up is above. (Below the
  // normal range get_d may give 0; the smallest normal double is then a bound.)
  const double truncated = largest.get_d();
  if (mpq_class(truncated) == largest)
    *rounding = truncated;
  else if (truncated == 0.0)
    *rounding = std::numeric_limits<double>::min();
  else
    *rounding = std::nextafter(truncated, std::numeric_limits<double>::infinity());
  return end;
}

}  // namespace exactccd::cli
