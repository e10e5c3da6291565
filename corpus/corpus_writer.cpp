#include "corpus/corpus_writer.hpp"

#include <gmpxx.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "exactccd/rational_query.hpp"

namespace exactccd::families {

std::size_t GeneratedFamily::collisions() const {
  std::size_t n = 0;
  for (const CcdResult& r : exact) n += r.collides ? 1 : 0;
  return n;
}

namespace {

RationalQuery rational(const QueryType type, const QueryPoints& p) {
  RationalQuery q;
  q.type = type;
  for (int i = 0; i < 8; ++i)
    q.points[i] = {mpq_class(p[i].x()), mpq_class(p[i].y()), mpq_class(p[i].z())};
  return q;
}

std::string format_double(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

/// Every member of every family decided by the exact path (with the minimum separation
/// `delta` when not null), in parallel; results[f][m] for member m of family f.
std::vector<std::vector<CcdResult>> decide_exactly(const std::vector<Family>& families,
                                                   const mpq_class* delta) {
  std::vector<std::pair<std::size_t, std::size_t>> work;
  for (std::size_t f = 0; f < families.size(); ++f)
    for (std::size_t m = 0; m < families[f].members.size(); ++m) work.push_back({f, m});
  std::vector<std::vector<CcdResult>> results(families.size());
  for (std::size_t f = 0; f < families.size(); ++f) results[f].resize(families[f].members.size());
  // Each result goes to its own slot: the output does not depend on the number of threads.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, work.size(), 4),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        const auto [f, m] = work[i];
                        const RationalQuery q =
                            rational(families[f].type, families[f].members[m].points);
                        results[f][m] = delta ? exact_ccd(q, *delta) : exact_ccd(q);
                      }
                    });
  return results;
}

}  // namespace

Corpus generate_corpus(std::uint64_t seed, int per_family, const std::vector<std::string>& names) {
  Corpus corpus;
  corpus.seed = seed;
  corpus.per_family = per_family;
  std::vector<Family> families = generate_families(seed, per_family, names);

  // Variants need their base's verdicts: decide the bases that are not in the list too.
  std::map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < families.size(); ++i) index_of[families[i].name] = i;
  const std::size_t listed = families.size();
  for (std::size_t i = 0; i < listed; ++i) {
    const std::string base = families[i].base;
    if (index_of.count(base) == 0) {
      index_of[base] = families.size();
      families.push_back(generate_base_family(base, seed, per_family));
    }
  }

  const std::vector<std::vector<CcdResult>> results = decide_exactly(families, nullptr);

  for (std::size_t f = 0; f < listed; ++f) {
    GeneratedFamily g;
    g.family = families[f];
    g.exact = results[f];
    if (g.family.is_variant()) {
      const std::vector<CcdResult>& base = results[index_of.at(g.family.base)];
      for (std::size_t m = 0; m < g.exact.size(); ++m)
        if (g.exact[m].collides ==
            base[static_cast<std::size_t>(g.family.members[m].source)].collides)
          ++g.kept_verdict;
      g.family.parameters["members_kept_verdict"] = g.kept_verdict;
      g.family.parameters["members_changed_verdict"] = g.exact.size() - g.kept_verdict;
    }
    corpus.families.push_back(std::move(g));
  }
  return corpus;
}

Corpus generate_min_separation_corpus(double delta, std::uint64_t seed, int per_family,
                                      const std::vector<std::string>& names) {
  Corpus corpus;
  corpus.seed = seed;
  corpus.per_family = per_family;
  corpus.min_separation = delta;
  std::vector<Family> families = generate_min_separation_families(delta, seed, per_family, names);
  const mpq_class exact_delta(delta);
  std::vector<std::vector<CcdResult>> results = decide_exactly(families, &exact_delta);
  for (std::size_t f = 0; f < families.size(); ++f)
    corpus.families.push_back({std::move(families[f]), std::move(results[f])});
  return corpus;
}

std::vector<std::string> claim_mismatches(const GeneratedFamily& g) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < g.family.members.size(); ++i) {
    const Member& m = g.family.members[i];
    if (!m.claim_known) continue;  // random families, rounded variants, inexact scalings
    const CcdResult& r = g.exact[i];
    const std::string where = g.family.name + " member " + std::to_string(i) + " (" + m.label + ")";
    if (r.collides != m.collides) {
      out.push_back(where + ": constructed " + (m.collides ? "contact" : "no contact") +
                    ", the exact path says " + (r.collides ? "contact" : "no contact"));
      continue;
    }
    if (!m.collides) continue;
    const mpq_class lo(r.toi_lo), hi(r.toi_hi);
    bool ok = lo <= m.toi && m.toi <= hi;
    if (mpq_class(m.toi.get_d()) == m.toi)
      ok = ok && lo == m.toi && hi == m.toi;
    else
      ok = ok && r.toi_hi == std::nextafter(r.toi_lo, std::numeric_limits<double>::infinity());
    if (!ok)
      out.push_back(where + ": constructed t* = " + m.toi.get_str() + ", exact path [" +
                    format_double(r.toi_lo) + ", " + format_double(r.toi_hi) + "]");
  }
  return out;
}

std::string exact_fraction(double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("non-finite coordinate");
  const mpq_class q(value);  // exact, in lowest terms
  return q.get_num().get_str() + "," + q.get_den().get_str();
}

std::string family_folder(const Family& family) {
  return family.name + "/" + to_string(family.type);
}

std::string data_csv_text(const GeneratedFamily& g) {
  std::string text;
  for (std::size_t i = 0; i < g.family.members.size(); ++i) {
    const char* truth = g.exact[i].collides ? ",1\n" : ",0\n";
    for (const Eigen::Vector3d& p : g.family.members[i].points) {
      text += exact_fraction(p.x());
      text += ',';
      text += exact_fraction(p.y());
      text += ',';
      text += exact_fraction(p.z());
      text += truth;
    }
  }
  return text;
}

std::string toi_csv_text(const GeneratedFamily& g) {
  std::string text;
  for (std::size_t i = 0; i < g.exact.size(); ++i) {
    const CcdResult& r = g.exact[i];
    text += std::to_string(i);
    text += r.collides ? ",1," : ",0,";
    if (r.collides)
      text += format_double(r.toi_lo) + "," + format_double(r.toi_hi);
    else
      text += ",";
    text += '\n';
  }
  return text;
}

std::string manifest_text(const Corpus& corpus) {
  nlohmann::json families = nlohmann::json::array();
  for (const GeneratedFamily& g : corpus.families) {
    const Family& f = g.family;
    families.push_back({{"name", f.name},
                        {"base", f.base},
                        {"type", to_string(f.type)},
                        {"scale", f.scale},
                        {"offset", f.offset},
                        {"parameters", f.parameters},
                        {"queries", f.members.size()},
                        {"collisions", g.collisions()},
                        {"description", f.description}});
  }
  nlohmann::json manifest = {
      {"generator", "exactccd generate"},
      {"seed", corpus.seed},
      {"per_family", corpus.per_family},
      {"format",
       "<family>/<type>/data_0.csv: benchmark CSV (8 rows per query: "
       "x_num,x_den,y_num,y_den,z_num,z_den,truth; exact lowest-terms fractions; truth from "
       "the exact path). <family>/<type>/toi_0.csv: index,collides,toi_lo,toi_hi per query "
       "(%.17g; the exact path's tightest pair of doubles around the first contact time; "
       "empty without contact)."},
      {"families", families}};
  if (corpus.min_separation) {
    // The delta of every family: truth and TOIs are those of minimum-separation CCD.
    manifest["min_separation"] = *corpus.min_separation;
    manifest["min_separation_exact"] = mpq_class(*corpus.min_separation).get_str();
    manifest["format"] = manifest["format"].get<std::string>() +
                         " Minimum separation: collides means the primitives come within "
                         "Euclidean distance min_separation; the TOI is the earliest such time.";
  }
  return manifest.dump(2) + "\n";
}

}  // namespace exactccd::families
