// The one pipeline (pipeline/dispatch.hpp): the order of its stages, read with an instrumented
// problem, and the stage recorded from the filter's outcome in one place; then every instance
// (linear and rigid, contact and minimum separation) through the public entries in every mode.
// PROOF: proofs/pipeline.md#one-pipeline
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "exactccd/ccd.hpp"
#include "exactccd/rigid.hpp"
#include "pipeline/dispatch.hpp"

namespace exactccd {
namespace {

using pipeline::FilterOutcome;
using Verdict = FilterOutcome::Verdict;

/// A problem that records which hooks the dispatcher called, in order, and answers what the
/// test scripts.
struct Script {
  bool culled = false;
  int exponent = 0;
  FilterOutcome outcome;
  std::vector<std::string> calls;
  double filtered_value = 0.0;  // the query value the filter saw
  const FilterOutcome* seen_by_exact = nullptr;
};
Script* script = nullptr;

struct FakeQuery {
  double value = 0.0;
};

/// The fake query has no motion to hold: the state at its start is itself (held_at_start.hpp,
/// found by argument-dependent lookup).
FakeQuery held_at_start(FakeQuery q) { return q; }

struct FakeStage {
  int tightened = 0;
};

struct FakeProblem {
  using Query = FakeQuery;
  static CcdResult float_only(const Query&, const CcdOptions&) {
    script->calls.push_back("float_only");
    CcdResult r;
    r.decided_by = Stage::float_only;
    return r;
  }
  static CcdResult exact(const Query&, const CcdOptions&) {
    script->calls.push_back("exact");
    return CcdResult{};
  }
  static bool culled(const Query&, const CcdOptions&) {
    script->calls.push_back("culled");
    return script->culled;
  }
  static int normalising_exponent(const Query&) { return script->exponent; }
  static Query scaled(const Query& q, int s) {
    script->calls.push_back("scaled");
    return {std::ldexp(q.value, s)};
  }
  static FakeStage exact_stage(const Query&, const CcdOptions&) {
    script->calls.push_back("exact_stage");
    return {};
  }
  static FilterOutcome filter(const Query& q, const CcdOptions&, FakeStage&) {
    script->calls.push_back("filter");
    script->filtered_value = q.value;
    return script->outcome;
  }
  static std::pair<double, double> tighten(FakeStage& stage, double lo, double hi,
                                           const CcdOptions&) {
    script->calls.push_back("tighten");
    ++stage.tightened;
    return {lo + (hi - lo) / 4, hi - (hi - lo) / 4};
  }
  static CcdResult after_filter(const Query&, const CcdOptions&, const FilterOutcome& f,
                                FakeStage&) {
    script->calls.push_back("after_filter");
    script->seen_by_exact = &f;
    CcdResult r;
    r.collides = true;
    r.toi_lo = r.toi_hi = f.cleared_until;
    return r;
  }
};

CcdResult run(Script& s, Mode mode = Mode::filtered, double value = 1.0) {
  script = &s;
  CcdOptions options;
  options.mode = mode;
  return pipeline::certified_ccd<FakeProblem>(FakeQuery{value}, options);
}

using Calls = std::vector<std::string>;

TEST(Pipeline, ModesChooseTheirPathAndNothingElse) {
  Script s;
  EXPECT_EQ(run(s, Mode::float_only).decided_by, Stage::float_only);
  EXPECT_EQ(s.calls, Calls{"float_only"});
  Script e;
  run(e, Mode::exact);
  EXPECT_EQ(e.calls, Calls{"exact"});
}

TEST(Pipeline, CullingAnswersBeforeAnyFilter) {
  Script s;
  s.culled = true;
  const CcdResult r = run(s);
  EXPECT_FALSE(r.collides);
  EXPECT_EQ(r.decided_by, Stage::culling);
  EXPECT_TRUE(std::isinf(r.toi_lo));
  EXPECT_EQ(s.calls, Calls{"culled"});
}

TEST(Pipeline, TheFilterSeesTheNormalisedQuery) {
  Script s;
  s.exponent = -3;
  s.outcome.verdict = Verdict::no_contact;
  run(s, Mode::filtered, 8.0);
  EXPECT_EQ(s.filtered_value, 1.0);
  EXPECT_EQ(s.calls, (Calls{"culled", "scaled", "exact_stage", "filter"}));
}

TEST(Pipeline, AContactWhoseBracketIsNotFinalIsTightenedByTheExactStage) {
  Script s;
  s.outcome.verdict = Verdict::contact;
  s.outcome.toi_lo = 0.25;
  s.outcome.toi_hi = 0.75;
  const CcdResult r = run(s);
  EXPECT_TRUE(r.collides);
  EXPECT_EQ(r.toi_lo, 0.375);
  EXPECT_EQ(r.toi_hi, 0.625);
  EXPECT_EQ(r.decided_by, Stage::filter_exact_toi);
  EXPECT_EQ(s.calls, (Calls{"culled", "exact_stage", "filter", "tighten"}));

  Script f = s;
  f.calls.clear();
  f.outcome.toi_final = true;
  const CcdResult g = run(f);
  EXPECT_EQ(g.toi_lo, 0.25);
  EXPECT_EQ(g.toi_hi, 0.75);
  EXPECT_EQ(g.decided_by, Stage::filter);
  EXPECT_EQ(f.calls, (Calls{"culled", "exact_stage", "filter"}));
}

TEST(Pipeline, AnUncertainOutcomeGoesToTheExactPathWithWhatItCertified) {
  Script s;
  s.outcome.verdict = Verdict::uncertain;
  s.outcome.cleared_until = 0.5;
  const CcdResult r = run(s);
  EXPECT_EQ(s.calls, (Calls{"culled", "exact_stage", "filter", "after_filter"}));
  EXPECT_EQ(r.toi_lo, 0.5);  // the exact path read the outcome the filter returned
}

TEST(Pipeline, StageIsReadFromTheOutcomeInOnePlace) {
  FilterOutcome f;
  f.verdict = Verdict::no_contact;
  EXPECT_EQ(pipeline::stage_of(f), Stage::filter);
  f.exact_used = true;
  EXPECT_EQ(pipeline::stage_of(f), Stage::exact_at_double);
  f.culled = true;
  EXPECT_EQ(pipeline::stage_of(f), Stage::culling);
  FilterOutcome c;
  c.verdict = Verdict::contact;
  c.toi_final = true;
  EXPECT_EQ(pipeline::stage_of(c), Stage::filter);
  c.toi_exact = true;
  EXPECT_EQ(pipeline::stage_of(c), Stage::filter_exact_toi);
  c.exact_used = true;
  EXPECT_EQ(pipeline::stage_of(c), Stage::exact_at_double);
}

/// Every instance through the public entries in every mode: certified modes agree on a contact
/// and a miss, float_only says it is float_only, and nothing throws "not supported".
TEST(Pipeline, EveryInstanceRunsInEveryMode) {
  // A vertex falling through a static triangle at t = 1/2; an edge crossing an edge at 1/2.
  VertexFaceQuery vf{{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                     {0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EdgeEdgeQuery ee{{0, 0.5, 1}, {1, 0.5, 1}, {0.5, 0, 0}, {0.5, 1, 0},
                   {0, 0.5, -1}, {1, 0.5, -1}, {0.5, 0, 0}, {0.5, 1, 0}};
  RigidVertexFaceQuery rvf;
  rvf.p = vf.p_t0, rvf.a = vf.a_t0, rvf.b = vf.b_t0, rvf.c = vf.c_t0;
  rvf.vertex.kind = PathKind::linear;
  rvf.vertex.linear_end[0] = vf.p_t1;
  rvf.face.kind = PathKind::rigid;
  rvf.face.rigid = RigidMotion::turn({0.25, 0.25, 0}, {0, 0, 1}, 0.5);
  RigidEdgeEdgeQuery ree;
  ree.ea0 = ee.ea0_t0, ree.ea1 = ee.ea1_t0, ree.eb0 = ee.eb0_t0, ree.eb1 = ee.eb1_t0;
  ree.edge_a.kind = PathKind::linear;
  ree.edge_a.linear_end[0] = ee.ea0_t1;
  ree.edge_a.linear_end[1] = ee.ea1_t1;
  ree.edge_b.kind = PathKind::rigid;
  ree.edge_b.rigid = RigidMotion::turn({0.5, 0.5, 0}, {0, 0, 1}, 0.5);
  for (const double delta : {0.0, 0.125}) {
    for (const Mode mode : {Mode::filtered, Mode::exact, Mode::float_only}) {
      CcdOptions o;
      o.mode = mode;
      o.min_separation = delta;
      SCOPED_TRACE(std::string(to_string(mode)) + " delta " + std::to_string(delta));
      const CcdResult results[4] = {vertex_face_ccd(vf, o), edge_edge_ccd(ee, o),
                                    vertex_face_ccd(rvf, o).ccd, edge_edge_ccd(ree, o).ccd};
      for (const CcdResult& r : results) {
        EXPECT_TRUE(r.collides);
        // Contact at 1/2, or within delta when the vertex (edge) is delta above: 1/2 - delta/2.
        if (mode == Mode::float_only) {  // uncertified: its time is not checked
          EXPECT_EQ(r.decided_by, Stage::float_only);
          continue;
        }
        EXPECT_NE(r.decided_by, Stage::float_only);
        EXPECT_LE(r.toi_lo, 0.5 - delta / 2);
        EXPECT_GE(r.toi_hi, 0.5 - delta / 2);
      }
    }
  }
}

}  // namespace
}  // namespace exactccd
