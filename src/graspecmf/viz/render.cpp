#include "graspecmf/viz/render.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"

namespace graspecmf::viz {
namespace {

constexpr double kAmbient = 0.25;
constexpr int kGutter = 4;
// A segment wins the depth test against a surface up to this many pixels behind it, so that lines
// lying on the surface stay visible.
constexpr double kSegmentDepthBias = 2.0;

Image blank(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 255);
  return image;
}

// A square image with a depth buffer; points are (column, row, depth) as Projection gives them.
class Canvas {
 public:
  explicit Canvas(int size)
      : image_(blank(size, size)),
        depth_(static_cast<std::size_t>(size) * static_cast<std::size_t>(size),
               std::numeric_limits<double>::infinity()) {}

  // Colours the pixels whose centres lie in the triangle abc where it is the nearest so far.
  void fill_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& rgb) {
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (std::abs(area) < 1e-12) return;
    const int n = image_.width;
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
        plot(x, y, wa * a.z() + wb * b.z() + wc * c.z(), rgb);
      }
    }
  }

  // A line `width` pixels wide from a to b (depths interpolated), drawn where it is the nearest so
  // far or less than `bias` behind.
  void draw_line(const Vec3& a, const Vec3& b, int width, double bias, const Vec3& rgb) {
    const double length = std::max(std::abs(b.x() - a.x()), std::abs(b.y() - a.y()));
    const int steps = static_cast<int>(std::ceil(2.0 * length)) + 1;  // ≤ half a pixel apart
    for (int k = 0; k <= steps; ++k) {
      const Vec3 p = a + (b - a) * (static_cast<double>(k) / steps);
      const int x0 = static_cast<int>(std::floor(p.x() - 0.5 * width));
      const int y0 = static_cast<int>(std::floor(p.y() - 0.5 * width));
      for (int y = std::max(0, y0); y < std::min(image_.height, y0 + width); ++y) {
        for (int x = std::max(0, x0); x < std::min(image_.width, x0 + width); ++x) {
          plot(x, y, p.z() - bias, rgb);
        }
      }
    }
  }

  const Image& image() const { return image_; }

 private:
  // Sets pixel (x, y) to rgb (components in [0, 1]) if depth is nearer than what it shows.
  void plot(int x, int y, double depth, const Vec3& rgb) {
    const std::size_t pixel = static_cast<std::size_t>(y) * static_cast<std::size_t>(image_.width) +
                              static_cast<std::size_t>(x);
    if (depth >= depth_[pixel]) return;
    depth_[pixel] = depth;
    for (int k = 0; k < 3; ++k) {
      image_.rgb[3 * pixel + static_cast<std::size_t>(k)] =
          static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(rgb[k], 0.0, 1.0)));
    }
  }

  Image image_;
  std::vector<double> depth_;
};

}  // namespace

Image render_mesh(const geometry::TriangleMesh& mesh, const ViewOptions& options) {
  return render_scene(mesh, {}, options);
}

Image render_scene(const geometry::TriangleMesh& mesh, const std::vector<Segment>& segments,
                   const ViewOptions& options) {
  if (mesh.triangles.empty()) throw Error("render: the mesh has no triangles");
  if (options.line_width < 1 || options.line_width > 16) {
    throw Error("render: the line width must be in [1, 16]");
  }
  std::vector<Vec3> fit = mesh.vertices;
  for (const Segment& s : segments) {
    fit.push_back(s.a);
    fit.push_back(s.b);
  }
  const Projection project(fit, options.size, options.direction, options.up);
  // Light from above-left of the camera.
  const Vec3 light = (-project.forward() + 0.5 * project.up() - 0.3 * project.right()).normalized();
  std::vector<Vec3> projected;
  projected.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) projected.push_back(project(v));

  Canvas canvas(options.size);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 normal = geometry::triangle_normal(mesh, t);
    if (normal.isZero()) continue;
    const double shade = kAmbient + (1.0 - kAmbient) * std::abs(normal.dot(light));
    const auto& tri = mesh.triangles[t];
    canvas.fill_triangle(projected[tri[0]], projected[tri[1]], projected[tri[2]],
                         options.color * shade);
  }
  const double bias = kSegmentDepthBias / project.scale();
  for (const Segment& s : segments) {
    const Vec3 rgb = Eigen::Vector3i(s.rgb[0], s.rgb[1], s.rgb[2]).cast<double>() / 255.0;
    canvas.draw_line(project(s.a), project(s.b), options.line_width, bias, rgb);
  }
  return canvas.image();
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
  std::string bytes;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, image.rgb.data(),
                             3 * image.width) == 0) {
    throw Error("cannot encode PNG " + path.string());
  }
  write_file_atomically(path, bytes);
}

}  // namespace graspecmf::viz
