#pragma once
// Procedural mugs: seeded shape parameters spanning real mugs, and a watertight, outward triangle
// mesh for them (a surface of revolution with a handle tube stitched into holes in the outer wall,
// so the mesh is one closed manifold without self-intersections).

#include <cstdint>
#include <string>

#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

enum class MugBody { straight, tapered, barrel, waisted };
enum class MugRim { flat, rounded };
enum class MugHandle { none, c_shape, d_loop };
enum class HandleSection { round, flat };

// Lengths in metres. The mug stands on z = 0 with its axis along z; the handle points to +x.
struct MugParameters {
  double height = 0.095;
  double outer_radius = 0.04;  // at the base
  double wall = 0.004;         // horizontal wall thickness
  double base = 0.006;         // bottom thickness
  MugBody body = MugBody::straight;
  // tapered: top radius = outer_radius × (1 + body_amount); barrel / waisted: the radius at mid
  // height is outer_radius × (1 ± body_amount).
  double body_amount = 0.0;
  MugRim rim = MugRim::flat;
  MugHandle handle = MugHandle::c_shape;
  HandleSection section = HandleSection::round;
  double handle_thickness = 0.01;   // radial size of the handle's cross-section
  double handle_width = 0.01;       // tangential size (= thickness for a round section)
  double handle_clearance = 0.025;  // gap between the wall and the handle's inner side
  double handle_low = 0.25;         // lower attachment height, fraction of height
  double handle_high = 0.8;         // upper attachment height, fraction of height
  // A flared lip: over the top flare_height (fraction of height) the radius grows smoothly
  // (quadratically) by up to flare metres, inside and out. 0 = no flare.
  double flare = 0.0;
  double flare_height = 0.0;
  // An uneven, modelled or scanned-looking surface: every wall vertex moves radially by up to
  // about this many metres (smooth dents plus fine per-vertex jitter, seeded). 0 = smooth.
  double roughness = 0.0;
  std::uint64_t roughness_seed = 0;
};

// The procedural families: `classic` (the mugs-v1 / mugs-v2 presets) and `varied` (wider sizes,
// flared lips, uneven surfaces, more cups without handles; the mugs-v3 preset).
enum class MugFamily { classic, varied };

// Parameters drawn from the family's ranges (docs/dataset.md). classic: height 7–13 cm, outer
// radius 3.2–5.2 cm, wall 2.5–6 mm, base 3–10 mm, all body and rim kinds, handles (6 % none)
// attached within 15–90 % of the height, thickness 6–15 mm, clearance 1.5–3.5 cm, no flare, smooth.
// Always valid for mug_mesh.
MugParameters random_mug_parameters(Rng& rng, MugFamily family = MugFamily::classic);
// Throws Error naming the first parameter that is out of range or geometrically inconsistent
// (e.g. a wall thicker than the radius, or a handle that does not fit between base and rim).
void validate(const MugParameters& mug);
// The mug's closed, consistently outward mesh (≈ 10–20 k triangles); validates first.
TriangleMesh mug_mesh(const MugParameters& mug);

// Names of the enum values as used in manifests ("straight", "c_shape", ...).
std::string to_string(MugBody body);
std::string to_string(MugRim rim);
std::string to_string(MugHandle handle);
std::string to_string(HandleSection section);
std::string to_string(MugFamily family);
// The family named `name` ("classic" or "varied"); throws Error naming the choices otherwise.
MugFamily mug_family_from_string(const std::string& name);

}  // namespace graspecmf::geometry
