// Physical sanity of the shake test across objects, on every 20th grasp of the sample mug: a more
// slippery mug is not held more often, grasp by grasp, and a heavier one about as often.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "graspecmf/sim/batch.hpp"
#include "sample_mug.hpp"

namespace graspecmf::sim {
namespace {

constexpr std::size_t kStride = 20;

struct Held {
  std::size_t count = 0;   // held in the variant
  std::size_t gained = 0;  // held in the variant but not by the sample mug
};

Held compare(const std::vector<TrialResult>& base, const std::vector<TrialResult>& variant) {
  Held held;
  for (std::size_t i = 0; i < base.size(); ++i) {
    held.count += variant[i].success;
    held.gained += variant[i].success && !base[i].success;
  }
  return held;
}

const testing::SampleMug& mug() {
  static const testing::SampleMug m = testing::sample_mug(kStride);
  return m;
}

const std::vector<TrialResult>& base_results() {
  static const std::vector<TrialResult> r = run_trials(mug().object, mug().grasps, {}, 2);
  return r;
}

std::size_t held(const std::vector<TrialResult>& results) {
  std::size_t n = 0;
  for (const TrialResult& r : results) n += r.success;
  return n;
}

// Five times the mass (the same shape at 750 kg/m³ instead of ACRONYM's 150). MuJoCo's contact
// stiffness is per unit of mass, so with one contact time constant for every object the heavier
// mug's pads are five times stiffer and hold 23 more of these 100 grasps; with the time constant
// scaled by √mass (contact_reference_mass, the default) the held count moves by less than 10.
SceneObject five_times_heavier() {
  SceneObject heavy = mug().object;
  heavy.mass *= 5.0;
  heavy.inertia *= 5.0;
  return heavy;
}

TEST(PhysicalSanity, AHeavierMugIsHeldAboutAsOften) {
  const Held h = compare(base_results(), run_trials(five_times_heavier(), mug().grasps, {}, 2));
  const auto base = static_cast<double>(held(base_results()));
  EXPECT_LE(std::abs(static_cast<double>(h.count) - base), 10.0);
  RecordProperty("held", std::to_string(h.count) + " of " + std::to_string(mug().grasps.size()));
}

TEST(PhysicalSanity, OneContactTimeConstantHoldsAHeavierMugMoreOften) {
  TrialConfig fixed;
  fixed.contact_reference_mass = 0.0;
  const Held h = compare(base_results(), run_trials(five_times_heavier(), mug().grasps, fixed, 2));
  EXPECT_GT(h.count, held(base_results()) + 15);
}

// Half the friction.
TEST(PhysicalSanity, AMoreSlipperyMugIsNotHeldMoreOften) {
  TrialConfig slippery;
  slippery.friction = 0.5;
  const Held h = compare(base_results(), run_trials(mug().object, mug().grasps, slippery, 2));
  EXPECT_LT(h.count, held(base_results()));
  // A grasp near a decision boundary may flip either way (measured: 3 of 100).
  EXPECT_LE(h.gained, 4u);
  RecordProperty("held", std::to_string(h.count) + " of " + std::to_string(mug().grasps.size()));
}

}  // namespace
}  // namespace graspecmf::sim
