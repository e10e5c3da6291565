// Shared by the libFuzzer harnesses (tests/fuzz/*_fuzz.cpp): a per-process scratch folder for
// the readers that take paths, a failed-property abort that libFuzzer records as a crash (with
// the input saved), and the checks of the public CCD API that more than one harness makes.
#pragma once

#include <gmpxx.h>

#include <Eigen/Core>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "exactccd/ccd.hpp"
#include "exactccd/contact.hpp"
#include "exactccd/rigid.hpp"
#include "exactccd/step.hpp"
#include "../result_text.hpp"

namespace exactccd::fuzz {

/// A property failed: print it and abort, so that libFuzzer saves the input as a crash.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "exactccd fuzz: property failed: %s\n", what.c_str());
  std::abort();
}

inline void require(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

/// A folder of its own for this process (under $TMPDIR, else /tmp), removed at exit; the
/// harnesses write each input there for the readers, which take paths.
inline const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/exactccd-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) fail("cannot create a scratch folder under " + pattern);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_folder(), ignored);
    });
    return std::filesystem::path(pattern);
  }();
  return folder;
}

/// Writes `data` to `path` (replacing it); aborts when that fails (the machine, not the input).
inline void write_file(const std::filesystem::path& path, const std::uint8_t* data,
                       std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) fail("cannot write " + path.string());
}

using Points = std::array<Eigen::Vector3d, 8>;  // the benchmark's row order

/// The largest minus the smallest binary exponent (std::ilogb) over the nonzero coordinates.
/// The exact path scales a query to integers over a common power-of-two denominator, so its
/// numbers are about this many bits wider than the coordinates' 53. Wide spreads once cost up to
/// a second per query, and the harnesses skipped spreads above 200; since issue 10's exact stage
/// for wide coordinates (below 1 ms per query in Release) every finite double is checked:
/// ilogb lies in [-1074, 1023], so no spread exceeds this bound.
inline constexpr int kMaxExponentSpread = 1023 + 1074;

inline int exponent_spread(const Points& v) {
  int lo = INT_MAX, hi = INT_MIN;
  for (const Eigen::Vector3d& p : v)
    for (int k = 0; k < 3; ++k)
      if (p[k] != 0.0) {
        const int e = std::ilogb(p[k]);
        lo = e < lo ? e : lo;
        hi = e > hi ? e : hi;
      }
  return lo == INT_MAX ? 0 : hi - lo;
}

inline CcdResult ccd(QueryType type, const Points& v, const CcdOptions& options) {
  if (type == QueryType::vertex_face)
    return vertex_face_ccd({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}, options);
  return edge_edge_ccd({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}, options);
}

inline std::string describe(QueryType type, const Points& v, const CcdOptions& o) {
  std::string s = std::string(to_string(type)) + " query (hex doubles, rows t0 then t1):";
  char buf[96];
  for (const Eigen::Vector3d& p : v) {
    std::snprintf(buf, sizeof buf, "\n  %a %a %a", p.x(), p.y(), p.z());
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "\n  t_max %a toi_width %a", o.t_max, o.toi_width);
  return s + buf;
}

inline std::string describe(const CcdResult& r) { return test::describe_result(r); }

/// Whether the API rejects the options or the coordinates with std::invalid_argument, as
/// ccd.hpp says it must for non-finite coordinates, t_max outside [0, 1] (0 is the state at
/// t = 0), and a negative or non-finite toi_width.
inline bool invalid_input(const Points& v, const CcdOptions& o) {
  for (const Eigen::Vector3d& p : v)
    if (!p.allFinite()) return true;
  return !(o.t_max >= 0.0 && o.t_max <= 1.0) || !(o.toi_width >= 0.0) ||
         !std::isfinite(o.toi_width);
}

/// Every mode must throw std::invalid_argument on invalid input; anything else escapes and
/// aborts.
inline void check_rejected(QueryType type, const Points& v, const CcdOptions& options) {
  for (Mode mode : {Mode::filtered, Mode::exact, Mode::float_only}) {
    CcdOptions o = options;
    o.mode = mode;
    bool threw = false;
    try {
      ccd(type, v, o);
    } catch (const std::invalid_argument&) {
      threw = true;
    }
    require(threw, std::string("no std::invalid_argument from mode ") + to_string(mode) +
                       " on invalid input: " + describe(type, v, o));
  }
}

/// The contract of one valid query (ccd.hpp, types.hpp): the default path equals the exact
/// path, bit for bit, at toi_width 0 (the tightest pair of doubles around t* is unique); at
/// the caller's toi_width both modes give the same verdict and an enclosure of t* (so it
/// contains the tightest pair) at most toi_width wide, computed exactly, or the tightest pair
/// itself when toi_width is narrower. float_only must run
/// without throwing (its answers are uncertified). Skips queries wider than
/// kMaxExponentSpread; returns whether the query was checked.
inline bool check_default_equals_exact(QueryType type, const Points& v, const CcdOptions& options) {
  if (exponent_spread(v) > kMaxExponentSpread) return false;
  CcdOptions tight = options;
  tight.toi_width = 0.0;
  tight.mode = Mode::exact;
  const CcdResult exact = ccd(type, v, tight);
  tight.mode = Mode::filtered;
  const CcdResult filtered = ccd(type, v, tight);
  const std::string where = describe(type, v, options);
  require(filtered.collides == exact.collides && filtered.toi_lo == exact.toi_lo &&
              filtered.toi_hi == exact.toi_hi,
          "default " + describe(filtered) + " != exact " + describe(exact) + " on " + where);
  if (exact.collides) {
    require(0.0 <= exact.toi_lo && exact.toi_lo <= exact.toi_hi &&
                exact.toi_hi <= options.t_max &&
                (exact.toi_lo == exact.toi_hi ||
                 std::nextafter(exact.toi_lo, 2.0) == exact.toi_hi),
            "not the tightest pair in [0, t_max]: " + describe(exact) + " on " + where);
  } else {
    constexpr double inf = std::numeric_limits<double>::infinity();
    require(exact.toi_lo == inf && exact.toi_hi == inf,
            "no contact but a finite TOI: " + describe(exact) + " on " + where);
  }
  if (exact.collides) {
    // The contact geometry: computed without an error (an empty enclosure would contradict
    // its proof and throws std::logic_error), parameters in [0, 1], the normal in [-1, 1].
    const ContactGeometry g =
        type == QueryType::vertex_face
            ? contact_geometry(VertexFaceQuery{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]},
                               exact)
            : contact_geometry(EdgeEdgeQuery{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]},
                               exact);
    for (int i = 0; i < g.parameter_count; ++i)
      require(0.0 <= g.parameters[i].lo && g.parameters[i].hi <= 1.0,
              "contact parameter outside [0, 1] on " + where);
    for (const Enclosure& e : g.normal)
      require(-1.0 <= e.lo && e.lo <= e.hi && e.hi <= 1.0, "normal outside [-1, 1] on " + where);
  }
  if (!v[2].isZero(0.0) && !v[6].isZero(0.0)) {
    // The same bytes as a point-plane query (p, origin, normal at t0: rows 0-2; at t1: rows
    // 4-6): the filtered path equals the exact one.
    const PointPlaneQuery plane{v[0], v[1], v[2], v[4], v[5], v[6]};
    CcdOptions o = options;
    o.toi_width = 0.0;
    o.mode = Mode::exact;
    const CcdResult plane_exact = point_plane_ccd(plane, o);
    o.mode = Mode::filtered;
    const CcdResult plane_filtered = point_plane_ccd(plane, o);
    require(plane_filtered.collides == plane_exact.collides &&
                plane_filtered.toi_lo == plane_exact.toi_lo &&
                plane_filtered.toi_hi == plane_exact.toi_hi &&
                plane_filtered.starts_within == plane_exact.starts_within,
            "point-plane: default " + describe(plane_filtered) + " != exact " +
                describe(plane_exact) + " on " + where);
    if (plane_exact.collides) {  // its contact geometry: certified ranges, no error
      const ContactGeometry g = contact_geometry(plane, plane_exact);
      for (const Enclosure& e : g.normal)
        require(-1.0 <= e.lo && e.lo <= e.hi && e.hi <= 1.0,
                "point-plane normal outside [-1, 1] on " + where);
    }
    // The point of rows 0 turned by the rigid motion (pivot row 4, translation row 5, Cayley
    // vector row 7) against the static plane through row 1 with normal row 2: the filtered path
    // equals the exact one (moderate values only: the exact path's cost grows with them).
    const bool moderate = [&] {
      for (int i : {0, 1, 2, 4, 5, 7})
        if (!(v[i].cwiseAbs().maxCoeff() < 1e6)) return false;
      return true;
    }();
    if (moderate) {
      RigidMotion m;
      m.pivot = v[4];
      m.translation = v[5];
      m.cayley = v[7];
      const RigidPointPlaneQuery rigid(v[0], m, v[1], v[2]);
      o.mode = Mode::exact;
      const RigidCcdResult rigid_exact = point_plane_ccd(rigid, o);
      o.mode = Mode::filtered;
      const RigidCcdResult rigid_filtered = point_plane_ccd(rigid, o);
      require(rigid_filtered.ccd.collides == rigid_exact.ccd.collides &&
                  rigid_filtered.ccd.toi_lo == rigid_exact.ccd.toi_lo &&
                  rigid_filtered.ccd.toi_hi == rigid_exact.ccd.toi_hi,
              "rigid point-plane: default " + describe(rigid_filtered.ccd) + " != exact " +
                  describe(rigid_exact.ccd) + " on " + where);
    }
  }
  {
    // The collision-free step: in [0, t_max], and limited whenever the pair collides.
    StepOptions step_options;
    step_options.t_max = options.t_max;
    const StepResult step =
        type == QueryType::vertex_face
            ? collision_free_step(VertexFaceQuery{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]},
                                  step_options)
            : collision_free_step(EdgeEdgeQuery{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]},
                                  step_options);
    require(0.0 <= step.step && step.step <= options.t_max, "step outside [0, t_max] on " + where);
    require(!exact.collides || step.limited, "a colliding pair's step is not limited on " + where);
    require(step.starts_within == exact.starts_within, "starts_within differs on " + where);
  }
  if (options.toi_width > 0.0) {
    for (Mode mode : {Mode::filtered, Mode::exact}) {
      CcdOptions o = options;
      o.mode = mode;
      const CcdResult r = ccd(type, v, o);
      const std::string what = std::string(to_string(mode)) + " at the caller's width " +
                               describe(r) + " (tightest " + describe(exact) + ") on " + where;
      require(r.collides == exact.collides, "verdict differs: " + what);
      if (!r.collides) continue;
      require(r.toi_lo <= exact.toi_lo && exact.toi_hi <= r.toi_hi,
              "enclosure misses t*: " + what);
      // A width below the spacing of the doubles around t* gets the tightest pair (toi_test).
      const bool tightest = r.toi_lo == exact.toi_lo && r.toi_hi == exact.toi_hi;
      require(tightest ||
                  mpq_class(r.toi_hi) - mpq_class(r.toi_lo) <= mpq_class(options.toi_width),
              "enclosure wider than toi_width: " + what);
    }
  }
  CcdOptions uncertified = options;
  uncertified.mode = Mode::float_only;
  ccd(type, v, uncertified);
  return true;
}

}  // namespace exactccd::fuzz
