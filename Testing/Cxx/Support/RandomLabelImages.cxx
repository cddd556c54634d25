// SPDX-License-Identifier: GPL-2.0-or-later
// Seeded, reproducible random multi-label images for the property tests.
#include "RandomLabelImages.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

namespace labelmesher
{
namespace testing
{

std::int64_t SeededRandom::Int(std::int64_t lo, std::int64_t hi)
{
  if (hi < lo)
    std::swap(lo, hi);
  const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1u; // 0 means 2^64
  if (span == 0)
    return static_cast<std::int64_t>(Next());
  // Reject the top partial bucket so every value is equally likely.
  const std::uint64_t limit = (~std::uint64_t(0)) - ((~std::uint64_t(0)) % span + 1u) % span;
  std::uint64_t x = Next();
  while (x > limit)
    x = Next();
  return lo + static_cast<std::int64_t>(x % span);
}

const char* ToString(RandomFeature feature)
{
  switch (feature)
  {
    case RandomFeature::Blob:
      return "blob";
    case RandomFeature::TouchingMaterials:
      return "touching";
    case RandomFeature::Sheet:
      return "sheet";
    case RandomFeature::Line:
      return "line";
    case RandomFeature::Cavity:
      return "cavity";
    case RandomFeature::Tunnel:
      return "tunnel";
    case RandomFeature::BorderContact:
      return "border";
    case RandomFeature::Speckle:
      return "speckle";
    case RandomFeature::Box:
      return "box";
  }
  return "?";
}

namespace
{

constexpr double kPi = 3.14159265358979323846;
using Vec = std::array<double, 3>;
using Mat = std::array<std::array<double, 3>, 3>;

std::string Fmt(double v)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}
std::string Fmt(const Vec& v, int dimension)
{
  std::string s = "(" + Fmt(v[0]) + "," + Fmt(v[1]);
  if (dimension == 3)
    s += "," + Fmt(v[2]);
  return s + ")";
}

/// Everything the painters need: the image, its dimension and the generator.
class Canvas
{
public:
  Canvas(LabelImage& image, SeededRandom& random)
    : Image(image)
    , Random(random)
    , Dim(image.Dimension())
  {
  }

  LabelImage& Image;
  SeededRandom& Random;
  int Dim;

  int N(int axis) const { return Image.Dimensions[axis]; }
  /// Smallest side over the axes in use.
  int MinSide() const
  {
    int m = std::min(N(0), N(1));
    if (Dim == 3)
      m = std::min(m, N(2));
    return m;
  }

  /// Paints `label` on every voxel whose centre satisfies `inside`; returns the count.
  template <class Inside>
  std::size_t Paint(std::int32_t label, Inside inside)
  {
    std::size_t count = 0;
    for (int k = 0; k < N(2); ++k)
      for (int j = 0; j < N(1); ++j)
        for (int i = 0; i < N(0); ++i)
          if (inside(Vec{ double(i), double(j), double(k) }))
          {
            Image(i, j, k) = label;
            ++count;
          }
    return count;
  }

  /// Random point with every used coordinate in [lo_a, N(a) - 1 - lo_a] (clamped to the centre).
  Vec RandomPointInside(const Vec& margin)
  {
    Vec p{ 0, 0, 0 };
    for (int a = 0; a < Dim; ++a)
    {
      double lo = margin[a], hi = N(a) - 1 - margin[a];
      if (hi < lo)
        lo = hi = 0.5 * (N(a) - 1);
      p[a] = Random.Real(lo, hi);
    }
    return p;
  }
  /// Random voxel centre at least `margin` voxels from the border where the image allows.
  Vec RandomVoxelCentre(int margin = 0)
  {
    Vec p{ 0, 0, 0 };
    for (int a = 0; a < Dim; ++a)
    {
      const int m = std::min(margin, (N(a) - 1) / 2);
      p[a] = double(Random.Int(m, N(a) - 1 - m));
    }
    return p;
  }
  /// Most primitives keep off the border (BorderContact is what puts labels there).
  bool KeepInside() { return Random.Chance(0.75); }

  /// Random rotation (rows: local axes in image coordinates). 2D: about z only.
  Mat RandomRotation()
  {
    if (Dim == 2)
    {
      const double t = Random.Real(0.0, 2.0 * kPi);
      const double c = std::cos(t), s = std::sin(t);
      return Mat{ { { c, s, 0 }, { -s, c, 0 }, { 0, 0, 1 } } };
    }
    // Shoemake's uniform random unit quaternion.
    const double u1 = Random.Unit(), u2 = Random.Real(0.0, 2.0 * kPi), u3 = Random.Real(0.0, 2.0 * kPi);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    const double w = a * std::sin(u2), x = a * std::cos(u2), y = b * std::sin(u3), z = b * std::cos(u3);
    return Mat{ { { 1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w) },
      { 2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w) },
      { 2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y) } } };
  }
  Vec RandomDirection()
  {
    const Mat r = RandomRotation();
    return r[0];
  }
};

Vec Local(const Mat& r, const Vec& c, const Vec& p)
{
  const Vec d{ p[0] - c[0], p[1] - c[1], p[2] - c[2] };
  return Vec{ r[0][0] * d[0] + r[0][1] * d[1] + r[0][2] * d[2],
    r[1][0] * d[0] + r[1][1] * d[1] + r[1][2] * d[2],
    r[2][0] * d[0] + r[2][1] * d[1] + r[2][2] * d[2] };
}

double Dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Inside test of a (rotated) ellipsoid / ellipse.
struct Ellipsoid
{
  Vec Centre;
  Vec Radii;
  Mat Rotation;
  int Dim;
  bool operator()(const Vec& p) const
  {
    const Vec q = Local(Rotation, Centre, p);
    double s = 0;
    for (int a = 0; a < Dim; ++a)
      s += (q[a] / Radii[a]) * (q[a] / Radii[a]);
    return s <= 1.0;
  }
  std::string Text() const
  {
    return "centre=" + Fmt(Centre, Dim) + " radii=" + Fmt(Radii, Dim);
  }
};

Ellipsoid RandomEllipsoid(Canvas& canvas, double minRadius, double maxRadius, bool fitInside)
{
  Ellipsoid e;
  e.Dim = canvas.Dim;
  e.Radii = { 1, 1, 1 };
  for (int a = 0; a < canvas.Dim; ++a)
    e.Radii[a] = canvas.Random.Real(minRadius, std::max(minRadius, maxRadius));
  e.Rotation = canvas.RandomRotation();
  const double rmax = std::max({ e.Radii[0], e.Radii[1], canvas.Dim == 3 ? e.Radii[2] : 0.0 });
  const double m = rmax + 1.0; // keeps the border voxels free
  e.Centre = canvas.RandomPointInside(fitInside ? Vec{ m, m, m } : Vec{ 0, 0, 0 });
  return e;
}

std::int32_t PickLabel(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  return labels[static_cast<std::size_t>(canvas.Random.Int(0, std::int64_t(labels.size()) - 1))];
}
/// A label different from `not`, or background (0) with probability pZero.
std::int32_t PickOther(Canvas& canvas, const std::vector<std::int32_t>& labels, std::int32_t not_, double pZero)
{
  if (canvas.Random.Chance(pZero))
    return 0;
  std::vector<std::int32_t> others;
  for (auto l : labels)
    if (l != not_)
      others.push_back(l);
  if (others.empty())
    return 0;
  return others[static_cast<std::size_t>(canvas.Random.Int(0, std::int64_t(others.size()) - 1))];
}

const char* AxisName(int a) { return a == 0 ? "x" : (a == 1 ? "y" : "z"); }

std::string PaintBlob(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  const std::int32_t label = PickLabel(canvas, labels);
  const int parts = int(canvas.Random.Int(1, 3));
  std::string text = "blob label=" + std::to_string(label) + " of " + std::to_string(parts) + ":";
  const double maxR = std::max(1.5, 0.35 * canvas.MinSide());
  for (int p = 0; p < parts; ++p)
  {
    const Ellipsoid e = RandomEllipsoid(canvas, 1.0, maxR, canvas.KeepInside());
    canvas.Paint(label, e);
    text += " [" + e.Text() + "]";
  }
  return text;
}

std::string PaintTouching(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  const std::int32_t a = PickLabel(canvas, labels);
  const std::int32_t b = PickOther(canvas, labels, a, 0.0);
  const Ellipsoid e =
    RandomEllipsoid(canvas, 2.0, std::max(2.5, 0.4 * canvas.MinSide()), canvas.KeepInside());
  const Vec n = canvas.RandomDirection();
  const double rmin = std::min(e.Radii[0], e.Radii[1]);
  const double offset = canvas.Random.Real(-0.3 * rmin, 0.3 * rmin);
  canvas.Paint(a, [&](const Vec& p) {
    if (!e(p))
      return false;
    const Vec d{ p[0] - e.Centre[0], p[1] - e.Centre[1], p[2] - e.Centre[2] };
    return Dot(d, n) >= offset;
  });
  canvas.Paint(b, [&](const Vec& p) {
    if (!e(p))
      return false;
    const Vec d{ p[0] - e.Centre[0], p[1] - e.Centre[1], p[2] - e.Centre[2] };
    return Dot(d, n) < offset;
  });
  return "touching labels=" + std::to_string(a) + "|" + std::to_string(b) + " " + e.Text() +
    " plane normal=" + Fmt(n, canvas.Dim) + " offset=" + Fmt(offset);
}

/// Random integer interval [lo, hi] inside [margin, n-1-margin] (margin dropped
/// when the image is too small) with hi - lo + 1 >= min(minLength, available).
std::pair<int, int> RandomInterval(Canvas& canvas, int n, int minLength, int margin = 0)
{
  if (n - 2 * margin < std::max(1, minLength))
    margin = 0;
  const int available = n - 2 * margin;
  minLength = std::max(1, std::min(minLength, available));
  const int length = int(canvas.Random.Int(minLength, available));
  const int lo = margin + int(canvas.Random.Int(0, available - length));
  return { lo, lo + length - 1 };
}

/// One-voxel-thick plate (3D) or one-pixel-thick band (2D).
std::string PaintSheet(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  const std::int32_t label = PickLabel(canvas, labels);
  const int d = canvas.Dim;
  const int margin = canvas.KeepInside() ? 1 : 0;
  if (canvas.Random.Chance(0.7))
  {
    // Axis-aligned: coordinate `axis` fixed, an interval along the other axes.
    const int axis = int(canvas.Random.Int(0, d - 1));
    const int at = RandomInterval(canvas, canvas.N(axis), 1, margin).first;
    std::array<std::pair<int, int>, 3> range{ { { 0, 0 }, { 0, 0 }, { 0, 0 } } };
    std::string extent;
    for (int a = 0; a < d; ++a)
    {
      if (a == axis)
        range[a] = { at, at };
      else
      {
        range[a] = RandomInterval(canvas, canvas.N(a), 3, margin);
        extent += std::string(" ") + AxisName(a) + "=[" + std::to_string(range[a].first) + "," +
          std::to_string(range[a].second) + "]";
      }
    }
    canvas.Paint(label, [&](const Vec& p) {
      for (int a = 0; a < d; ++a)
        if (p[a] < range[a].first || p[a] > range[a].second)
          return false;
      return true;
    });
    return "sheet label=" + std::to_string(label) + " axis=" + AxisName(axis) + " at " +
      std::to_string(at) + extent;
  }
  // Oblique naive digital plane (line in 2D): |n.(p - c)| < ||n||_inf / 2, which is
  // exactly one voxel thick along the dominant axis of n; limited to a ball.
  const Vec n = canvas.RandomDirection();
  const Vec c = canvas.RandomPointInside({ 0, 0, 0 });
  const double radius = canvas.Random.Real(2.0, std::max(2.5, 0.6 * canvas.MinSide()));
  const double half = 0.5 * std::max({ std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]) });
  canvas.Paint(label, [&](const Vec& p) {
    const Vec q{ p[0] - c[0], p[1] - c[1], p[2] - c[2] };
    const double s = Dot(q, n);
    if (margin > 0)
      for (int a = 0; a < d; ++a)
        if (p[a] < margin || p[a] > canvas.N(a) - 1 - margin)
          return false;
    return s >= -half && s < half && Dot(q, q) <= radius * radius;
  });
  return "sheet label=" + std::to_string(label) + " oblique normal=" + Fmt(n, d) + " through " +
    Fmt(c, d) + " radius=" + Fmt(radius);
}

/// One-voxel-thick line: along an axis, or a digital segment between two voxels.
std::string PaintLine(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  const std::int32_t label = PickLabel(canvas, labels);
  const int d = canvas.Dim;
  const int margin = canvas.KeepInside() ? 1 : 0;
  if (canvas.Random.Chance(0.6))
  {
    const int axis = int(canvas.Random.Int(0, d - 1));
    Vec at = canvas.RandomVoxelCentre(margin);
    const auto range = RandomInterval(canvas, canvas.N(axis), 2, margin);
    canvas.Paint(label, [&](const Vec& p) {
      for (int a = 0; a < 3; ++a)
        if (a == axis ? (p[a] < range.first || p[a] > range.second) : p[a] != at[a])
          return false;
      return true;
    });
    at[axis] = range.first;
    return "line label=" + std::to_string(label) + " axis=" + AxisName(axis) + " from " + Fmt(at, d) +
      " length " + std::to_string(range.second - range.first + 1);
  }
  const Vec p0 = canvas.RandomVoxelCentre(margin), p1 = canvas.RandomVoxelCentre(margin);
  double steps = 0;
  for (int a = 0; a < 3; ++a)
    steps = std::max(steps, std::fabs(p1[a] - p0[a]));
  const int n = int(steps);
  for (int s = 0; s <= n; ++s)
  {
    const double t = n > 0 ? double(s) / n : 0.0;
    int idx[3];
    for (int a = 0; a < 3; ++a)
      idx[a] = int(std::floor(p0[a] + t * (p1[a] - p0[a]) + 0.5));
    canvas.Image(idx[0], idx[1], idx[2]) = label;
  }
  return "line label=" + std::to_string(label) + " digital from " + Fmt(p0, d) + " to " + Fmt(p1, d);
}

/// A blob with an enclosed hole (empty or filled with another label).
std::string PaintCavity(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  const std::int32_t outer = PickLabel(canvas, labels);
  const std::int32_t inner = PickOther(canvas, labels, outer, 0.6);
  const double maxR = std::max(3.0, 0.45 * canvas.MinSide());
  Ellipsoid e = RandomEllipsoid(canvas, 3.0, maxR, true);
  double rmin = std::min(e.Radii[0], e.Radii[1]);
  if (canvas.Dim == 3)
    rmin = std::min(rmin, e.Radii[2]);
  const double ri = canvas.Random.Real(0.8, std::max(0.9, rmin - 1.6));
  canvas.Paint(outer, e);
  const Vec c = e.Centre;
  canvas.Paint(inner, [&](const Vec& p) {
    const Vec q{ p[0] - c[0], p[1] - c[1], p[2] - c[2] };
    return Dot(q, q) <= ri * ri;
  });
  return "cavity label=" + std::to_string(outer) + " " + e.Text() + " hole radius=" + Fmt(ri) +
    " filled with " + std::to_string(inner);
}

/// A solid torus or a drilled blob (3D); a ring (2D).
std::string PaintTunnel(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  const std::int32_t label = PickLabel(canvas, labels);
  const int d = canvas.Dim;
  const double m = canvas.MinSide();
  if (d == 2 || canvas.Random.Chance(0.5))
  {
    // Torus (ring in 2D): distance to a circle of radius R in the local xy-plane <= r.
    const double R = canvas.Random.Real(2.5, std::max(2.6, 0.35 * m));
    const double r = canvas.Random.Real(0.8, std::max(0.9, std::min(R - 1.2, 0.2 * m)));
    const Mat rot = canvas.RandomRotation();
    const double reach = R + r + 1.0; // fit the whole ring when possible
    const Vec c = canvas.RandomPointInside({ reach, reach, reach });
    canvas.Paint(label, [&](const Vec& p) {
      const Vec q = Local(rot, c, p);
      const double rho = std::sqrt(q[0] * q[0] + q[1] * q[1]) - R;
      const double z = d == 3 ? q[2] : 0.0;
      return rho * rho + z * z <= r * r;
    });
    return std::string(d == 2 ? "ring" : "torus") + " label=" + std::to_string(label) + " centre=" +
      Fmt(c, d) + " R=" + Fmt(R) + " r=" + Fmt(r);
  }
  // Drilled blob: an ellipsoid with a cylinder through it along a random direction.
  const std::int32_t fill = PickOther(canvas, labels, label, 0.6);
  const Ellipsoid e = RandomEllipsoid(canvas, 3.0, std::max(3.0, 0.45 * m), true);
  const double rmin = std::min({ e.Radii[0], e.Radii[1], e.Radii[2] });
  const double rc = canvas.Random.Real(0.7, std::max(0.8, rmin - 1.5));
  const Vec axis = canvas.RandomDirection();
  canvas.Paint(label, e);
  canvas.Paint(fill, [&](const Vec& p) {
    if (!e(p))
      return false;
    const Vec q{ p[0] - e.Centre[0], p[1] - e.Centre[1], p[2] - e.Centre[2] };
    const double t = Dot(q, axis);
    return Dot(q, q) - t * t <= rc * rc;
  });
  return "drilled label=" + std::to_string(label) + " " + e.Text() + " hole radius=" + Fmt(rc) +
    " along " + Fmt(axis, 3) + " filled with " + std::to_string(fill);
}

/// A ball cut by the image border, or a slab on one image face.
std::string PaintBorder(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  const std::int32_t label = PickLabel(canvas, labels);
  const int d = canvas.Dim;
  const int axis = int(canvas.Random.Int(0, d - 1));
  const bool high = canvas.Random.Chance(0.5);
  if (canvas.Random.Chance(0.65))
  {
    const double r = canvas.Random.Real(1.5, std::max(2.0, 0.4 * canvas.MinSide()));
    Vec c = canvas.RandomVoxelCentre();
    const double out = canvas.Random.Real(0.0, 0.5 * r);
    c[axis] = high ? canvas.N(axis) - 1 + out : -out;
    canvas.Paint(label, [&](const Vec& p) {
      const Vec q{ p[0] - c[0], p[1] - c[1], p[2] - c[2] };
      return Dot(q, q) <= r * r;
    });
    return "border ball label=" + std::to_string(label) + " centre=" + Fmt(c, d) + " radius=" + Fmt(r);
  }
  const int depth = int(canvas.Random.Int(1, 3));
  std::array<std::pair<int, int>, 3> range{ { { 0, 0 }, { 0, 0 }, { 0, 0 } } };
  for (int a = 0; a < d; ++a)
    range[a] = a == axis ? (high ? std::make_pair(canvas.N(a) - depth, canvas.N(a) - 1)
                                 : std::make_pair(0, depth - 1))
                         : RandomInterval(canvas, canvas.N(a), 2);
  canvas.Paint(label, [&](const Vec& p) {
    for (int a = 0; a < d; ++a)
      if (p[a] < range[a].first || p[a] > range[a].second)
        return false;
    return true;
  });
  return "border slab label=" + std::to_string(label) + " on " + (high ? "+" : "-") + AxisName(axis) +
    " depth " + std::to_string(depth);
}

std::string PaintSpeckle(Canvas& canvas, const std::vector<std::int32_t>& labels)
{
  const std::int64_t maxCount =
    std::max<std::int64_t>(1, std::min<std::int64_t>(20, canvas.Image.NumberOfVoxels() / 200));
  const int count = int(canvas.Random.Int(1, maxCount));
  std::string text = "speckle x" + std::to_string(count) + ":";
  for (int s = 0; s < count; ++s)
  {
    const Vec p = canvas.RandomVoxelCentre(canvas.Random.Chance(0.8) ? 1 : 0);
    const std::int32_t label = canvas.Random.Chance(0.2) ? 0 : PickLabel(canvas, labels);
    canvas.Image(int(p[0]), int(p[1]), int(p[2])) = label;
    if (s < 6)
      text += " " + std::to_string(label) + "@" + Fmt(p, canvas.Dim);
  }
  if (count > 6)
    text += " ...";
  return text;
}

int DrawSide(SeededRandom& random, int lo, int hi)
{
  if (hi < lo)
    std::swap(lo, hi);
  // Most images small: 75% in the lowest quarter, 20% in the lower half, 5% anywhere.
  const double u = random.Unit();
  int top = hi;
  if (u < 0.75)
    top = lo + (hi - lo) / 4;
  else if (u < 0.95)
    top = lo + (hi - lo) / 2;
  return int(random.Int(lo, std::max(lo, top)));
}

} // namespace

RandomLabelImage GenerateRandomLabelImageWithDescription(
  std::uint64_t seed, int dimension, const RandomImageOptions& options)
{
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("GenerateRandomLabelImage: dimension must be 2 or 3");
  if (options.MinLabels < 1 || options.MaxLabels < options.MinLabels)
    throw std::invalid_argument("GenerateRandomLabelImage: bad label count range");
  if (options.MaxLabelId < options.MaxLabels)
    throw std::invalid_argument("GenerateRandomLabelImage: MaxLabelId smaller than MaxLabels");

  RandomLabelImage result;
  result.Seed = seed;
  // Mix the dimension into the stream so 2D and 3D images of one seed are unrelated.
  SeededRandom random(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(dimension));

  // Size: an unusual side per axis keeps anisotropic shapes in the mix.
  std::array<int, 3> dims{ 1, 1, 1 };
  const int lo = dimension == 3 ? options.MinSize3D : options.MinSize2D;
  const int hi = dimension == 3 ? options.MaxSize3D : options.MaxSize2D;
  const int base = DrawSide(random, lo, hi);
  for (int a = 0; a < dimension; ++a)
    dims[a] = std::max(lo, std::min(hi, base + int(random.Int(-base / 4, base / 4))));
  result.Image = LabelImage(dims[0], dims[1], dims[2]);

  // Labels.
  const int count = int(random.Int(options.MinLabels, options.MaxLabels));
  std::vector<std::int32_t> labels;
  if (random.Chance(options.SparseLabelProbability))
  {
    while (int(labels.size()) < count)
    {
      const auto id = static_cast<std::int32_t>(random.Int(1, options.MaxLabelId));
      if (std::find(labels.begin(), labels.end(), id) == labels.end())
        labels.push_back(id);
    }
  }
  else
    for (int l = 1; l <= count; ++l)
      labels.push_back(l);

  // Features: a random subset, each maybe twice; at least one blob-like one.
  std::vector<RandomFeature> plan;
  for (RandomFeature f : options.Features)
    if (random.Chance(options.FeatureProbability))
    {
      plan.push_back(f);
      if (random.Chance(0.25))
        plan.push_back(f);
    }
  const bool hasBody = std::any_of(plan.begin(), plan.end(), [](RandomFeature f) {
    return f == RandomFeature::Blob || f == RandomFeature::TouchingMaterials;
  });
  if (!hasBody)
    plan.push_back(random.Chance(0.5) ? RandomFeature::Blob : RandomFeature::TouchingMaterials);
  // Fisher-Yates with our own integers; speckle always last so it stays isolated.
  for (std::size_t i = plan.size(); i > 1; --i)
    std::swap(plan[i - 1], plan[static_cast<std::size_t>(random.Int(0, std::int64_t(i) - 1))]);
  std::stable_partition(plan.begin(), plan.end(), [](RandomFeature f) { return f != RandomFeature::Speckle; });

  Canvas canvas(result.Image, random);
  for (RandomFeature f : plan)
  {
    std::string text;
    switch (f)
    {
      case RandomFeature::Blob:
        text = PaintBlob(canvas, labels);
        break;
      case RandomFeature::TouchingMaterials:
        text = PaintTouching(canvas, labels);
        break;
      case RandomFeature::Sheet:
        text = PaintSheet(canvas, labels);
        break;
      case RandomFeature::Line:
        text = PaintLine(canvas, labels);
        break;
      case RandomFeature::Cavity:
        text = PaintCavity(canvas, labels);
        break;
      case RandomFeature::Tunnel:
        text = PaintTunnel(canvas, labels);
        break;
      case RandomFeature::BorderContact:
        text = PaintBorder(canvas, labels);
        break;
      case RandomFeature::Speckle:
        text = PaintSpeckle(canvas, labels);
        break;
      case RandomFeature::Box:
        throw std::invalid_argument("GenerateRandomLabelImage: boxes come from GenerateRandomBoxImage");
    }
    result.Features.push_back({ f, text });
  }

  // Every drawn label must be present: give missing ones a small blob, and if
  // that keeps failing, a single voxel taken from a label that has more than
  // one voxel (so no other label vanishes).
  for (int round = 0; round < 1000; ++round)
  {
    std::map<std::int32_t, std::size_t> counts;
    for (auto l : result.Image.LabelsAsInt32())
      ++counts[l];
    std::int32_t missing = -1;
    for (auto l : labels)
      if (counts.find(l) == counts.end())
      {
        missing = l;
        break;
      }
    if (missing < 0)
      break;
    if (round < 2 * count)
    {
      // First a small blob of the missing label, kept inside the image.
      const Ellipsoid e = RandomEllipsoid(canvas, 1.0, std::max(1.0, std::min(2.5, 0.2 * canvas.MinSide())), true);
      canvas.Paint(missing, e);
      result.Features.push_back(
        { RandomFeature::Blob, "blob label=" + std::to_string(missing) + " (fill-in) " + e.Text() });
      continue;
    }
    const Vec p = canvas.RandomVoxelCentre(1);
    auto voxel = result.Image(int(p[0]), int(p[1]), int(p[2]));
    if (counts[voxel] <= 1)
      continue;
    voxel = missing;
    result.Features.push_back({ RandomFeature::Speckle,
      "fill-in voxel label=" + std::to_string(missing) + " at " + Fmt(p, dimension) });
  }
  result.LabelIds = PresentLabels(result.Image);
  return result;
}

LabelImage GenerateRandomLabelImage(std::uint64_t seed, int dimension, const RandomImageOptions& options)
{
  return GenerateRandomLabelImageWithDescription(seed, dimension, options).Image;
}

std::string DescribeRandomLabelImage(std::uint64_t seed, int dimension, const RandomImageOptions& options)
{
  return GenerateRandomLabelImageWithDescription(seed, dimension, options).Describe();
}

bool RandomLabelImage::Has(RandomFeature feature) const
{
  return std::any_of(
    Features.begin(), Features.end(), [&](const RandomFeatureRecord& r) { return r.Kind == feature; });
}

RandomLabelImage GenerateRandomBoxImage(std::uint64_t seed, int dimension, int size)
{
  if ((dimension != 2 && dimension != 3) || size < 2)
    throw std::invalid_argument("GenerateRandomBoxImage: dimension must be 2 or 3, size at least 2");
  RandomLabelImage result;
  result.Seed = seed;
  SeededRandom random(seed * 0xD1B54A32D192ED03ull + static_cast<std::uint64_t>(dimension));
  result.Image = LabelImage(size, size, dimension == 3 ? size : 1);
  const int boxes = int(random.Int(3, 10));
  for (int b = 0;; ++b)
  {
    const std::vector<std::int32_t> labels = result.Image.LabelsAsInt32();
    const bool foreground = std::any_of(labels.begin(), labels.end(), [](std::int32_t l) { return l != 0; });
    if (b >= boxes && foreground)
      break; // else one more box, until something is left in the foreground
    int lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
    for (int a = 0; a < dimension; ++a)
    {
      lo[a] = int(random.Int(0, size - 1));
      hi[a] = random.Chance(0.4) ? lo[a] : std::min(size - 1, lo[a] + int(random.Int(1, size / 2)));
    }
    const std::int32_t label = b < boxes && random.Chance(0.25) ? 0 : (random.Chance(0.5) ? 1 : 4);
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
          result.Image(i, j, k) = label;
    std::ostringstream text;
    text << "box label=" << label << " [" << lo[0] << "," << hi[0] << "]x[" << lo[1] << "," << hi[1] << "]";
    if (dimension == 3)
      text << "x[" << lo[2] << "," << hi[2] << "]";
    result.Features.push_back({ RandomFeature::Box, text.str() });
  }
  result.LabelIds = PresentLabels(result.Image);
  return result;
}

std::string RandomLabelImage::Describe() const
{
  std::ostringstream out;
  const auto& d = Image.Dimensions;
  out << "random label image seed=" << Seed << " dim=" << Image.Dimension() << " size=" << d[0] << "x"
      << d[1];
  if (Image.Dimension() == 3)
    out << "x" << d[2];
  std::map<std::int32_t, std::size_t> counts;
  for (auto l : Image.LabelsAsInt32())
    ++counts[l];
  out << " labels(voxels):";
  for (const auto& [label, n] : counts)
    out << " " << label << "(" << n << ")";
  out << " checksum=" << std::hex << LabelImageChecksum(Image) << std::dec << "\n";
  out << "  one-voxel-thick: " << (HasOneVoxelThickStructure(Image) ? "yes" : "no")
      << ", foreground on border: " << (HasForegroundOnBorder(Image) ? "yes" : "no") << "\n";
  for (const auto& f : Features)
    out << "  - " << f.Text << "\n";
  return out.str();
}

std::uint64_t LabelImageChecksum(const LabelImage& image)
{
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](std::uint32_t v) {
    for (int b = 0; b < 4; ++b)
    {
      h ^= (v >> (8 * b)) & 0xffu;
      h *= 1099511628211ull;
    }
  };
  for (int a = 0; a < 3; ++a)
    mix(static_cast<std::uint32_t>(image.Dimensions[a]));
  for (auto l : image.LabelsAsInt32())
    mix(static_cast<std::uint32_t>(l));
  return h;
}

bool HasOneVoxelThickStructure(const LabelImage& image)
{
  const auto& d = image.Dimensions;
  const int dim = image.Dimension();
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        const std::int32_t l = image.At(i, j, k);
        if (l == 0)
          continue;
        if (image.At(i - 1, j, k) != l && image.At(i + 1, j, k) != l)
          return true;
        if (image.At(i, j - 1, k) != l && image.At(i, j + 1, k) != l)
          return true;
        if (dim == 3 && image.At(i, j, k - 1) != l && image.At(i, j, k + 1) != l)
          return true;
      }
  return false;
}

bool HasForegroundOnBorder(const LabelImage& image)
{
  const auto& d = image.Dimensions;
  const int dim = image.Dimension();
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        const bool border = i == 0 || j == 0 || i == d[0] - 1 || j == d[1] - 1 ||
          (dim == 3 && (k == 0 || k == d[2] - 1));
        if (border && image.At(i, j, k) != 0)
          return true;
      }
  return false;
}

std::vector<std::int32_t> PresentLabels(const LabelImage& image)
{
  std::vector<bool> small(1024, false);
  std::vector<std::int32_t> large;
  for (auto l : image.LabelsAsInt32())
  {
    if (l == 0)
      continue;
    if (l > 0 && l < 1024)
      small[static_cast<std::size_t>(l)] = true;
    else if (std::find(large.begin(), large.end(), l) == large.end())
      large.push_back(l);
  }
  std::vector<std::int32_t> present;
  for (std::int32_t l = 1; l < 1024; ++l)
    if (small[static_cast<std::size_t>(l)])
      present.push_back(l);
  present.insert(present.end(), large.begin(), large.end());
  std::sort(present.begin(), present.end());
  return present;
}

LabelImage StackedAlongLastAxis(const LabelImage& image, int copies)
{
  const auto& n = image.Dimensions;
  const bool flat = n[2] == 1;
  LabelImage tall(n[0], flat ? n[1] * copies : n[1], flat ? 1 : n[2] * copies, image.BytesPerLabel());
  for (int c = 0; c < copies; ++c)
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
          tall(i, flat ? j + c * n[1] : j, flat ? k : k + c * n[2]) = image(i, j, k);
  return tall;
}

} // namespace testing
} // namespace labelmesher
