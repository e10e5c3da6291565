// PROOF: proofs/api_reductions.md#point-families
#include "corpus/point_families.hpp"

#include <Eigen/Geometry>  // cross

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>

#include "exactccd/ccd.hpp"

namespace exactccd::families {

namespace {

using V = Eigen::Vector3d;

Eigen::Vector2d flat(const V& x) { return {x.x(), x.y()}; }

/// Draws of the constructions: small dyadic numbers (exact in every sum and product below) and
/// a power-of-two scale applied to a whole query (exact: no member leaves the normal range).
struct Draw {
  std::mt19937_64 rng;
  /// k / 8, k in [-32, 32].
  double dyadic() { return std::uniform_int_distribution<int>(-32, 32)(rng) / 8.0; }
  /// k / 8, k in [1, 32].
  double positive() { return std::uniform_int_distribution<int>(1, 32)(rng) / 8.0; }
  V vector(bool planar) { return {dyadic(), dyadic(), planar ? 0.0 : dyadic()}; }
  /// An integer vector, not zero.
  V integer_vector(bool planar) {
    for (;;) {
      std::uniform_int_distribution<int> u(-3, 3);
      const V v(u(rng), u(rng), planar ? 0 : u(rng));
      if (!v.isZero()) return v;
    }
  }
  double scale() { return std::ldexp(1.0, std::uniform_int_distribution<int>(-30, 30)(rng)); }
};

PointRows scaled(PointRows rows, double s) {
  for (V& x : rows) x *= s;
  return rows;
}

double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

/// A family: its name, claim, construction line, and a builder of one member.
struct Recipe {
  const char* name;
  bool collides;
  const char* what;
  std::function<PointRows(Draw&)> build;
};

/// Point-edge (3D, or 2D with z = 0): rows p, e0, e1 at t0, then at t1.
std::vector<Recipe> point_edge_recipes(bool planar) {
  std::vector<Recipe> r;
  r.push_back({"through_endpoint", true,
               "the point passes exactly through the segment's moving endpoint e1 at t = 1/2",
               [planar](Draw& d) {
                 const V a = d.vector(planar), b = d.vector(planar) + V(1, 0, 0);
                 const V move = d.vector(planar), dir = d.integer_vector(planar);
                 const double s = d.scale();
                 // p(t) = b - dir + t (2 dir + move) meets b(t) = b + t move at t = 1/2.
                 return scaled({b - dir, a, b, b + dir + move, a + move, b + move}, s);
               }});
  r.push_back({"beyond_endpoint_ulp", false,
               "the point crosses the segment's line one unit in the last place beyond e1",
               [planar](Draw& d) {
                 const double s = d.scale();
                 const double y = d.dyadic() * s, z = planar ? 0.0 : d.dyadic() * s;
                 const double x0 = -d.positive() * s, x1 = d.positive() * s;
                 const double h = d.positive() * s, beyond = up(x1);
                 // The segment along x from x0 to x1; the point moves along y at x = x1 + ulp.
                 const V e0(x0, y, z), e1(x1, y, z);
                 return PointRows{V(beyond, y - h, z), e0, e1, V(beyond, y + h, z), e0, e1};
               }});
  r.push_back({"slide_to_endpoint", true,
               "the point slides along the segment's line and reaches e1 exactly at t = 1",
               [planar](Draw& d) {
                 const double s = d.scale();
                 const double y = d.dyadic() * s, z = planar ? 0.0 : d.dyadic() * s;
                 const double x0 = -d.positive() * s, x1 = d.positive() * s;
                 const V e0(x0, y, z), e1(x1, y, z);
                 return PointRows{V(x1 + d.positive() * s, y, z), e0, e1, e1, e0, e1};
               }});
  r.push_back({"slide_short_ulp", false,
               "the point slides along the segment's line and stops one ulp short of e1",
               [planar](Draw& d) {
                 const double s = d.scale();
                 const double y = d.dyadic() * s, z = planar ? 0.0 : d.dyadic() * s;
                 const double x0 = -d.positive() * s, x1 = d.positive() * s;
                 const V e0(x0, y, z), e1(x1, y, z);
                 return PointRows{V(x1 + d.positive() * s, y, z), e0, e1, V(up(x1), y, z), e0, e1};
               }});
  if (!planar)
    r.push_back({"skew_near_miss", false,
                 "the point crosses the segment's interior 2^-30 of its length above it",
                 [](Draw& d) {
                   const double s = d.scale();
                   const double x0 = -d.positive() * s, x1 = d.positive() * s;
                   const double h = d.positive() * s, gap = std::ldexp(x1 - x0, -30);
                   const V e0(x0, 0, 0), e1(x1, 0, 0);
                   const double x = (x0 + x1) / 2;
                   return PointRows{V(x, -h, gap), e0, e1, V(x, h, gap), e0, e1};
                 }});
  return r;
}

/// Point-point (3D, or 2D): rows p, q at t0, then at t1.
std::vector<Recipe> point_point_recipes(bool planar) {
  std::vector<Recipe> r;
  // q - p starts at r0 and changes by w = -2^m r0 over the step: it is zero at t = 2^-m.
  const auto meeting = [planar](Draw& d, int m, V* p0, V* q0, V* p1, V* q1) {
    *p0 = d.vector(planar);
    V r0 = d.integer_vector(planar);
    if (!planar) r0.z() = 0;  // the miss family nudges z
    else r0.y() = 0;          // ... or y in 2D
    if (r0.isZero()) r0.x() = 1;
    *q0 = *p0 + r0;
    const V move = d.vector(planar);
    *p1 = *p0 + move;
    *q1 = *q0 + move - std::ldexp(1.0, m) * r0;
  };
  r.push_back({"meet_at_dyadic", true, "the points meet exactly at t = 2^-m, m in [0, 4]",
               [meeting](Draw& d) {
                 V p0, q0, p1, q1;
                 meeting(d, std::uniform_int_distribution<int>(0, 4)(d.rng), &p0, &q0, &p1, &q1);
                 return scaled({p0, q0, p1, q1}, d.scale());
               }});
  r.push_back({"miss_by_ulp", false,
               "as meet_at_dyadic, with q's end one ulp off across the relative path",
               [meeting, planar](Draw& d) {
                 V p0, q0, p1, q1;
                 meeting(d, std::uniform_int_distribution<int>(0, 4)(d.rng), &p0, &q0, &p1, &q1);
                 PointRows rows = scaled({p0, q0, p1, q1}, d.scale());
                 const int axis = planar ? 1 : 2;  // where q - p is 0 at t = 0
                 rows[3][axis] = up(rows[3][axis]);
                 return rows;
               }});
  r.push_back({"coincident", true, "the points coincide throughout", [planar](Draw& d) {
                 const V p0 = d.vector(planar), p1 = p0 + d.vector(planar);
                 return scaled({p0, p0, p1, p1}, d.scale());
               }});
  r.push_back({"meet_at_end", true, "the points meet exactly at t = 1", [planar](Draw& d) {
                 const V p0 = d.vector(planar), p1 = d.vector(planar);
                 return scaled({p0, p0 + d.integer_vector(planar), p1, p1}, d.scale());
               }});
  return r;
}

/// Point-plane: rows p, origin, normal at t0, then at t1.
std::vector<Recipe> point_plane_recipes() {
  std::vector<Recipe> r;
  // u, v: integer vectors orthogonal to the integer normal n (u . n = 0 exactly).
  const auto in_plane = [](Draw& d, const V& n) -> V {  // a V: no expression over temporaries
    return n.cross(d.integer_vector(false)) * std::uniform_int_distribution<int>(-2, 2)(d.rng);
  };
  r.push_back({"cross_at_dyadic", true,
               "the point crosses a tilted static plane (integer normal) from above to below",
               [in_plane](Draw& d) {
                 const V n = d.integer_vector(false), o = d.vector(false);
                 const V p0 = o + in_plane(d, n) + d.positive() * n;
                 const V p1 = o + in_plane(d, n) - d.positive() * n;
                 return scaled({p0, o, n, p1, o, n}, d.scale());
               }});
  r.push_back({"slide_in_plane", true,
               "the point moves within the plane throughout (offset identically 0)",
               [in_plane](Draw& d) {
                 const V n = d.integer_vector(false), o = d.vector(false);
                 return scaled({o + in_plane(d, n), o, n, o + in_plane(d, n), o, n}, d.scale());
               }});
  r.push_back({"touch_at_end", true, "the point reaches the plane exactly at t = 1",
               [in_plane](Draw& d) {
                 const V n = d.integer_vector(false), o = d.vector(false);
                 const V p0 = o + in_plane(d, n) + d.positive() * n;
                 return scaled({p0, o, n, o + in_plane(d, n), o, n}, d.scale());
               }});
  r.push_back({"stop_short_ulp", false,
               "the point falls onto a floor z = c and stops one ulp above it", [](Draw& d) {
                 const double s = d.scale();
                 const V o(d.dyadic() * s, d.dyadic() * s, d.dyadic() * s);
                 const V n(0, 0, d.positive() * s);
                 const V p0(d.dyadic() * s, d.dyadic() * s, o.z() + d.positive() * s);
                 const V p1(d.dyadic() * s, d.dyadic() * s, up(o.z()));
                 return PointRows{p0, o, n, p1, o, n};
               }});
  // p - o(t) = (c, 0, a (1 - 2t)) and n(t) = (t, 0, 1 - 2t): the offset is c t + a (1 - 2t)^2,
  // a double root at t = 1/2 when c = 0 (the plane grazes the point), positive throughout when
  // c > 0.
  const auto turning = [](Draw& d, bool graze) {
    const double a = d.positive(), c = graze ? 0.0 : std::ldexp(a, -30);
    const V shift = d.vector(false);
    const V p = shift + V(c, 0, a);
    return PointRows{p, shift, V(0, 0, 1), p, shift + V(0, 0, 2 * a), V(1, 0, -1)};
  };
  r.push_back({"graze_turning", true,
               "a turning, rising plane touches the point at t = 1/2 without crossing (a double "
               "root)",
               [turning](Draw& d) { return scaled(turning(d, true), d.scale()); }});
  r.push_back({"near_graze_turning", false,
               "as graze_turning, the point 2^-30 of the rise off the plane's path",
               [turning](Draw& d) { return scaled(turning(d, false), d.scale()); }});
  return r;
}

std::vector<Recipe> recipes_of(PrimitiveKind kind) {
  switch (kind) {
    case PrimitiveKind::point_edge: return point_edge_recipes(false);
    case PrimitiveKind::point_edge_2d: return point_edge_recipes(true);
    case PrimitiveKind::point_point: return point_point_recipes(false);
    case PrimitiveKind::point_point_2d: return point_point_recipes(true);
    case PrimitiveKind::point_plane: return point_plane_recipes();
  }
  return {};
}

}  // namespace

CcdResult decide_point_query(PrimitiveKind kind, const PointRows& x, const CcdOptions& options) {
  if (x.size() != rows_per_query(kind))
    throw std::invalid_argument("exactccd: decide_point_query: wrong number of rows");
  switch (kind) {
    case PrimitiveKind::point_edge:
      return point_edge_ccd({x[0], x[1], x[2], x[3], x[4], x[5]}, options);
    case PrimitiveKind::point_edge_2d:
      return point_edge_ccd_2d(
          {flat(x[0]), flat(x[1]), flat(x[2]), flat(x[3]), flat(x[4]), flat(x[5])}, options);
    case PrimitiveKind::point_point:
      return point_point_ccd({x[0], x[1], x[2], x[3]}, options);
    case PrimitiveKind::point_point_2d:
      return point_point_ccd_2d({flat(x[0]), flat(x[1]), flat(x[2]), flat(x[3])}, options);
    case PrimitiveKind::point_plane:
      return point_plane_ccd({x[0], x[1], x[2], x[3], x[4], x[5]}, options);
  }
  throw std::invalid_argument("exactccd: decide_point_query: unknown kind");
}

std::vector<PointFamily> generate_point_families(PrimitiveKind kind, std::uint64_t seed,
                                                 int per_family) {
  std::vector<PointFamily> out;
  const std::vector<Recipe> recipes = recipes_of(kind);
  for (std::size_t f = 0; f < recipes.size(); ++f) {
    const Recipe& recipe = recipes[f];
    PointFamily family;
    family.name = std::string(to_string(kind)) + "_" + recipe.name;
    family.kind = kind;
    family.collides = recipe.collides;
    family.what = recipe.what;
    Draw draw{std::mt19937_64(seed * 1000003u + f)};
    CcdOptions exact;
    exact.mode = Mode::exact;
    for (int i = 0; i < per_family; ++i) {
      family.members.push_back(recipe.build(draw));
      family.exact.push_back(decide_point_query(kind, family.members.back(), exact));
    }
    out.push_back(std::move(family));
  }
  return out;
}

std::string point_family_csv(const PointFamily& family) {
  std::string text;
  const bool planar = dimension_of(family.kind) == 2;
  for (std::size_t i = 0; i < family.members.size(); ++i)
    for (const V& x : family.members[i]) {
      for (int k = 0; k < (planar ? 2 : 3); ++k) {
        append_exact_fraction(text, x[k]);
        text += ',';
      }
      text += family.exact[i].collides ? "1\n" : "0\n";
    }
  return text;
}

std::vector<std::string> point_claim_mismatches(const PointFamily& family) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < family.members.size(); ++i)
    if (family.exact[i].collides != family.collides)
      out.push_back(family.name + " member " + std::to_string(i) + ": constructed to " +
                    (family.collides ? "collide" : "miss") + ", the exact path says " +
                    (family.exact[i].collides ? "collides" : "misses"));
  return out;
}

}  // namespace exactccd::families
