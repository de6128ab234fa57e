#include "inspect_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "graspecmf/data/object_summary.hpp"
#include "graspecmf/dataset/dataset_report.hpp"
#include "graspecmf/geometry/watertight_cache.hpp"
#include "mesh_json.hpp"

namespace graspecmf::apps {
namespace {

struct InspectOptions {
  std::string grasp_file;
  std::string mesh_root;
  bool json = false;
  bool no_repair = false;
};

double percent(std::size_t part, std::size_t whole) {
  return whole ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

nlohmann::json vec_json(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

double relative_difference(double computed, double stored) {
  return std::abs(computed - stored) / std::max(std::abs(stored), 1e-300);
}

// Frobenius-norm difference of two inertia tensors relative to the stored one.
double relative_difference(const Eigen::Matrix3d& computed, const Eigen::Matrix3d& stored) {
  return (computed - stored).norm() / std::max(stored.norm(), 1e-300);
}

// Distance between two points relative to the object's size (bounding-box diagonal).
double relative_offset(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double size) {
  return (a - b).norm() / size;
}

nlohmann::json to_json(const data::ObjectSummary& s) {
  const data::AcronymGraspFile& r = s.record;
  const data::AcronymObjectInfo& o = r.object;
  nlohmann::json j;
  j["grasp_file"] = s.grasp_file.string();
  j["mesh_file"] = s.mesh_file.string();
  j["object"] = {{"file", o.file}, {"scale", o.scale}};
  for (const auto& [key, value] : {std::pair{"density", o.density},
                                   {"friction", o.friction},
                                   {"mass", o.mass},
                                   {"volume", o.volume}}) {
    j["object"][key] = value ? nlohmann::json(*value) : nlohmann::json(nullptr);
  }
  j["object"]["com"] = o.com ? vec_json(*o.com) : nlohmann::json(nullptr);
  j["gripper"] = {
      {"type", r.gripper_type},
      {"configuration", r.gripper_configuration ? nlohmann::json(*r.gripper_configuration)
                                                : nlohmann::json(nullptr)}};
  j["grasps"] = {{"count", r.size()},
                 {"successful", r.num_successful()},
                 {"labelled", r.qualities.has_value()},
                 {"max_rigidity_error", s.max_rigidity_error}};
  const geometry::MeshTopology& t = s.topology;
  j["mesh"] = mesh_topology_json(s.num_vertices, s.num_triangles, t);
  j["mesh"]["bbox_min"] = vec_json(s.bounding_box.min);
  j["mesh"]["bbox_max"] = vec_json(s.bounding_box.max);
  j["mesh"]["repair"] = nullptr;
  if (s.repair) {
    const geometry::WatertightReport& w = *s.repair;
    j["mesh"]["repair"] = {{"wrapped", w.wrapped},
                           {"reoriented", w.reoriented},
                           {"backend", geometry::watertight_backend()},
                           {"alpha", w.alpha},
                           {"offset", w.offset},
                           {"hausdorff", w.distance.hausdorff()},
                           {"vertices", w.vertices_after},
                           {"triangles", w.triangles_after},
                           {"genus", w.topology_after.genus}};
  }
  nlohmann::json& check = j["mesh"]["mass_properties"];
  if (!s.mass_properties) {
    check = nullptr;
    return j;
  }
  const geometry::MassProperties& m = *s.mass_properties;
  check = {{"volume", m.volume},
           {"mass", m.mass},
           {"center_of_mass", vec_json(m.center_of_mass)},
           {"inertia",
            {vec_json(m.inertia.row(0)), vec_json(m.inertia.row(1)), vec_json(m.inertia.row(2))}}};
  const double size = s.bounding_box.extent().norm();
  if (o.volume) check["volume_relative_difference"] = relative_difference(m.volume, *o.volume);
  if (o.mass) check["mass_relative_difference"] = relative_difference(m.mass, *o.mass);
  if (o.com) check["com_offset_relative_to_size"] = relative_offset(m.center_of_mass, *o.com, size);
  if (o.inertia) {
    check["inertia_relative_difference"] =
        relative_difference(m.inertia, data::standard_inertia(*o.inertia));
  }
  return j;
}

std::string vec_text(const Eigen::Vector3d& v) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x(), v.y(), v.z());
}

void print_text(const data::ObjectSummary& s, std::ostream& out) {
  const data::AcronymGraspFile& r = s.record;
  const data::AcronymObjectInfo& o = r.object;
  const geometry::MeshTopology& t = s.topology;
  out << fmt::format("grasp file       {}\n", s.grasp_file.string());
  out << fmt::format("object file      {}\n", o.file);
  out << fmt::format("mesh             {}\n", s.mesh_file.string());
  out << fmt::format("scale            {:.10g}\n", o.scale);
  out << fmt::format("gripper          {}{}\n", r.gripper_type,
                     r.gripper_configuration
                         ? fmt::format(" (finger joint {:g} m)", *r.gripper_configuration)
                         : "");
  if (r.qualities) {
    out << fmt::format("grasps           {} ({} successful, {:.1f} %)\n", r.size(),
                       r.num_successful(), percent(r.num_successful(), r.size()));
  } else {
    out << fmt::format("grasps           {} (no success labels)\n", r.size());
  }
  out << fmt::format("rigid transforms {} (max deviation {:.2g})\n",
                     s.max_rigidity_error < 1e-6 ? "all" : "NOT all", s.max_rigidity_error);
  out << fmt::format("mesh             {} vertices, {} triangles, {} component(s)\n",
                     s.num_vertices, s.num_triangles, t.num_components);
  if (t.consistently_oriented) {
    out << fmt::format("watertight       yes, consistently oriented, genus {}\n", t.genus);
  } else {
    out << fmt::format("watertight       {} ({} boundary, {} non-manifold, {} misoriented edges)\n",
                       t.watertight ? "yes but inconsistently oriented" : "no",
                       t.num_boundary_edges, t.num_nonmanifold_edges, t.num_misoriented_edges);
  }
  if (s.repair) {
    out << fmt::format(
        "repaired         {}, {} vertices: the volume, mass and inertia below are the wrap's\n",
        geometry::repair_summary(*s.repair), s.repair->vertices_after);
  }
  out << fmt::format("bbox min         {} m\n", vec_text(s.bounding_box.min));
  out << fmt::format("bbox max         {} m\n", vec_text(s.bounding_box.max));
  if (o.density) out << fmt::format("density          {:g} kg/m³\n", *o.density);
  if (!s.mass_properties) {
    out << "volume           not computed: the mesh is not a closed, oriented surface "
           "(--no-repair)\n";
    return;
  }
  const geometry::MassProperties& m = *s.mass_properties;
  out << fmt::format("volume           {:.6g} m³ ({})\n", m.volume,
                     m.volume > 0 ? "outward normals" : "INWARD normals");
  if (o.volume) {
    out << fmt::format("volume (file)    {:.6g} m³ (relative difference {:.1e})\n", *o.volume,
                       relative_difference(m.volume, *o.volume));
  }
  out << fmt::format("mass             {:.6g} kg\n", m.mass);
  if (o.mass) {
    out << fmt::format("mass (file)      {:.6g} kg (relative difference {:.1e})\n", *o.mass,
                       relative_difference(m.mass, *o.mass));
  }
  out << fmt::format("centre of mass   {} m\n", vec_text(m.center_of_mass));
  if (o.com) {
    out << fmt::format("com (file)       {} m (offset {:.1e} of the object size)\n",
                       vec_text(*o.com),
                       relative_offset(m.center_of_mass, *o.com, s.bounding_box.extent().norm()));
  }
  out << fmt::format("inertia diagonal {} kg m² (about the centre of mass)\n",
                     vec_text(m.inertia.diagonal()));
  if (o.inertia) {
    out << fmt::format("inertia (file)   {} kg m² (relative difference {:.1e})\n",
                       vec_text(o.inertia->diagonal()),
                       relative_difference(m.inertia, data::standard_inertia(*o.inertia)));
  }
}

// The per-object success fractions' quantiles, labelled for text and JSON.
std::vector<std::pair<std::string, double>> success_quantiles(const dataset::DatasetReport& r) {
  std::vector<double> fractions;
  for (const data::ObjectEntry& e : r.objects) {
    fractions.push_back(e.num_grasps ? static_cast<double>(e.num_successful) /
                                           static_cast<double>(e.num_grasps)
                                     : 0.0);
  }
  std::vector<std::pair<std::string, double>> q;
  for (const auto& [label, at] : {std::pair{"min", 0.0},
                                  {"p10", 0.1},
                                  {"p25", 0.25},
                                  {"median", 0.5},
                                  {"p75", 0.75},
                                  {"p90", 0.9},
                                  {"max", 1.0}}) {
    q.emplace_back(label, dataset::quantile(fractions, at));
  }
  return q;
}

nlohmann::json to_json(const dataset::DatasetReport& r) {
  nlohmann::json j;
  for (const data::ObjectEntry& e : r.objects) {
    j["objects"].push_back(
        {{"name", e.name}, {"grasps", e.num_grasps}, {"successful", e.num_successful}});
  }
  for (const data::SkippedObject& s : r.unreadable) {
    j["unreadable"].push_back({{"name", s.name}, {"reason", s.reason}});
  }
  for (const auto& [label, value] : success_quantiles(r)) j["success_fraction"][label] = value;
  j["min_successful"] = r.min_successful;
  j["usable"] = r.usable;
  if (r.split) {
    j["split"] = {{"train", r.split->train.size()},
                  {"val", r.split->val.size()},
                  {"test", r.split->test.size()}};
  }
  j["labelled_objects"] = r.labelled_objects;
  j["labelling_seconds"] = r.labelling_seconds;
  return j;
}

void print_text(const std::string& root, const dataset::DatasetReport& r, std::ostream& out) {
  std::size_t grasps = 0, successful = 0;
  for (const data::ObjectEntry& e : r.objects) {
    grasps += e.num_grasps;
    successful += e.num_successful;
  }
  out << fmt::format("dataset          {}\n", root);
  out << fmt::format("objects          {} readable, {} unreadable\n", r.objects.size(),
                     r.unreadable.size());
  for (const data::SkippedObject& s : r.unreadable) {
    out << fmt::format("  unreadable     {}: {}\n", s.name, s.reason);
  }
  out << fmt::format("grasps           {} ({} successful, {:.1f} %)\n", grasps, successful,
                     percent(successful, grasps));
  std::string quantiles;
  for (const auto& [label, value] : success_quantiles(r)) {
    quantiles += fmt::format("{}{} {:.3f}", quantiles.empty() ? "" : ", ", label, value);
  }
  out << fmt::format("success/object   {}\n", quantiles);
  out << fmt::format("≥ {} successful  {} of {} objects ({:.1f} %)\n", r.min_successful, r.usable,
                     r.objects.size(), percent(r.usable, r.objects.size()));
  for (const data::ObjectEntry& e : r.objects) {
    if (e.num_successful < r.min_successful) {
      out << fmt::format("  below          {}: {} of {}\n", e.name, e.num_successful, e.num_grasps);
    }
  }
  if (r.split) {
    out << fmt::format("split            {} train, {} val, {} test (splits.json)\n",
                       r.split->train.size(), r.split->val.size(), r.split->test.size());
  }
  if (r.labelled_objects > 0) {
    out << fmt::format("labelling        {} objects in {:.2f} h, {:.1f} objects/hour (log.jsonl)\n",
                       r.labelled_objects, r.labelling_seconds / 3600.0,
                       3600.0 * static_cast<double>(r.labelled_objects) / r.labelling_seconds);
  }
}

}  // namespace

void add_inspect_command(CLI::App& app) {
  auto options = std::make_shared<InspectOptions>();
  CLI::App* cmd = app.add_subcommand("inspect",
                                     "Summarise an ACRONYM grasp file and check it against its "
                                     "mesh, or summarise a dataset folder");
  cmd->add_option("file", options->grasp_file,
                  "ACRONYM grasp file (.h5), or a dataset folder holding grasps/")
      ->required();
  cmd->add_option("--mesh-root", options->mesh_root,
                  "Folder the file's object/file path is relative to (default: the folder above "
                  "the file's grasps/ folder)");
  cmd->add_flag("--json", options->json, "Print the summary as JSON");
  cmd->add_flag("--no-repair", options->no_repair,
                "Do not compute the volume and mass of an open mesh from its alpha wrap");
  cmd->callback([options] {
    if (std::filesystem::is_directory(options->grasp_file)) {
      const dataset::DatasetReport report = dataset::report_dataset(options->grasp_file);
      if (options->json) {
        std::cout << to_json(report).dump(2) << "\n";
      } else {
        print_text(options->grasp_file, report, std::cout);
      }
      return;
    }
    const data::ObjectSummary summary = data::summarize_acronym_object(
        options->grasp_file, options->mesh_root, !options->no_repair);
    if (options->json) {
      std::cout << to_json(summary).dump(2) << "\n";
    } else {
      print_text(summary, std::cout);
    }
  });
}

}  // namespace graspecmf::apps
