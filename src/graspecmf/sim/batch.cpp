#include "graspecmf/sim/batch.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "graspecmf/core/error.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::sim {

std::vector<TrialResult> run_trials(const SceneObject& object, const std::vector<lie::Pose>& grasps,
                                    const TrialConfig& config, int threads,
                                    const ProgressCallback& progress) {
  if (threads < 1) throw Error("the number of threads must be at least 1");
  std::vector<TrialResult> results(grasps.size());
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0;
  std::mutex mutex;  // guards finished, progress and first_error
  std::exception_ptr first_error;

  const auto worker = [&] {
    try {
      GraspSimulator simulator(object, config);
      for (std::size_t i = next++; i < grasps.size(); i = next++) {
        results[i] = simulator.run(grasps[i]);
        const std::lock_guard<std::mutex> lock(mutex);
        ++finished;
        if (progress) progress(finished, grasps.size());
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!first_error) first_error = std::current_exception();
      next = grasps.size();  // stop the other workers early
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
  if (first_error) std::rethrow_exception(first_error);
  return results;
}

GraspOutcomes grasp_outcomes(const SceneObject& object, const geometry::MeshRayCaster& mesh,
                             const std::vector<lie::Pose>& grasps, const TrialConfig& config,
                             int threads) {
  const std::vector<TrialResult> results = run_trials(object, grasps, config, threads);
  GraspOutcomes outcomes;
  for (std::size_t i = 0; i < grasps.size(); ++i) {
    const std::size_t success = results[i].success ? 1 : 0;
    outcomes.all.successes += success;
    ++outcomes.all.trials;
    if (!gripper::in_collision(mesh, grasps[i])) {
      outcomes.collision_free.successes += success;
      ++outcomes.collision_free.trials;
    }
  }
  return outcomes;
}

data::GraspQualities acronym_qualities(const std::vector<TrialResult>& results) {
  data::GraspQualities q;
  for (const TrialResult& r : results) {
    q.object_in_gripper.push_back(r.success ? 1 : 0);
    q.motion_closing_linear.push_back(r.closing_linear);
    q.motion_closing_angular.push_back(r.closing_angular);
    q.motion_shaking_linear.push_back(r.shaking_linear);
    q.motion_shaking_angular.push_back(r.shaking_angular);
  }
  return q;
}

}  // namespace graspecmf::sim
