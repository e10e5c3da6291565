#include "corpus/meshes.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "exactccd/query_file.hpp"

namespace exactccd::scenes {

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Builds a mesh from row lists.
Mesh make_mesh(const std::vector<Eigen::Vector3d>& vertices,
               const std::vector<Eigen::Vector3i>& triangles) {
  Mesh m;
  m.positions.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t i = 0; i < vertices.size(); ++i)
    m.positions.row(static_cast<Eigen::Index>(i)) = vertices[i].transpose();
  m.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    m.triangles.row(static_cast<Eigen::Index>(f)) = triangles[f].transpose();
  return m;
}

/// Appends `part` to `whole` (a triangle soup: no vertex is merged).
void append(Mesh& whole, const Mesh& part) {
  const Eigen::Index v = whole.positions.rows(), f = whole.triangles.rows();
  whole.positions.conservativeResize(v + part.positions.rows(), 3);
  whole.positions.bottomRows(part.positions.rows()) = part.positions;
  whole.triangles.conservativeResize(f + part.triangles.rows(), 3);
  whole.triangles.bottomRows(part.triangles.rows()) =
      part.triangles.array() + static_cast<std::int32_t>(v);
}

/// Coordinate i of n+1 equally spaced values from lo to hi, ends exact.
double lerp(double lo, double hi, int i, int n) {
  if (i == 0) return lo;
  if (i == n) return hi;
  return lo + (hi - lo) * i / n;
}

}  // namespace

Mesh box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  return subdivided_box(lo, hi, 1, 1);
}

Mesh subdivided_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int nx, int ny) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("subdivided_box: nx and ny must be >= 1");
  if (!(lo.array() < hi.array()).all()) throw std::invalid_argument("subdivided_box: need lo < hi");
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector3i> t;
  const int row = nx + 1, layer = (nx + 1) * (ny + 1);
  // Layer 0: the top grid (z = hi.z); layer 1: the bottom grid (z = lo.z).
  for (const double z : {hi.z(), lo.z()})
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        v.emplace_back(lerp(lo.x(), hi.x(), i, nx), lerp(lo.y(), hi.y(), j, ny), z);
  const auto top = [&](int i, int j) { return j * row + i; };
  const auto bottom = [&](int i, int j) { return layer + j * row + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      t.emplace_back(top(i, j), top(i + 1, j), top(i + 1, j + 1));  // normal +z
      t.emplace_back(top(i, j), top(i + 1, j + 1), top(i, j + 1));
      t.emplace_back(bottom(i, j), bottom(i + 1, j + 1), bottom(i + 1, j));  // normal -z
      t.emplace_back(bottom(i, j), bottom(i, j + 1), bottom(i + 1, j + 1));
    }
  // The grids' boundary, counterclockwise seen from +z; a side quad between consecutive boundary
  // points a -> b faces outward along (b - a) x z.
  std::vector<std::pair<int, int>> loop;
  for (int i = 0; i < nx; ++i) loop.emplace_back(i, 0);
  for (int j = 0; j < ny; ++j) loop.emplace_back(nx, j);
  for (int i = nx; i > 0; --i) loop.emplace_back(i, ny);
  for (int j = ny; j > 0; --j) loop.emplace_back(0, j);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const auto [ai, aj] = loop[k];
    const auto [bi, bj] = loop[(k + 1) % loop.size()];
    t.emplace_back(bottom(ai, aj), bottom(bi, bj), top(bi, bj));
    t.emplace_back(bottom(ai, aj), top(bi, bj), top(ai, aj));
  }
  return make_mesh(v, t);
}

Mesh grid_sheet(int n, double width, const Eigen::Vector3d& center) {
  if (n < 1) throw std::invalid_argument("grid_sheet: n must be >= 1");
  const double x0 = center.x() - width / 2, x1 = center.x() + width / 2;
  const double y0 = center.y() - width / 2, y1 = center.y() + width / 2;
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector3i> t;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) v.emplace_back(lerp(x0, x1, i, n), lerp(y0, y1, j, n), center.z());
  const auto at = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      t.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      t.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return make_mesh(v, t);
}

Mesh thin_slab(int n, double width, double thickness, const Eigen::Vector3d& center) {
  const Eigen::Vector3d half(width / 2, width / 2, thickness / 2);
  return subdivided_box(center - half, center + half, n, n);
}

Mesh uv_sphere(const Eigen::Vector3d& center, double radius, int slices, int stacks) {
  if (slices < 3 || stacks < 2)
    throw std::invalid_argument("uv_sphere: needs slices >= 3 and stacks >= 2");
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector3i> t;
  v.push_back(center + Eigen::Vector3d(0, 0, radius));
  for (int k = 1; k < stacks; ++k) {
    const double theta = kPi * k / stacks;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2 * kPi * j / slices;
      v.push_back(center + radius * Eigen::Vector3d(std::sin(theta) * std::cos(phi),
                                                    std::sin(theta) * std::sin(phi),
                                                    std::cos(theta)));
    }
  }
  v.push_back(center - Eigen::Vector3d(0, 0, radius));
  const int south = static_cast<int>(v.size()) - 1;
  const auto ring = [&](int k, int j) { return 1 + (k - 1) * slices + (j % slices); };
  for (int j = 0; j < slices; ++j) {
    t.emplace_back(0, ring(1, j), ring(1, j + 1));
    for (int k = 1; k + 1 < stacks; ++k) {
      t.emplace_back(ring(k, j), ring(k + 1, j), ring(k + 1, j + 1));
      t.emplace_back(ring(k, j), ring(k + 1, j + 1), ring(k, j + 1));
    }
    t.emplace_back(south, ring(stacks - 1, j + 1), ring(stacks - 1, j));
  }
  return make_mesh(v, t);
}

std::array<Box3, 4> square_hole_block_boxes(double center_x, double center_y, double outer,
                                            double hole, double z_bottom, double z_top) {
  if (!(0 < hole && hole < outer && z_bottom < z_top))
    throw std::invalid_argument("square_hole_block_boxes: need 0 < hole < outer, z_bottom < z_top");
  const double o0x = center_x - outer / 2, o1x = center_x + outer / 2;
  const double o0y = center_y - outer / 2, o1y = center_y + outer / 2;
  const double h0x = center_x - hole / 2, h1x = center_x + hole / 2;
  const double h0y = center_y - hole / 2, h1y = center_y + hole / 2;
  return {Box3{{o0x, o0y, z_bottom}, {h0x, o1y, z_top}},   // x below the hole, all y
          Box3{{h1x, o0y, z_bottom}, {o1x, o1y, z_top}},   // x above the hole, all y
          Box3{{h0x, o0y, z_bottom}, {h1x, h0y, z_top}},   // between them, y below the hole
          Box3{{h0x, h1y, z_bottom}, {h1x, o1y, z_top}}};  // between them, y above the hole
}

Mesh open_tube(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, double radius, int sides,
               int segments) {
  if (sides < 3 || segments < 1 || p0 == p1)
    throw std::invalid_argument("open_tube: needs sides >= 3, segments >= 1 and p0 != p1");
  const Eigen::Vector3d axis = (p1 - p0).normalized();
  // Any unit vector across the axis, then the third of a right-handed frame.
  const Eigen::Vector3d e1 = axis.unitOrthogonal();
  const Eigen::Vector3d e2 = axis.cross(e1);
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector3i> t;
  for (int k = 0; k <= segments; ++k) {
    const Eigen::Vector3d c = p0 + (p1 - p0) * (static_cast<double>(k) / segments);
    for (int j = 0; j < sides; ++j) {
      const double phi = 2 * kPi * j / sides;
      v.push_back(c + radius * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }
  }
  const auto at = [&](int k, int j) { return k * sides + (j % sides); };
  for (int k = 0; k < segments; ++k)
    for (int j = 0; j < sides; ++j) {
      t.emplace_back(at(k, j), at(k, j + 1), at(k + 1, j + 1));
      t.emplace_back(at(k, j), at(k + 1, j + 1), at(k + 1, j));
    }
  return make_mesh(v, t);
}

Mesh block_with_square_hole(double center_x, double center_y, double outer, double hole,
                            double z_bottom, double z_top) {
  Mesh m;
  for (const Box3& b :
       square_hole_block_boxes(center_x, center_y, outer, hole, z_bottom, z_top))
    append(m, box(b.lo, b.hi));
  return m;
}

Positions translated(const Positions& positions, const Eigen::Vector3d& offset) {
  Positions out = positions;
  out.rowwise() += offset.transpose();
  return out;
}

Box3 bounds(const Positions& positions) {
  if (positions.rows() == 0) throw std::invalid_argument("bounds: no positions");
  return {positions.colwise().minCoeff().transpose(), positions.colwise().maxCoeff().transpose()};
}

std::optional<TimeInterval> moving_box_meets_box(const Box3& start, const Box3& end,
                                                 const Box3& fixed) {
  TimeInterval t{mpq_class(0), mpq_class(1)};
  // Each constraint f(t) = (1 - t) f0 + t f1 >= 0 is linear in t: it keeps t on one side of
  // its root, or everywhere / nowhere when f is constant.
  const auto keep = [&t](const mpq_class& f0, const mpq_class& f1) {
    const mpq_class slope = f1 - f0;
    if (sgn(slope) == 0) {
      if (sgn(f0) < 0) t.first = 2;  // empty
      return;
    }
    const mpq_class root = -f0 / slope;
    if (sgn(slope) > 0)
      t.first = std::max(t.first, root);
    else
      t.last = std::min(t.last, root);
  };
  for (int axis = 0; axis < 3; ++axis) {
    // hi(t) >= fixed.lo and lo(t) <= fixed.hi.
    keep(mpq_class(start.hi[axis]) - mpq_class(fixed.lo[axis]),
         mpq_class(end.hi[axis]) - mpq_class(fixed.lo[axis]));
    keep(mpq_class(fixed.hi[axis]) - mpq_class(start.lo[axis]),
         mpq_class(fixed.hi[axis]) - mpq_class(end.lo[axis]));
  }
  if (t.first > t.last) return std::nullopt;
  return t;
}

// ---- QueryCsvWriter ------------------------------------------------------------------------------

QueryCsvWriter::QueryCsvWriter(const std::string& dir) {
  static const std::regex data_file("data_[0-9]+\\.csv");
  const fs::path root = fs::path(dir) / "queries";
  const fs::path folders[2] = {root / "vertex-face", root / "edge-edge"};
  for (int k = 0; k < 2; ++k) {
    std::error_code error;
    fs::create_directories(folders[k], error);
    if (error || !fs::is_directory(folders[k]))
      throw std::runtime_error(folders[k].string() + ": cannot create the folder");
    std::vector<fs::path> stale;
    for (const auto& entry : fs::directory_iterator(folders[k]))
      if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), data_file))
        stale.push_back(entry.path());
    for (const fs::path& p : stale) fs::remove(p);
    folders_[k] = folders[k].string();
  }
}

void QueryCsvWriter::add_step(const Scene& scene, const SceneResult& result) {
  if (result.candidates.empty() && !result.contacts.empty())
    throw std::invalid_argument(
        "QueryCsvWriter::add_step: the result has no candidates (set record_candidates)");
  const auto by_pair = [](const SceneContact& c, const ScenePair& p) { return c.pair < p; };
  for (const ScenePair& pair : result.candidates) {
    // result.contacts is sorted by pair (scene.hpp).
    const auto it =
        std::lower_bound(result.contacts.begin(), result.contacts.end(), pair, by_pair);
    const bool truth = it != result.contacts.end() && it->pair == pair;
    if (pair.type == QueryType::vertex_face) {
      append_query(text_[0], scene.vertex_face_query(pair), truth);
      ++pending_.vertex_face;
      pending_.vertex_face_colliding += truth;
    } else {
      append_query(text_[1], scene.edge_edge_query(pair), truth);
      ++pending_.edge_edge;
      pending_.edge_edge_colliding += truth;
    }
  }
}

QueryBatch QueryCsvWriter::flush() {
  const QueryBatch written = pending_;
  for (int k = 0; k < 2; ++k) {
    if (text_[k].empty()) continue;
    const fs::path path =
        fs::path(folders_[k]) / ("data_" + std::to_string(written.index) + ".csv");
    std::ofstream out(path, std::ios::binary);
    out << text_[k];
    out.close();
    if (!out) throw std::runtime_error(path.string() + ": write failed");
    text_[k].clear();
  }
  pending_ = QueryBatch{};
  pending_.index = written.index + 1;
  return written;
}

}  // namespace exactccd::scenes
