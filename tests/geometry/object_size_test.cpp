#include "graspecmf/geometry/object_size.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {
namespace {

// Two corners of a box of the given largest side.
std::vector<Vec3> box_of(double side) {
  return {Vec3(0, 0, 0), Vec3(side, 0.5 * side, 0.2 * side)};
}

std::string size_error(double side, ScaleSource source = ScaleSource::kOptions) {
  try {
    require_plausible_size(box_of(side), "obj", source);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ObjectSize, PlausibleSizesPass) {
  EXPECT_EQ(size_error(0.01), "");
  EXPECT_EQ(size_error(0.1), "");
  EXPECT_EQ(size_error(1.0), "");
  EXPECT_NO_THROW(require_plausible_size({}, "empty"));
  EXPECT_DOUBLE_EQ(largest_side(box_of(0.3)), 0.3);
}

// The suggested unit is the one that brings the object nearest 10 cm.
TEST(ObjectSize, WrongUnitsNameTheLikelyOne) {
  const std::string mm = size_error(101.0);
  EXPECT_NE(mm.find("obj is 101 m across, larger than a graspable object"), std::string::npos)
      << mm;
  EXPECT_NE(mm.find("--units mm (or --scale 0.001), which makes it 10.1 cm"), std::string::npos)
      << mm;
  EXPECT_NE(mm.find("--allow-any-size"), std::string::npos) << mm;
  EXPECT_NE(size_error(8.0).find("--units cm"), std::string::npos);
  EXPECT_NE(size_error(101.0, ScaleSource::kFile).find("the file's scale is likely off by 0.001"),
            std::string::npos);
  const std::string tiny = size_error(0.002);
  EXPECT_NE(tiny.find("smaller than a graspable object"), std::string::npos) << tiny;
  EXPECT_NE(tiny.find("--scale 50 would make it 10 cm"), std::string::npos) << tiny;
}

// The Python module's callers get its keywords, not the command's flags.
TEST(ObjectSize, KeywordCallersGetKeywordHints) {
  const std::string mm = size_error(101.0, ScaleSource::kKeywords);
  EXPECT_NE(mm.find("give units='mm' (or scale=0.001), which makes it 10.1 cm"), std::string::npos)
      << mm;
  EXPECT_NE(mm.find("or allow_any_size=True to go on"), std::string::npos) << mm;
  EXPECT_EQ(mm.find("--"), std::string::npos) << mm;
  const std::string tiny = size_error(0.002, ScaleSource::kKeywords);
  EXPECT_NE(tiny.find("scale=50 would make it 10 cm"), std::string::npos) << tiny;
}

TEST(ObjectSize, UnitNames) {
  EXPECT_DOUBLE_EQ(metres_per_unit("mm"), 0.001);
  EXPECT_DOUBLE_EQ(metres_per_unit("in"), 0.0254);
  EXPECT_THROW(metres_per_unit("furlong"), Error);
}

}  // namespace
}  // namespace graspecmf::geometry
