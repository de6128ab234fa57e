#include "graspecmf/viz/render.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"

namespace graspecmf::viz {
namespace {

constexpr double kMargin = 0.05;
constexpr double kAmbient = 0.25;
constexpr int kGutter = 4;

Image blank(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 255);
  return image;
}

}  // namespace

Image render_mesh(const geometry::TriangleMesh& mesh, const ViewOptions& options) {
  if (mesh.triangles.empty()) throw Error("render: the mesh has no triangles");
  if (options.size < 8 || options.size > 4096) throw Error("render: size must be in [8, 4096]");
  const Vec3 forward = options.direction.normalized();
  const Vec3 right = forward.cross(options.up);
  if (!(right.norm() > 1e-9)) throw Error("render: the view direction is parallel to up");
  const Vec3 screen_x = right.normalized();
  const Vec3 screen_y = screen_x.cross(forward);
  // Light from above-left of the camera.
  const Vec3 light = (-forward + 0.5 * screen_y - 0.3 * screen_x).normalized();

  std::vector<Eigen::Vector3d> projected;  // pixel x, pixel y, depth
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const Vec3& v : mesh.vertices) {
    const Eigen::Vector2d p(v.dot(screen_x), v.dot(screen_y));
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    projected.emplace_back(p.x(), p.y(), v.dot(forward));
  }
  const int n = options.size;
  const double extent = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-12});
  const double scale = n * (1.0 - 2.0 * kMargin) / extent;
  const Eigen::Vector2d center = 0.5 * (lo + hi);
  for (Eigen::Vector3d& p : projected) {
    p.x() = 0.5 * n + (p.x() - center.x()) * scale;
    p.y() = 0.5 * n - (p.y() - center.y()) * scale;  // image rows grow downwards
  }

  Image image = blank(n, n);
  std::vector<double> depth(static_cast<std::size_t>(n) * static_cast<std::size_t>(n),
                            std::numeric_limits<double>::infinity());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 normal = geometry::triangle_normal(mesh, t);
    if (normal.isZero()) continue;
    const double shade = kAmbient + (1.0 - kAmbient) * std::abs(normal.dot(light));
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = projected[tri[0]];
    const Eigen::Vector3d& b = projected[tri[1]];
    const Eigen::Vector3d& c = projected[tri[2]];
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (std::abs(area) < 1e-12) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 = std::min(n - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 = std::min(n - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double wa = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
        const double wb = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
        const double wc = 1.0 - wa - wb;
        if (wa < 0 || wb < 0 || wc < 0) continue;
        const double z = wa * a.z() + wb * b.z() + wc * c.z();
        const std::size_t pixel =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(n) + static_cast<std::size_t>(x);
        if (z >= depth[pixel]) continue;
        depth[pixel] = z;
        for (int k = 0; k < 3; ++k) {
          image.rgb[3 * pixel + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(
              std::lround(255.0 * std::clamp(options.color[k] * shade, 0.0, 1.0)));
        }
      }
    }
  }
  return image;
}

Image contact_sheet(const std::vector<Image>& images, int columns) {
  if (images.empty() || columns < 1) throw Error("contact sheet: need images and ≥ 1 column");
  const int w = images.front().width, h = images.front().height;
  for (const Image& image : images) {
    if (image.width != w || image.height != h) throw Error("contact sheet: images differ in size");
  }
  const int count = static_cast<int>(images.size());
  const int cols = std::min(columns, count);
  const int rows = (count + cols - 1) / cols;
  Image sheet = blank(cols * (w + kGutter) + kGutter, rows * (h + kGutter) + kGutter);
  for (int i = 0; i < count; ++i) {
    const int ox = kGutter + (i % cols) * (w + kGutter);
    const int oy = kGutter + (i / cols) * (h + kGutter);
    for (int y = 0; y < h; ++y) {
      const auto* src = images[static_cast<std::size_t>(i)].rgb.data() + 3 * y * w;
      auto* dst = sheet.rgb.data() + 3 * ((oy + y) * sheet.width + ox);
      std::copy(src, src + 3 * w, dst);
    }
  }
  return sheet;
}

void write_png(const Image& image, const std::filesystem::path& path) {
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    if (stbi_write_png(tmp.c_str(), image.width, image.height, 3, image.rgb.data(),
                       3 * image.width) == 0) {
      throw Error("cannot write PNG " + path.string());
    }
  });
}

}  // namespace graspecmf::viz
