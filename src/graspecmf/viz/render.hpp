#pragma once
// Small software renderer for previews: a shaded, z-buffered orthographic view of a triangle mesh
// and coloured line segments (e.g. gripper markers), contact sheets of several views, and PNG
// output (stb_image_write).

#include <cstdint>
#include <filesystem>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"
#include "graspecmf/viz/projection.hpp"
#include "graspecmf/viz/segment.hpp"

namespace graspecmf::viz {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row-major, top row first, 3 bytes per pixel
};

struct ViewOptions {
  int size = 256;                      // square image, pixels
  Vec3 direction = Vec3(-1, -2, -1);   // from the camera towards the object (need not be unit)
  Vec3 up = Vec3(0, 0, 1);             // projected to the screen's vertical
  Vec3 color = Vec3(0.55, 0.65, 0.8);  // surface colour, components in [0, 1]
  int line_width = 2;                  // of segments, pixels
};

// The mesh fitted to the image (5 % margin), Lambert-shaded from a light near the camera, on a
// white background. Throws Error for a mesh without triangles, a non-finite vertex, a size outside
// [8, 4096] or a direction parallel to up.
Image render_mesh(const geometry::TriangleMesh& mesh, const ViewOptions& options = {});
// render_mesh with the segments drawn over it, flat in their colours and line_width pixels wide,
// hidden where the mesh (or another segment) is nearer; the view is fitted to the mesh's vertices
// and the segments' ends together: Projection(those points, size, direction, up). Throws as
// render_mesh does, and for a non-finite point or a line width outside [1, 16].
Image render_scene(const geometry::TriangleMesh& mesh, const std::vector<Segment>& segments,
                   const ViewOptions& options = {});
// The images, all of one size, in rows of `columns` with a 4-pixel white gutter.
Image contact_sheet(const std::vector<Image>& images, int columns);
// Writes the image as PNG, atomically; throws Error if encoding or writing fails.
void write_png(const Image& image, const std::filesystem::path& path);

}  // namespace graspecmf::viz
