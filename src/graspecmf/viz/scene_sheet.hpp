#pragma once
// A PNG-ready overview of a mesh and segments (e.g. an object and its grasps' gripper markers):
// the scene rendered from several fixed directions, tiled into one contact sheet.

#include <array>
#include <vector>

#include "graspecmf/viz/render.hpp"

namespace graspecmf::viz {

// The sheet's views, row by row in kSheetColumns columns: from above at four azimuths 90° apart,
// from below, and almost straight down (+z up in every view).
inline constexpr int kSheetColumns = 3;
std::array<Vec3, 6> sheet_directions();

// render_scene of the mesh and segments (default ViewOptions but `size`) from each of
// sheet_directions(), each view fitted on its own, tiled by contact_sheet in kSheetColumns
// columns. Throws as render_scene does.
Image scene_sheet(const geometry::TriangleMesh& mesh, const std::vector<Segment>& segments,
                  int size = 320);

}  // namespace graspecmf::viz
