// SPDX-License-Identifier: GPL-2.0-or-later
// The image boundary as voxel faces with their two labels, and a grid to find those near a box.
#include "Decimation/ImageBoundary.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace labelmesher
{

void BoxAround(const ConvexPiece& piece, double margin, Point3& lo, Point3& hi)
{
  lo = hi = piece.Points[0];
  for (int i = 1; i < piece.Count; ++i)
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], piece.Points[i][a]);
      hi[a] = std::max(hi[a], piece.Points[i][a]);
    }
  for (int a = 0; a < 3; ++a)
  {
    lo[a] -= margin;
    hi[a] += margin;
  }
}

ImageBoundary::ImageBoundary(const LabelImage& image)
  : Dimension(image.Dimension())
{
  const auto& n = image.Dimensions;
  if (static_cast<std::size_t>(n[0]) * n[1] * n[2] * 3 >= (std::size_t(1) << 32))
    throw std::invalid_argument("the image is too large for the decimator's face index (2^32 voxel faces)");
  // Faces between voxel (i, j, k) and its +axis neighbour, from i = -1 (the
  // outside) to n - 1; of a slab, those whose two voxels it holds.
  const int slab = image.SlabAxis(), first = image.SlabFirst(), end = image.SlabEnd();
  for (int axis = 0; axis < Dimension; ++axis)
  {
    std::array<int, 3> lo{ axis == 0 ? -1 : 0, axis == 1 ? -1 : 0, axis == 2 ? -1 : 0 };
    std::array<int, 3> hi{ n[0], n[1], n[2] }; // exclusive
    if (axis == slab)
    {
      lo[slab] = first == 0 ? -1 : first;
      hi[slab] = end == n[slab] ? end : end - 1;
    }
    else
    {
      lo[slab] = first;
      hi[slab] = end;
    }
    for (int k = lo[2]; k < hi[2]; ++k)
      for (int j = lo[1]; j < hi[1]; ++j)
        for (int i = lo[0]; i < hi[0]; ++i)
        {
          const std::int32_t here = image.At(i, j, k);
          const std::int32_t there = image.At(i + (axis == 0), j + (axis == 1), k + (axis == 2));
          if (here != there)
            FaceList.push_back(Face{ { i, j, k }, axis, std::min(here, there), std::max(here, there) });
        }
  }

  for (int a = 0; a < Dimension; ++a)
  {
    Bins[a] = (n[a] + 2) / Bin + 1;
    Size[static_cast<std::size_t>(a)] = n[a];
  }
  // Bin b holds the face centres c with b = floor((c + 1) / Bin): every face
  // it would hold on the whole image when the voxels along the slab axis
  // [Bin b - 1, Bin b + 3] are held (or outside the image).
  const int lastBin = Bins[slab] - 1;
  FirstBin = first == 0 ? 0 : BinOf(first - 0.5, slab);
  const int endBin = end == n[slab] ? lastBin : BinOf(end - 0.5, slab);
  StoredBins = endBin - FirstBin + 1;
  const auto floorDiv = [](int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
  WholeBins = { first == 0 ? 0 : floorDiv(first + 1 + Bin - 1, Bin), end == n[slab] ? lastBin : floorDiv(end - 4, Bin) };
  const std::size_t across = slab == 2 ? static_cast<std::size_t>(Bins[0]) * Bins[1] : Bins[0];
  const std::size_t bins = across * static_cast<std::size_t>(StoredBins);
  BinStart.assign(bins + 1, 0);
  std::vector<std::uint32_t> binOf(FaceList.size());
  for (std::size_t f = 0; f < FaceList.size(); ++f)
  {
    const Face& face = FaceList[f];
    std::size_t bin = 0;
    for (int a = Dimension - 1; a >= 0; --a)
    {
      const double centre = face.Voxel[a] + (a == face.Axis ? 0.5 : 0.0);
      bin = bin * Bins[a] + (BinOf(centre, a) - (a == slab ? FirstBin : 0));
    }
    binOf[f] = static_cast<std::uint32_t>(bin);
    ++BinStart[bin + 1];
  }
  for (std::size_t b = 0; b < bins; ++b)
    BinStart[b + 1] += BinStart[b];
  FaceOrder.resize(FaceList.size());
  std::vector<std::uint32_t> next(BinStart.begin(), BinStart.end() - 1);
  for (std::size_t f = 0; f < FaceList.size(); ++f)
    FaceOrder[next[binOf[f]]++] = static_cast<std::uint32_t>(f);
  // Within a bin by label pair: a query for one pair reads only its run.
  for (std::size_t b = 0; b < bins; ++b)
    std::sort(FaceOrder.begin() + BinStart[b], FaceOrder.begin() + BinStart[b + 1], [&](std::uint32_t x, std::uint32_t y) {
      const Face& p = FaceList[x];
      const Face& q = FaceList[y];
      return p.Low != q.Low ? p.Low < q.Low : (p.High != q.High ? p.High < q.High : x < y);
    });
}

int ImageBoundary::SlabMargin(double distance)
{
  // A query box reaches `distance` and half a voxel beyond the cells, then a
  // face's half voxel and a whole bin on either side; two more for rounding.
  return static_cast<int>(std::ceil(distance)) + 2 * Bin + 2;
}

int ImageBoundary::BinOf(double coordinate, int axis) const
{
  const int bin = static_cast<int>(std::floor((coordinate + 1.0) / Bin));
  return std::clamp(bin, 0, Bins[axis] - 1);
}

ConvexPiece ImageBoundary::Piece(std::size_t f) const
{
  const Face& face = FaceList[f];
  Point3 centre{ double(face.Voxel[0]), double(face.Voxel[1]), double(face.Voxel[2]) };
  centre[face.Axis] += 0.5;
  if (Dimension == 2)
  {
    Point3 a = centre, b = centre;
    a[1 - face.Axis] -= 0.5;
    b[1 - face.Axis] += 0.5;
    return ConvexPiece{ 2, { a, b } };
  }
  const int u = (face.Axis + 1) % 3, v = (face.Axis + 2) % 3;
  ConvexPiece square{ 4, {} };
  const double corner[4][2] = { { -0.5, -0.5 }, { 0.5, -0.5 }, { 0.5, 0.5 }, { -0.5, 0.5 } };
  for (int c = 0; c < 4; ++c)
  {
    Point3 p = centre;
    p[u] += corner[c][0];
    p[v] += corner[c][1];
    square.Points[c] = p;
  }
  return square;
}

void ImageBoundary::Pieces(const Point3& lo, const Point3& hi, std::int32_t low, std::int32_t high,
  std::vector<ConvexPiece>& out) const
{
  // A face reaches half a voxel from its centre.
  int from[3] = { 0, 0, 0 }, to[3] = { 0, 0, 0 };
  for (int a = 0; a < Dimension; ++a)
  {
    from[a] = BinOf(lo[a] - 0.5, a);
    to[a] = BinOf(hi[a] + 0.5, a);
  }
  // Every face lies within [-0.5, n - 0.5] along every axis: a box beyond that along any axis
  // meets none, whatever slices a slab holds (a process's parts may hold cells far beyond the
  // image, and no slab is cut for them).
  for (int a = 0; a < Dimension; ++a)
    if (hi[a] < -0.5 || lo[a] > Size[static_cast<std::size_t>(a)] - 0.5)
      return;
  const int slab = Dimension - 1;
  if (from[slab] < WholeBins[0] || to[slab] > WholeBins[1])
    throw std::logic_error("the image boundary was asked for faces beyond this process's slab of the image");
  from[slab] -= FirstBin;
  to[slab] -= FirstBin;
  for (int bz = from[2]; bz <= to[2]; ++bz)
    for (int by = from[1]; by <= to[1]; ++by)
      for (int bx = from[0]; bx <= to[0]; ++bx)
      {
        const std::size_t bin = (static_cast<std::size_t>(bz) * Bins[1] + by) * Bins[0] + bx;
        const auto first = FaceOrder.begin() + BinStart[bin], last = FaceOrder.begin() + BinStart[bin + 1];
        const auto run = std::lower_bound(first, last, 0u, [&](std::uint32_t f, std::uint32_t) {
          const Face& face = FaceList[f];
          return face.Low != low ? face.Low < low : face.High < high;
        });
        for (auto it = run; it != last; ++it)
        {
          const std::uint32_t f = *it;
          const Face& face = FaceList[f];
          if (face.Low != low || face.High != high)
            break;
          bool meets = true;
          for (int a = 0; a < Dimension && meets; ++a)
          {
            const double c = face.Voxel[a] + (a == face.Axis ? 0.5 : 0.0);
            const double reach = a == face.Axis ? 0.0 : 0.5;
            meets = c + reach >= lo[a] && c - reach <= hi[a];
          }
          if (meets)
            out.push_back(Piece(f));
        }
      }
}

} // namespace labelmesher
