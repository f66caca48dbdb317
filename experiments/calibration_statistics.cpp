// The calibration's statistics: its space-filling design and Spearman's rank correlations.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "common/random.h"
#include "common/table.h"
#include "experiments/calibration.h"
#include "experiments/calibration_detail.h"
#include "experiments/runner.h"

namespace multicpg::experiments {

namespace calibration_detail {
namespace {

// A portable stream of draws (common/random.h).
class Stream {
 public:
  explicit Stream(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() { return splitmix64_next(state_); }
  double uniform() { return unit_from_bits(next()); }
  // Uniform in 0..n-1 (n small: the modulo bias is below 2^-50).
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }

 private:
  std::uint64_t state_;
};

std::vector<Point> latin_hypercube(std::size_t n, std::size_t d, Stream& rng) {
  std::vector<Point> pts(n, Point(d));
  for (std::size_t j = 0; j < d; ++j) {
    std::vector<std::size_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    for (std::size_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
    for (std::size_t i = 0; i < n; ++i) {
      pts[i][j] = (static_cast<double>(perm[i]) + rng.uniform()) / static_cast<double>(n);
    }
  }
  return pts;
}

double min_distance(const std::vector<Point>& pts) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < pts.size(); ++a) {
    for (std::size_t b = a + 1; b < pts.size(); ++b) {
      double s = 0.0;
      for (std::size_t j = 0; j < pts[a].size(); ++j) {
        const double e = pts[a][j] - pts[b][j];
        s += e * e;
      }
      best = std::min(best, s);
    }
  }
  return std::sqrt(best);
}

}  // namespace

std::vector<Point> maximin_design(std::size_t n, std::size_t d, std::uint64_t seed) {
  Stream rng(derive_seed(seed, "design"));
  std::vector<Point> best;
  double best_distance = -1.0;
  for (int draw = 0; draw < kDesignDraws; ++draw) {
    std::vector<Point> pts = latin_hypercube(n, d, rng);
    const double dist = min_distance(pts);
    if (dist > best_distance) {
      best_distance = dist;
      best = std::move(pts);
    }
  }
  return best;
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return 0.0;
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

namespace {

// --- Spearman ----------------------------------------------------------------------------------

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    const double mid = 0.5 * static_cast<double>(i + j) + 1.0;  // ties share their mean rank
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = mid;
    i = j + 1;
  }
  return r;
}

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const double ma = mean(a);
  const double mb = mean(b);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  if (saa == 0.0 || sbb == 0.0) return 0.0;
  return sab / std::sqrt(saa * sbb);
}

}  // namespace
}  // namespace calibration_detail

using namespace calibration_detail;

Sensitivity sensitivity(const Table& candidates) {
  const std::size_t stage = column_index(candidates, "stage");
  const std::size_t failure = column_index(candidates, "failure");
  Sensitivity s;
  // The searched parameters: the columns between the stage and the first scenario.
  std::size_t first_number = stage + 1;
  while (first_number < candidates.columns.size() &&
         candidates.columns[first_number].title.rfind(kFitPrefix, 0) != 0) {
    s.params.push_back(candidates.columns[first_number].title);
    ++first_number;
  }
  const std::string mean_suffix = " mean_deg";
  const auto ends_with = [](const std::string& t, const std::string& end) {
    return t.size() >= end.size() && t.compare(t.size() - end.size(), end.size(), end) == 0;
  };
  std::vector<std::size_t> columns;
  const auto add = [&](std::size_t col, std::string label) {
    columns.push_back(col);
    s.numbers.push_back(std::move(label));
  };
  const auto scenario_means = [&](const std::string& prefix, const std::string& suffix) {
    for (std::size_t i = 0; i < candidates.columns.size(); ++i) {
      const std::string& t = candidates.columns[i].title;
      if (t.rfind(prefix, 0) == 0 && ends_with(t, mean_suffix)) {
        add(i, t.substr(prefix.size(), t.size() - prefix.size() - mean_suffix.size()) + suffix);
      }
    }
  };
  scenario_means(kFitPrefix, "");
  add(column_index(candidates, kScoreColumn), "score");
  add(column_index(candidates, kIntactYawColumn), "intact yaw");
  add(column_index(candidates, kSpeedColumn), "speed");
  scenario_means(kPaperPrefix, " paper's");

  std::vector<const std::vector<std::string>*> used;
  for (const std::vector<std::string>& row : candidates.rows) {
    if (row[stage] == "design" && row[failure].empty()) used.push_back(&row);
  }
  s.candidates = used.size();
  const auto values = [&](std::size_t col) {
    std::vector<double> v;
    for (const std::vector<std::string>* row : used) v.push_back(std::stod((*row)[col]));
    return ranks(v);
  };
  for (std::size_t p = 0; p < s.params.size(); ++p) {
    const std::vector<double> rx = values(stage + 1 + p);
    std::vector<double> row;
    for (std::size_t col : columns) row.push_back(pearson(rx, values(col)));
    s.rho.push_back(std::move(row));
  }
  return s;
}

}  // namespace multicpg::experiments
