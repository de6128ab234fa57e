#include "prepare_mesh_command.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/output_paths.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/watertight.hpp"
#include "graspecmf/geometry/watertight_cache.hpp"
#include "mesh_json.hpp"
#include "object_units.hpp"

namespace graspecmf::apps {
namespace {
namespace fs = std::filesystem;

struct PrepareMeshArgs {
  std::string in, out, alpha, offset, cache;
  ObjectUnits units;
  bool force = false, no_cache = false, json = false;
};

// "0.003" (metres) or "2%" (of the bounding-box diagonal).
geometry::WrapLength parse_length(const std::string& text, const char* option) {
  std::string number = text;
  geometry::WrapLength length;
  if (!number.empty() && number.back() == '%') {
    number.pop_back();
    length.relative = true;
  }
  const char* end = number.data() + number.size();
  const auto parsed = std::from_chars(number.data(), end, length.value);
  if (number.empty() || parsed.ec != std::errc() || parsed.ptr != end ||
      !std::isfinite(length.value) || !(length.value > 0.0)) {
    throw Error(std::string("prepare-mesh: ") + option + " '" + text +
                "' is not a positive length (metres, or a percentage of the bounding-box "
                "diagonal such as 2%)");
  }
  if (length.relative) length.value /= 100.0;
  return length;
}

void check_paths(const PrepareMeshArgs& a) {
  const std::string ext = lower_extension(a.out);
  if (ext != ".obj" && ext != ".ply") {
    throw Error("prepare-mesh: --out " + a.out + " must end in .obj or .ply");
  }
  require_distinct_output("--out", a.out, {a.in});
}

nlohmann::json mesh_json(std::size_t vertices, std::size_t triangles,
                         const geometry::MeshTopology& t, const std::optional<double>& volume) {
  nlohmann::json j = mesh_topology_json(vertices, triangles, t);
  j["volume"] = volume ? nlohmann::json(*volume) : nlohmann::json(nullptr);
  return j;
}

nlohmann::json to_json(const PrepareMeshArgs& a, double scale,
                       const geometry::WatertightReport& r) {
  return {
      {"input", a.in},
      {"output", a.out},
      {"scale", scale},
      {"wrapped", r.wrapped},
      {"reoriented", r.reoriented},
      {"from_cache", r.from_cache},
      {"backend", geometry::watertight_backend()},
      {"alpha", r.alpha},
      {"offset", r.offset},
      {"hausdorff", r.distance.hausdorff()},
      {"distance_input_to_output", r.distance.a_to_b},
      {"distance_output_to_input", r.distance.b_to_a},
      {"before",
       mesh_json(r.vertices_before, r.triangles_before, r.topology_before, r.volume_before)},
      {"after", mesh_json(r.vertices_after, r.triangles_after, r.topology_after, r.volume_after)},
      {"seconds", r.seconds}};
}

std::string topology_text(const geometry::MeshTopology& t) {
  if (t.consistently_oriented) {
    return fmt::format("watertight, consistently oriented, genus {}", t.genus);
  }
  return fmt::format("{} ({} boundary, {} non-manifold, {} misoriented edges)",
                     t.watertight ? "watertight but not consistently oriented" : "not watertight",
                     t.num_boundary_edges, t.num_nonmanifold_edges, t.num_misoriented_edges);
}

std::string mm(double metres) {
  return fmt::format("{:.3g} mm", 1000.0 * metres);
}

void print_text(const PrepareMeshArgs& a, double scale, const geometry::TriangleMesh& metric,
                const geometry::WatertightReport& r, std::ostream& out) {
  const geometry::BoundingBox box = geometry::bounding_box(metric);
  out << fmt::format("input            {}: {} vertices, {} triangles, {} component(s)\n", a.in,
                     r.vertices_before, r.triangles_before, r.topology_before.num_components);
  out << fmt::format("                 {}\n", topology_text(r.topology_before));
  out << fmt::format(
      "scale            {:.10g} m per unit; bounding box {:.1f} × {:.1f} × {:.1f} mm\n", scale,
      1000 * box.extent().x(), 1000 * box.extent().y(), 1000 * box.extent().z());
  if (r.wrapped) {
    out << fmt::format("wrap             alpha {}, offset {} ({}{}), {:.2f} s\n", mm(r.alpha),
                       mm(r.offset), geometry::watertight_backend(),
                       r.from_cache ? ", from the cache" : "", r.seconds);
  } else if (r.reoriented) {
    out << "wrap             not needed: the input is closed but faced inwards; every triangle "
           "flipped\n";
  } else {
    out << "wrap             not needed: the input is closed, consistently oriented and outward "
           "(--force wraps it anyway)\n";
  }
  out << fmt::format("output           {}: {} vertices, {} triangles, {}\n", a.out,
                     r.vertices_after, r.triangles_after, topology_text(r.topology_after));
  const auto genus = [](const geometry::MeshTopology& t) {
    return t.consistently_oriented ? std::to_string(t.genus) : std::string("-");
  };
  out << fmt::format("volume           {} → {:.6g} m³\n",
                     r.volume_before ? fmt::format("{:.6g} m³", *r.volume_before) : "-",
                     r.volume_after);
  out << fmt::format("genus            {} → {}\n", genus(r.topology_before),
                     genus(r.topology_after));
  if (r.wrapped) {
    out << fmt::format("Hausdorff        {} (input → output {}, output → input {})\n",
                       mm(r.distance.hausdorff()), mm(r.distance.a_to_b), mm(r.distance.b_to_a));
  }
}

void run(const PrepareMeshArgs& a) {
  check_paths(a);
  geometry::WatertightOptions options;
  if (!a.alpha.empty()) options.alpha = parse_length(a.alpha, "--alpha");
  if (!a.offset.empty()) options.offset = parse_length(a.offset, "--offset");
  options.force = a.force;
  const double scale = a.units.metres_per_unit();
  const geometry::TriangleMesh metric = geometry::scaled(geometry::read_mesh(a.in), scale);
  a.units.size.check(metric.vertices, a.in);
  const fs::path cache = a.cache.empty() ? geometry::default_watertight_cache() : fs::path(a.cache);
  const geometry::WatertightResult result =
      a.no_cache ? geometry::make_watertight(metric, options)
                 : geometry::cached_make_watertight(metric, options, cache);
  geometry::write_mesh(result.mesh, a.out);
  if (a.json) {
    std::cout << to_json(a, scale, result.report).dump(2) << "\n";
  } else {
    print_text(a, scale, metric, result.report, std::cout);
  }
}

}  // namespace

void add_prepare_mesh_command(CLI::App& app) {
  auto a = std::make_shared<PrepareMeshArgs>();
  CLI::App* cmd = app.add_subcommand(
      "prepare-mesh",
      "Make a mesh (open pieces, holes, flipped faces, any unit) a closed, outward solid in metres "
      "by alpha wrapping");
  cmd->add_option("mesh", a->in, "Input mesh (.obj, .stl, .ply, .glb, .gltf)")->required();
  cmd->add_option("--out", a->out, "Output mesh in metres (.obj or .ply), written atomically")
      ->required();
  a->units.add_options(cmd);
  cmd->add_option("--alpha", a->alpha,
                  "Wrap ball radius: metres (0.003) or % of the bounding-box diagonal (2%); "
                  "default 3 mm, kept within 1/150–1/50 of the diagonal");
  cmd->add_option("--offset", a->offset,
                  "Distance of the wrap outside the input: metres or % of the diagonal; "
                  "default alpha / 30");
  cmd->add_flag("--force", a->force, "Wrap even a mesh that is already closed and outward");
  cmd->add_option("--cache", a->cache, "Wrap cache folder (default ~/.cache/graspecmf/watertight)");
  cmd->add_flag("--no-cache", a->no_cache, "Neither read nor write the wrap cache");
  cmd->add_flag("--json", a->json, "Print the report as JSON");
  cmd->callback([a] { run(*a); });
}

}  // namespace graspecmf::apps
