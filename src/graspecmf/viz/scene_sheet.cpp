#include "graspecmf/viz/scene_sheet.hpp"

namespace graspecmf::viz {

std::array<Vec3, 6> sheet_directions() {
  return {Vec3(1, 1, -0.8),  Vec3(-1, 1, -0.8),   Vec3(-1, -1, -0.8),
          Vec3(1, -1, -0.8), Vec3(-1, -0.5, 1.2), Vec3(-0.2, -0.3, -1)};
}

Image scene_sheet(const geometry::TriangleMesh& mesh, const std::vector<Segment>& segments,
                  int size) {
  std::vector<Image> views;
  for (const Vec3& direction : sheet_directions()) {
    ViewOptions options;
    options.size = size;
    options.direction = direction;
    views.push_back(render_scene(mesh, segments, options));
  }
  return contact_sheet(views, kSheetColumns);
}

}  // namespace graspecmf::viz
