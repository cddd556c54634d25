// SPDX-License-Identifier: GPL-2.0-or-later
// Both distance bounds on the curved interfaces, certified on polylines, kept by shortening pieces.
#include "Curving/CurveFidelity.h"

#include "Criteria/DistanceBound.h"
#include "Curving/CurveCrossings.h"
#include "Support/BoxBins.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>

namespace labelmesher
{
namespace
{

/// A piece of boundary in index space: a pixel edge, a straight mesh edge or
/// one segment of a curved piece's polyline (Piece >= 0).
struct BoundarySegment
{
  Point2 A;
  Point2 B;
  std::int32_t First;  ///< materials on its two sides (0: background or outside)
  std::int32_t Second;
  std::int64_t Piece = -1;
  bool Bounds(std::int32_t m) const { return m != 0 && (First == m || Second == m); }
};

ConvexPiece AsPiece(const BoundarySegment& s)
{
  ConvexPiece p;
  p.Count = 2;
  p.Points[0] = { s.A[0], s.A[1], 0.0 };
  p.Points[1] = { s.B[0], s.B[1], 0.0 };
  return p;
}

/// Segments binned by their boxes grown by `reach`: a point's bin lists every
/// segment within `reach` of it (and others).
BoxBins BinSegments(const std::vector<BoundarySegment>& segments, double reach, double cell)
{
  BoxBins bins(cell);
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    const auto& g = segments[s];
    bins.Insert(s, { std::min(g.A[0], g.B[0]) - reach, std::min(g.A[1], g.B[1]) - reach },
      { std::max(g.A[0], g.B[0]) + reach, std::max(g.A[1], g.B[1]) + reach });
  }
  return bins;
}

/// The pixel edges between different labels, outside the image counting as 0.
std::vector<BoundarySegment> ImageBoundary(const LabelImage& image)
{
  std::vector<BoundarySegment> edges;
  const int nx = image.Dimensions[0], ny = image.Dimensions[1];
  for (int j = -1; j < ny; ++j)
  {
    for (int i = -1; i < nx; ++i)
    {
      const std::int32_t here = image.At(i, j, 0);
      const std::int32_t right = image.At(i + 1, j, 0), up = image.At(i, j + 1, 0);
      if (j >= 0 && right != here)
        edges.push_back({ { i + 0.5, j - 0.5 }, { i + 0.5, j + 0.5 }, here, right });
      if (i >= 0 && up != here)
        edges.push_back({ { i - 0.5, j + 0.5 }, { i + 0.5, j + 0.5 }, here, up });
    }
  }
  return edges;
}

/// The linear mesh's boundary edges (between different materials or on one
/// cell), with the edge's piece index when it is a curved interface piece.
struct MeshBoundaryEdge
{
  std::int64_t A, B;
  std::int32_t First, Second;
  std::int64_t Piece;
};

std::vector<MeshBoundaryEdge> MeshBoundary(const SimplexMesh& linear, const std::vector<CurvePiece>& pieces)
{
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::int32_t>> sides;
  for (std::size_t c = 0; c < linear.NumberOfCells(); ++c)
  {
    const std::int64_t* v = linear.Cell(c);
    for (int k = 0; k < 3; ++k)
    {
      const std::int64_t a = v[k], b = v[(k + 1) % 3];
      sides[{ std::min(a, b), std::max(a, b) }].push_back(linear.Materials[c]);
    }
  }
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> pieceOf;
  for (std::size_t p = 0; p < pieces.size(); ++p)
    pieceOf[{ std::min(pieces[p].From, pieces[p].To), std::max(pieces[p].From, pieces[p].To) }] =
      static_cast<std::int64_t>(p);
  std::vector<MeshBoundaryEdge> edges;
  for (const auto& [key, materials] : sides)
  {
    const std::int32_t first = materials[0];
    const std::int32_t second = materials.size() > 1 ? materials[1] : 0;
    if (materials.size() > 1 && first == second)
      continue;
    const auto it = pieceOf.find(key);
    edges.push_back({ key.first, key.second, first, second, it == pieceOf.end() ? -1 : it->second });
  }
  return edges;
}

class FidelityTest
{
public:
  FidelityTest(const SimplexMesh& linear, const std::vector<CurvePiece>& pieces, const ImageOnMesh& image,
    const CurveBounds& bounds)
    : Linear(linear)
    , Pieces(pieces)
    , Image(image)
    , Bounds(bounds)
    , PixelEdges(ImageBoundary(*image.Image))
    , PixelBins(BinSegments(PixelEdges, 0.5, 4.0))
    , Edges(MeshBoundary(linear, pieces))
  {
  }

  /// Pieces whose curves break a bound at their current scales.
  std::set<std::size_t> Failing() const
  {
    std::vector<BoundarySegment> segments;
    std::set<std::size_t> failing;
    for (const MeshBoundaryEdge& e : Edges)
    {
      if (e.Piece < 0 || Pieces[static_cast<std::size_t>(e.Piece)].Scale <= 0.0)
      {
        segments.push_back({ IndexPoint(e.A), IndexPoint(e.B), e.First, e.Second, -1 });
        continue;
      }
      const CurvePiece& piece = Pieces[static_cast<std::size_t>(e.Piece)];
      std::array<Point2, 4> p = piece.ControlPoints(Linear);
      for (Point2& q : p)
        q = Image.ToIndex(q);
      const std::vector<Point2> polyline = FlattenCubic(p, Bounds.Tolerance);
      const std::size_t first = segments.size();
      for (std::size_t k = 0; k + 1 < polyline.size(); ++k)
        segments.push_back({ polyline[k], polyline[k + 1], e.First, e.Second, e.Piece });
      if (!MeshToImageHolds(segments, first, segments.size()))
        failing.insert(static_cast<std::size_t>(e.Piece));
    }
    ImageToMeshFailures(segments, failing);
    CrossingFailures(failing);
    return failing;
  }

private:
  Point2 IndexPoint(std::int64_t v) const { return Image.ToIndex({ Linear.Points[v][0], Linear.Points[v][1] }); }

  /// Every segment of one piece's polyline within h(M, I) − ε of the image
  /// boundary of each non-zero material on its sides.
  bool MeshToImageHolds(const std::vector<BoundarySegment>& segments, std::size_t first, std::size_t last) const
  {
    const double h = Bounds.MeshToImage - Bounds.Tolerance;
    if (h < 0.0)
      return false;
    for (std::int32_t m : { segments[first].First, segments[first].Second })
    {
      if (m == 0)
        continue;
      // Pixel edges within reach of the piece: their midpoints within h + 1/2 of its box.
      Point2 lo = segments[first].A, hi = lo;
      for (std::size_t s = first; s < last; ++s)
        for (const Point2& q : { segments[s].A, segments[s].B })
          for (int a = 0; a < 2; ++a)
          {
            lo[a] = std::min(lo[a], q[a]);
            hi[a] = std::max(hi[a], q[a]);
          }
      std::vector<ConvexPiece> targets;
      std::set<std::size_t> seen;
      const double reach = h + 0.5;
      // One query point in every bin the grown box overlaps.
      const double cell = PixelBins.CellSize();
      for (double y = std::floor((lo[1] - reach) / cell) * cell; y <= hi[1] + reach + cell; y += cell)
        for (double x = std::floor((lo[0] - reach) / cell) * cell; x <= hi[0] + reach + cell; x += cell)
          for (std::size_t e : PixelBins.At({ x, y }))
            if (PixelEdges[e].Bounds(m) && seen.insert(e).second)
              targets.push_back(AsPiece(PixelEdges[e]));
      for (std::size_t s = first; s < last; ++s)
        if (!WithinDistance(AsPiece(segments[s]), targets, h))
          return false;
    }
    return true;
  }

  /// Pixel edges of material m farther than h(I, M) from m's curved boundary:
  /// the curved pieces within their reach fail.
  void ImageToMeshFailures(const std::vector<BoundarySegment>& segments, std::set<std::size_t>& failing) const
  {
    const double h = Bounds.ImageToMesh;
    const BoxBins bins = BinSegments(segments, h + 0.5, 4.0);
    for (const BoundarySegment& edge : PixelEdges)
    {
      const Point2 mid{ 0.5 * (edge.A[0] + edge.B[0]), 0.5 * (edge.A[1] + edge.B[1]) };
      const auto& near = bins.At(mid);
      for (std::int32_t m : { edge.First, edge.Second })
      {
        if (m == 0)
          continue;
        std::vector<ConvexPiece> straight, all;
        std::set<std::int64_t> curved;
        for (std::size_t s : near)
        {
          if (!segments[s].Bounds(m))
            continue;
          all.push_back(AsPiece(segments[s]));
          if (segments[s].Piece < 0)
            straight.push_back(all.back());
          else
            curved.insert(segments[s].Piece);
        }
        if (curved.empty())
          continue; // the linear mesh's own boundary here: certified by the decimator
        const ConvexPiece element = AsPiece(edge);
        if (WithinDistance(element, straight, h) ||
          (h >= Bounds.Tolerance && WithinDistance(element, all, h - Bounds.Tolerance)))
          continue;
        for (std::int64_t p : curved)
          failing.insert(static_cast<std::size_t>(p));
      }
    }
  }

  /// Curved pieces that may meet another boundary curve away from a shared
  /// vertex (CurveCrossings.h). Kept apart from Checks/CurvedBoundary.h's
  /// count, which re-measures the output on polylines.
  void CrossingFailures(std::set<std::size_t>& failing) const
  {
    std::vector<BoundaryCurve> curves;
    std::vector<std::int64_t> pieceOf;
    for (const MeshBoundaryEdge& e : Edges)
    {
      BoundaryCurve curve;
      std::int64_t piece = -1;
      if (e.Piece >= 0 && Pieces[static_cast<std::size_t>(e.Piece)].Scale > 0.0)
      {
        piece = e.Piece;
        const CurvePiece& p = Pieces[static_cast<std::size_t>(piece)];
        curve.ControlPoints = p.ControlPoints(Linear);
        curve.From = p.From;
        curve.To = p.To;
      }
      else
      {
        const Point2 a{ Linear.Points[e.A][0], Linear.Points[e.A][1] };
        const Point2 b{ Linear.Points[e.B][0], Linear.Points[e.B][1] };
        curve.ControlPoints = { a, Point2{ (2 * a[0] + b[0]) / 3, (2 * a[1] + b[1]) / 3 },
          Point2{ (a[0] + 2 * b[0]) / 3, (a[1] + 2 * b[1]) / 3 }, b };
        curve.From = e.A;
        curve.To = e.B;
      }
      for (Point2& q : curve.ControlPoints)
        q = Image.ToIndex(q);
      curves.push_back(curve);
      pieceOf.push_back(piece);
    }
    for (std::size_t c : MeetingCurves(curves, Bounds.Tolerance))
      if (pieceOf[c] >= 0)
        failing.insert(static_cast<std::size_t>(pieceOf[c]));
  }

  const SimplexMesh& Linear;
  const std::vector<CurvePiece>& Pieces;
  const ImageOnMesh& Image;
  const CurveBounds& Bounds;
  std::vector<BoundarySegment> PixelEdges;
  BoxBins PixelBins;
  std::vector<MeshBoundaryEdge> Edges;
};

} // namespace

FidelityOutcome KeepDistanceBounds(const SimplexMesh& linear, std::vector<CurvePiece>& pieces,
  const ImageOnMesh& image, const CurveBounds& bounds)
{
  FidelityOutcome outcome;
  if (!image.Image || pieces.empty())
    return outcome;
  const FidelityTest test(linear, pieces, image, bounds);
  std::set<std::size_t> shortened;
  for (;;)
  {
    ++outcome.Rounds;
    const std::set<std::size_t> failing = test.Failing();
    bool changed = false;
    outcome.Uncertified = 0;
    for (std::size_t p : failing)
    {
      if (ShortenPiece(pieces[p]))
      {
        shortened.insert(p);
        changed = true;
      }
      else
      {
        ++outcome.Uncertified;
      }
    }
    if (!changed)
      break;
  }
  outcome.ShortenedPieces = shortened.size();
  return outcome;
}

} // namespace labelmesher
