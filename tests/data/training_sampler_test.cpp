#include "graspecmf/data/training_sampler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "../geometry/test_meshes.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/lie/rotation_sets.hpp"

namespace graspecmf::data {
namespace {

// n box objects of different sizes, each with `grasps` random grasps.
std::vector<GraspObject> boxes(std::size_t n, std::size_t grasps) {
  std::vector<GraspObject> objects;
  Rng rng(1);
  for (std::size_t i = 0; i < n; ++i) {
    GraspObject object;
    object.name = "box" + std::to_string(i);
    const double size = 0.05 + 0.01 * static_cast<double>(i);
    object.mesh =
        geometry::testing::make_box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d::Constant(size));
    for (std::size_t g = 0; g < grasps; ++g) {
      lie::Pose pose;
      pose.R = lie::random_rotation(rng);
      pose.p = Eigen::Vector3d(rng.uniform(), rng.uniform(), rng.uniform()) * size;
      object.grasps.push_back(pose);
    }
    objects.push_back(std::move(object));
  }
  return objects;
}

Eigen::Vector3d at(const std::vector<float>& v, std::size_t i) {
  return Eigen::Vector3d(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
}

TEST(TrainingSampler, ObjectSampleIsRotatedCentredAndScaled) {
  const std::vector<GraspObject> objects = boxes(1, 5);
  const geometry::SurfacePoints cloud = geometry::sample_surface(objects[0].mesh, 200, 3);
  Rng rng(4);
  const Eigen::Matrix3d g = lie::random_rotation(rng);
  const ObjectSample s = make_object_sample(cloud, objects[0].grasps, g, 8.0);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < 200; ++i) mean += at(s.points, i);
  EXPECT_LT((mean / 200).norm(), 1e-5);
  // Undoing the transformation recovers the inputs (float precision).
  for (std::size_t i = 0; i < 200; ++i) {
    const Eigen::Vector3d back = g.transpose() * (at(s.points, i) / 8.0 + s.centroid);
    EXPECT_LT((back - cloud.points[i]).norm(), 1e-6);
  }
  for (std::size_t k = 0; k < 5; ++k) {
    Eigen::Matrix3d R;
    for (int r = 0; r < 3; ++r) R.row(r) = at(s.rotations, 3 * k + static_cast<std::size_t>(r));
    EXPECT_LT((g.transpose() * R - objects[0].grasps[k].R).norm(), 1e-6);
    const Eigen::Vector3d p = g.transpose() * (at(s.positions, k) / 8.0 + s.centroid);
    EXPECT_LT((p - objects[0].grasps[k].p).norm(), 1e-6);
  }
}

TEST(TrainingSampler, EpochsVisitEveryObjectOnceAndGraspsAreDistinct) {
  TrainingSamplerOptions options;
  options.objects_per_step = 2;
  options.grasps_per_object = 7;
  options.points = 64;
  TrainingSampler sampler(boxes(5, 10), options, 9);
  std::map<std::size_t, int> visits;
  for (int step = 0; step < 5; ++step) {
    for (const ObjectSample& s : sampler.next_step()) {
      ++visits[s.object];
      EXPECT_EQ(s.points.size(), 64u * 3u);
      ASSERT_EQ(s.positions.size(), 7u * 3u);
      std::set<std::vector<float>> distinct;
      for (std::size_t k = 0; k < 7; ++k) {
        distinct.insert({s.rotations.begin() + 9 * k, s.rotations.begin() + 9 * k + 9});
      }
      EXPECT_EQ(distinct.size(), 7u);
    }
  }
  ASSERT_EQ(visits.size(), 5u);  // 10 draws = 2 epochs of 5 objects
  for (const auto& [object, count] : visits) EXPECT_EQ(count, 2) << object;
}

TEST(TrainingSampler, AugmentationSettingsDrawTheRightRotations) {
  TrainingSamplerOptions options;
  options.objects_per_step = 3;
  options.points = 16;
  for (Augmentation a : {Augmentation::none, Augmentation::z, Augmentation::so3}) {
    options.augmentation = a;
    TrainingSampler sampler(boxes(3, 4), options, 5);
    for (const ObjectSample& s : sampler.next_step()) {
      EXPECT_NEAR(s.rotation.determinant(), 1.0, 1e-12);
      EXPECT_LT((s.rotation.transpose() * s.rotation - Eigen::Matrix3d::Identity()).norm(), 1e-12);
      if (a == Augmentation::none) {
        EXPECT_TRUE(s.rotation.isIdentity(0));
      } else if (a == Augmentation::z) {
        EXPECT_NEAR(s.rotation(2, 2), 1.0, 1e-12);
      } else {
        EXPECT_LT(std::abs(s.rotation(2, 2)), 1.0 - 1e-9);
      }
    }
  }
  EXPECT_EQ(parse_augmentation(to_string(Augmentation::z)), Augmentation::z);
  EXPECT_THROW(parse_augmentation("SO3"), Error);
}

TEST(TrainingSampler, StretchScalesPointsAndMovesEachGraspWithItsPadCentre) {
  std::vector<GraspObject> objects = boxes(1, 6);
  geometry::SurfacePoints cloud = geometry::sample_surface(objects[0].mesh, 50, 2);
  const geometry::SurfacePoints original = cloud;
  std::vector<lie::Pose> grasps = objects[0].grasps;
  const Eigen::Vector3d factors(1.1, 0.8, 1.25);
  stretch_object(cloud, grasps, factors);
  for (std::size_t i = 0; i < 50; ++i) {
    EXPECT_LT((cloud.points[i] - original.points[i].cwiseProduct(factors)).norm(), 1e-15);
    // A box face's normal is an axis, so stretching leaves it unchanged.
    EXPECT_LT((cloud.normals[i] - original.normals[i]).norm(), 1e-12);
  }
  for (std::size_t k = 0; k < 6; ++k) {
    const lie::Pose& before = objects[0].grasps[k];
    EXPECT_TRUE(grasps[k].R.isApprox(before.R, 0));
    const Eigen::Vector3d approach = before.R.col(2) * gripper::panda::kPadCenterZ;
    EXPECT_LT(((grasps[k].p + approach) - (before.p + approach).cwiseProduct(factors)).norm(),
              1e-15);
  }
}

TEST(TrainingSampler, StretchFactorsStayInTheirRangeAndZeroTurnsItOff) {
  TrainingSamplerOptions options;
  options.objects_per_step = 3;
  options.grasps_per_object = 4;
  options.points = 16;
  TrainingSampler plain(boxes(3, 4), options, 5);
  options.stretch = 0.2;
  TrainingSampler stretched(boxes(3, 4), options, 5);
  const std::vector<ObjectSample> a = plain.next_step(), b = stretched.next_step();
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(a[i].stretch.isOnes(0));
    EXPECT_EQ(a[i].object, b[i].object);
    EXPECT_FALSE(b[i].stretch.isOnes(1e-3));
    EXPECT_LE((b[i].stretch - Eigen::Vector3d::Ones()).cwiseAbs().maxCoeff(), 0.2);
  }
  // The first object's draws before its stretch are the unstretched sampler's.
  EXPECT_TRUE(a[0].rotation.isApprox(b[0].rotation, 0));
  options.stretch = 0.5;
  EXPECT_THROW(TrainingSampler(boxes(1, 1), options, 1), Error);
}

// Unsigned distance from q to the surface of the box [0, size]³.
double box_distance(const Eigen::Vector3d& q, double size) {
  const Eigen::Vector3d outside = (-q.array()).max(q.array() - size).max(0.0).matrix();
  if (outside.norm() > 0) return outside.norm();
  return q.cwiseMin(Eigen::Vector3d::Constant(size) - q).minCoeff();
}

TEST(TrainingSampler, DistanceTargetsAreTheSurfaceDistanceInNetworkUnits) {
  TrainingSamplerOptions options;
  options.objects_per_step = 3;
  options.grasps_per_object = 2;
  options.points = 64;
  options.distance_points = 300;
  TrainingSampler sampler(boxes(3, 2), options, 7);
  for (const ObjectSample& s : sampler.next_step()) {
    ASSERT_EQ(s.distance_points.size(), 900U);
    ASSERT_EQ(s.distances.size(), 300U);
    const double size = 0.05 + 0.01 * static_cast<double>(s.object);
    std::size_t inside = 0, far = 0;
    for (std::size_t i = 0; i < 300; ++i) {
      const Eigen::Vector3d q =
          s.rotation.transpose() * (at(s.distance_points, i) / s.scale + s.centroid);
      EXPECT_NEAR(s.distances[i] / s.scale, box_distance(q, size), 1e-6) << i;
      inside += (q.array() > 0).all() && (q.array() < size).all();
      // Beyond 0.02 · radius mostly comes from the wider offsets.
      far += s.distances[i] / s.scale > 0.02 * 0.5 * std::sqrt(3.0) * size;
    }
    EXPECT_GT(inside, 60U);  // about half lie inside
    EXPECT_LT(inside, 240U);
    EXPECT_GT(far, 60U);
  }
  options.distance_points = 0;
  TrainingSampler none(boxes(1, 2), options, 7);
  EXPECT_TRUE(none.next_step()[0].distances.empty());
}

TEST(TrainingSampler, RestoredStateGivesTheSameSteps) {
  TrainingSamplerOptions options;
  options.objects_per_step = 2;
  options.grasps_per_object = 3;
  options.points = 32;
  TrainingSampler a(boxes(3, 6), options, 21);
  a.next_step();
  a.next_step();
  const std::string saved = a.state();
  const std::vector<ObjectSample> expected = a.next_step(), expected2 = a.next_step();
  TrainingSampler b(boxes(3, 6), options, 777);
  b.restore(saved);
  const std::vector<ObjectSample> got = b.next_step(), got2 = b.next_step();
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(got[i].object, expected[i].object);
    EXPECT_EQ(got[i].points, expected[i].points);
    EXPECT_EQ(got[i].rotations, expected[i].rotations);
    EXPECT_EQ(got2[i].positions, expected2[i].positions);
  }
  EXPECT_THROW(b.restore("5 2 0 9\nxx"), Error);
}

// The object-frame points of a sample (undoing rotation, centring and scale).
std::vector<Eigen::Vector3d> object_points(const ObjectSample& s) {
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i = 0; i < s.points.size() / 3; ++i) {
    points.push_back(s.rotation.transpose() * (at(s.points, i) / s.scale + s.centroid));
  }
  return points;
}

// Points well inside the box's face x = 0 (axis 0, side 0) or x = size (side 1), etc.
std::size_t on_face(const std::vector<Eigen::Vector3d>& points, double size, int axis, int side) {
  std::size_t count = 0;
  for (const Eigen::Vector3d& q : points) {
    bool inside = std::abs(q[axis] - side * size) < 0.002;
    for (int other = 0; other < 3; ++other) {
      if (other != axis) inside = inside && q[other] > 0.008 && q[other] < size - 0.008;
    }
    count += inside;
  }
  return count;
}

TEST(TrainingSampler, PartialInputIsWhatOneCameraAboveSees) {
  TrainingSamplerOptions options;
  options.objects_per_step = 3;
  options.grasps_per_object = 2;
  options.points = 256;
  options.input = CloudInput::partial;
  options.augmentation = Augmentation::so3;
  TrainingSampler sampler(boxes(3, 2), options, 11);
  for (int step = 0; step < 4; ++step) {
    for (const ObjectSample& s : sampler.next_step()) {
      ASSERT_EQ(s.points.size(), 3u * 256u);
      const double size = 0.05 + 0.01 * static_cast<double>(s.object);
      const std::vector<Eigen::Vector3d> points = object_points(s);
      std::vector<double> off;
      for (const Eigen::Vector3d& q : points) off.push_back(box_distance(q, size));
      std::sort(off.begin(), off.end());
      EXPECT_LT(off[off.size() / 2], 0.002);  // the camera's noise: about 1.3 mm
      EXPECT_LT(off[off.size() * 95 / 100], 0.005);
      // Never the bottom, on the table; the top from above; of each pair of opposite sides, at
      // most the one facing the camera.
      EXPECT_EQ(on_face(points, size, 2, 0), 0u);
      EXPECT_GT(on_face(points, size, 2, 1), 10u);
      for (int axis = 0; axis < 2; ++axis) {
        EXPECT_EQ(std::min(on_face(points, size, axis, 0), on_face(points, size, axis, 1)), 0u);
      }
    }
  }
  // Mixed: about half the clouds are partial (none on the bottom), the others whole.
  options.input = CloudInput::mixed;
  options.objects_per_step = 40;
  TrainingSampler mixed(boxes(3, 2), options, 12);
  std::size_t partial = 0;
  for (const ObjectSample& s : mixed.next_step()) {
    partial += on_face(object_points(s), 0.05 + 0.01 * static_cast<double>(s.object), 2, 0) == 0;
  }
  EXPECT_GT(partial, 10u);
  EXPECT_LT(partial, 30u);
  // Resuming continues the same views.
  const std::string saved = mixed.state();
  const std::vector<ObjectSample> expected = mixed.next_step();
  TrainingSampler again(boxes(3, 2), options, 99);
  again.restore(saved);
  const std::vector<ObjectSample> got = again.next_step();
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].points, expected[i].points);
  EXPECT_EQ(parse_cloud_input("mixed"), CloudInput::mixed);
  EXPECT_EQ(to_string(CloudInput::partial), "partial");
  EXPECT_THROW(parse_cloud_input("half"), Error);
}

TEST(TrainingSampler, RejectsUnusableInput) {
  EXPECT_THROW(TrainingSampler({}, {}, 1), Error);
  std::vector<GraspObject> objects = boxes(2, 3);
  objects[1].grasps.clear();
  EXPECT_THROW(TrainingSampler(objects, {}, 1), Error);
  TrainingSamplerOptions zero;
  zero.points = 0;
  EXPECT_THROW(TrainingSampler(boxes(1, 1), zero, 1), Error);
  TrainingSamplerOptions views;
  views.input = CloudInput::partial;
  views.views.max_distance = 9.0;
  EXPECT_THROW(TrainingSampler(boxes(1, 1), views, 1), Error);
}

}  // namespace
}  // namespace graspecmf::data
