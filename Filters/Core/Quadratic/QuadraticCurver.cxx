// SPDX-License-Identifier: GPL-2.0-or-later
// Fit, then certify and pull back until every cell and face holds.
#include "Quadratic/QuadraticCurver.h"

#include "Quadratic/InterfaceFaces.h"
#include "Quadratic/InteriorUntangler.h"
#include "Quadratic/QuadraticCorners.h"
#include "Quadratic/TetraJacobian.h"
#include "Support/Geometry.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

namespace labelmesher
{
namespace
{

double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Levels of red refinement the Jacobian bound may use on a cell it cannot certify whole.
constexpr int kSubdivisionDepth = 2;

/// Corner angles within this of the bound hold (round-off of a straight corner's tangents).
constexpr double kCornerTolerance = 1e-9;

/// Factors a corner may apply to the curves through it, largest first: it takes the largest
/// under which it holds (with the other curves as they are), at most 0.9 so that every round
/// makes progress. Halving instead took half the curves' gain on smooth shapes (sphere: 596
/// misclassified voxels linear, 387 curved with halving, 330 so) and twice the rounds of a
/// factor 3/4 (totalseg: 21 of those, 11 so).
constexpr double kCornerFactors[] = { 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.0 };

/// Below this share of its fitted offset a curve is made straight (rounds must end).
constexpr double kSmallestScale = 0.05;

/// Offset × 1/2, 1/4, then straight.
void PullBack(double& scale)
{
  scale = scale > 0.3 ? scale * 0.5 : 0.0;
}

std::array<double, 6> ImageBox(const LabelImage& image)
{
  // Voxel centres are at integers, so the sides are at -1/2 and n - 1/2.
  return { -0.5, image.Dimensions[0] - 0.5, -0.5, image.Dimensions[1] - 0.5, -0.5, image.Dimensions[2] - 0.5 };
}

} // namespace

QuadraticResult FitQuadraticMesh(SimplexMesh linear, const LabelImage& image, const QuadraticParameters& parameters)
{
  if (linear.Dimension != 3)
    throw std::invalid_argument("quadratic curving needs a tetrahedral mesh");
  QuadraticResult result;
  const auto start = std::chrono::steady_clock::now();
  result.Mesh = MakeQuadraticMesh(std::move(linear));
  result.Faces = FindInterfaceFaces(result.Mesh);
  result.Curvable = CurvableEdges(result.Mesh, result.Faces, ImageBox(image));
  result.FittedEdges = FitInterfaceMidNodes(result.Mesh, result.Faces, result.Curvable, image, parameters.Fit);
  result.FitSeconds = SecondsSince(start);
  return result;
}

QuadraticResult CurveQuadratic(SimplexMesh linear, const LabelImage& image, const QuadraticParameters& parameters,
  const ProgressObserver& observer)
{
  if (!observer.Report("quadratic fit", 0.0))
    throw AbortRequested{};
  QuadraticResult result = FitQuadraticMesh(std::move(linear), image, parameters);
  CertifyQuadraticMesh(result, image, parameters, observer);
  return result;
}

void CertifyQuadraticMesh(QuadraticResult& result, const LabelImage& image, const QuadraticParameters& parameters,
  const ProgressObserver& observer)
{
  if (!(parameters.MinimumScaledJacobian >= 0.0 && parameters.MinimumScaledJacobian < 1.0))
    throw std::invalid_argument("the minimum scaled Jacobian must be in [0, 1)");
  if (!(parameters.MinimumCornerAngle >= 0.0 && parameters.MinimumCornerAngle < 90.0))
    throw std::invalid_argument("the minimum corner angle must be in [0, 90) degrees");
  const auto start = std::chrono::steady_clock::now();
  QuadraticMesh& mesh = result.Mesh;
  if (result.Curvable.size() != mesh.Edges.size())
  {
    result.Faces = FindInterfaceFaces(mesh);
    result.Curvable = CurvableEdges(mesh, result.Faces, ImageBox(image));
  }
  const std::vector<MaterialFace> faces = std::move(result.Faces);
  // Edges on an interface or the box are bounding; the others (interior) are free to untangle.
  // Only interface sheets may bend: the box's faces stay flat (what the homeomorphism needs).
  const std::vector<char> curvable = std::move(result.Curvable);
  result.Faces.clear(), result.Curvable.clear();
  std::vector<char> free(mesh.Edges.size(), 1);
  for (const MaterialFace& f : faces)
    for (std::int64_t e : f.Edges)
      free[static_cast<std::size_t>(e)] = 0;
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
  {
    if (!free[e] && mesh.Curved(e) && !curvable[e])
    {
      mesh.Scales[e] = 0.0;
      ++result.StraightenedEdges;
    }
    if (free[e] && !parameters.Untangle)
      mesh.Scales[e] = 0.0, free[e] = 0;
  }
  auto curvedInterfaceEdges = [&](std::size_t c, std::set<std::size_t>& out) {
    for (int e = 0; e < 6; ++e)
    {
      const auto id = static_cast<std::size_t>(mesh.CellEdges[c * 6 + e]);
      if (!free[id] && mesh.Curved(id))
        out.insert(id);
    }
  };

  // The straight mesh must meet the corner bound, or the loop could not end: never above the
  // linear mesh's smallest dihedral angle.
  result.CornerAngleBound = 0.0;
  if (parameters.MinimumCornerAngle > 0.0)
  {
    double linear = 180.0;
    for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
    {
      const std::array<Point3, 10> n = mesh.Nodes(c);
      linear = std::min(linear, geometry::MinimumDihedralAngle(n[0], n[1], n[2], n[3]));
    }
    result.CornerAngleBound = std::min(parameters.MinimumCornerAngle, linear);
  }
  // Per cell: a bit for each corner below the bound with a curved edge through it (a corner of
  // straight edges is the linear mesh's, which holds the bound).
  std::vector<std::uint8_t> cornersBelow(mesh.NumberOfCells(), 0);
  auto failingCorners = [&](std::size_t c, const std::array<Point3, 10>& nodes) {
    std::uint8_t mask = 0;
    double smallest = 180.0;
    for (int k = 0; k < 4; ++k)
    {
      const std::array<double, 3> angles = CornerDihedralAngles(nodes, k);
      const double corner = std::min({ angles[0], angles[1], angles[2] });
      smallest = std::min(smallest, corner);
      bool curved = false;
      for (int e : CornerEdges(k))
        curved = curved || mesh.Curved(static_cast<std::size_t>(mesh.CellEdges[c * 6 + static_cast<std::size_t>(e)]));
      if (curved && corner < result.CornerAngleBound - kCornerTolerance)
        mask = static_cast<std::uint8_t>(mask | (1u << k));
    }
    result.CornerAngle[c] = smallest;
    return mask;
  };
  std::set<std::size_t> failedCorners;

  const QuadraticBounds bounds{ parameters.ImageToMeshDistance, parameters.MeshToImageDistance, parameters.Tolerance };
  std::set<std::size_t> shortened, failedCells, failedFaces;
  result.ScaledJacobian.assign(mesh.NumberOfCells(), 1.0);
  result.CornerAngle.assign(mesh.NumberOfCells(), 180.0);
  // A round tests again only the cells and faces whose mid-nodes moved since the last one.
  std::vector<Point3> before(mesh.Edges.size());
  std::vector<char> edgeMoved(mesh.Edges.size(), 1), faceMoved(faces.size(), 1);
  std::vector<char> facePending(faces.size(), 0); ///< moved since the distances were last tested
  InteriorUntangler untangler(mesh, free);
  for (;;)
  {
    ++result.Rounds;
    result.UntangledEdges = parameters.Untangle ? untangler.Solve(mesh) : 0;
    for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
    {
      const Point3 now = mesh.MidNode(e);
      edgeMoved[e] = edgeMoved[e] || now != before[e];
      before[e] = now;
    }
    std::size_t moving = 0;
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
      faceMoved[f] = edgeMoved[static_cast<std::size_t>(faces[f].Edges[0])] ||
        edgeMoved[static_cast<std::size_t>(faces[f].Edges[1])] || edgeMoved[static_cast<std::size_t>(faces[f].Edges[2])];
      moving += faceMoved[f] ? 1 : 0;
    }
    // Most of a run is its first round (every face); later rounds test what still moves.
    const double done = 1.0 - static_cast<double>(moving) / static_cast<double>(std::max<std::size_t>(faces.size(), 1));
    if (!observer.Report("quadratic certify", result.Rounds == 1 ? 0.0 : 0.5 + 0.5 * done))
      throw AbortRequested{};
    std::set<std::size_t> failing; // interface edges to pull back
    std::map<std::size_t, double> cornerFactor; // those a corner alone blames, and how far
    bool pinned = false;
    const double roundStart = result.Rounds == 1 ? 0.0 : 0.5 + 0.5 * done;
    for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
    {
      // The first round certifies every cell and is most of a run: its progress moves with them.
      if (c % 4096 == 4095 &&
        !observer.Report("quadratic certify",
          result.Rounds == 1 ? 0.5 * static_cast<double>(c) / static_cast<double>(mesh.NumberOfCells()) : roundStart))
        throw AbortRequested{};
      bool moved = false;
      for (int e = 0; e < 6; ++e)
        moved = moved || edgeMoved[static_cast<std::size_t>(mesh.CellEdges[c * 6 + e])];
      if (moved)
      {
        const std::array<Point3, 10> nodes = mesh.Nodes(c);
        result.ScaledJacobian[c] = mesh.CellIsCurved(c)
          ? CertifiedScaledJacobian(nodes, std::max(parameters.MinimumScaledJacobian, 1e-9), kSubdivisionDepth)
          : 1.0;
        cornersBelow[c] = failingCorners(c, nodes);
      }
      if (parameters.CertifyCorners && cornersBelow[c] != 0)
      {
        failedCorners.insert(c);
        for (int k = 0; k < 4; ++k)
        {
          if (!(cornersBelow[c] & (1u << k)))
            continue;
          // The fitted curves through the corner are pulled back, as little as the corner needs.
          // When even straight ones would not do, the untangled interior edges through it bend it:
          // those are pinned straight instead, and the fitted curves stay.
          const std::array<Point3, 10> nodes = mesh.Nodes(c);
          std::vector<int> pulled, interior;
          for (int e : CornerEdges(k))
          {
            const auto id = static_cast<std::size_t>(mesh.CellEdges[c * 6 + static_cast<std::size_t>(e)]);
            if (mesh.Curved(id))
              (free[id] ? interior : pulled).push_back(e);
          }
          double factor = -1.0; // none holds
          for (double f : kCornerFactors)
          {
            std::array<Point3, 10> trial = nodes;
            for (int e : pulled)
            {
              const Point3 middle = geometry::Scale(geometry::Add(nodes[kTetraEdges[e][0]], nodes[kTetraEdges[e][1]]), 0.5);
              trial[static_cast<std::size_t>(4 + e)] =
                geometry::Add(middle, geometry::Scale(geometry::Sub(nodes[static_cast<std::size_t>(4 + e)], middle), f));
            }
            const std::array<double, 3> angles = CornerDihedralAngles(trial, k);
            if (std::min({ angles[0], angles[1], angles[2] }) >= result.CornerAngleBound - kCornerTolerance)
            {
              factor = f;
              break;
            }
          }
          if (factor < 0.0 && interior.empty())
            factor = 0.0; // straight edges only: the linear corner, which holds (round-off aside)
          if (factor >= 0.0)
            for (int e : pulled)
            {
              const auto id = static_cast<std::size_t>(mesh.CellEdges[c * 6 + static_cast<std::size_t>(e)]);
              const auto [it, added] = cornerFactor.emplace(id, factor);
              if (!added)
                it->second = std::min(it->second, factor);
            }
          else
            for (int e : interior)
            {
              const auto id = static_cast<std::size_t>(mesh.CellEdges[c * 6 + static_cast<std::size_t>(e)]);
              free[id] = 0, mesh.Scales[id] = 0.0, ++result.PinnedEdges, pinned = true;
              untangler.Pin(id);
            }
        }
      }
      const double ratio = result.ScaledJacobian[c];
      if (!parameters.CertifyValidity || (ratio > 0.0 && ratio >= parameters.MinimumScaledJacobian))
        continue;
      failedCells.insert(c);
      std::set<std::size_t> blamed;
      curvedInterfaceEdges(c, blamed);
      if (blamed.empty())
      {
        // Only untangled interior edges bend it: pin them straight (the cell is then straight).
        for (int e = 0; e < 6; ++e)
        {
          const auto id = static_cast<std::size_t>(mesh.CellEdges[c * 6 + e]);
          if (free[id])
          {
            free[id] = 0, mesh.Scales[id] = 0.0, ++result.PinnedEdges, pinned = true;
            untangler.Pin(id);
          }
        }
      }
      failing.insert(blamed.begin(), blamed.end());
    }
    std::fill(edgeMoved.begin(), edgeMoved.end(), 0);
    for (std::size_t f = 0; f < faces.size(); ++f)
      facePending[f] = facePending[f] || faceMoved[f];
    // The distances are tested once the cells hold: a round that pulls curves back for a cell
    // moves those faces again, and their test would be wasted (the loop ends only after a round
    // that changes nothing, which has tested every face moved since the last test).
    if (parameters.CertifyDistances && failing.empty() && cornerFactor.empty() && !pinned)
    {
      const auto keepGoing = [&] { return observer.Report("quadratic certify", result.Rounds == 1 ? 0.5 : roundStart); };
      for (std::size_t f : FacesBreakingDistances(mesh, faces, image, bounds, &facePending, keepGoing))
      {
        failedFaces.insert(f);
        for (std::int64_t e : faces[f].Edges)
          failing.insert(static_cast<std::size_t>(e));
      }
      std::fill(facePending.begin(), facePending.end(), 0);
    }
    bool changed = pinned;
    for (std::size_t e : failing)
      cornerFactor.erase(e);
    for (const auto& [e, factor] : cornerFactor)
    {
      if (!mesh.Curved(e))
        continue;
      mesh.Scales[e] = mesh.Scales[e] * factor >= kSmallestScale ? mesh.Scales[e] * factor : 0.0;
      shortened.insert(e);
      result.StraightenedEdges += mesh.Scales[e] == 0.0 ? 1 : 0;
      changed = true;
    }
    for (std::size_t e : failing)
    {
      if (!mesh.Curved(e))
        continue;
      PullBack(mesh.Scales[e]);
      shortened.insert(e);
      result.StraightenedEdges += mesh.Scales[e] == 0.0 ? 1 : 0;
      changed = true;
    }
    if (!changed)
      break;
  }
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
    result.CurvedEdges += !free[e] && mesh.Curved(e) ? 1 : 0;
  result.ShortenedEdges = shortened.size();
  result.CellsFailedQuality = failedCells.size();
  result.FacesFailedDistance = failedFaces.size();
  result.CellsFailedCornerAngle = failedCorners.size();
  result.CertifySeconds = SecondsSince(start);
}

} // namespace labelmesher
