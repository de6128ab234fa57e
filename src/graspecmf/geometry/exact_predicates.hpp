#pragma once
// Exact geometric predicates: floating-point evaluation with an error bound, falling back to exact
// expansion arithmetic when the bound cannot certify the sign.

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::geometry {

// Exact sign of ((b − a) × (c − a)) · (d − a): +1 if d lies above the plane of the
// counter-clockwise triangle abc, −1 below, 0 on it.
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace graspecmf::geometry
