#pragma once
// Whether an object's size is plausible for the parallel-jaw gripper, and which unit would make it
// so: a mesh in millimetres read as metres is 1000× too large and must not pass silently.

#include <optional>
#include <string>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// Objects whose largest bounding-box side (metres) lies in [kMinObjectSize, kMaxObjectSize] are
// plausible for a hand that opens 8 cm.
constexpr double kMinObjectSize = 0.01;
constexpr double kMaxObjectSize = 1.0;

// A named length unit and its factor to metres.
struct LengthUnit {
  const char* name;
  double metres;
};
// mm, cm, m and in (inches), in that order.
const std::vector<LengthUnit>& length_units();
// The factor to metres of a unit named in length_units(); throws Error naming the choices.
double metres_per_unit(const std::string& name);

// The largest side of the axis-aligned bounding box of points (0 for none).
double largest_side(const std::vector<Vec3>& points);

// Where a wrong size comes from, for the error's suggestion: command-line options the user gives
// (--units, --scale), the Python module's keywords (units=, scale=), or a scale stored in a file
// (ACRONYM's /object/scale).
enum class ScaleSource { kOptions, kKeywords, kFile };

// Throws Error unless the points' largest side (metres) is a plausible object size. The one-line
// message names `what` and the size, suggests the unit that would bring it into range (as --units
// and --scale or their keywords, or as a factor on the file's scale), and mentions
// --allow-any-size (allow_any_size=True for keywords). Does nothing for an empty set.
void require_plausible_size(const std::vector<Vec3>& points, const std::string& what,
                            ScaleSource source = ScaleSource::kOptions);

}  // namespace graspecmf::geometry
