// The methods and settings the study measures: the uncertified float_only mode and tolerance
// method (core/float_only/tolerance_ccd.hpp), the filtered path at each TOI width, the exact path;
// each deciding contact, or with a minimum separation D > 0 "within distance D".
#pragma once

#include <string>
#include <vector>

#include "core/float_only/tolerance_ccd.hpp"
#include "exactccd/ccd.hpp"

namespace exactccd::study {

enum class Kind { float_only, tolerance, filtered, exact };

struct Method {
  Kind kind = Kind::filtered;
  double parameter = 0.0;  // tolerance: eps; filtered: the TOI width
  std::string name;        // float_only, tolerance, filtered, exact
  std::string setting;     // eps=1e-9, width=0, or empty
  bool certified = false;
  /// D >= 0: every method decides "within distance D" (float_only: the common practice with
  /// eps = D; tolerance: distance <= D + eps at a cubic root; filtered, exact: min_separation D).
  double min_separation = 0.0;

  std::string label() const { return setting.empty() ? name : name + " " + setting; }
};

/// The methods and settings measured, in report order: float_only; the tolerance method at
/// each eps; the filtered path at each TOI width; exact; all with minimum separation D.
std::vector<Method> methods_of(const std::vector<double>& tolerances,
                               const std::vector<double>& widths, double min_separation = 0.0);

/// Calls f(decide_vertex_face, decide_edge_edge) with the method's two deciders, so that the
/// timed loops call them directly, with no per-query dispatch on the method.
template <class F>
auto with_method(const Method& m, F&& f) {
  CcdOptions options;
  options.min_separation = m.min_separation;
  switch (m.kind) {
    case Kind::tolerance: {
      // The common practice's test with a minimum separation: distance <= D + eps (in doubles).
      const double eps = m.min_separation + m.parameter;
      return f(
          [eps](const VertexFaceQuery& q) { return methods::tolerance_vertex_face_ccd(q, eps); },
          [eps](const EdgeEdgeQuery& q) { return methods::tolerance_edge_edge_ccd(q, eps); });
    }
    case Kind::float_only: options.mode = Mode::float_only; break;
    case Kind::filtered:
      options.mode = Mode::filtered;
      options.toi_width = m.parameter;
      break;
    case Kind::exact: options.mode = Mode::exact; break;
  }
  return f([options](const VertexFaceQuery& q) { return vertex_face_ccd(q, options); },
           [options](const EdgeEdgeQuery& q) { return edge_edge_ccd(q, options); });
}

}  // namespace exactccd::study
