#include "view_command.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/output_paths.hpp"
#include "graspecmf/data/dataset.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/viz/html_view.hpp"
#include "graspecmf/viz/scene_sheet.hpp"

namespace graspecmf::apps {
namespace {

struct ViewArgs {
  std::string grasp_file, mesh_root, out, png;
  std::size_t max = 200;
  bool successful_only = false;
};

constexpr std::array<int, 3> kSuccess{40, 160, 60}, kFailure{200, 50, 50}, kUnlabelled{40, 90, 200};

void run(const ViewArgs& a) {
  if (a.out.empty() && a.png.empty()) {
    throw Error("view: nothing to write; give --out FILE.html, --png FILE.png or both");
  }
  require_distinct_output("--out", a.out, {a.grasp_file});
  require_distinct_output("--png", a.png, {a.grasp_file, a.out});
  const data::AcronymGraspFile record = data::read_acronym_file(a.grasp_file);
  const geometry::TriangleMesh mesh = geometry::scaled(
      geometry::read_mesh(data::find_object_mesh(a.grasp_file, record.object.file, a.mesh_root)),
      record.object.scale);
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < record.size(); ++i) {
    const bool success = record.qualities && record.qualities->object_in_gripper[i] != 0;
    if (!a.successful_only || success) chosen.push_back(i);
  }
  // At most `max` grasps, evenly spread over the file's order.
  std::vector<std::size_t> shown;
  for (std::size_t k = 0; k < std::min(a.max, chosen.size()); ++k) {
    shown.push_back(chosen[k * chosen.size() / std::min(a.max, chosen.size())]);
  }
  const double opening = record.gripper_configuration ? 2.0 * *record.gripper_configuration
                                                      : gripper::panda::kMaxOpening;
  const auto marker = gripper::marker_segments(std::min(opening, gripper::panda::kMaxOpening));
  std::vector<viz::Segment> segments;
  for (std::size_t i : shown) {
    const lie::Pose pose = lie::Pose::from_matrix(record.transforms[i]);
    const auto color = !record.qualities                        ? kUnlabelled
                       : record.qualities->object_in_gripper[i] ? kSuccess
                                                                : kFailure;
    for (const auto& [p, q] : marker)
      segments.push_back({lie::apply(pose, p), lie::apply(pose, q), color});
  }
  const std::string title =
      fmt::format("{}: {} of {} grasps", std::filesystem::path(a.grasp_file).filename().string(),
                  shown.size(), record.size());
  if (!a.out.empty()) {
    write_file_atomically(a.out, viz::html_view(mesh, segments, title));
    std::cout << fmt::format("wrote {} ({})\n", a.out, title);
  }
  if (!a.png.empty()) {
    viz::write_png(viz::scene_sheet(mesh, segments), a.png);
    std::cout << fmt::format("wrote {} ({})\n", a.png, title);
  }
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Write an interactive 3-D HTML view and/or a PNG contact sheet of a grasp file");
  cmd->add_option("file", a->grasp_file, "ACRONYM grasp file (.h5)")->required();
  cmd->add_option("--mesh-root", a->mesh_root, "Folder the file's object/file is relative to");
  cmd->add_option("--max", a->max, "Show at most this many grasps")->check(CLI::Range(1, 100000));
  cmd->add_flag("--successful-only", a->successful_only, "Show only successful grasps");
  cmd->add_option("--out", a->out, "Output .html (interactive view)");
  cmd->add_option("--png", a->png, "Output .png (contact sheet of six views)");
  cmd->callback([a] { run(*a); });
}

}  // namespace graspecmf::apps
