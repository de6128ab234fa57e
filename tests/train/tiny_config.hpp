#pragma once
// A training config small enough to train a few steps of any model type in a test.

#include "graspecmf/models/train_config.hpp"

namespace graspecmf::testing {

// A model small enough to train for a few steps in a test.
inline models::TrainConfig tiny_config() {
  models::TrainConfig c;
  c.model.encoder.widths = {4, 4, 4, 4, 4};
  c.model.encoder.k = 4;
  c.model.encoder.out_channels = 6;
  c.model.encoder.points = 32;
  c.model.field.z_channels = 6;
  c.model.field.hidden_widths = {8, 8};
  c.model.graspnet.centroids = 8;
  c.model.se3dif.distance_points = 16;
  c.data.points = 32;
  c.data.objects_per_step = 2;
  c.data.grasps_per_object = 8;
  c.steps = 6;
  c.log_every = 1;
  c.checkpoint_every = 3;
  c.validate_every = 0;
  c.validation_grasps = 4;
  c.validation_objects = 1;
  c.sampling.steps = 2;
  return c;
}

}  // namespace graspecmf::testing
