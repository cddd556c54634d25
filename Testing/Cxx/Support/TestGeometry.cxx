// SPDX-License-Identifier: GPL-2.0-or-later
// Support/Geometry.h: the distance to a degenerate triangle (two equal points, or three on a line)
// is the distance to the segment it spans, not NaN. The mesher's distance test, the quadratic
// fidelity and the independent checks (Checks/) share the function: a NaN there would read as
// "not within" in one place and pass a `<=` silently nowhere.
#include "Support/Geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using labelmesher::Point3;
using labelmesher::geometry::SquaredDistanceToSegment;
using labelmesher::geometry::SquaredDistanceToTriangle;

TEST(Geometry, ADegenerateTriangleIsTheSegmentItSpans)
{
  std::mt19937 random(20261206);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  for (int trial = 0; trial < 4000; ++trial)
  {
    // Half the trials far from the origin (a 16,000-voxel image's lattice), where the region
    // tests' products round.
    const double offset = trial % 2 == 0 ? 0.0 : 8191.5;
    auto point = [&] {
      return Point3{ offset + coordinate(random), offset + coordinate(random), offset + coordinate(random) };
    };
    const Point3 p = point(), a = point(), c = point();
    const double segment = SquaredDistanceToSegment(p, a, c);
    // Two equal points, in every position; then a third point on the segment (a line through it).
    const Point3 middle{ (a[0] + c[0]) / 2, (a[1] + c[1]) / 2, (a[2] + c[2]) / 2 };
    const Point3 triangles[][3] = { { a, a, c }, { a, c, c }, { a, c, a }, { c, a, a }, { a, middle, c },
      { middle, a, c }, { a, c, middle } };
    for (const auto& t : triangles)
    {
      const double d = SquaredDistanceToTriangle(p, t[0], t[1], t[2]);
      ASSERT_FALSE(std::isnan(d)) << "trial " << trial;
      EXPECT_NEAR(d, segment, 1e-9 * (1.0 + segment)) << "trial " << trial;
    }
    // All three equal: the point.
    const double toA = SquaredDistanceToTriangle(p, a, a, a);
    EXPECT_NEAR(toA, SquaredDistanceToSegment(p, a, a), 1e-12 * (1.0 + toA));
  }
}

} // namespace
