// Uses an installed exactccd through its public API only: decides one vertex-face query, then
// walks a two-mesh scene to its earliest contact. Exits non-zero when an answer is not the one
// worked out by hand below, so that the test suite can run it against a fresh install.
#include <cmath>
#include <cstdio>
#include <cstring>

#include <exactccd/ccd.hpp>
#include <exactccd/scene.hpp>
#include <exactccd/version.hpp>

namespace {

int failures = 0;

void expect(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "consumer: FAILED: %s\n", what);
    ++failures;
  }
}

}  // namespace

int main() {
  std::printf("exactccd headers %s, library %s\n", EXACTCCD_VERSION_STRING,
              exactccd::library_version());
  expect(std::strcmp(EXACTCCD_VERSION_STRING, exactccd::library_version()) == 0,
         "the headers and the library are the same version");

  // A vertex falls from z = 1 to z = -1 through the unit triangle in z = 0: contact at t = 1/2,
  // a double, so the tightest enclosure is the point [0.5, 0.5].
  exactccd::VertexFaceQuery q;
  q.p_t0 = {0.25, 0.25, 1.0};
  q.p_t1 = {0.25, 0.25, -1.0};
  q.a_t0 = q.a_t1 = {0.0, 0.0, 0.0};
  q.b_t0 = q.b_t1 = {1.0, 0.0, 0.0};
  q.c_t0 = q.c_t1 = {0.0, 1.0, 0.0};
  const exactccd::CcdResult r = exactccd::vertex_face_ccd(q);
  std::printf("vertex-face: collides %d, toi [%.17g, %.17g], decided by %s\n", r.collides,
              r.toi_lo, r.toi_hi, exactccd::to_string(r.decided_by));
  expect(r.collides && r.toi_lo == 0.5 && r.toi_hi == 0.5, "vertex-face contact at t = 1/2");

  // Two meshes: a static floor (two triangles at z = 0) and a moving triangle that falls from
  // z = 1 to z = -3, so its vertices reach the floor at t = 1/4.
  exactccd::Positions floor(4, 3);
  floor << -2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0;
  exactccd::Triangles floor_faces(2, 3);
  floor_faces << 0, 1, 2, 0, 2, 3;
  exactccd::Positions start(3, 3), end(3, 3);
  start << 0, 0, 1, 1, 0, 1, 0, 1, 1;
  end << 0, 0, -3, 1, 0, -3, 0, 1, -3;
  exactccd::Triangles faces(1, 3);
  faces << 0, 1, 2;

  exactccd::Scene scene;
  scene.add_static_mesh(floor, floor_faces);
  const exactccd::MeshId falling = scene.add_mesh(start, faces);
  scene.set_motion(falling, start, end);
  const exactccd::EarliestContact first = scene.earliest_contact();
  std::printf("scene: collides %d, earliest toi [%.17g, %.17g], %llu vertex-face candidates\n",
              first.collides, first.contact.toi_lo, first.contact.toi_hi,
              static_cast<unsigned long long>(first.stats.vertex_face_candidates));
  expect(first.collides && first.contact.toi_lo == 0.25 && first.contact.toi_hi == 0.25,
         "the falling triangle reaches the floor at t = 1/4");

  if (failures == 0) std::printf("consumer: all answers as expected\n");
  return failures == 0 ? 0 : 1;
}
