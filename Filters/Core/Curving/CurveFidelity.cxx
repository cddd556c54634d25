// SPDX-License-Identifier: GPL-2.0-or-later
// Both distance bounds on the curved interfaces, certified on polylines, kept by shortening pieces.
#include "Curving/CurveFidelity.h"

#include "Criteria/DistanceBound.h"

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
  std::int64_t IdA = -1; ///< point ids of A and B (mesh vertices, then polyline points): segments meet there
  std::int64_t IdB = -1;
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

/// Segments binned on a uniform grid by their boxes grown by `reach`: a
/// query at p returns every segment within `reach` of p (and others).
class SegmentBins
{
public:
  SegmentBins(const std::vector<BoundarySegment>& segments, double reach, double cell)
    : Cell(cell)
  {
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      const auto& g = segments[s];
      const long x0 = Bin(std::min(g.A[0], g.B[0]) - reach), x1 = Bin(std::max(g.A[0], g.B[0]) + reach);
      const long y0 = Bin(std::min(g.A[1], g.B[1]) - reach), y1 = Bin(std::max(g.A[1], g.B[1]) + reach);
      for (long y = y0; y <= y1; ++y)
        for (long x = x0; x <= x1; ++x)
          Bins[Key(x, y)].push_back(s);
    }
  }
  const std::vector<std::size_t>& Near(const Point2& p) const
  {
    const auto it = Bins.find(Key(Bin(p[0]), Bin(p[1])));
    return it == Bins.end() ? Empty : it->second;
  }

private:
  long Bin(double x) const { return static_cast<long>(std::floor(x / Cell)); }
  static long long Key(long x, long y) { return (static_cast<long long>(x) << 32) ^ (y & 0xffffffffLL); }
  double Cell;
  std::unordered_map<long long, std::vector<std::size_t>> Bins;
  std::vector<std::size_t> Empty;
};

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
    , PixelBins(PixelEdges, 0.5, 4.0)
    , Edges(MeshBoundary(linear, pieces))
  {
  }

  /// Pieces whose curves break a bound at their current scales.
  std::set<std::size_t> Failing() const
  {
    std::vector<BoundarySegment> segments;
    std::set<std::size_t> failing;
    std::int64_t nextId = static_cast<std::int64_t>(Linear.Points.size());
    for (const MeshBoundaryEdge& e : Edges)
    {
      if (e.Piece < 0 || Pieces[static_cast<std::size_t>(e.Piece)].Scale <= 0.0)
      {
        segments.push_back({ IndexPoint(e.A), IndexPoint(e.B), e.First, e.Second, -1, e.A, e.B });
        continue;
      }
      const CurvePiece& piece = Pieces[static_cast<std::size_t>(e.Piece)];
      std::array<Point2, 4> p = piece.ControlPoints(Linear);
      for (Point2& q : p)
        q = Image.ToIndex(q);
      const std::vector<Point2> polyline = FlattenCubic(p, Bounds.Tolerance);
      const std::size_t first = segments.size();
      for (std::size_t k = 0; k + 1 < polyline.size(); ++k)
      {
        const std::int64_t a = k == 0 ? piece.From : nextId + static_cast<std::int64_t>(k) - 1;
        const std::int64_t b = k + 2 == polyline.size() ? piece.To : nextId + static_cast<std::int64_t>(k);
        segments.push_back({ polyline[k], polyline[k + 1], e.First, e.Second, e.Piece, a, b });
      }
      nextId += static_cast<std::int64_t>(polyline.size()) - 2;
      if (!MeshToImageHolds(segments, first, segments.size()))
        failing.insert(static_cast<std::size_t>(e.Piece));
    }
    ImageToMeshFailures(segments, failing);
    CrossingFailures(segments, failing);
    TangentOrderFailures(failing);
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
      for (double y = std::floor((lo[1] - reach) / 4.0) * 4.0; y <= hi[1] + reach + 4.0; y += 4.0)
        for (double x = std::floor((lo[0] - reach) / 4.0) * 4.0; x <= hi[0] + reach + 4.0; x += 4.0)
          for (std::size_t e : PixelBins.Near({ x, y }))
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
    const SegmentBins bins(segments, h + 0.5, 4.0);
    for (const BoundarySegment& edge : PixelEdges)
    {
      const Point2 mid{ 0.5 * (edge.A[0] + edge.B[0]), 0.5 * (edge.A[1] + edge.B[1]) };
      const auto& near = bins.Near(mid);
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

  /// Curved pieces whose polylines cross or touch another boundary segment
  /// away from a shared point. Kept apart from Checks/CurvedBoundary.h's count,
  /// which re-measures the output.
  static void CrossingFailures(const std::vector<BoundarySegment>& segments, std::set<std::size_t>& failing)
  {
    constexpr double kBin = 4.0;
    std::unordered_map<long long, std::vector<std::size_t>> bins;
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      const auto& g = segments[s];
      const long x0 = static_cast<long>(std::floor(std::min(g.A[0], g.B[0]) / kBin));
      const long x1 = static_cast<long>(std::floor(std::max(g.A[0], g.B[0]) / kBin));
      const long y0 = static_cast<long>(std::floor(std::min(g.A[1], g.B[1]) / kBin));
      const long y1 = static_cast<long>(std::floor(std::max(g.A[1], g.B[1]) / kBin));
      for (long y = y0; y <= y1; ++y)
        for (long x = x0; x <= x1; ++x)
          bins[(static_cast<long long>(x) << 32) ^ (y & 0xffffffffLL)].push_back(s);
    }
    for (const auto& [key, members] : bins)
      for (std::size_t i = 0; i < members.size(); ++i)
        for (std::size_t j = i + 1; j < members.size(); ++j)
        {
          const BoundarySegment& s = segments[members[i]];
          const BoundarySegment& t = segments[members[j]];
          if ((s.Piece < 0 && t.Piece < 0) || !Meet(s, t))
            continue;
          for (const BoundarySegment* g : { &s, &t })
            if (g->Piece >= 0)
              failing.insert(static_cast<std::size_t>(g->Piece));
        }
  }

  /// Around every vertex, the boundary curves must leave in the order their
  /// chords do: curves whose tangents swap order cross arbitrarily close to
  /// the vertex, below any polyline's resolution. Checked in index space on the
  /// end handles (the chord for a straight piece): the counter-clockwise turns
  /// from each handle to the next, in the chords' order, must be positive and
  /// add up to one full turn.
  void TangentOrderFailures(std::set<std::size_t>& failing) const
  {
    constexpr double kTwoPi = 6.283185307179586;
    std::map<std::int64_t, std::vector<std::array<double, 3>>> around; // vertex: chord angle, handle angle, piece
    for (const MeshBoundaryEdge& e : Edges)
    {
      std::array<Point2, 4> p;
      if (e.Piece >= 0)
      {
        const CurvePiece& piece = Pieces[static_cast<std::size_t>(e.Piece)];
        p = piece.ControlPoints(Linear);
        if (piece.From != e.A)
          std::swap(p[0], p[3]), std::swap(p[1], p[2]);
      }
      else
      {
        p = { Point2{ Linear.Points[e.A][0], Linear.Points[e.A][1] }, Point2{}, Point2{},
          Point2{ Linear.Points[e.B][0], Linear.Points[e.B][1] } };
        p[1] = p[3];
        p[2] = p[0];
      }
      for (Point2& q : p)
        q = Image.ToIndex(q);
      auto angle = [](const Point2& from, const Point2& to) { return std::atan2(to[1] - from[1], to[0] - from[0]); };
      const double piece = static_cast<double>(e.Piece);
      around[e.A].push_back({ angle(p[0], p[3]), angle(p[0], p[1]), piece });
      around[e.B].push_back({ angle(p[3], p[0]), angle(p[3], p[2]), piece });
    }
    for (auto& [vertex, edges] : around)
    {
      if (edges.size() < 3)
        continue;
      std::sort(edges.begin(), edges.end());
      double turn = 0.0;
      bool ordered = true;
      for (std::size_t k = 0; k < edges.size(); ++k)
      {
        double d = edges[(k + 1) % edges.size()][1] - edges[k][1];
        while (d <= 0.0)
          d += kTwoPi;
        while (d > kTwoPi)
          d -= kTwoPi;
        ordered = ordered && d > 0.0 && d < kTwoPi;
        turn += d;
      }
      if (ordered && std::abs(turn - kTwoPi) < 1e-6)
        continue;
      for (const auto& edge : edges)
        if (edge[2] >= 0.0)
          failing.insert(static_cast<std::size_t>(edge[2]));
    }
  }

  static double Orientation(const Point2& o, const Point2& a, const Point2& b)
  {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  }
  static bool Inside(const Point2& p, const Point2& a, const Point2& b)
  {
    return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= p[1] &&
      p[1] <= std::max(a[1], b[1]);
  }
  /// Two boundary segments meet other than at a point they share.
  static bool Meet(const BoundarySegment& s, const BoundarySegment& t)
  {
    const bool sharesA = s.IdA == t.IdA || s.IdA == t.IdB;
    const bool sharesB = s.IdB == t.IdA || s.IdB == t.IdB;
    if (sharesA && sharesB)
      return false; // the same edge
    if (sharesA || sharesB)
    {
      // Sharing an end they meet again only by overlapping: the far end of one on the other.
      const Point2& o = sharesA ? s.A : s.B;
      const Point2& p = sharesA ? s.B : s.A;
      const Point2& q = (t.IdA == (sharesA ? s.IdA : s.IdB)) ? t.B : t.A;
      return (Orientation(o, q, p) == 0.0 && Inside(p, o, q)) || (Orientation(o, p, q) == 0.0 && Inside(q, o, p));
    }
    const double d1 = Orientation(t.A, t.B, s.A), d2 = Orientation(t.A, t.B, s.B);
    const double d3 = Orientation(s.A, s.B, t.A), d4 = Orientation(s.A, s.B, t.B);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
      return true;
    return (d1 == 0 && Inside(s.A, t.A, t.B)) || (d2 == 0 && Inside(s.B, t.A, t.B)) ||
      (d3 == 0 && Inside(t.A, s.A, s.B)) || (d4 == 0 && Inside(t.B, s.A, s.B));
  }

  const SimplexMesh& Linear;
  const std::vector<CurvePiece>& Pieces;
  const ImageOnMesh& Image;
  const CurveBounds& Bounds;
  std::vector<BoundarySegment> PixelEdges;
  SegmentBins PixelBins;
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
