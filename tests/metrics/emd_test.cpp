#include "graspecmf/metrics/emd.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "graspecmf/lie/so3.hpp"
#include "graspecmf/metrics/assignment.hpp"

namespace graspecmf::metrics {
namespace {

double assignment_cost(const Eigen::MatrixXd& cost, const std::vector<int>& column) {
  double total = 0;
  for (std::size_t i = 0; i < column.size(); ++i) {
    total += cost(static_cast<Eigen::Index>(i), column[i]);
  }
  return total;
}

bool is_permutation(std::vector<int> column) {
  std::sort(column.begin(), column.end());
  for (std::size_t i = 0; i < column.size(); ++i) {
    if (column[i] != static_cast<int>(i)) return false;
  }
  return true;
}

TEST(Assignment, MatchesBruteForceOnSmallRandomMatrices) {
  Rng rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + static_cast<int>(rng.index(7));
    Eigen::MatrixXd cost(n, n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        // Integers in [0, 5) make ties common; otherwise continuous values.
        cost(i, j) = trial % 2 ? std::floor(rng.uniform(0, 5)) : rng.uniform(-1, 3);
      }
    }
    std::vector<int> permutation(static_cast<std::size_t>(n));
    std::iota(permutation.begin(), permutation.end(), 0);
    double best = std::numeric_limits<double>::infinity();
    do {
      best = std::min(best, assignment_cost(cost, permutation));
    } while (std::next_permutation(permutation.begin(), permutation.end()));
    const std::vector<int> column = min_cost_assignment(cost);
    ASSERT_TRUE(is_permutation(column));
    ASSERT_NEAR(assignment_cost(cost, column), best, 1e-12) << "trial " << trial;
  }
}

TEST(Assignment, LargeRandomMatrixGivesAPermutationFarBelowTheIdentityMatching) {
  Rng rng(5);
  const int n = 300;
  Eigen::MatrixXd cost(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) cost(i, j) = rng.uniform();
  }
  const std::vector<int> column = min_cost_assignment(cost);
  ASSERT_TRUE(is_permutation(column));
  std::vector<int> identity(n);
  std::iota(identity.begin(), identity.end(), 0);
  // Random uniform costs: the optimum is far below the identity's n/2.
  EXPECT_LT(assignment_cost(cost, column), 0.1 * assignment_cost(cost, identity));
}

TEST(Assignment, RejectsBadMatrices) {
  EXPECT_THROW(min_cost_assignment(Eigen::MatrixXd::Zero(2, 3)), Error);
  Eigen::MatrixXd nan = Eigen::MatrixXd::Zero(2, 2);
  nan(1, 0) = std::nan("");
  EXPECT_THROW(min_cost_assignment(nan), Error);
  EXPECT_TRUE(min_cost_assignment(Eigen::MatrixXd(0, 0)).empty());
}

std::vector<lie::Pose> random_poses(std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<lie::Pose> poses;
  for (const Eigen::Matrix3d& R : lie::random_rotations(n, seed)) {
    lie::Pose pose;
    pose.R = R;
    pose.p = Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()) * 0.05;
    poses.push_back(pose);
  }
  return poses;
}

TEST(Emd, ZeroForTheSameSetInAnyOrder) {
  std::vector<lie::Pose> a = random_poses(50, 1);
  std::vector<lie::Pose> b = a;
  std::reverse(b.begin(), b.end());
  EXPECT_NEAR(earth_movers_distance(a, b), 0.0, 1e-12);
}

TEST(Emd, AShiftOfWellSeparatedGraspsCostsTheShift) {
  const std::vector<lie::Pose> a = random_poses(40, 2);
  std::vector<lie::Pose> b = a;
  for (lie::Pose& pose : b) pose.p += Eigen::Vector3d(0.001, 0, 0);
  EXPECT_NEAR(earth_movers_distance(a, b), 0.001, 1e-12);
  // A rotation of every grasp by 0.01 rad about its own z axis.
  std::vector<lie::Pose> c = a;
  for (lie::Pose& pose : c) pose.R = pose.R * lie::so3_exp(Eigen::Vector3d(0, 0, 0.01));
  EXPECT_NEAR(earth_movers_distance(a, c), 0.01, 1e-9);
  EXPECT_NEAR(earth_movers_distance(a, c, GraspDistance::diffusion_fields), 1.0 - std::cos(0.01),
              1e-12);
}

TEST(Emd, IsSymmetricAndBelowTheIndexMatching) {
  const std::vector<lie::Pose> a = random_poses(60, 3), b = random_poses(60, 4);
  const double ab = earth_movers_distance(a, b);
  EXPECT_NEAR(ab, earth_movers_distance(b, a), 1e-12);
  double index_matching = 0;
  for (std::size_t i = 0; i < a.size(); ++i) index_matching += lie::pose_distance(a[i], b[i]);
  EXPECT_LT(ab, index_matching / static_cast<double>(a.size()));
}

TEST(Emd, RejectsMismatchedEmptyOrNonFiniteSets) {
  const std::vector<lie::Pose> a = random_poses(3, 5);
  EXPECT_THROW(earth_movers_distance(a, random_poses(4, 6)), Error);
  EXPECT_THROW(earth_movers_distance({}, {}), Error);
  std::vector<lie::Pose> bad = random_poses(3, 7);
  bad[1].p.x() = std::nan("");
  EXPECT_THROW(earth_movers_distance(a, bad), Error);
}

}  // namespace
}  // namespace graspecmf::metrics
