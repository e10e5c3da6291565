#include "oracle/barrier_report.hpp"

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "corpus/barrier_steps.hpp"
#include "exactccd/scene.hpp"

namespace exactccd::oracle {
namespace {

/// The same contacts (pairs and TOI doubles, both sorted by pair) and the same earliest.
bool same_contacts(const SceneResult& a, const SceneResult& b) {
  const auto same = [](const SceneContact& x, const SceneContact& y) {
    return x.pair == y.pair && x.toi_lo == y.toi_lo && x.toi_hi == y.toi_hi;
  };
  return a.contacts.size() == b.contacts.size() && same(a.earliest, b.earliest) &&
         std::equal(a.contacts.begin(), a.contacts.end(), b.contacts.begin(), same);
}

/// A time in JSON: 17 significant digits, or null for no contact (JSON has no infinity).
std::string json_time(double t) {
  if (!std::isfinite(t)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", t);
  return text;
}

double peak_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

/// Starts a new peak of the resident set (Linux: "5" to /proc/self/clear_refs resets VmHWM);
/// false where that is not possible.
bool reset_peak() {
#if defined(__GLIBC__)
  malloc_trim(0);  // hand the previous steps' freed memory back, so that it is not counted
#endif
  std::FILE* f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  const bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

/// The peak resident set since the last reset_peak (VmHWM), in MiB; the process's peak where
/// /proc is not readable.
double peak_since_reset_mib() {
  if (std::FILE* f = std::fopen("/proc/self/status", "r")) {
    char line[256];
    long kib = -1;
    while (std::fgets(line, sizeof line, f))
      if (std::sscanf(line, "VmHWM: %ld kB", &kib) == 1) break;
    std::fclose(f);
    if (kib >= 0) return static_cast<double>(kib) / 1024.0;
  }
  return peak_mib();
}

template <class F>
double median_ms(int repetitions, F&& f) {
  std::vector<double> t;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace

int run_barrier_report(const BarrierReportOptions& options, std::FILE* out) {
  const std::vector<std::string>& names = corpus::barrier_step_names();
  for (const std::string& s : options.steps)
    if (std::find(names.begin(), names.end(), s) == names.end())
      throw std::invalid_argument("no barrier step named \"" + s + "\"");
  if (!(options.scale > 0) || !std::isfinite(options.scale))
    throw std::invalid_argument("the scale must be positive and finite");
  if (!(options.min_separation >= 0) || !std::isfinite(options.min_separation))
    throw std::invalid_argument("the minimum separation must be finite and >= 0");
  if (options.repetitions < 1) throw std::invalid_argument("repetitions must be >= 1");
  if (!options.json)
    std::fprintf(out, "%-14s %-5s %8s %10s %10s %9s %12s %9s %9s %9s %9s %8s\n", "step", "time",
                 "tris", "candidates", "time_cuts", "contacts", "earliest", "ec_1t_ms",
                 "ec_2t_ms", "fc_1t_ms", "fc_2t_ms", "peak_mib");
  int status = 0;
  for (const std::string& name : names) {
    if (!options.steps.empty() &&
        std::find(options.steps.begin(), options.steps.end(), name) == options.steps.end())
      continue;
    const bool per_step = reset_peak();
    const std::vector<corpus::StepBody> bodies = corpus::barrier_step(name, options.scale);
    long triangles = 0;
    for (const corpus::StepBody& b : bodies) triangles += static_cast<long>(b.mesh.triangles.rows());
    Scene scene = corpus::make_scene(bodies);
    SceneResult reference;
    for (const bool by_time : {true, false}) {
      if (!by_time && !options.compare_off) break;
      SceneOptions o;
      o.min_separation = options.min_separation;
      o.cull_by_time = by_time;
      double ms[2][2];  // [earliest, find][threads - 1]
      SceneResult r;
      EarliestContact e;
      for (int threads = 1; threads <= 2; ++threads) {
        o.max_threads = threads;
        ms[0][threads - 1] = median_ms(options.repetitions, [&] { e = scene.earliest_contact(o); });
        ms[1][threads - 1] = median_ms(options.earliest_only ? 1 : options.repetitions,
                                       [&] { r = scene.find_contacts(o); });
      }
      if (!(e.contact.pair == r.earliest.pair) || e.contact.toi_lo != r.earliest.toi_lo ||
          e.contact.toi_hi != r.earliest.toi_hi) {
        std::fprintf(stderr, "%s: earliest_contact differs from find_contacts().earliest\n",
                     name.c_str());
        status = 1;
      }
      if (by_time) {
        reference = r;
      } else if (!same_contacts(r, reference)) {
        std::fprintf(stderr, "%s: the cull by time changed an answer\n", name.c_str());
        status = 1;
      }
      const unsigned long long candidates =
          r.stats.vertex_face_candidates + r.stats.edge_edge_candidates;
      // The step's peak resident memory (its scene, both settings so far) where Linux can reset
      // the peak, else the process's.
      const double peak = per_step ? peak_since_reset_mib() : peak_mib();
      if (options.json) {
        std::fprintf(
            out,
            "{\"step\": \"%s\", \"cull_by_time\": %s, \"min_separation\": %.17g, \"triangles\": "
            "%ld, \"candidates\": %llu, \"time_culled\": %llu, \"contacts\": %zu, "
            "\"earliest\": %s, \"earliest_contact_ms\": [%.3f, %.3f], "
            "\"find_contacts_ms\": [%.3f, %.3f], \"peak_mib\": %.1f}\n",
            name.c_str(), by_time ? "true" : "false", options.min_separation, triangles,
            candidates, static_cast<unsigned long long>(r.stats.time_culled), r.contacts.size(),
            json_time(r.earliest.toi_lo).c_str(), ms[0][0], ms[0][1], ms[1][0], ms[1][1],
            peak);
      } else {
        std::fprintf(out,
                     "%-14s %-5s %8ld %10llu %10llu %9zu %12.6g %9.1f %9.1f %9.1f %9.1f %8.1f\n",
                     name.c_str(), by_time ? "on" : "off", triangles, candidates,
                     static_cast<unsigned long long>(r.stats.time_culled), r.contacts.size(),
                     r.earliest.toi_lo, ms[0][0], ms[0][1], ms[1][0], ms[1][1], peak);
      }
      std::fflush(out);
    }
  }
  if (!options.json) std::fprintf(out, "peak memory %.1f MiB\n", peak_mib());
  return status;
}

}  // namespace exactccd::oracle
