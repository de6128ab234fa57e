#pragma once
// Small software renderer for previews: a shaded, z-buffered orthographic view of a triangle mesh,
// contact sheets of several views, and PNG output (stb_image_write).

#include <cstdint>
#include <filesystem>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::viz {

using Vec3 = Eigen::Vector3d;

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row-major, top row first, 3 bytes per pixel
};

struct ViewOptions {
  int size = 256;                      // square image, pixels
  Vec3 direction = Vec3(-1, -2, -1);   // from the camera towards the object (need not be unit)
  Vec3 up = Vec3(0, 0, 1);             // projected to the screen's vertical
  Vec3 color = Vec3(0.55, 0.65, 0.8);  // surface colour, components in [0, 1]
};

// The mesh fitted to the image (5 % margin), Lambert-shaded from a light near the camera, on a
// white background. Throws Error for a mesh without triangles, a size outside [8, 4096] or a
// direction parallel to up.
Image render_mesh(const geometry::TriangleMesh& mesh, const ViewOptions& options = {});
// The images, all of one size, in rows of `columns` with a 4-pixel white gutter.
Image contact_sheet(const std::vector<Image>& images, int columns);
// Writes the image as PNG, atomically; throws Error if encoding or writing fails.
void write_png(const Image& image, const std::filesystem::path& path);

}  // namespace graspecmf::viz
