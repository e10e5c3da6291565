#include "rigid_scene_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "exactccd/query_file.hpp"
#include "obj_reader.hpp"
#include "oracle/names.hpp"

namespace exactccd::cli {

const char* to_string(BodyKind kind) {
  switch (kind) {
    case BodyKind::rigid: return "rigid";
    case BodyKind::fixed: return "static";
    case BodyKind::deformable: return "deformable";
    case BodyKind::plane: return "plane";
  }
  return "unknown";
}

namespace {

using Json = nlohmann::json;

/// Larger scene files are refused (meshes that large belong in OBJ files).
constexpr std::size_t kMaxSceneBytes = std::size_t(1) << 30;

std::string system_message(int error) {
  return std::error_code(error, std::generic_category()).message();
}

/// The whole file; only a regular file is opened (as LineReader: stat first, then O_NONBLOCK
/// and fstat, so that a FIFO or a device is never read).
std::string read_regular_file(const std::string& path) {
  require_regular_file(path, "a JSON scene file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(path, 0, system_message(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat status {};
  if (::fstat(fd, &status) != 0) throw InputError(path, 0, system_message(errno));
  if (!S_ISREG(status.st_mode)) throw InputError(path, 0, "is not a regular file");
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      text.append(buffer, static_cast<std::size_t>(n));
      if (text.size() > kMaxSceneBytes)
        throw InputError(path, 0, "larger than " + std::to_string(kMaxSceneBytes) +
                                      " bytes (put large meshes in OBJ files)");
      continue;
    }
    if (n == 0) return text;
    if (errno != EINTR) throw InputError(path, 0, "read error: " + system_message(errno));
  }
}

/// Reads one scene file; every error names the file and the key path.
class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw InputError(path_, 0, where + ": " + what);
  }

  void expect(bool ok, const Json& v, const std::string& where, const std::string& wanted) const {
    if (!ok) fail(where, "expected " + wanted + ", found " + describe(v));
  }

  /// The value's type and, for a scalar, the value (arrays and objects are never dumped: they
  /// may be huge or deeply nested).
  static std::string describe(const Json& v) {
    if (v.is_array()) return "an array of " + std::to_string(v.size()) + " elements";
    if (v.is_object()) return "an object";
    if (v.is_string()) return "the string " + quote_for_message(v.get<std::string>());
    return std::string(v.type_name()) + " " + v.dump();
  }

  void only_keys(const Json& object, const std::string& where,
                 std::initializer_list<const char*> keys) const {
    for (auto it = object.begin(); it != object.end(); ++it)
      if (std::none_of(keys.begin(), keys.end(), [&](const char* k) { return it.key() == k; })) {
        std::string allowed;
        for (const char* k : keys) allowed += (allowed.empty() ? "" : ", ") + std::string(k);
        fail(where, "unknown key " + quote_for_message(it.key()) + " (allowed: " + allowed + ")");
      }
  }

  const Json& require(const Json& object, const std::string& where, const char* key) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(where, std::string("missing key \"") + key + "\"");
    return *it;
  }

  double number(const Json& v, const std::string& where) const {
    expect(v.is_number(), v, where, "a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(where, "the number is not finite (beyond the doubles)");
    return x;
  }

  Eigen::Vector3d vector3(const Json& v, const std::string& where) const {
    expect(v.is_array() && v.size() == 3, v, where, "an array of 3 numbers");
    return {number(v[0], where + "[0]"), number(v[1], where + "[1]"), number(v[2], where + "[2]")};
  }

  Positions positions(const Json& v, const std::string& where) const {
    expect(v.is_array() && !v.empty(), v, where, "a non-empty array of [x, y, z]");
    if (v.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
      fail(where, "too many vertices");
    Positions x(static_cast<Eigen::Index>(v.size()), 3);
    for (std::size_t i = 0; i < v.size(); ++i)
      x.row(static_cast<Eigen::Index>(i)) =
          vector3(v[i], where + "[" + std::to_string(i) + "]").transpose();
    return x;
  }

  Triangles triangles(const Json& v, const std::string& where, Eigen::Index vertices) const {
    expect(v.is_array(), v, where, "an array of [i, j, k]");
    Triangles t(static_cast<Eigen::Index>(v.size()), 3);
    for (std::size_t f = 0; f < v.size(); ++f) {
      const std::string at = where + "[" + std::to_string(f) + "]";
      expect(v[f].is_array() && v[f].size() == 3, v[f], at, "an array of 3 vertex indices");
      for (int k = 0; k < 3; ++k) {
        const Json& index = v[f][k];
        const std::string ak = at + "[" + std::to_string(k) + "]";
        expect(index.is_number_integer(), index, ak, "an integer vertex index (0-based)");
        const bool in_range = index.is_number_unsigned()
                                  ? index.get<std::uint64_t>() < static_cast<std::uint64_t>(vertices)
                                  : index.get<std::int64_t>() >= 0 &&
                                        index.get<std::int64_t>() < vertices;
        if (!in_range)
          fail(ak, "vertex index " + index.dump() + " out of range (indices 0 to " +
                       std::to_string(vertices - 1) + ": the body has " +
                       std::to_string(vertices) + (vertices == 1 ? " vertex)" : " vertices)"));
        t(static_cast<Eigen::Index>(f), k) = static_cast<std::int32_t>(index.get<std::int64_t>());
      }
      const auto row = static_cast<Eigen::Index>(f);
      if (t(row, 0) == t(row, 1) || t(row, 1) == t(row, 2) || t(row, 0) == t(row, 2))
        fail(at, "the triangle repeats a vertex");
    }
    return t;
  }

  RigidMotion motion(const Json& v, const std::string& where) const {
    expect(v.is_object(), v, where, "a motion object");
    only_keys(v, where, {"pivot", "translation", "cayley", "axis", "angle_degrees", "comment"});
    const auto vector_or_zero = [&](const char* key) -> Eigen::Vector3d {
      const auto it = v.find(key);
      return it == v.end() ? Eigen::Vector3d::Zero() : vector3(*it, where + "." + key);
    };
    const Eigen::Vector3d pivot = vector_or_zero("pivot");
    const Eigen::Vector3d translation = vector_or_zero("translation");
    const bool cayley = v.contains("cayley");
    const bool turn = v.contains("axis") || v.contains("angle_degrees");
    if (cayley && turn)
      fail(where, "give either \"cayley\" or \"axis\" with \"angle_degrees\", not both");
    if (!turn) return RigidMotion{pivot, translation, vector_or_zero("cayley")};
    const Eigen::Vector3d axis = vector3(require(v, where, "axis"), where + ".axis");
    const double degrees = number(require(v, where, "angle_degrees"), where + ".angle_degrees");
    if (!(std::abs(degrees) < 180.0))
      fail(where + ".angle_degrees", "a turn must be less than 180 degrees either way");
    if (axis == Eigen::Vector3d::Zero()) fail(where + ".axis", "the axis must not be zero");
    try {
      return RigidMotion::turn(pivot, axis, degrees * (M_PI / 180.0), translation);
    } catch (const std::invalid_argument& e) {
      // A rounding corner case (|angle| rounded to pi); the message without its "exactccd: ",
      // which the command prints once in front of the file name.
      std::string what = e.what();
      if (what.rfind("exactccd: ", 0) == 0) what.erase(0, 10);
      fail(where, what);
    }
  }

  SceneBody body(const Json& v, const std::string& where, const std::filesystem::path& folder,
                 std::size_t index) const {
    expect(v.is_object(), v, where, "a body object");
    only_keys(v, where, {"name", "kind", "obj", "positions", "triangles", "end_positions",
                         "motion", "steps", "origin", "normal", "comment"});
    SceneBody b;
    b.name = "body " + std::to_string(index);
    if (const auto it = v.find("name"); it != v.end()) {
      expect(it->is_string(), *it, where + ".name", "a string");
      b.name = it->get<std::string>();
    }
    const Json& kind = require(v, where, "kind");
    expect(kind.is_string(), kind, where + ".kind",
           "\"rigid\", \"static\", \"deformable\" or \"plane\"");
    const std::string k = kind.get<std::string>();
    if (k == "rigid")
      b.kind = BodyKind::rigid;
    else if (k == "static")
      b.kind = BodyKind::fixed;
    else if (k == "deformable")
      b.kind = BodyKind::deformable;
    else if (k == "plane")
      return plane(v, where, std::move(b));
    else
      fail(where + ".kind", "expected \"rigid\", \"static\", \"deformable\" or \"plane\", found " +
                                quote_for_message(k));
    for (const char* key : {"origin", "normal"})
      if (v.contains(key))
        fail(where + "." + key, std::string("only a plane has an ") + key + " (a " +
                                    to_string(b.kind) + " body)");
    // The mesh: an OBJ file, or inline arrays.
    const bool obj = v.contains("obj");
    if (obj && (v.contains("positions") || v.contains("triangles")))
      fail(where, "give either \"obj\" or \"positions\" with \"triangles\", not both");
    if (obj) {
      const Json& file = v["obj"];
      expect(file.is_string() && !file.get<std::string>().empty(), file, where + ".obj",
             "a path (relative to the scene file's folder)");
      const ObjMesh mesh = read_obj((folder / file.get<std::string>()).string());
      b.positions = mesh.positions;
      b.triangles = mesh.triangles;
    } else {
      if (!v.contains("positions"))
        fail(where, "missing key \"obj\" or \"positions\" (with \"triangles\")");
      b.positions = positions(v["positions"], where + ".positions");
      b.triangles = triangles(require(v, where, "triangles"), where + ".triangles",
                              b.positions.rows());
    }
    b.end_positions = b.positions;
    if (v.contains("end_positions")) {
      if (b.kind != BodyKind::deformable)
        fail(where + ".end_positions", std::string("only a deformable body has end positions (a ") +
                                           to_string(b.kind) + " one)");
      b.end_positions = positions(v["end_positions"], where + ".end_positions");
      if (b.end_positions.rows() != b.positions.rows())
        fail(where + ".end_positions",
             std::to_string(b.end_positions.rows()) + " rows, but the body has " +
                 std::to_string(b.positions.rows()) + " vertices");
    }
    const bool one = v.contains("motion"), several = v.contains("steps");
    if ((one || several) && b.kind != BodyKind::rigid)
      fail(where + (one ? ".motion" : ".steps"),
           std::string("only a rigid body has motions (a ") + to_string(b.kind) + " one)");
    if (one && several) fail(where, "give either \"motion\" or \"steps\", not both");
    if (one) b.steps.push_back(motion(v["motion"], where + ".motion"));
    if (several) {
      const Json& steps = v["steps"];
      expect(steps.is_array(), steps, where + ".steps", "an array of motions");
      for (std::size_t s = 0; s < steps.size(); ++s)
        b.steps.push_back(motion(steps[s], where + ".steps[" + std::to_string(s) + "]"));
    }
    return b;
  }

  /// A static plane (Scene::add_plane): "origin" and "normal" (non-zero), nothing else.
  SceneBody plane(const Json& v, const std::string& where, SceneBody b) const {
    b.kind = BodyKind::plane;
    for (const char* key : {"obj", "positions", "triangles", "end_positions", "motion", "steps"})
      if (v.contains(key))
        fail(where + "." + key, "a plane has only \"origin\" and \"normal\"");
    b.origin = vector3(require(v, where, "origin"), where + ".origin");
    b.normal = vector3(require(v, where, "normal"), where + ".normal");
    if (b.normal.isZero(0)) fail(where + ".normal", "the normal is zero: no plane");
    b.positions = Positions(0, 3);
    b.end_positions = b.positions;
    return b;
  }

  RigidSceneFile scene(const Json& v, const std::filesystem::path& folder) const {
    expect(v.is_object(), v, "the scene", "an object with \"bodies\"");
    only_keys(v, "the scene",
              {"bodies", "t_max", "toi_width", "mode", "min_separation", "comment"});
    RigidSceneFile s;
    if (const auto it = v.find("t_max"); it != v.end()) {
      s.t_max = number(*it, "t_max");
      if (!(s.t_max > 0.0 && s.t_max <= 1.0)) fail("t_max", "must lie in (0, 1]");
    }
    if (const auto it = v.find("toi_width"); it != v.end()) {
      s.toi_width = number(*it, "toi_width");
      if (!(s.toi_width >= 0.0)) fail("toi_width", "must be >= 0");
    }
    if (const auto it = v.find("min_separation"); it != v.end()) {
      s.min_separation = number(*it, "min_separation");  // finite
      if (!(s.min_separation >= 0.0)) fail("min_separation", "must be >= 0");
    }
    if (const auto it = v.find("mode"); it != v.end()) {
      expect(it->is_string(), *it, "mode", oracle::mode_names_text());
      const std::string mode = it->get<std::string>();
      // float_only: the uncertified double test, for comparison; "default": filtered's old name
      if (const std::optional<Mode> m = oracle::parse_mode_name(mode))
        s.mode = *m;
      else
        fail("mode", "expected " + oracle::mode_names_text() + ", found " +
                         quote_for_message(mode));
    }
    const Json& bodies = require(v, "the scene", "bodies");
    expect(bodies.is_array() && !bodies.empty(), bodies, "bodies", "a non-empty array of bodies");
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      s.bodies.push_back(body(bodies[i], "bodies[" + std::to_string(i) + "]", folder, i));
      s.step_count = std::max(s.step_count, s.bodies.back().steps.size());
    }
    return s;
  }

 private:
  std::string path_;
};

}  // namespace

namespace {

/// JSON's text ends at its last byte: nlohmann's lexer takes a NUL byte for the end of the input
/// and would ignore whatever follows it.
void refuse_nul_bytes(const std::string& text, const std::string& path) {
  const std::size_t at = text.find('\0');
  if (at == std::string::npos) return;
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  throw InputError(path, static_cast<std::size_t>(line),
                   "a NUL byte at offset " + std::to_string(at) + " (JSON text has none)");
}

/// nlohmann keeps the last of repeated keys silently; a scene file whose "t_max" appears twice
/// is a mistake to report, not a choice to make. The callback sees every key as it is parsed.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(std::string path) : path_(std::move(path)) {}
  bool operator()(int, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start: keys_.emplace_back(); break;
      case Json::parse_event_t::object_end: keys_.pop_back(); break;
      case Json::parse_event_t::key: {
        const std::string& key = parsed.get_ref<const std::string&>();
        if (!keys_.back().insert(key).second)
          throw InputError(path_, 0,
                           "the key " + quote_for_message(key) +
                               " appears twice in one object (each key at most once)");
        break;
      }
      default: break;
    }
    return true;
  }

 private:
  std::string path_;
  std::vector<std::set<std::string>> keys_;
};

}  // namespace

RigidSceneFile read_rigid_scene_file(const std::string& path) {
  const std::string text = read_regular_file(path);
  refuse_nul_bytes(text, path);
  Json json;
  try {
    json = Json::parse(text, DuplicateKeyCheck(path));
  } catch (const Json::exception& e) {  // parse_error, and out_of_range for 1e999
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ..." without the tag.
    std::string what = e.what();
    if (const auto end = what.find("] "); what.rfind("[json.exception", 0) == 0 && end != what.npos)
      what = what.substr(end + 2);
    throw InputError(path, 0, "invalid JSON: " + printable(what));
  }
  return Reader(path).scene(json, std::filesystem::path(path).parent_path());
}

}  // namespace exactccd::cli
