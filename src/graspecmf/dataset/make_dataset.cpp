#include "graspecmf/dataset/make_dataset.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/output_lock.hpp"
#include "graspecmf/core/version.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/data/splits.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/watertight_cache.hpp"
#include "graspecmf/sim/batch.hpp"
#include "graspecmf/sim/scene_object.hpp"
#include "graspecmf/viz/render.hpp"

namespace graspecmf::dataset {
namespace fs = std::filesystem;
using nlohmann::json;
namespace {

constexpr std::size_t kPreviewObjects = 30;
constexpr int kPreviewSize = 160;
constexpr int kPreviewColumns = 6;
// Objects with fewer successful grasps are left out of the split (docs/dataset.md; the paper's
// filter).
constexpr std::size_t kMinSuccessful = 100;

// A well-mixed 64-bit seed for (seed, index, stream) (splitmix64 finaliser).
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t index, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (index + 1) + 0xBF58476D1CE4E5B9ULL * stream;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

std::string grasp_file_name(const ObjectSource& s) {
  return fmt::format("grasps/{}_{}_{}.h5", s.category, s.name, s.scale);
}

std::string mesh_file_name(const ObjectSource& s) {
  return fmt::format("meshes/{}/{}.obj", s.category, s.name);
}

json mug_json(const geometry::MugParameters& m) {
  return {{"height", m.height},
          {"outer_radius", m.outer_radius},
          {"wall", m.wall},
          {"base", m.base},
          {"body", geometry::to_string(m.body)},
          {"body_amount", m.body_amount},
          {"rim", geometry::to_string(m.rim)},
          {"handle", geometry::to_string(m.handle)},
          {"section", geometry::to_string(m.section)},
          {"handle_thickness", m.handle_thickness},
          {"handle_width", m.handle_width},
          {"handle_clearance", m.handle_clearance},
          {"handle_low", m.handle_low},
          {"handle_high", m.handle_high},
          {"flare", m.flare},
          {"flare_height", m.flare_height},
          {"roughness", m.roughness},
          {"roughness_seed", m.roughness_seed}};
}

json length_json(const geometry::WrapLength& length) {
  return {{"value", length.value}, {"relative", length.relative}};
}

// Everything that determines the dataset's content; a resumed run must match it exactly.
json options_json(const MakeDatasetOptions& o) {
  const AntipodalOptions& c = o.candidates;
  const geometry::DecompositionOptions& d = o.decomposition;
  json objects = json::array();
  for (const ObjectSource& s : o.objects) {
    json entry = {{"name", s.name}, {"category", s.category}, {"scale", s.scale}};
    if (s.mug) {
      entry["mug"] = mug_json(*s.mug);
    } else {
      entry["mesh_file"] = fs::absolute(s.mesh_file).lexically_normal().string();
      // How a mesh that is not a closed solid is wrapped (value 0: the default rule), or false.
      entry["repair"] = o.repair ? json{{"alpha", length_json(o.wrap.alpha)},
                                        {"offset", length_json(o.wrap.offset)}}
                                 : json(false);
    }
    objects.push_back(entry);
  }
  return {{"preset", o.preset},
          {"seed", o.seed},
          {"density", o.density},
          {"val_count", o.val_count},
          {"test_count", o.test_count},
          {"min_successful_in_split", kMinSuccessful},
          {"candidates",
           {{"num_grasps", c.num_grasps},
            {"max_attempts", c.max_attempts},
            {"ray_cone", c.ray_cone},
            {"max_contact_angle", c.max_contact_angle},
            {"opening", c.opening},
            {"width_margin", c.width_margin}}},
          {"trial", sim::to_json(o.trial)},
          {"decomposition",
           {{"resolution", d.resolution},
            {"max_parts", d.max_parts},
            {"concavity", d.concavity},
            {"planes_per_axis", d.planes_per_axis}}},
          {"objects", objects}};
}

json outcome_json(const ObjectOutcome& r) {
  json j = {{"name", r.name}};
  if (!r.skipped.empty()) {
    j["skipped"] = r.skipped;
    return j;
  }
  j["grasp_file"] = r.grasp_file;
  j["candidates"] = r.candidates;
  j["successful"] = r.successful;
  return j;
}

void write_manifest(const MakeDatasetOptions& o, const std::vector<ObjectOutcome>& done) {
  json objects = json::array();
  for (const ObjectOutcome& r : done) objects.push_back(outcome_json(r));
  const json manifest = {{"format", "graspecmf-dataset-1"},
                         {"software_version", kVersion},
                         {"options", options_json(o)},
                         {"results", objects}};
  write_file_atomically(o.out / "manifest.json", manifest.dump(1) + "\n");
}

// A manifest's options as this version writes them: manifests written before pad_normal_inset
// and mujoco_convex existed were labelled with MuJoCo's own contact normals and convex collider,
// which those settings call −1 and true; those written before legacy_object_frame and
// contact_reference_mass existed were labelled in the mesh frame with one contact time constant
// for every object, which those settings call true and 0.
json upgraded_options(json options) {
  json& trial = options["trial"];
  if (trial.is_object() && !trial.contains("pad_normal_inset")) trial["pad_normal_inset"] = -1.0;
  if (trial.is_object() && !trial.contains("mujoco_convex")) trial["mujoco_convex"] = true;
  if (trial.is_object() && !trial.contains("legacy_object_frame")) {
    trial["legacy_object_frame"] = true;
  }
  if (trial.is_object() && !trial.contains("contact_reference_mass")) {
    trial["contact_reference_mass"] = 0.0;
  }
  // Mugs written before flared lips and rough surfaces existed had neither.
  if (options.contains("objects") && options["objects"].is_array()) {
    for (json& entry : options["objects"]) {
      if (!entry.is_object() || !entry.contains("mug") || !entry["mug"].is_object()) continue;
      for (const char* key : {"flare", "flare_height", "roughness"}) {
        if (!entry["mug"].contains(key)) entry["mug"][key] = 0.0;
      }
      if (!entry["mug"].contains("roughness_seed")) entry["mug"]["roughness_seed"] = 0;
    }
  }
  return options;
}

// Manifests written before meshes could be repaired lack the objects' "repair" setting. Every
// object they made was already closed, which any setting leaves as it is, so they take the
// setting of the run that resumes them.
json with_repair_settings(json found, const json& expected) {
  if (!found.contains("objects") || !found["objects"].is_array() ||
      found["objects"].size() != expected["objects"].size()) {
    return found;
  }
  for (std::size_t i = 0; i < found["objects"].size(); ++i) {
    json& entry = found["objects"][i];
    const json& wanted = expected["objects"][i];
    if (entry.is_object() && entry.contains("mesh_file") && !entry.contains("repair") &&
        wanted.contains("repair")) {
      entry["repair"] = wanted["repair"];
    }
  }
  return found;
}

// Fails unless out can hold the dataset: creates and locks the folders, refuses a folder made with
// other options, proves that files can be written there, and removes the temporary files of a
// killed run. The folder stays locked while the result lives.
[[nodiscard]] OutputLock prepare_output(const MakeDatasetOptions& o) {
  std::error_code ec;
  fs::create_directories(o.out / "grasps", ec);
  if (ec) throw Error(o.out.string() + ": cannot create the output folder (" + ec.message() + ")");
  OutputLock lock = OutputLock::folder(o.out);
  const fs::path manifest = o.out / "manifest.json";
  if (fs::exists(manifest)) {
    std::ifstream in(manifest);
    json existing;
    try {
      existing = json::parse(in);
    } catch (const json::exception&) {
      throw Error(manifest.string() + ": unreadable; remove it or choose another --out");
    }
    const json expected = options_json(o);
    if (!existing.contains("options") ||
        with_repair_settings(upgraded_options(existing["options"]), expected) != expected) {
      throw Error(o.out.string() +
                  " holds a dataset made with other options; choose another --out or remove it");
    }
  }
  write_file_atomically(o.out / ".write-test", "ok\n");
  fs::remove(o.out / ".write-test");
  remove_temporary_files(o.out);
  return lock;
}

// The outcome recorded by an existing grasp file, or nothing if it cannot be read.
std::optional<ObjectOutcome> resumed_outcome(const fs::path& out, const ObjectSource& s) {
  const fs::path path = out / grasp_file_name(s);
  if (!fs::exists(path)) return std::nullopt;
  try {
    const data::AcronymGraspFile record = data::read_acronym_file(path);
    ObjectOutcome r;
    r.name = s.name;
    r.grasp_file = grasp_file_name(s);
    r.resumed = true;
    r.candidates = record.size();
    r.successful = record.num_successful();
    return r;
  } catch (const Error&) {
    return std::nullopt;  // not ours or damaged: make it again
  }
}

// The object's mesh as stored (raw units) and in metres; throws Error if it is unusable. A mesh
// that is not a closed, outward solid is replaced by its repair (with o.repair), noted in
// `repaired`; the metric mesh is then the stored one times the scale, as readers will see it.
std::pair<geometry::TriangleMesh, geometry::TriangleMesh> object_meshes(const ObjectSource& s,
                                                                        const MakeDatasetOptions& o,
                                                                        std::string& repaired) {
  geometry::TriangleMesh raw =
      s.mug ? geometry::mug_mesh(*s.mug) : geometry::read_mesh(s.mesh_file);
  geometry::TriangleMesh metric = geometry::scaled(raw, s.scale);
  geometry::ClosedMeshOptions closing;
  closing.repair = o.repair;
  closing.wrap = o.wrap;
  closing.cache_dir = o.wrap_cache;
  geometry::ClosedMesh closed = geometry::closed_mesh_for_simulation(metric, s.name, closing);
  if (closed.repaired) {
    repaired = geometry::repair_note(s.name, closed.report);
    raw = geometry::scaled(closed.mesh, 1.0 / s.scale);
    metric = geometry::scaled(raw, s.scale);
  }
  return {std::move(raw), std::move(metric)};
}

ObjectOutcome make_object(const MakeDatasetOptions& o, std::size_t index,
                          const std::function<void(std::size_t)>& trials_done) {
  const ObjectSource& s = o.objects[index];
  ObjectOutcome r;
  r.name = s.name;
  geometry::TriangleMesh raw, metric;
  data::AcronymObjectInfo info;
  sim::SceneObject scene;
  std::vector<GraspCandidate> candidates;
  try {
    std::tie(raw, metric) = object_meshes(s, o, r.repaired);
    const geometry::MassProperties mp = geometry::mass_properties(metric, o.density);
    if (!(mp.volume > 0)) throw Error("the mesh is not outward oriented (negative volume)");
    info.file = mesh_file_name(s);
    info.scale = s.scale;
    info.density = o.density;
    info.friction = o.trial.friction;
    info.mass = mp.mass;
    info.volume = mp.volume;
    info.com = mp.center_of_mass;
    info.inertia = data::standard_inertia(mp.inertia);  // the same sign flip both ways
    candidates = sample_antipodal_grasps(metric, o.candidates, derive_seed(o.seed, index, 1));
    if (candidates.empty()) throw Error("no collision-free antipodal grasp was found");
    const fs::path cache = o.cache.empty() ? sim::default_decomposition_cache() : o.cache;
    scene = sim::make_scene_object(metric, info, o.trial, o.decomposition, cache);
  } catch (const Error& e) {
    r.skipped = e.what();
    return r;
  }
  std::vector<lie::Pose> grasps;
  for (const GraspCandidate& c : candidates) grasps.push_back(c.grasp);
  const std::vector<sim::TrialResult> results = sim::run_trials(
      scene, grasps, o.trial, o.threads, [&](std::size_t done, std::size_t) { trials_done(done); });

  data::AcronymGraspFile record;
  for (const lie::Pose& g : grasps) record.transforms.push_back(g.matrix());
  record.qualities = sim::acronym_qualities(results);
  record.gripper_configuration = 0.5 * o.candidates.opening;
  record.object = info;
  fs::create_directories(o.out / "meshes" / s.category);
  geometry::write_mesh(raw, o.out / info.file);
  data::write_acronym_file(record, o.out / grasp_file_name(s));  // last: marks the object done

  r.grasp_file = grasp_file_name(s);
  r.candidates = results.size();
  for (const sim::TrialResult& t : results) {
    r.successful += t.success;
    r.unstable += t.unstable;
  }
  return r;
}

void write_split(const MakeDatasetOptions& o, const std::vector<ObjectOutcome>& outcomes) {
  std::vector<std::string> usable;
  for (const ObjectOutcome& r : outcomes) {
    if (r.skipped.empty() && r.successful >= kMinSuccessful) {
      usable.push_back(fs::path(r.grasp_file).stem().string());
    }
  }
  const double n = static_cast<double>(std::max<std::size_t>(usable.size(), 1));
  data::SplitFractions fractions;
  fractions.val = std::min(1.0, static_cast<double>(o.val_count) / n);
  fractions.test = std::min(1.0 - fractions.val, static_cast<double>(o.test_count) / n);
  data::write_split_file(data::random_split(usable, fractions, derive_seed(o.seed, 0, 2)),
                         o.out / data::kSplitFileName);
}

void write_preview(const MakeDatasetOptions& o, const std::vector<ObjectOutcome>& outcomes) {
  std::vector<viz::Image> images;
  viz::ViewOptions view;
  view.size = kPreviewSize;
  for (std::size_t i = 0; i < outcomes.size() && images.size() < kPreviewObjects; ++i) {
    if (!outcomes[i].skipped.empty()) continue;
    const ObjectSource& s = o.objects[i];
    const geometry::TriangleMesh mesh = geometry::read_mesh(o.out / mesh_file_name(s));
    images.push_back(viz::render_mesh(geometry::scaled(mesh, s.scale), view));
  }
  if (!images.empty()) {
    viz::write_png(viz::contact_sheet(images, kPreviewColumns), o.out / "preview.png");
  }
}

void validate_sources(const std::vector<ObjectSource>& objects) {
  if (objects.empty()) throw Error("make-dataset: no objects to make");
  std::set<std::string> names;
  for (const ObjectSource& s : objects) {
    if (s.name.empty() || !std::all_of(s.name.begin(), s.name.end(), [](char ch) {
          return std::isalnum(static_cast<unsigned char>(ch)) || ch == '-';
        })) {
      throw Error("make-dataset: object name '" + s.name + "' must be letters, digits and '-'");
    }
    if (!names.insert(s.name).second) throw Error("make-dataset: two objects are named " + s.name);
    if (!(s.scale > 0) || !std::isfinite(s.scale)) {
      throw Error("make-dataset: the scale must be a positive number");
    }
  }
}

}  // namespace

std::vector<ObjectSource> procedural_mug_sources(std::size_t count, std::uint64_t seed,
                                                 geometry::MugFamily family) {
  std::vector<ObjectSource> sources;
  for (std::size_t i = 0; i < count; ++i) {
    Rng rng(derive_seed(seed, i, 0));
    ObjectSource s;
    s.name = fmt::format("mug-{}-{:04d}", seed, i);
    s.category = "Mug";
    s.mug = geometry::random_mug_parameters(rng, family);
    sources.push_back(std::move(s));
  }
  return sources;
}

std::vector<ObjectSource> mesh_folder_sources(const fs::path& dir, double scale) {
  if (!fs::is_directory(dir)) throw Error(dir.string() + ": not a folder");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string ext = lower_extension(entry.path());
    if (entry.is_regular_file() &&
        (ext == ".obj" || ext == ".stl" || ext == ".ply" || ext == ".glb" || ext == ".gltf")) {
      files.push_back(entry.path());
    }
  }
  if (files.empty()) throw Error(dir.string() + ": no .obj, .stl, .ply, .glb or .gltf file");
  std::sort(files.begin(), files.end());
  std::vector<ObjectSource> sources;
  std::set<std::string> names;
  for (const fs::path& file : files) {
    ObjectSource s;
    s.name = file.stem().string();
    for (char& ch : s.name) {
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '-';
    }
    if (!names.insert(s.name).second) {
      throw Error(dir.string() + ": two files map to the object name " + s.name);
    }
    s.category = "Object";
    s.mesh_file = file;
    s.scale = scale;
    sources.push_back(std::move(s));
  }
  return sources;
}

std::vector<ObjectOutcome> make_dataset(const MakeDatasetOptions& o,
                                        const DatasetProgress& progress) {
  validate_sources(o.objects);
  validate(o.candidates);
  sim::validate(o.trial);
  if (!(o.density > 0) || !std::isfinite(o.density)) {
    throw Error("make-dataset: the density must be a positive number");
  }
  if (o.threads < 1) throw Error("make-dataset: the number of threads must be at least 1");
  const OutputLock lock = prepare_output(o);

  // Progress counts only the objects this run makes, so the ETA reflects their pace.
  const std::size_t per_object = o.candidates.num_grasps;
  std::size_t pending = 0;
  for (const ObjectSource& s : o.objects) pending += !fs::exists(o.out / grasp_file_name(s));
  const std::size_t total = std::max<std::size_t>(1, per_object * pending);
  std::size_t made = 0;
  std::vector<ObjectOutcome> outcomes;
  for (std::size_t i = 0; i < o.objects.size(); ++i) {
    const std::size_t before = std::min(per_object * made, total);
    const auto start = std::chrono::steady_clock::now();
    ObjectOutcome r;
    if (std::optional<ObjectOutcome> resumed = resumed_outcome(o.out, o.objects[i])) {
      r = *resumed;
    } else {
      r = make_object(o, i, [&](std::size_t done) {
        if (progress.trials) {
          progress.trials(std::min(before + std::min(done, per_object), total), total);
        }
      });
      ++made;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcomes.push_back(r);
    if (!r.resumed) write_manifest(o, outcomes);
    append_file_text(o.out / kTimingLogName, json{{"name", r.name},
                                                  {"resumed", r.resumed},
                                                  {"skipped", r.skipped},
                                                  {"seconds", r.seconds},
                                                  {"unstable", r.unstable},
                                                  {"threads", o.threads}}
                                                     .dump() +
                                                 "\n");
    if (progress.trials && !r.resumed) progress.trials(std::min(per_object * made, total), total);
    if (progress.object) progress.object(r);
  }
  write_manifest(o, outcomes);
  write_split(o, outcomes);
  write_preview(o, outcomes);
  return outcomes;
}

}  // namespace graspecmf::dataset
