// SPDX-License-Identifier: GPL-2.0-or-later
// Pixel-edge midpoints given to the interface segments they belong to.
#include "Curving/BoundarySamples.h"

#include "Support/BoxBins.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace labelmesher
{
namespace
{

struct IndexSegment
{
  std::size_t Chain;
  std::size_t Segment;
  Point2 A;
  Point2 B;
  std::pair<std::int32_t, std::int32_t> Materials; ///< smaller label first
};

std::pair<std::int32_t, std::int32_t> Ordered(std::int32_t a, std::int32_t b)
{
  return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

/// Distance from p to segment ab and the parameter of its nearest point.
std::pair<double, double> ProjectOnSegment(const Point2& p, const Point2& a, const Point2& b)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return { std::hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]), t };
}

} // namespace

std::vector<std::vector<BoundarySample>> CollectBoundarySamples(const SimplexMesh& linear,
  const std::vector<InterfaceChain>& chains, const ImageOnMesh& image, double reach)
{
  std::vector<std::vector<BoundarySample>> samples(chains.size());
  if (!image.Image || image.Image->Dimension() != 2)
    return samples;
  const LabelImage& labels = *image.Image;

  std::vector<IndexSegment> segments;
  for (std::size_t c = 0; c < chains.size(); ++c)
  {
    const InterfaceChain& chain = chains[c];
    const std::size_t n = chain.Vertices.size();
    const std::size_t count = chain.Closed ? n : n - 1;
    for (std::size_t s = 0; s < count; ++s)
    {
      const Point3& a = linear.Points[chain.Vertices[s]];
      const Point3& b = linear.Points[chain.Vertices[(s + 1) % n]];
      segments.push_back({ c, s, image.ToIndex({ a[0], a[1] }), image.ToIndex({ b[0], b[1] }),
        Ordered(chain.FirstMaterial, chain.SecondMaterial) });
    }
  }
  // Segments by their boxes grown by `reach`: a midpoint's bin lists every segment within reach.
  BoxBins grid(std::max(2.0, reach));
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    const auto& g = segments[s];
    grid.Insert(s, { std::min(g.A[0], g.B[0]) - reach, std::min(g.A[1], g.B[1]) - reach },
      { std::max(g.A[0], g.B[0]) + reach, std::max(g.A[1], g.B[1]) + reach });
  }

  auto assign = [&](const Point2& midpoint, std::int32_t a, std::int32_t b) {
    const auto materials = Ordered(a, b);
    double best = std::numeric_limits<double>::infinity();
    std::size_t bestSegment = segments.size();
    double bestParameter = 0.0;
    for (std::size_t s : grid.At(midpoint))
    {
      if (segments[s].Materials != materials)
        continue;
      const auto [distance, t] = ProjectOnSegment(midpoint, segments[s].A, segments[s].B);
      if (distance < best)
      {
        best = distance;
        bestSegment = s;
        bestParameter = t;
      }
    }
    // A midpoint nearest to a segment's end belongs to no segment's inside (a corner).
    if (bestSegment == segments.size() || best > reach || bestParameter <= 0.0 || bestParameter >= 1.0)
      return;
    const IndexSegment& g = segments[bestSegment];
    samples[g.Chain].push_back({ g.Segment, image.ToMesh(midpoint), bestParameter });
  };

  const int nx = labels.Dimensions[0], ny = labels.Dimensions[1];
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const std::int32_t here = labels.At(i, j, 0);
      if (i + 1 < nx && labels.At(i + 1, j, 0) != here)
        assign({ i + 0.5, static_cast<double>(j) }, here, labels.At(i + 1, j, 0));
      if (j + 1 < ny && labels.At(i, j + 1, 0) != here)
        assign({ static_cast<double>(i), j + 0.5 }, here, labels.At(i, j + 1, 0));
    }
  }
  return samples;
}

} // namespace labelmesher
