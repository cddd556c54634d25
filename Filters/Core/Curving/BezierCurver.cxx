// SPDX-License-Identifier: GPL-2.0-or-later
// The 2D curvilinear mesher of chapter 4: smooth the interfaces, prove validity, untangle.
#include "Curving/BezierCurver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <map>
#include <set>
#include <string>

namespace labelmesher
{
namespace
{

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The curver needs counter-clockwise, non-degenerate triangles: the elastic
/// body and every Jacobian bound are defined relative to them.
void ValidateLinearMesh(const SimplexMesh& mesh)
{
  if (mesh.Dimension != 2)
  {
    throw std::invalid_argument("the curver needs a 2D triangle mesh");
  }
  if (mesh.NumberOfCells() == 0)
  {
    throw std::invalid_argument("the mesh has no triangles");
  }
  const auto points = static_cast<std::int64_t>(mesh.Points.size());
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* v = mesh.Cell(c);
    for (int k = 0; k < 3; ++k)
    {
      if (v[k] < 0 || v[k] >= points)
      {
        throw std::invalid_argument("triangle " + std::to_string(c) + " refers to a missing point");
      }
    }
    const Point3& a = mesh.Points[v[0]];
    const Point3& b = mesh.Points[v[1]];
    const Point3& d = mesh.Points[v[2]];
    const double area2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    if (!(area2 > 0.0))
    {
      throw std::invalid_argument("triangle " + std::to_string(c) +
        (area2 == 0.0 ? " is degenerate" : " is clockwise (inverted)"));
    }
  }
}

/// Section 4.1: one smooth Bézier path per interface chain, a piece per chain
/// segment whose inner control points become the targets of that edge's.
std::vector<CurvePiece> SmoothInterfaces(const SimplexMesh& linear, const CurvedMesh& curved,
  const std::vector<InterfaceChain>& chains, const CurvingParameters& parameters)
{
  const SmoothingOptions& options = parameters.Smoothing;
  // C1 curves follow the image when there is one (BoundaryFit.h); C2 paths
  // are fixed by the vertices.
  const bool fit = parameters.Image.Image && options.Continuity == Smoothness::C1;
  std::vector<std::vector<BoundarySample>> samples;
  if (fit)
    samples = CollectBoundarySamples(linear, chains, parameters.Image, parameters.SampleReach);
  std::vector<CurvePiece> pieces;
  for (std::size_t c = 0; c < chains.size(); ++c)
  {
    const InterfaceChain& chain = chains[c];
    std::vector<Point2> vertices;
    vertices.reserve(chain.Vertices.size());
    for (std::int64_t v : chain.Vertices)
    {
      vertices.push_back({ linear.Points[v][0], linear.Points[v][1] });
    }
    const FitOptions fitting{ options.Tension, parameters.FitRegularisation, 3 };
    auto segments = fit ? FitChain(vertices, chain.Closed, samples[c], fitting) : SmoothChain(vertices, chain.Closed, options);
    if (fit && parameters.Order == 2)
      segments = FitQuadraticSegments(vertices, chain.Closed, samples[c], segments, fitting);
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      CurvePiece piece;
      piece.From = chain.Vertices[s];
      piece.To = chain.Vertices[(s + 1) % chain.Vertices.size()];
      piece.ControlIds = curved.EdgePoints(piece.From, piece.To);
      piece.Fitted = segments[s];
      if (parameters.Order == 2)
      {
        // Fitted as a quadratic (above), or the quadratic nearest to the smoothed cubic: the joints
        // are then G1 only where both happen to be, the price of one control point per edge.
        const Point2& a = vertices[s];
        const Point2& b = vertices[(s + 1) % vertices.size()];
        piece.Fitted = ElevateQuadratic(a, NearestQuadraticControl(a, segments[s][0], segments[s][1], b), b);
        piece.Quadratic = true;
      }
      piece.Left = chain.FirstMaterial;
      piece.Right = chain.SecondMaterial;
      pieces.push_back(piece);
    }
  }
  return pieces;
}

/// The pieces' inner control points at their scales, as the untangler's targets.
std::vector<std::pair<std::int64_t, Point2>> Targets(const SimplexMesh& linear, const std::vector<CurvePiece>& pieces)
{
  std::vector<std::pair<std::int64_t, Point2>> prescribed;
  prescribed.reserve(2 * pieces.size());
  for (const CurvePiece& piece : pieces)
  {
    const auto p = piece.ControlPoints(linear);
    prescribed.emplace_back(piece.ControlIds[0], p[1]);
    prescribed.emplace_back(piece.ControlIds[1], p[2]);
  }
  return prescribed;
}

/// A cell that failed a round, and the corners (bits 0, 1, 2: its vertices
/// in order) whose curves are to blame: all three for an invalid cell or one
/// below the scaled Jacobian, those below the angle for a corner angle.
struct FailingCell
{
  std::size_t Cell = 0;
  std::uint8_t Corners = 7;
  /// A corner angle alone: a cubic curve leaves its vertex along its handle
  /// whatever its scale, so halving would not turn it; the cubic curves at the
  /// corner are made straight at once.
  bool AngleOnly = false;
};

/// Shortens the curved pieces on the edges of `cells` that meet their
/// failing corners; for a cell without such a curved edge, those ending at
/// those corners, or failing that at the corners of the cells around them,
/// ring by ring (a sliver is squeezed by the elastic displacement of curves
/// nearby). `invalidRounds` counts the rounds each cell has failed in; from
/// its second, its pieces are made straight rather than halved. False when
/// none was left.
bool ShortenPiecesOfCells(const SimplexMesh& linear, const std::vector<FailingCell>& cells,
  std::map<std::size_t, int>& invalidRounds, std::vector<CurvePiece>& pieces, std::set<std::size_t>& shortened)
{
  constexpr int kRings = 8;
  std::map<std::pair<std::int64_t, std::int64_t>, std::size_t> pieceOf;
  std::multimap<std::int64_t, std::size_t> piecesAt;
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    pieceOf[{ std::min(pieces[p].From, pieces[p].To), std::max(pieces[p].From, pieces[p].To) }] = p;
    piecesAt.emplace(pieces[p].From, p);
    piecesAt.emplace(pieces[p].To, p);
  }
  std::multimap<std::int64_t, std::size_t> cellsAt;
  for (std::size_t c = 0; c < linear.NumberOfCells(); ++c)
    for (int k = 0; k < 3; ++k)
      cellsAt.emplace(linear.Cell(c)[k], c);

  std::set<std::size_t> chosen, straighten;
  for (const FailingCell& failing : cells)
  {
    // A cell still invalid after a halving gets its curves straightened at
    // once: halving them again and again would run out of rounds.
    const bool persistent = ++invalidRounds[failing.Cell] >= 2;
    const std::int64_t* v = linear.Cell(failing.Cell);
    auto blamed = [&failing](int corner) { return (failing.Corners >> corner & 1) != 0; };
    std::set<std::size_t> own;
    std::set<std::int64_t> ring;
    for (int k = 0; k < 3; ++k)
    {
      if (blamed(k))
        ring.insert(v[k]);
      if (!blamed(k) && !blamed((k + 1) % 3))
        continue; // edge k -> k+1 meets no failing corner
      const auto it = pieceOf.find({ std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3]) });
      if (it != pieceOf.end() && pieces[it->second].Scale > 0.0)
        own.insert(it->second);
    }
    const bool atCorner = !own.empty(); // curves that leave a failing corner, not the rings'
    for (int r = 0; own.empty() && r < kRings; ++r)
    {
      for (std::int64_t vertex : ring)
        for (auto [it, end] = piecesAt.equal_range(vertex); it != end; ++it)
          if (pieces[it->second].Scale > 0.0)
            own.insert(it->second);
      std::set<std::int64_t> wider = ring;
      for (std::int64_t vertex : ring)
        for (auto [it, end] = cellsAt.equal_range(vertex); it != end; ++it)
          wider.insert(linear.Cell(it->second), linear.Cell(it->second) + 3);
      ring = std::move(wider);
    }
    chosen.insert(own.begin(), own.end());
    // A quadratic piece's tangent does turn towards its chord as it is halved (its one control
    // point moves towards the chord's midpoint): only a cubic one is straightened at once.
    const bool quadratic = !own.empty() && pieces[*own.begin()].Quadratic;
    if (persistent || (failing.AngleOnly && atCorner && !quadratic))
      straighten.insert(own.begin(), own.end());
  }
  for (std::size_t p : chosen)
  {
    if (straighten.count(p))
      pieces[p].Scale = 0.0;
    else
      ShortenPiece(pieces[p]);
    shortened.insert(p);
  }
  return !chosen.empty();
}

/// A box no mesh vertex lies on: without a known image border every interface is curved.
Box2 BoxAroundMesh(const SimplexMesh& mesh)
{
  Box2 box = BoundingBox2(mesh);
  const double margin = 1.0 + std::max(box[1] - box[0], box[3] - box[2]);
  return { box[0] - margin, box[1] + margin, box[2] - margin, box[3] + margin };
}

/// Rounds after MaximumShorteningRounds that straighten the curves of failing cells at once.
constexpr int kStraighteningRounds = 8;

/// A straight cell's corners are its angles, computed the same way; curved ones are compared with
/// the bound to within rounding (the straight control points the untangler returns are not
/// bit for bit those of MakeStraightCurvedMesh).
constexpr double kCornerAngleRounding = 1e-9;

/// The smallest corner angle (degrees) of `straight`, the linear mesh's cells in cubic form: the
/// linear mesh's smallest angle, as SmallestCornerAngle measures it.
double SmallestStraightCornerAngle(const CurvedMesh& straight)
{
  double smallest = 180.0;
  for (std::size_t c = 0; c < straight.Cells.size(); ++c)
    smallest = std::min(smallest, SmallestCornerAngle(straight.Cell(c)));
  return smallest;
}

/// The cells of `mesh` below the quality asked of a valid mesh, in order: a certified scaled
/// Jacobian below `scaledJacobian` (every corner to blame), or corners whose angle is below
/// `cornerAngle` (a bound of 0 asks nothing). Counts each kind (a cell may be both).
std::vector<FailingCell> CellsBelowQuality(const CurvedMesh& mesh, double scaledJacobian, double cornerAngle,
  std::size_t& belowScaledJacobian, std::size_t& belowCornerAngle)
{
  std::vector<FailingCell> below;
  belowScaledJacobian = belowCornerAngle = 0;
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
  {
    const CubicTriangle cell = mesh.Cell(c);
    const bool jacobian = scaledJacobian > 0.0 && BoundJacobian(cell).ScaledJacobian() < scaledJacobian;
    std::uint8_t corners = 0;
    if (cornerAngle > 0.0)
    {
      const std::array<double, 3> angles = CornerAngles(cell);
      for (int k = 0; k < 3; ++k)
        corners |= angles[k] < cornerAngle - kCornerAngleRounding ? 1 << k : 0;
    }
    belowScaledJacobian += jacobian ? 1 : 0;
    belowCornerAngle += corners != 0 ? 1 : 0;
    if (jacobian || corners != 0)
      below.push_back({ c, static_cast<std::uint8_t>(jacobian ? 7 : corners), !jacobian });
  }
  return below;
}

/// Cells not proven valid when the control points sit at `positions` (the
/// mesh's cells, other positions): no copy of the mesh's cells and edge map.
std::size_t CountInvalidCells(const CurvedMesh& mesh, const std::vector<Point2>& positions)
{
  std::size_t invalid = 0;
  for (const auto& ids : mesh.Cells)
  {
    CubicTriangle cell;
    for (int k = 0; k < 10; ++k)
      cell.ControlPoints[k] = positions[static_cast<std::size_t>(ids[k])];
    invalid += ClassifyValidity(cell) != Validity::Valid ? 1 : 0;
  }
  return invalid;
}

/// Order 2: brings what untangling moved back to quadratics (QuadraticForm.h) and certifies the
/// cells again, since the nearest quadratics are not the equilibrium untangling proved valid.
void CertifyQuadraticForm(CurvedMesh& mesh, UntanglingResult& untangled)
{
  MakeQuadraticForm(mesh);
  untangled.InvalidCells.clear();
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
    if (ClassifyValidity(mesh.Cell(c)) != Validity::Valid)
      untangled.InvalidCells.push_back(c);
  untangled.Valid = untangled.InvalidCells.empty();
}

} // namespace

CurvingResult CurveMesh(
  const SimplexMesh& linear, const CurvingParameters& parameters, const ProgressObserver& observer)
{
  ValidateLinearMesh(linear);
  if (parameters.Order != 2 && parameters.Order != 3)
  {
    throw std::invalid_argument("the curved cells' order must be 2 or 3, not " + std::to_string(parameters.Order));
  }
  if (!(parameters.MinimumCornerAngle >= 0.0 && parameters.MinimumCornerAngle < 180.0))
  {
    throw std::invalid_argument("the minimum corner angle must be in [0, 180) degrees, not " +
      std::to_string(parameters.MinimumCornerAngle));
  }
  if (!observer.Report("Smoothing boundaries", 0.0))
  {
    throw AbortRequested{};
  }
  CurvingResult result;
  auto start = Clock::now();
  const Box2 border = parameters.HasBorder ? parameters.Border : BoxAroundMesh(linear);
  result.Linear = linear;
  std::vector<InterfaceChain> chains = ExtractInterfaceChains(result.Linear, border);
  if (parameters.MinimumCornerAngle > 0.0)
  {
    // No ear split: it would halve angles of the linear mesh, the fallback that keeps the bound.
    // The chains turn at ears instead (each side's tangent its own), checked like every corner.
    const std::vector<std::int64_t> ears = EarVertices(result.Linear, chains);
    chains = BreakChainsAt(chains, ears);
    result.EarCorners = ears.size();
  }
  else
  {
    result.SplitEars = SplitBoundaryEars(result.Linear, chains, border);
  }
  result.NumberOfChains = chains.size();
  for (const InterfaceChain& chain : chains)
  {
    result.NumberOfClosedChains += chain.Closed ? 1 : 0;
  }
  result.Mesh = MakeStraightCurvedMesh(result.Linear);
  if (parameters.MinimumCornerAngle > 0.0)
    result.CornerAngleBound = std::min(parameters.MinimumCornerAngle, SmallestStraightCornerAngle(result.Mesh));
  std::vector<CurvePiece> pieces = SmoothInterfaces(result.Linear, result.Mesh, chains, parameters);
  // C1 survives one rotation of both handles at a joint; C2 (second derivatives) would not.
  if (result.CornerAngleBound > 0.0 && parameters.Order == 2)
    result.HandlesTurnedForCorners = PullQuadraticsToKeepCorners(result.Linear, pieces, result.CornerAngleBound);
  else if (result.CornerAngleBound > 0.0 && parameters.Smoothing.Continuity == Smoothness::C1)
    result.HandlesTurnedForCorners = TurnHandlesToKeepCorners(result.Linear, chains, pieces, result.CornerAngleBound);
  result.NumberOfCurvedEdges = pieces.size();
  result.Timings.push_back({ "smooth boundaries", SecondsSince(start) });

  // How many cells curving the boundary alone would break (the dissertation's
  // "invalid elements" before the FE method, section 5.2.4).
  start = Clock::now();
  {
    std::vector<Point2> boundaryOnly = result.Mesh.ControlPoints;
    for (const auto& [id, target] : Targets(result.Linear, pieces))
    {
      boundaryOnly[static_cast<std::size_t>(id)] = target;
    }
    result.InvalidBeforeUntangling = CountInvalidCells(result.Mesh, boundaryOnly);
  }
  result.Timings.push_back({ "validity before untangling", SecondsSince(start) });

  // Pieces that break a distance bound, and then pieces of cells that
  // untangling cannot make valid, are shortened until neither happens
  // (CurvePieces.h); shortening for validity can move a curve, so the bounds
  // are tested again after it.
  const bool bounded = parameters.Image.Image && parameters.Bounds.ImageToMesh >= 0.0 &&
    parameters.Bounds.MeshToImage >= 0.0;
  const CurvedMesh straight = result.Mesh;
  std::set<std::size_t> shortenedForValidity;
  std::set<std::size_t> shortenedForBounds;
  std::map<std::size_t, int> invalidRounds;
  bool invalidAfterRounds = false, everValid = false;
  for (int round = 0;; ++round)
  {
    if (bounded)
    {
      // Where the previous round's untangling ended (below): progress never goes back.
      if (!observer.Report("Keeping distance bounds", 0.05 + 0.85 * (1.0 - std::ldexp(1.0, -round))))
      {
        throw AbortRequested{};
      }
      start = Clock::now();
      const std::vector<CurvePiece> before = pieces;
      const FidelityOutcome outcome = KeepDistanceBounds(result.Linear, pieces, parameters.Image, parameters.Bounds);
      for (std::size_t p = 0; p < pieces.size(); ++p)
        if (pieces[p].Scale != before[p].Scale)
          shortenedForBounds.insert(p);
      result.UncertifiedPieces = outcome.Uncertified;
      result.Timings.push_back({ "distance bounds", SecondsSince(start) });
    }
    start = Clock::now();
    ProgressObserver untangling;
    // Round r fills [1 - 2^-r, 1 - 2^-(r+1)] of the untangling's share, so
    // that progress never goes back when a round follows.
    untangling.Callback = [&observer, round](const std::string& stage, double fraction) {
      const double done = 1.0 - std::ldexp(1.0, -round), next = 1.0 - std::ldexp(1.0, -round - 1);
      return observer.Report(stage, 0.05 + 0.85 * (done + (next - done) * fraction));
    };
    result.Mesh = straight;
    UntanglingResult untangled =
      UntangleControlNets(result.Mesh, Targets(result.Linear, pieces), parameters.Untangling, untangling);
    if (parameters.Order == 2)
      CertifyQuadraticForm(result.Mesh, untangled);
    result.UntanglingSteps = untangled.Steps;
    result.UntanglingRounds = round + 1;
    result.Timings.push_back({ "untangle", SecondsSince(start) });
    // Invalid cells first; a valid mesh may still have cells below the scaled Jacobian or the
    // corner angle asked for.
    std::vector<FailingCell> failing;
    for (std::size_t c : untangled.InvalidCells)
      failing.push_back({ c, 7, false });
    std::size_t belowScaledJacobian = 0, belowCornerAngle = 0;
    if (untangled.Valid)
      failing = CellsBelowQuality(result.Mesh, parameters.MinimumScaledJacobian, result.CornerAngleBound,
        belowScaledJacobian, belowCornerAngle);
    // Past the rounds asked for, cells still failing get a few more, each making the curves
    // around them straight at once (halving again would not end). Once untangling has made the
    // mesh valid, a round that shortened curves for quality can break it again (a halved curve
    // squeezes a neighbour): those cells take the same rounds. A mesh untangling never made
    // valid ends the rounds as asked, and the run fails with the cells marked.
    everValid = everValid || untangled.Valid;
    const bool pastRounds = round + 1 >= parameters.MaximumShorteningRounds;
    if (pastRounds && everValid)
      for (const FailingCell& f : failing)
        invalidRounds[f.Cell] = std::max(invalidRounds[f.Cell], 1);
    if (failing.empty() || (pastRounds && !everValid) ||
      round + 1 >= parameters.MaximumShorteningRounds + kStraighteningRounds ||
      !ShortenPiecesOfCells(result.Linear, failing, invalidRounds, pieces, shortenedForValidity))
    {
      result.CellsBelowScaledJacobian = belowScaledJacobian;
      result.CellsBelowCornerAngle = belowCornerAngle;
      invalidAfterRounds = !untangled.Valid && everValid;
      break;
    }
  }
  // The last resort: the straight cells of the linear mesh (valid, scaled Jacobian 1, corner
  // angles the linear angles).
  if (result.CellsBelowScaledJacobian > 0 || result.CellsBelowCornerAngle > 0 || invalidAfterRounds)
  {
    for (CurvePiece& piece : pieces)
      if (piece.Scale > 0.0)
      {
        piece.Scale = 0.0;
        shortenedForValidity.insert(static_cast<std::size_t>(&piece - pieces.data()));
      }
    result.Mesh = straight;
    UntangleControlNets(result.Mesh, Targets(result.Linear, pieces), parameters.Untangling);
    if (parameters.Order == 2)
      MakeQuadraticForm(result.Mesh);
    result.StraightenedForScaledJacobian = result.CellsBelowScaledJacobian > 0;
    result.StraightenedForCornerAngle = result.CellsBelowCornerAngle > 0;
    result.StraightenedForValidity = invalidAfterRounds;
  }
  result.PiecesShortenedForBounds = shortenedForBounds.size();
  result.PiecesShortenedForValidity = shortenedForValidity.size();
  for (const CurvePiece& piece : pieces)
  {
    result.StraightenedPieces += piece.Scale == 0.0 ? 1 : 0;
    result.ShortenedPieces += piece.Scale < 1.0 ? 1 : 0;
  }
  result.Pieces = pieces;

  // Section 4.2: a proven bound for every cell. A cell is valid when either the
  // control net (Theorem 4.2.1) or the subdivided Jacobian proves det J > 0.
  start = Clock::now();
  if (!observer.Report("Bounding Jacobians", 0.9))
  {
    throw AbortRequested{};
  }
  result.CellBounds.reserve(result.Mesh.Cells.size());
  for (std::size_t c = 0; c < result.Mesh.Cells.size(); ++c)
  {
    const CubicTriangle cell = result.Mesh.Cell(c);
    result.CellBounds.push_back(BoundJacobian(cell));
    if (ClassifyValidity(cell) != Validity::Valid)
    {
      result.InvalidCells.push_back(c);
    }
  }
  result.Valid = result.InvalidCells.empty();
  result.Timings.push_back({ "bound Jacobians", SecondsSince(start) });
  observer.Report("Bounding Jacobians", 1.0);
  return result;
}

} // namespace labelmesher
