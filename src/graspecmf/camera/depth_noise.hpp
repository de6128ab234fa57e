#pragma once
// A depth camera's errors, applied to an exact rendered view: depth-dependent noise along the ray,
// pixels lost at grazing angles and at depth edges, random dropout, and disparity quantisation.
// Defaults follow published measurements of structured-light and stereo cameras (docs/camera.md).

#include <cstdint>

#include "graspecmf/camera/depth_render.hpp"

namespace graspecmf::camera {

struct DepthNoise {
  // Axial noise σ(z, θ) = base + quadratic (z − 0.4 m)² + angle θ² / (√z (π/2 − θ)²), metres
  // (Nguyen, Izadi and Lovell 2012; θ is the angle between the surface normal and the ray).
  double sigma_base = 0.0012;
  double sigma_quadratic = 0.0019;
  double sigma_angle = 0.0001;
  // Grazing surfaces return nothing: the loss probability rises from 0 to 1 between these
  // angles (degrees) of the normal to the ray.
  double grazing_start_degrees = 70.0;
  double grazing_end_degrees = 85.0;
  // A pixel whose depth differs from a 4-neighbour's by more than edge_jump (m) is lost with
  // probability edge_dropout (the mixed pixels and stereo shadows at silhouettes).
  double edge_jump = 0.02;
  double edge_dropout = 0.5;
  double random_dropout = 0.005;  // every pixel's loss probability
  // Stereo disparity quantisation: disparity fx · baseline / z rounded to multiples of subpixel.
  double baseline = 0.05;  // m
  double subpixel = 0.08;  // pixels; 0 turns quantisation off
};

// Throws Error "<what>: <why>" for a negative or non-finite parameter, a probability above 1, or
// grazing angles outside 0 ≤ start < end ≤ 90.
void validate(const DepthNoise& noise, const std::string& what);

// The view's depth with the noise applied, seeded and deterministic; lost pixels read 0.
DepthImage noisy_depth(const RenderedView& view, const Intrinsics& intrinsics,
                       const DepthNoise& noise, std::uint64_t seed);

}  // namespace graspecmf::camera
