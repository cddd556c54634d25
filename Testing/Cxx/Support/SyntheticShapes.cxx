// SPDX-License-Identifier: GPL-2.0-or-later
// Analytic label images (discs, ellipses, spheres, tori, the Cassini volume) for tests and benchmarks.
#include "SyntheticShapes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace labelmesher
{
namespace testing
{

namespace
{

constexpr double kPi = 3.14159265358979323846;

void RequirePositive(int n, const char* what)
{
  if (n <= 0)
    throw std::invalid_argument(std::string(what) + ": image sides must be positive");
}

/// Paints `label` on every voxel whose centre, relative to the image centre, satisfies `inside`.
template <class Inside>
void PaintCentred(LabelImage& image, std::int32_t label, Inside inside)
{
  const auto& d = image.Dimensions;
  const double cx = 0.5 * (d[0] - 1), cy = 0.5 * (d[1] - 1), cz = 0.5 * (d[2] - 1);
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
        if (inside(i - cx, j - cy, k - cz))
          image(i, j, k) = label;
}

} // namespace

LabelImage MakeDisc(int n, double radius, std::int32_t label)
{
  return MakeEllipse(n, n, radius, radius, 0.0, label);
}

LabelImage MakeEllipse(int nx, int ny, double rx, double ry, double angleDegrees, std::int32_t label)
{
  RequirePositive(nx, "MakeEllipse");
  RequirePositive(ny, "MakeEllipse");
  LabelImage image(nx, ny, 1);
  const double t = angleDegrees * kPi / 180.0, c = std::cos(t), s = std::sin(t);
  PaintCentred(image, label, [&](double x, double y, double) {
    const double u = c * x + s * y, v = -s * x + c * y;
    return (u / rx) * (u / rx) + (v / ry) * (v / ry) <= 1.0;
  });
  return image;
}

LabelImage MakeTouchingBlobs2D(
  int nx, int ny, std::int32_t labelA, std::int32_t labelB, double radius, double overlap)
{
  RequirePositive(nx, "MakeTouchingBlobs2D");
  RequirePositive(ny, "MakeTouchingBlobs2D");
  LabelImage image(nx, ny, 1);
  if (radius <= 0)
    radius = std::max(2.0, ny / 4.0 - 1.0);
  const double half = radius * overlap; // centre offset from the mid-line
  PaintCentred(image, labelA, [&](double x, double y, double) {
    return x < 0 && (x + half) * (x + half) + y * y <= radius * radius;
  });
  PaintCentred(image, labelB, [&](double x, double y, double) {
    return x >= 0 && (x - half) * (x - half) + y * y <= radius * radius;
  });
  return image;
}

LabelImage MakeSphere(int n, double radius, std::int32_t label)
{
  return MakeEllipsoid(n, n, n, radius, radius, radius, label);
}

LabelImage MakeEllipsoid(int nx, int ny, int nz, double rx, double ry, double rz, std::int32_t label)
{
  RequirePositive(nx, "MakeEllipsoid");
  RequirePositive(ny, "MakeEllipsoid");
  RequirePositive(nz, "MakeEllipsoid");
  LabelImage image(nx, ny, nz);
  PaintCentred(image, label, [&](double x, double y, double z) {
    return (x / rx) * (x / rx) + (y / ry) * (y / ry) + (z / rz) * (z / rz) <= 1.0;
  });
  return image;
}

LabelImage MakeTorus(int n, double majorRadius, double minorRadius, std::int32_t label)
{
  RequirePositive(n, "MakeTorus");
  LabelImage image(n, n, n);
  PaintCentred(image, label, [&](double x, double y, double z) {
    const double rho = std::sqrt(x * x + y * y) - majorRadius;
    return rho * rho + z * z <= minorRadius * minorRadius;
  });
  return image;
}

LabelImage MakeNestedSpheres(int n, const std::vector<double>& radii, const std::vector<std::int32_t>& labels)
{
  RequirePositive(n, "MakeNestedSpheres");
  if (radii.size() != labels.size())
    throw std::invalid_argument("MakeNestedSpheres: one label per radius");
  for (std::size_t i = 1; i < radii.size(); ++i)
    if (!(radii[i] < radii[i - 1]))
      throw std::invalid_argument("MakeNestedSpheres: radii must decrease");
  LabelImage image(n, n, n);
  for (std::size_t s = 0; s < radii.size(); ++s)
  {
    const double r2 = radii[s] * radii[s];
    PaintCentred(image, labels[s], [&](double x, double y, double z) { return x * x + y * y + z * z <= r2; });
  }
  return image;
}

double CassiniFocalDistance(int n, const CassiniOptions& options)
{
  // Length along x: 2 sqrt(a^2 + b^2) = 2 a sqrt(1 + ratio^2) = n - 2 margin.
  const double length = n - 2.0 * options.Margin;
  return 0.5 * length / std::sqrt(1.0 + options.ShapeRatio * options.ShapeRatio);
}

LabelImage MakeCassiniVolume(int n, const CassiniOptions& options)
{
  RequirePositive(n, "MakeCassiniVolume");
  if (!(options.ShapeRatio > 0) || n - 2.0 * options.Margin <= 2.0)
    throw std::invalid_argument("MakeCassiniVolume: image too small for the margins or bad ratio");
  const double a = CassiniFocalDistance(n, options);
  const double b = options.ShapeRatio * a;
  const double a2 = a * a, b4 = b * b * b * b;
  LabelImage image(n, n, n);
  const double c = 0.5 * (n - 1);
  // Row by row: the y-z part of the sum is shared along x.
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
    {
      const double y = j - c, z = k - c, yz = y * y + z * z;
      if (yz > b * b) // |p - F1| |p - F2| >= (distance to the x axis)^2
        continue;
      const std::size_t row = image.Index(0, j, k);
      for (int i = 0; i < n; ++i)
      {
        const double x = i - c;
        const double s = x * x + yz + a2;
        if (s * s - 4.0 * a2 * x * x <= b4)
          image.SetLabel(row + i, (options.SplitLobes && x >= 0) ? options.LabelB : options.LabelA);
      }
    }
  return image;
}

} // namespace testing
} // namespace labelmesher
