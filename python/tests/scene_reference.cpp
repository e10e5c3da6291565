// The C++ side of test_scene.py: decides a scene file with exactccd::Scene and prints what the
// Python module's Scene must return, doubles as hexadecimal floats (exact).
//   scene_reference SCENE_FILE
// SCENE_FILE: "meshes N", then per mesh "moving V F" (V lines x0 y0 z0 x1 y1 z1) or
// "static V F" (V lines x y z), then F lines "i j k".
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "exactccd/scene.hpp"

namespace {

double read_double(std::istream& in) {
  std::string text;
  in >> text;
  return std::strtod(text.c_str(), nullptr);  // hexadecimal floats too
}

void print_pair(const exactccd::ScenePair& p) {
  std::printf("%s %u %u %u %u", exactccd::to_string(p.type), p.first_mesh, p.first_index,
              p.second_mesh, p.second_index);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: scene_reference SCENE_FILE\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  std::string word;
  int meshes = 0;
  in >> word >> meshes;
  exactccd::Scene scene;
  for (int m = 0; m < meshes; ++m) {
    int v = 0, f = 0;
    in >> word >> v >> f;
    const bool moving = word == "moving";
    exactccd::Positions start(v, 3), end(v, 3);
    for (int i = 0; i < v; ++i) {
      for (int k = 0; k < 3; ++k) start(i, k) = read_double(in);
      for (int k = 0; k < 3; ++k) end(i, k) = moving ? read_double(in) : start(i, k);
    }
    exactccd::Triangles triangles(f, 3);
    for (int i = 0; i < f; ++i) in >> triangles(i, 0) >> triangles(i, 1) >> triangles(i, 2);
    if (!in) {
      std::fprintf(stderr, "scene_reference: malformed %s\n", argv[1]);
      return 2;
    }
    if (moving) {
      const exactccd::MeshId id = scene.add_mesh(start, triangles);
      scene.set_motion(id, start, end);
    } else {
      scene.add_static_mesh(start, triangles);
    }
  }
  exactccd::SceneOptions options;
  options.record_candidates = true;
  const exactccd::SceneResult result = scene.find_contacts(options);
  for (const exactccd::SceneContact& c : result.contacts) {
    std::printf("contact ");
    print_pair(c.pair);
    std::printf(" %a %a\n", c.toi_lo, c.toi_hi);
  }
  std::printf("candidates %zu vf %llu ee %llu\n", result.candidates.size(),
              static_cast<unsigned long long>(result.stats.vertex_face_candidates),
              static_cast<unsigned long long>(result.stats.edge_edge_candidates));
  const exactccd::EarliestContact earliest = scene.earliest_contact(options);
  if (earliest.collides) {
    std::printf("earliest ");
    print_pair(earliest.contact.pair);
    std::printf(" %a %a\n", earliest.contact.toi_lo, earliest.contact.toi_hi);
  } else {
    std::printf("earliest none\n");
  }
  return 0;
}
