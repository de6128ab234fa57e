#include "graspecmf/viz/html_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "graspecmf/core/error.hpp"

namespace graspecmf::viz {
namespace {

geometry::TriangleMesh tetrahedron() {
  geometry::TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}, {0, 0, 0.1}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

// The JSON scene embedded in the page.
nlohmann::json embedded_scene(const std::string& html) {
  const std::string open = R"(<script id="scene" type="application/json">)";
  const std::size_t start = html.find(open) + open.size();
  return nlohmann::json::parse(html.substr(start, html.find("</script>", start) - start));
}

TEST(HtmlView, EmbedsTheMeshAndSegmentsAsJson) {
  const std::vector<Segment> segments = {{{0, 0, 0}, {0.2, 0, 0}, {1, 2, 3}},
                                         {{0.5, 0.5, 0.5}, {0, 0, 1}, {250, 0, 0}}};
  const std::string html = html_view(tetrahedron(), segments, "tet <test>");
  const nlohmann::json scene = embedded_scene(html);
  EXPECT_EQ(scene["vertices"].size(), 12u);
  EXPECT_EQ(scene["triangles"].size(), 12u);
  ASSERT_EQ(scene["segments"].size(), 18u);
  EXPECT_DOUBLE_EQ(scene["segments"][3].get<double>(), 0.2);
  EXPECT_EQ(scene["segments"][15].get<int>(), 250);
  EXPECT_NE(html.find("<canvas"), std::string::npos);
  EXPECT_NE(html.find("tet &lt;test&gt;"), std::string::npos);  // the title is escaped
  EXPECT_EQ(html.find("src="), std::string::npos);              // no external scripts
}

TEST(HtmlView, RejectsAnEmptyMeshOrNonFiniteInput) {
  EXPECT_THROW(html_view(geometry::TriangleMesh{}, {}, "x"), Error);
  EXPECT_THROW(html_view(tetrahedron(), {{{0, 0, 0}, {std::nan(""), 0, 0}, {0, 0, 0}}}, "x"),
               Error);
}

}  // namespace
}  // namespace graspecmf::viz
