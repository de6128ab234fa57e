#include "graspecmf/sim/label_agreement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "graspecmf/core/error.hpp"

namespace graspecmf::sim {
namespace {

// The shaking motion a threshold is compared with; unstable trials never pass.
double shaking_motion(const TrialResult& r) {
  return r.unstable ? std::numeric_limits<double>::infinity() : r.shaking_linear;
}

}  // namespace

LabelAgreement compare_labels(const std::vector<TrialResult>& results,
                              const std::vector<std::int64_t>& reference) {
  if (results.size() != reference.size()) {
    throw Error("cannot compare " + std::to_string(results.size()) + " simulated labels with " +
                std::to_string(reference.size()) + " reference labels");
  }
  if (results.empty()) throw Error("no labels to compare");
  LabelAgreement a;
  a.count = results.size();
  for (std::size_t i = 0; i < a.count; ++i) {
    const bool ref = reference[i] != 0, sim = results[i].success;
    a.both_success += ref && sim;
    a.both_failure += !ref && !sim;
    a.only_reference_success += ref && !sim;
    a.only_simulated_success += !ref && sim;
  }
  const double n = static_cast<double>(a.count);
  a.accuracy = static_cast<double>(a.both_success + a.both_failure) / n;

  // Sweep the threshold upwards through the sorted motions: passing grasp i flips its prediction
  // from failure to success, so correct += (reference success ? +1 : −1).
  std::vector<std::size_t> order(a.count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return shaking_motion(results[i]) < shaking_motion(results[j]);
  });
  long correct = std::count(reference.begin(), reference.end(), 0);  // threshold below all
  long best = correct;
  a.best_shaking_threshold = order.empty() ? 0.0 : shaking_motion(results[order[0]]);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const double motion = shaking_motion(results[order[k]]);
    if (!std::isfinite(motion)) break;
    correct += reference[order[k]] != 0 ? 1 : -1;
    const bool boundary = k + 1 == order.size() || shaking_motion(results[order[k + 1]]) > motion;
    if (boundary && correct > best) {
      best = correct;
      const double next = k + 1 < order.size() ? shaking_motion(results[order[k + 1]]) : motion;
      a.best_shaking_threshold = std::isfinite(next) ? 0.5 * (motion + next) : motion * 1.001;
    }
  }
  a.best_threshold_accuracy = static_cast<double>(best) / n;
  return a;
}

}  // namespace graspecmf::sim
