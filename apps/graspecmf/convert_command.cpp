#include "convert_command.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/output_paths.hpp"
#include "graspecmf/formats/grasp_files.hpp"

namespace graspecmf::apps {
namespace {

struct ConvertArgs {
  std::string in, out, from, to, isaac_frame = "auto", object;
  double scale = 1.0, graspnet_depth = 0.01;
  int graspnet_object_id = 0;
};

void run(const ConvertArgs& a) {
  require_distinct_output("OUT", a.out, {a.in});
  formats::FormatOptions in_options, out_options;
  in_options.isaac_gripper_frame = formats::parse_isaac_gripper_frame(a.isaac_frame);
  out_options.isaac_gripper_frame = in_options.isaac_gripper_frame;
  if (!a.from.empty()) in_options.format = formats::parse_format(a.from);
  if (!a.to.empty()) out_options.format = formats::parse_format(a.to);
  out_options.graspnet_depth = a.graspnet_depth;
  out_options.graspnet_object_id = a.graspnet_object_id;
  const formats::GraspFormat from =
      in_options.format ? *in_options.format : formats::format_of_path(a.in);
  const formats::GraspFormat to =
      out_options.format ? *out_options.format : formats::format_of_path(a.out);
  formats::GraspSet grasps = formats::read_grasps(a.in, in_options);
  if (!a.object.empty()) {
    grasps.object = data::AcronymObjectInfo{};
    grasps.object->file = a.object;
    grasps.object->scale = a.scale;
  }
  formats::write_grasps(grasps, a.out, out_options);
  std::string lost;
  for (const std::string& field : formats::unkept_fields(grasps, to)) {
    lost += (lost.empty() ? "" : ", ") + field;
  }
  std::cout << fmt::format("wrote {} ({} grasps, {} → {}{})\n", a.out, grasps.size(),
                           formats::format_name(from), formats::format_name(to),
                           lost.empty() ? "" : "; not kept: " + lost);
}

}  // namespace

void add_convert_command(CLI::App& app) {
  auto a = std::make_shared<ConvertArgs>();
  CLI::App* cmd = app.add_subcommand(
      "convert",
      "Rewrite a grasp file in another format (ACRONYM .h5/.json, plain .json, Isaac "
      ".yaml, GraspNet .npy, Contact-GraspNet .npz)");
  cmd->add_option("in", a->in, "Input grasp file")->required();
  cmd->add_option("out", a->out, "Output grasp file")->required();
  const std::vector<std::string> names = formats::format_names();
  cmd->add_option("--from", a->from, "Input format (default: by extension; .json by content)")
      ->check(CLI::IsMember(names));
  cmd->add_option("--to", a->to, "Output format (default: by extension)")
      ->check(CLI::IsMember(names));
  cmd->add_option("--isaac-gripper-frame", a->isaac_frame,
                  "isaac_grasp poses are of ACRONYM's gripper frame or Isaac Sim's panda_hand "
                  "(auto: read the file's gripper_frame, write panda_hand)")
      ->check(CLI::IsMember({"auto", "acronym", "panda_hand"}))
      ->capture_default_str();
  cmd->add_option("--graspnet-depth", a->graspnet_depth,
                  "GraspNet depth written: the grasp point lies this far (m) behind the fingertips")
      ->check(CLI::Range(0.0, 0.1122))
      ->capture_default_str();
  cmd->add_option("--graspnet-object-id", a->graspnet_object_id, "GraspNet object id written")
      ->check(CLI::Range(0, 1 << 24))
      ->capture_default_str();
  cmd->add_option("--object", a->object,
                  "Mesh path to record as the grasps' object (ACRONYM .h5 output needs one)");
  cmd->add_option("--scale", a->scale, "Scale to record with --object")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->callback([a] { run(*a); });
}

}  // namespace graspecmf::apps
