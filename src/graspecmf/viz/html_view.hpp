#pragma once
// A self-contained interactive 3-D view (one HTML file, no external scripts): a shaded mesh and
// coloured line segments, e.g. gripper markers of grasps. Drag to rotate, wheel to zoom.

#include <string>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"
#include "graspecmf/viz/segment.hpp"

namespace graspecmf::viz {

// The page's HTML; the scene is embedded as JSON in <script id="scene">, metres. Throws Error for a
// mesh without triangles or a non-finite coordinate.
std::string html_view(const geometry::TriangleMesh& mesh, const std::vector<Segment>& segments,
                      const std::string& title);

}  // namespace graspecmf::viz
