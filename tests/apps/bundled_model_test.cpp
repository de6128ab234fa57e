// The quality gate of the bundled model (models/mugs): it loads through the same lookup as
// `graspecmf sample`, and on the ACRONYM sample mug (never a training object) its grasps are close
// to our simulator's successful grasps of that mesh, mostly hold in the simulator, and turn with
// the mug. Fixed seeds; the bounds are set from measurement with margin (models/README.md).

#include "graspecmf/models/bundled_model.hpp"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <algorithm>

#include "../sim/sample_mug.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/eval/evaluation.hpp"
#include "graspecmf/geometry/ray_cast.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"
#include "graspecmf/gripper/cloud_grasp_filter.hpp"
#include "graspecmf/metrics/emd.hpp"
#include "graspecmf/models/grasp_sampling.hpp"
#include "graspecmf/models/model_folder.hpp"
#include "graspecmf/sim/batch.hpp"

namespace graspecmf {
namespace {

constexpr std::size_t kGrasps = 200;     // generated and reference grasps compared by EMD
constexpr std::size_t kSimulated = 100;  // generated grasps simulated
// Measured with the shipped weights and their guidance 2.0 (models/README.md, "Quality gate"):
// EMD 0.958 (random grasps score about 0.86 here: at this guidance the model covers this mug's
// grasp set poorly, so the EMD bound only catches a broken model), success 1.00, 1 % in
// collision. The bounds leave margin for machine-to-machine differences.
constexpr double kMaxEmd = 1.05;
constexpr double kMinSuccess = 0.80;
constexpr double kMaxCollision = 0.12;
constexpr double kRotationSlack = 1.3;  // rotated-vs-turned EMD ≤ this × seed-vs-seed EMD

// Our simulator's labels of the sample mug's 2000 ACRONYM grasps (graspecmf simulate).
std::filesystem::path our_labels_file() {
  return testing::sample_root() / "graspecmf-labels" / testing::sample_grasp_file().filename();
}

struct Gate : public ::testing::Test {
  static void SetUpTestSuite() { at::set_num_threads(1); }

  models::TrainedModel model = models::load_trained_model(models::bundled_model_dir());
  geometry::TriangleMesh mesh =
      geometry::scaled(geometry::read_mesh(testing::sample_mesh_file()),
                       data::read_acronym_file(testing::sample_grasp_file()).object.scale);

  // kGrasps grasps for the mug's cloud (seed 1) turned by `turn`, from prior seed `seed`, in the
  // mug's frame, sampled as `graspecmf sample` does by default.
  std::vector<lie::Pose> generate(std::uint64_t seed, const Eigen::Matrix3d& turn) const {
    const models::SamplingSettings& settings = model.config.sampling;
    const std::size_t points = static_cast<std::size_t>(settings.clouds) *
                               static_cast<std::size_t>(model.config.model.encoder.points);
    std::vector<Eigen::Vector3d> cloud = geometry::sample_surface(mesh, points, 1).points;
    for (Eigen::Vector3d& q : cloud) q = turn * q;
    std::vector<lie::Pose> grasps =
        models::sample_grasps(*model.model, cloud, model.config, kGrasps, settings, seed);
    for (lie::Pose& g : grasps) g = {turn.transpose() * g.R, turn.transpose() * g.p};
    return grasps;
  }
};

TEST_F(Gate, OurLabelsFixtureMatchesTheSimulator) {
  const data::AcronymGraspFile ours = data::read_acronym_file(our_labels_file());
  ASSERT_EQ(ours.size(), 2000u);
  constexpr std::size_t kStride = 100;
  const sim::testing::SampleMug mug = sim::testing::sample_mug(kStride);
  const std::vector<sim::TrialResult> results = sim::run_trials(mug.object, mug.grasps, {}, 1);
  std::size_t equal = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    equal += results[i].success == (ours.qualities->object_in_gripper[i * kStride] != 0);
  }
  EXPECT_GE(equal, results.size() - 1);  // the trial is chaotic: allow one flip across machines
}

TEST_F(Gate, SampleMugGraspsAreCloseToOurSuccessfulGraspsAndHold) {
  std::vector<lie::Pose> reference = data::read_acronym_file(our_labels_file()).successful_grasps();
  Rng rng(7);
  rng.shuffle(reference);
  reference.resize(kGrasps);
  const std::vector<lie::Pose> generated = generate(2, Eigen::Matrix3d::Identity());
  const double emd = metrics::earth_movers_distance(generated, reference);
  EXPECT_LT(emd, kMaxEmd);

  const sim::testing::SampleMug mug = sim::testing::sample_mug(2000);
  const geometry::MeshRayCaster caster(mesh);
  const std::vector<lie::Pose> simulated(generated.begin(), generated.begin() + kSimulated);
  const sim::GraspOutcomes outcomes = sim::grasp_outcomes(mug.object, caster, simulated, {}, 1);
  EXPECT_GE(outcomes.all.rate(), kMinSuccess);
  EXPECT_LE(outcomes.collision_rate(), kMaxCollision);
  std::cout << "gate: EMD " << emd << ", success " << outcomes.all.rate() << ", in collision "
            << outcomes.collision_rate() << "\n";
}

TEST_F(Gate, RotatedMugGetsTheRotatedGraspDistribution) {
  const Eigen::Matrix3d turn = eval::test_rotations().front();
  const std::vector<lie::Pose> base = generate(2, Eigen::Matrix3d::Identity());
  const double seeds =
      metrics::earth_movers_distance(base, generate(3, Eigen::Matrix3d::Identity()));
  const double turned = metrics::earth_movers_distance(base, generate(3, turn));
  EXPECT_LE(turned, kRotationSlack * seeds);
  std::cout << "gate: EMD between seeds " << seeds << ", turned " << turned << "\n";
}

}  // namespace
}  // namespace graspecmf
