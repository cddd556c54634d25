// SPDX-License-Identifier: GPL-2.0-or-later
// Point location in a curved mesh and the misclassified-pixel measure of section 5.2.3.
#include "Curving/CurvedMeshLocator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace labelmesher
{
namespace
{

/// Position and the two reference-coordinate derivatives of a cubic triangle at
/// (x̂, ŷ) = (v, w): ∂X/∂x̂ = ∂X/∂v − ∂X/∂u, ∂X/∂ŷ = ∂X/∂w − ∂X/∂u.
struct CubicJet
{
  Point2 Position{ 0.0, 0.0 };
  Point2 DerivativeX{ 0.0, 0.0 };
  Point2 DerivativeY{ 0.0, 0.0 };
};

CubicJet EvaluateJet(const CubicTriangle& t, double v, double w)
{
  const double u = 1.0 - v - w;
  const double bary[3] = { u, v, w };
  CubicJet jet;
  // Quadratic Bernstein weights times the forward differences of the net.
  for (int i = 0; i <= 2; ++i)
  {
    for (int j = 0; j <= 2 - i; ++j)
    {
      const int k = 2 - i - j;
      const double fact[3] = { 1.0, 1.0, 2.0 };
      const double b2 = 2.0 / (fact[i] * fact[j] * fact[k]) * std::pow(bary[0], i) *
        std::pow(bary[1], j) * std::pow(bary[2], k);
      const Point2& pu = t.ControlPoints[CubicControlPointIndex(i + 1, j, k)];
      const Point2& pv = t.ControlPoints[CubicControlPointIndex(i, j + 1, k)];
      const Point2& pw = t.ControlPoints[CubicControlPointIndex(i, j, k + 1)];
      for (int d = 0; d < 2; ++d)
      {
        jet.DerivativeX[d] += 3.0 * b2 * (pv[d] - pu[d]);
        jet.DerivativeY[d] += 3.0 * b2 * (pw[d] - pu[d]);
      }
    }
  }
  jet.Position = EvaluateCubicTriangle(t, u, v, w);
  return jet;
}

/// Barycentric (v, w) of p in the straight triangle of the cell's corners: the
/// starting guess for Newton's method.
std::array<double, 2> StraightCoordinates(const CubicTriangle& t, const Point2& p)
{
  const Point2& a = t.ControlPoints[0];
  const Point2& b = t.ControlPoints[1];
  const Point2& c = t.ControlPoints[2];
  const double e1x = b[0] - a[0], e1y = b[1] - a[1];
  const double e2x = c[0] - a[0], e2y = c[1] - a[1];
  const double det = e1x * e2y - e1y * e2x;
  if (det == 0.0)
  {
    return { 1.0 / 3.0, 1.0 / 3.0 };
  }
  const double px = p[0] - a[0], py = p[1] - a[1];
  return { (px * e2y - py * e2x) / det, (e1x * py - e1y * px) / det };
}

bool CellContains(const CubicTriangle& t, const Point2& p, double scale)
{
  auto [v, w] = StraightCoordinates(t, p);
  for (int iteration = 0; iteration < 30; ++iteration)
  {
    const CubicJet jet = EvaluateJet(t, v, w);
    const double rx = jet.Position[0] - p[0];
    const double ry = jet.Position[1] - p[1];
    const double det =
      jet.DerivativeX[0] * jet.DerivativeY[1] - jet.DerivativeX[1] * jet.DerivativeY[0];
    if (det == 0.0 || !std::isfinite(det))
    {
      return false;
    }
    const double dv = (rx * jet.DerivativeY[1] - ry * jet.DerivativeY[0]) / det;
    const double dw = (jet.DerivativeX[0] * ry - jet.DerivativeX[1] * rx) / det;
    v -= dv;
    w -= dw;
    // Far outside the reference triangle the cubic extrapolates wildly: give up.
    if (v < -1.0 || w < -1.0 || v + w > 2.0)
    {
      return false;
    }
    if (std::abs(rx) + std::abs(ry) < 1e-12 * scale && std::abs(dv) + std::abs(dw) < 1e-12)
    {
      break;
    }
  }
  const CubicJet jet = EvaluateJet(t, v, w);
  if (std::abs(jet.Position[0] - p[0]) + std::abs(jet.Position[1] - p[1]) > 1e-9 * scale)
  {
    return false;
  }
  const double tolerance = 1e-9;
  return v >= -tolerance && w >= -tolerance && v + w <= 1.0 + tolerance;
}

std::array<double, 4> ControlBox(const CubicTriangle& t)
{
  std::array<double, 4> box{ std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max(), -std::numeric_limits<double>::max() };
  for (const Point2& q : t.ControlPoints)
  {
    box[0] = std::min(box[0], q[0]);
    box[1] = std::max(box[1], q[0]);
    box[2] = std::min(box[2], q[1]);
    box[3] = std::max(box[3], q[1]);
  }
  return box;
}

} // namespace

CurvedMeshLocator::CurvedMeshLocator(const CurvedMesh& mesh)
  : Mesh(mesh)
{
  const std::size_t cells = mesh.Cells.size();
  if (cells == 0)
  {
    BinStart.assign(2, 0);
    return;
  }
  std::vector<std::array<double, 4>> boxes(cells);
  std::array<double, 4> all{ std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max(), -std::numeric_limits<double>::max() };
  for (std::size_t c = 0; c < cells; ++c)
  {
    boxes[c] = ControlBox(mesh.Cell(c));
    all[0] = std::min(all[0], boxes[c][0]);
    all[1] = std::max(all[1], boxes[c][1]);
    all[2] = std::min(all[2], boxes[c][2]);
    all[3] = std::max(all[3], boxes[c][3]);
  }
  // About one cell per bin on average.
  const double width = std::max(all[1] - all[0], 1e-300);
  const double height = std::max(all[3] - all[2], 1e-300);
  BinSize = std::sqrt(width * height / static_cast<double>(cells));
  BinSize = std::max({ BinSize, width / 4096.0, height / 4096.0 });
  Origin = { all[0], all[2] };
  Bins = { std::max(1, static_cast<int>(std::ceil(width / BinSize))),
    std::max(1, static_cast<int>(std::ceil(height / BinSize))) };
  auto binRange = [&](const std::array<double, 4>& b) {
    const int x0 = std::clamp(static_cast<int>((b[0] - Origin[0]) / BinSize), 0, Bins[0] - 1);
    const int x1 = std::clamp(static_cast<int>((b[1] - Origin[0]) / BinSize), 0, Bins[0] - 1);
    const int y0 = std::clamp(static_cast<int>((b[2] - Origin[1]) / BinSize), 0, Bins[1] - 1);
    const int y1 = std::clamp(static_cast<int>((b[3] - Origin[1]) / BinSize), 0, Bins[1] - 1);
    return std::array<int, 4>{ x0, x1, y0, y1 };
  };
  // Counting sort of (bin, cell) pairs.
  BinStart.assign(static_cast<std::size_t>(Bins[0]) * Bins[1] + 1, 0);
  for (std::size_t c = 0; c < cells; ++c)
  {
    const auto r = binRange(boxes[c]);
    for (int y = r[2]; y <= r[3]; ++y)
      for (int x = r[0]; x <= r[1]; ++x)
        ++BinStart[static_cast<std::size_t>(y) * Bins[0] + x + 1];
  }
  for (std::size_t b = 1; b < BinStart.size(); ++b)
  {
    BinStart[b] += BinStart[b - 1];
  }
  BinCells.resize(BinStart.back());
  std::vector<std::size_t> fill(BinStart.begin(), BinStart.end() - 1);
  for (std::size_t c = 0; c < cells; ++c)
  {
    const auto r = binRange(boxes[c]);
    for (int y = r[2]; y <= r[3]; ++y)
      for (int x = r[0]; x <= r[1]; ++x)
        BinCells[fill[static_cast<std::size_t>(y) * Bins[0] + x]++] = static_cast<std::int64_t>(c);
  }
}

std::int64_t CurvedMeshLocator::FindCell(const Point2& p) const
{
  if (BinCells.empty())
  {
    return -1;
  }
  const double fx = (p[0] - Origin[0]) / BinSize;
  const double fy = (p[1] - Origin[1]) / BinSize;
  if (fx < -1e-9 || fy < -1e-9 || fx > Bins[0] + 1e-9 || fy > Bins[1] + 1e-9)
  {
    return -1;
  }
  const int x = std::clamp(static_cast<int>(fx), 0, Bins[0] - 1);
  const int y = std::clamp(static_cast<int>(fy), 0, Bins[1] - 1);
  const std::size_t bin = static_cast<std::size_t>(y) * Bins[0] + x;
  for (std::size_t n = BinStart[bin]; n < BinStart[bin + 1]; ++n)
  {
    const std::int64_t c = BinCells[n];
    const CubicTriangle t = Mesh.Cell(static_cast<std::size_t>(c));
    const auto box = ControlBox(t);
    const double slack = 1e-9 * BinSize;
    if (p[0] < box[0] - slack || p[0] > box[1] + slack || p[1] < box[2] - slack || p[1] > box[3] + slack)
    {
      continue;
    }
    if (CellContains(t, p, std::max(box[1] - box[0], box[3] - box[2])))
    {
      return c;
    }
  }
  return -1;
}

std::int32_t CurvedMeshLocator::MaterialAt(const Point2& p) const
{
  const std::int64_t c = FindCell(p);
  return c < 0 ? 0 : Mesh.Materials[static_cast<std::size_t>(c)];
}

PixelAccuracy MeasurePixelAccuracy(
  const CurvedMesh& mesh, const LabelImage& image, const std::array<double, 6>& m)
{
  const CurvedMeshLocator locator(mesh);
  PixelAccuracy accuracy;
  for (int j = 0; j < image.Dimensions[1]; ++j)
  {
    for (int i = 0; i < image.Dimensions[0]; ++i)
    {
      const std::int32_t label = image.At(i, j, 0);
      const Point2 p{ m[0] + m[1] * i + m[2] * j, m[3] + m[4] * i + m[5] * j };
      const std::int32_t material = locator.MaterialAt(p);
      ++accuracy.Pixels;
      if (material != label)
      {
        ++accuracy.Misclassified;
        if (label != 0)
          ++accuracy.Missed[label];
        if (material != 0)
          ++accuracy.Claimed[material];
      }
    }
  }
  return accuracy;
}

} // namespace labelmesher
