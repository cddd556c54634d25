// SPDX-License-Identifier: GPL-2.0-or-later
// Voxel-by-voxel reference meshes for testing the checks.
#include "VoxelMeshes.h"

#include <utility>

namespace labelmesher
{
namespace testing
{

double Det(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double w[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
    u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// Every voxel of the image as a cube split into 6 Kuhn tetrahedra (a pixel
/// into 2 triangles in 2D), material = label. Background voxels are meshed
/// only if withBackground. All points are moved by `shift`.
SimplexMesh VoxelMesh(const LabelImage& image, bool withBackground, Point3 shift)
{
  SimplexMesh m;
  const int nx = image.Dimensions[0], ny = image.Dimensions[1], nz = image.Dimensions[2];
  const bool is2D = nz == 1;
  m.Dimension = is2D ? 2 : 3;
  const int lz = is2D ? 1 : nz + 1;
  std::vector<std::int64_t> id(static_cast<std::size_t>(nx + 1) * (ny + 1) * lz, -1);
  auto point = [&](int i, int j, int k) {
    std::int64_t& p = id[(static_cast<std::size_t>(k) * (ny + 1) + j) * (nx + 1) + i];
    if (p < 0)
    {
      p = static_cast<std::int64_t>(m.Points.size());
      m.Points.push_back({ i - 0.5 + shift[0], j - 0.5 + shift[1], is2D ? 0.0 : k - 0.5 + shift[2] });
    }
    return p;
  };
  const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const std::int32_t l = image.At(i, j, k);
        if (l == 0 && !withBackground)
          continue;
        auto corner = [&](int b) {
          return point(i + (b & 1), j + ((b >> 1) & 1), is2D ? 0 : k + ((b >> 2) & 1));
        };
        if (is2D)
        {
          m.Connectivity.insert(
            m.Connectivity.end(), { corner(0), corner(1), corner(3), corner(0), corner(3), corner(2) });
          m.Materials.insert(m.Materials.end(), { l, l });
          continue;
        }
        for (const auto& p : perms)
        {
          std::int64_t v[4] = { corner(0), corner(1 << p[0]), corner((1 << p[0]) | (1 << p[1])), corner(7) };
          if (Det(m.Points[v[0]], m.Points[v[1]], m.Points[v[2]], m.Points[v[3]]) < 0)
            std::swap(v[1], v[2]);
          m.Connectivity.insert(m.Connectivity.end(), v, v + 4);
          m.Materials.push_back(l);
        }
      }
  return m;
}

LabelImage RandomImage(std::mt19937& rng, int nx, int ny, int nz, int labels, int fillPercent)
{
  LabelImage image(nx, ny, nz);
  for (std::size_t v = 0; v < image.NumberOfVoxels(); ++v)
    image.SetLabel(v, static_cast<int>(rng() % 100) < fillPercent ? 1 + static_cast<std::int32_t>(rng() % labels) : 0);
  return image;
}

} // namespace testing
} // namespace labelmesher
