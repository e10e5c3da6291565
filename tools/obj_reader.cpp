#include "obj_reader.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "exactccd/query_file.hpp"

namespace exactccd::cli {

namespace {

std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line.substr(0, line.find('#')));
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

/// The whole word as a finite double, else nothing.
bool parse_double(const std::string& word, double& value) {
  if (word.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size() && std::isfinite(value);
}

bool parse_integer(const std::string& word, long long& value) {
  if (word.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(word.c_str(), &end, 10);
  return errno == 0 && end == word.c_str() + word.size();
}

}  // namespace

ObjMesh read_obj(const std::string& path) {
  LineReader in(path, "an OBJ file");
  std::vector<double> coordinates;
  std::vector<std::int32_t> corners;
  std::int32_t largest = -1;  // the largest vertex a face refers to, and its line
  std::size_t largest_line = 0;
  const auto fail = [&](const std::string& what) {
    return InputError(path, in.line_number(), what);
  };
  std::string line;
  while (in.next(line)) {
    const std::vector<std::string> w = words_of(line);
    if (w.empty()) continue;
    if (w[0] == "v") {
      // x y z, with an optional w (rational curves) or r g b (vertex colours) after them.
      if (w.size() != 4 && w.size() != 5 && w.size() != 7)
        throw fail("a vertex needs x y z (optionally w, or r g b), found " +
                   std::to_string(w.size() - 1) + " numbers");
      for (int k = 1; k <= 3; ++k) {
        double x;
        if (!parse_double(w[k], x))
          throw fail("vertex coordinate " + quote_for_message(w[k]) +
                     " is not a finite number");
        coordinates.push_back(x);
      }
      if (coordinates.size() / 3 > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw fail("too many vertices");
    } else if (w[0] == "f") {
      if (w.size() < 4) throw fail("a face needs at least 3 vertices");
      const long long defined = static_cast<long long>(coordinates.size() / 3);
      std::vector<std::int32_t> face;
      for (std::size_t k = 1; k < w.size(); ++k) {
        long long index;
        if (!parse_integer(w[k].substr(0, w[k].find('/')), index) || index == 0)
          throw fail("face vertex " + quote_for_message(w[k]) +
                     " is not a vertex number (1, 2, ... or -1, -2, ...)");
        // Negative: relative to the vertices read so far (-1 is the last one).
        const long long zero_based = index < 0 ? defined + index : index - 1;
        if (zero_based < 0 || zero_based >= std::numeric_limits<std::int32_t>::max())
          throw fail("face vertex " + quote_for_message(w[k]) + " is out of range");
        face.push_back(static_cast<std::int32_t>(zero_based));
        if (face.back() > largest) {
          largest = face.back();
          largest_line = in.line_number();
        }
      }
      for (std::size_t i = 0; i < face.size(); ++i)
        for (std::size_t j = i + 1; j < face.size(); ++j)
          if (face[i] == face[j])
            throw fail("the face repeats vertex " + std::to_string(face[i] + 1));
      for (std::size_t k = 1; k + 1 < face.size(); ++k)
        corners.insert(corners.end(), {face[0], face[k], face[k + 1]});
    }
  }
  const auto vertex_count = static_cast<Eigen::Index>(coordinates.size() / 3);
  if (vertex_count == 0) throw InputError(path, 0, "no vertex (no 'v' line)");
  ObjMesh mesh;
  mesh.positions = Eigen::Map<const Positions>(coordinates.data(), vertex_count, 3);
  mesh.triangles = Eigen::Map<const Triangles>(corners.data(),
                                               static_cast<Eigen::Index>(corners.size() / 3), 3);
  if (largest >= vertex_count)
    throw InputError(path, largest_line,
                     "the face refers to vertex " + std::to_string(largest + 1) +
                         ", but the file has " + std::to_string(vertex_count) + " vertices");
  return mesh;
}

}  // namespace exactccd::cli
