// Generates grasps for a mesh (in metres after SCALE) with the bundled model and prints the first.
#include <torch/torch.h>

#include <iostream>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/models/bundled_model.hpp"
#include "graspecmf/models/object_grasps.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: sample_grasps MESH SCALE NUM\n";
    return 2;
  }
  try {
    namespace models = graspecmf::models;
    at::set_num_threads(1);
    const models::TrainedModel model = models::load_trained_model(models::bundled_model_dir());
    const auto& settings = model.config.sampling;
    const auto mesh =
        graspecmf::geometry::scaled(graspecmf::geometry::read_mesh(argv[1]), std::stod(argv[2]));
    const graspecmf::gripper::GraspChecks checks;  // no filters
    const auto object =
        models::object_points(mesh, models::input_points(model, settings), checks, 0);
    const auto grasps =
        models::sample_object_grasps(model, object, std::stoul(argv[3]), settings, checks, 0);
    std::cout << grasps.size() << " grasps; the first, T_object_gripper in metres:\n"
              << grasps.front().matrix() << "\n";
  } catch (const graspecmf::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
