#include "corpus/assembly/assembly_step.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>

#include "exactccd/ccd.hpp"

namespace exactccd::assembly {

namespace {

using Eigen::Vector3d;

Vector3d row(const Positions& x, std::int32_t i) { return x.row(i).transpose(); }

SideMotion at_rest() { return SideMotion::of(RigidMotion{}); }

/// All candidates as pair keys, in one list.
std::vector<PairKey> pair_keys(const Candidates& c) {
  std::vector<PairKey> out;
  out.reserve(c.size());
  for (const auto& [k, l] : c.moving_vertex_static_face)
    out.push_back({PairKind::key_vertex_lock_face, k, l});
  for (const auto& [k, l] : c.static_vertex_moving_face)
    out.push_back({PairKind::lock_vertex_key_face, k, l});
  for (const auto& [k, l] : c.edge_edge) out.push_back({PairKind::edge_edge, k, l});
  return out;
}

struct Outcome {
  CcdResult ccd;
  bool has_time = false;
  double time_lo = 0, time_hi = 0;
};

/// Runs `decide(pair)` on every candidate in parallel and gathers the contacts.
template <class Decide>
StepDecision decide_all(const Candidates& candidates, Decide&& decide) {
  const std::vector<PairKey> keys = pair_keys(candidates);
  std::vector<Outcome> out(keys.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, keys.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = decide(keys[i]);
                    });
  StepDecision d;
  d.queries = keys.size();
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const Stage s = out[i].ccd.decided_by;
    if (s == Stage::culling)
      ++d.decided_by_culling;
    else if (s == Stage::exact || s == Stage::exact_at_double)
      ++d.decided_by_exact;
    else
      ++d.decided_by_filter;
    if (!out[i].ccd.collides) continue;
    PairContact c{keys[i], out[i].ccd.toi_lo, out[i].ccd.toi_hi, out[i].has_time, out[i].time_lo,
                  out[i].time_hi};
    d.contacts.push_back(c);
    if (!d.collides || c.toi_lo < d.earliest.toi_lo ||
        (c.toi_lo == d.earliest.toi_lo && c.pair < d.earliest.pair))
      d.earliest = c;
    d.collides = true;
  }
  return d;  // keys were sorted by kind, then pair: so are the contacts
}

}  // namespace

StepDecision from_scene(const SceneResult& result, MeshId key, MeshId lock) {
  StepDecision d;
  d.queries = result.stats.vertex_face_candidates + result.stats.edge_edge_candidates;
  for (const SceneContact& sc : result.contacts) {
    const ScenePair& p = sc.pair;
    const auto first = static_cast<std::int32_t>(p.first_index);
    const auto second = static_cast<std::int32_t>(p.second_index);
    PairKey k;
    if (p.type == QueryType::edge_edge) {
      k = p.first_mesh == key ? PairKey{PairKind::edge_edge, first, second}
                              : PairKey{PairKind::edge_edge, second, first};
    } else if (p.first_mesh == key && p.second_mesh == lock) {
      k = {PairKind::key_vertex_lock_face, first, second};
    } else {
      k = {PairKind::lock_vertex_key_face, second, first};
    }
    d.contacts.push_back({k, sc.toi_lo, sc.toi_hi, sc.has_time, sc.time_lo, sc.time_hi});
  }
  std::sort(d.contacts.begin(), d.contacts.end(),
            [](const PairContact& a, const PairContact& b) { return a.pair < b.pair; });
  for (const PairContact& c : d.contacts) {
    if (!d.collides || c.toi_lo < d.earliest.toi_lo) d.earliest = c;  // ties: the least pair
    d.collides = true;
  }
  return d;
}

const char* to_string(PairKind k) {
  switch (k) {
    case PairKind::key_vertex_lock_face: return "key vertex - lock face";
    case PairKind::lock_vertex_key_face: return "lock vertex - key face";
    case PairKind::edge_edge: return "key edge - lock edge";
  }
  return "?";
}

RigidVertexFaceQuery rigid_vertex_face(const StepMeshes& m, const Positions& start,
                                       const RigidMotion& motion, const PairKey& p) {
  RigidVertexFaceQuery q;
  if (p.kind == PairKind::key_vertex_lock_face) {
    const auto f = m.lock_triangles->row(p.lock);
    q.p = row(start, p.key);
    q.a = row(*m.lock_positions, f[0]);
    q.b = row(*m.lock_positions, f[1]);
    q.c = row(*m.lock_positions, f[2]);
    q.vertex = SideMotion::of(motion);
    q.face = at_rest();
  } else {
    const auto f = m.key_triangles->row(p.key);
    q.p = row(*m.lock_positions, p.lock);
    q.a = row(start, f[0]);
    q.b = row(start, f[1]);
    q.c = row(start, f[2]);
    q.vertex = at_rest();
    q.face = SideMotion::of(motion);
  }
  return q;
}

RigidEdgeEdgeQuery rigid_edge_edge(const StepMeshes& m, const Positions& start,
                                   const RigidMotion& motion, const PairKey& p) {
  RigidEdgeEdgeQuery q;
  q.ea0 = row(start, (*m.key_edges)(p.key, 0));
  q.ea1 = row(start, (*m.key_edges)(p.key, 1));
  q.eb0 = row(*m.lock_positions, (*m.lock_edges)(p.lock, 0));
  q.eb1 = row(*m.lock_positions, (*m.lock_edges)(p.lock, 1));
  q.edge_a = SideMotion::of(motion);
  q.edge_b = at_rest();
  return q;
}

StepDecision decide_rigid(const StepMeshes& m, const Positions& start, const RigidMotion& motion,
                          const Candidates& candidates, const CcdOptions& options) {
  return decide_all(candidates, [&](const PairKey& p) {
    const RigidCcdResult r = p.kind == PairKind::edge_edge
                                 ? edge_edge_ccd(rigid_edge_edge(m, start, motion, p), options)
                                 : vertex_face_ccd(rigid_vertex_face(m, start, motion, p), options);
    return Outcome{r.ccd, r.has_time, r.time_lo, r.time_hi};
  });
}

StepDecision decide_linear(const StepMeshes& m, const Positions& start, const Positions& end,
                           const Candidates& candidates, const CcdOptions& options) {
  const Positions& lock = *m.lock_positions;
  return decide_all(candidates, [&](const PairKey& p) {
    CcdResult r;
    if (p.kind == PairKind::key_vertex_lock_face) {
      const auto f = m.lock_triangles->row(p.lock);
      r = vertex_face_ccd(VertexFaceQuery{row(start, p.key), row(lock, f[0]), row(lock, f[1]),
                                          row(lock, f[2]), row(end, p.key), row(lock, f[0]),
                                          row(lock, f[1]), row(lock, f[2])},
                          options);
    } else if (p.kind == PairKind::lock_vertex_key_face) {
      const auto f = m.key_triangles->row(p.key);
      r = vertex_face_ccd(VertexFaceQuery{row(lock, p.lock), row(start, f[0]), row(start, f[1]),
                                          row(start, f[2]), row(lock, p.lock), row(end, f[0]),
                                          row(end, f[1]), row(end, f[2])},
                          options);
    } else {
      const std::int32_t a0 = (*m.key_edges)(p.key, 0), a1 = (*m.key_edges)(p.key, 1);
      const std::int32_t b0 = (*m.lock_edges)(p.lock, 0), b1 = (*m.lock_edges)(p.lock, 1);
      r = edge_edge_ccd(EdgeEdgeQuery{row(start, a0), row(start, a1), row(lock, b0), row(lock, b1),
                                      row(end, a0), row(end, a1), row(lock, b0), row(lock, b1)},
                        options);
    }
    return Outcome{r, true, r.toi_lo, r.toi_hi};
  });
}

std::size_t count_not_in(const std::vector<PairContact>& a, const std::vector<PairContact>& b) {
  std::size_t n = 0, j = 0;
  for (const PairContact& c : a) {
    while (j < b.size() && b[j].pair < c.pair) ++j;
    if (j == b.size() || !(b[j].pair == c.pair)) ++n;
  }
  return n;
}

}  // namespace exactccd::assembly
