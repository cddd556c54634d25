// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file ElasticUntangler.cxx
 * UntangleControlNets: the iterative finite element method of section 4.3
 * (Figures 20-22).
 *
 * The body is the union of the control nets, nine P1 plane-strain triangles
 * per cell. Its points are of three kinds: prescribed (moved to a target),
 * fixed (mesh vertices, and the points of mesh-boundary edges nobody
 * prescribed, e.g. straight edges on the image border, which must not bulge)
 * and free (every other point: interior edge points and cell interior points).
 * A prescribed mesh vertex moves like any prescribed point.
 *
 * With n load fractions the prescribed displacement is applied in n equal
 * increments; each increment is solved on the body as the previous increment
 * left it (the stiffness is re-assembled on the current geometry), which is
 * what lets the iterative method of Figure 21 untangle nets the one-step method
 * cannot. n runs through 1, 2, 4, ... up to MaximumSteps, each attempt starting
 * from the original body; the first attempt whose cells are all proven valid
 * wins, and QualityIterations further doublings replace it only when they raise
 * the worst scaled Jacobian. The search also ends when every cell still invalid
 * is beyond repair (CannotBecomeValid below).
 *
 * Stiffness: Young's modulus of every sub-triangle is mean area / area
 * (Jacobian-based stiffening, Stein, Tezduyar and Benney 2003, exponent 1):
 * small and squashed sub-triangles stiffen and pass the deformation on to
 * larger ones instead of inverting. On meshes from the linear mesher it halves
 * or quarters the load fractions needed and raises the worst scaled Jacobian
 * compared with a homogeneous body. On a body of equal-area sub-triangles (a
 * straight mesh of equal cells) it is the homogeneous material, so affine
 * fields are reproduced exactly there.
 *
 * Solver: Jacobi-preconditioned conjugate gradients, warm-started from the
 * previous increment (the first increment of an attempt then costs nothing: it
 * is the previous attempt's first solution scaled). Eigen's simplicial
 * Cholesky fills in heavily on these 2D bodies and factorises several times
 * slower; it remains the fallback when CG stalls on a badly conditioned body
 * (very long thin cells), with the symbolic analysis done once.
 */

#include "Curving/ElasticUntangler.h"

#include "Curving/JacobianBound.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace labelmesher
{

namespace
{
const std::string Stage = "Untangling";

/// A sub-triangle's area is clamped to this fraction of its squared edge
/// lengths, so that flat (or collapsed) sub-triangles of a deformed body stay
/// finite, very stiff elements instead of producing infinities and NaNs.
constexpr double MinimumAreaRatio = 1e-6;

/// Relative residual of the iterative solve: far below any geometric tolerance.
constexpr double SolverTolerance = 1e-11;
/// Free degrees of freedom up to which the body is factorised without trying
/// CG: on decimated meshes (thousands of cells whose areas differ by orders of
/// magnitude) CG needs hundreds of iterations per step and the fill-in is small.
constexpr Eigen::Index kLargestDirectBody = 100000;

/// The nine control triangles of a cubic net as VTK slots: six upward
/// (P_{i+1,j,k}, P_{i,j+1,k}, P_{i,j,k+1}), i + j + k = 2, and three downward
/// (P_{i,j+1,k+1}, P_{i+1,j,k+1}, P_{i+1,j+1,k}), i + j + k = 1. All are
/// counter-clockwise in a counter-clockwise straight cell.
std::array<std::array<int, 3>, 9> NetTriangles()
{
  std::array<std::array<int, 3>, 9> triangles{};
  int t = 0;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; i + j <= 2; ++j)
    {
      const int k = 2 - i - j;
      triangles[t++] = { CubicControlPointIndex(i + 1, j, k), CubicControlPointIndex(i, j + 1, k),
        CubicControlPointIndex(i, j, k + 1) };
    }
  for (int i = 0; i <= 1; ++i)
    for (int j = 0; i + j <= 1; ++j)
    {
      const int k = 1 - i - j;
      triangles[t++] = { CubicControlPointIndex(i, j + 1, k + 1), CubicControlPointIndex(i + 1, j, k + 1),
        CubicControlPointIndex(i + 1, j + 1, k) };
    }
  return triangles;
}

/// The control-net body: the free-free block K_ff of its stiffness, whose
/// sparsity pattern (and symbolic factorisation, when needed) every load step shares.
class ElasticBody
{
public:
  ElasticBody(const CurvedMesh& mesh, std::vector<std::int64_t> freeIndex, std::int64_t numberOfFree,
    double poissonRatio);

  /// One load step on the body in configuration `x`: constrained points move
  /// by `increment`, free points to equilibrium. False when the solve fails.
  bool Step(std::vector<Point2>& x, const std::vector<Point2>& increment);

  /// The next solve starts from the last solution times `factor` (the ratio of the load increments).
  void ScaleGuess(double factor) { Solution *= factor; }

private:
  std::vector<std::array<std::int64_t, 3>> Triangles;
  std::vector<std::int64_t> FreeIndex; // per control point, -1 when constrained
  /// Per triangle, the value index in K of each local dof pair (a >= b), -1 when not free-free.
  std::vector<std::array<int, 21>> Slots;
  std::vector<double> Areas;
  double Lambda, Mu;
  Eigen::SparseMatrix<double> K; // lower triangle of K_ff
  Eigen::VectorXd Rhs, Solution;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower> Iterative;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> Direct;
  bool Analysed = false;
};

ElasticBody::ElasticBody(
  const CurvedMesh& mesh, std::vector<std::int64_t> freeIndex, std::int64_t numberOfFree, double poissonRatio)
  : FreeIndex(std::move(freeIndex))
{
  // Plane strain, Young's modulus 1 (scaled per element in Step).
  const double nu = poissonRatio;
  Lambda = nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  Mu = 1.0 / (2.0 * (1.0 + nu));

  const auto net = NetTriangles();
  std::vector<Eigen::Triplet<double, int>> pattern;
  pattern.reserve(9 * 21 * mesh.Cells.size());
  for (const auto& cell : mesh.Cells)
    for (const auto& t : net)
    {
      const std::array<std::int64_t, 3> ids{ cell[t[0]], cell[t[1]], cell[t[2]] };
      // Without a free point a sub-triangle adds nothing to K_ff or the right-hand side.
      if (FreeIndex[ids[0]] < 0 && FreeIndex[ids[1]] < 0 && FreeIndex[ids[2]] < 0)
        continue;
      Triangles.push_back(ids);
      for (int a = 0; a < 6; ++a)
        for (int b = 0; b <= a; ++b)
        {
          const std::int64_t fa = FreeIndex[ids[a / 2]], fb = FreeIndex[ids[b / 2]];
          if (fa >= 0 && fb >= 0)
          {
            const int ra = static_cast<int>(2 * fa + a % 2), rb = static_cast<int>(2 * fb + b % 2);
            pattern.emplace_back(std::max(ra, rb), std::min(ra, rb), 0.0);
          }
        }
    }
  const auto dofs = static_cast<Eigen::Index>(2 * numberOfFree);
  K.resize(dofs, dofs);
  K.setFromTriplets(pattern.begin(), pattern.end());
  K.makeCompressed();
  Rhs.resize(dofs);
  Solution = Eigen::VectorXd::Zero(dofs);
  Iterative.setTolerance(SolverTolerance);
  Iterative.setMaxIterations(static_cast<Eigen::Index>(4.0 * std::sqrt(double(dofs)) + 200.0));
  Areas.resize(Triangles.size());

  // Value index of (row, col) in the compressed column-major lower triangle.
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  Slots.resize(Triangles.size());
  for (std::size_t e = 0; e < Triangles.size(); ++e)
  {
    int s = 0;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b <= a; ++b, ++s)
      {
        const std::int64_t fa = FreeIndex[Triangles[e][a / 2]], fb = FreeIndex[Triangles[e][b / 2]];
        Slots[e][s] = -1;
        if (fa < 0 || fb < 0)
          continue;
        const int ra = static_cast<int>(2 * fa + a % 2), rb = static_cast<int>(2 * fb + b % 2);
        const int row = std::max(ra, rb), col = std::min(ra, rb);
        Slots[e][s] = static_cast<int>(std::lower_bound(inner + outer[col], inner + outer[col + 1], row) - inner);
      }
  }
}

bool ElasticBody::Step(std::vector<Point2>& x, const std::vector<Point2>& increment)
{
  double meanArea = 0.0;
  for (std::size_t e = 0; e < Triangles.size(); ++e)
  {
    const Point2 &p = x[Triangles[e][0]], &q = x[Triangles[e][1]], &r = x[Triangles[e][2]];
    const double area = 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
    const double edges = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
      (r[0] - q[0]) * (r[0] - q[0]) + (r[1] - q[1]) * (r[1] - q[1]) + (p[0] - r[0]) * (p[0] - r[0]) +
      (p[1] - r[1]) * (p[1] - r[1]);
    Areas[e] = std::max(area, MinimumAreaRatio * edges); // 0 only when all three points coincide
    meanArea += Areas[e];
  }
  meanArea /= std::max<std::size_t>(Triangles.size(), 1);

  std::fill(K.valuePtr(), K.valuePtr() + K.nonZeros(), 0.0);
  Rhs.setZero();
  for (std::size_t e = 0; e < Triangles.size(); ++e)
  {
    if (Areas[e] == 0.0)
      continue;
    const auto& ids = Triangles[e];
    // Gradients of the hat functions times 2A: (b_i, c_i).
    double b[3], c[3];
    for (int i = 0; i < 3; ++i)
    {
      const Point2 &q = x[ids[(i + 1) % 3]], &r = x[ids[(i + 2) % 3]];
      b[i] = q[1] - r[1];
      c[i] = r[0] - q[0];
    }
    // K_e = A E (B^T D B) with B = (b, c) / 2A and E = meanArea / A.
    const double scale = meanArea / (4.0 * Areas[e] * Areas[e]);
    const double l2m = (Lambda + 2.0 * Mu) * scale, l = Lambda * scale, m = Mu * scale;
    auto entry = [&](int da, int db) {
      const int i = da / 2, j = db / 2;
      if (da % 2 == 0 && db % 2 == 0)
        return l2m * b[i] * b[j] + m * c[i] * c[j];
      if (da % 2 == 1 && db % 2 == 1)
        return l2m * c[i] * c[j] + m * b[i] * b[j];
      if (da % 2 == 0) // x of i, y of j
        return l * b[i] * c[j] + m * c[i] * b[j];
      return l * c[i] * b[j] + m * b[i] * c[j];
    };
    double* values = K.valuePtr();
    int s = 0;
    for (int a = 0; a < 6; ++a)
    {
      const std::int64_t fa = FreeIndex[ids[a / 2]];
      for (int bb = 0; bb <= a; ++bb, ++s)
      {
        if (Slots[e][s] >= 0)
          values[Slots[e][s]] += entry(a, bb);
      }
      if (fa < 0)
        continue;
      // Known displacements of the constrained points go to the right-hand side.
      for (int d = 0; d < 6; ++d)
      {
        if (FreeIndex[ids[d / 2]] < 0)
          Rhs[2 * fa + a % 2] -= entry(a, d) * increment[ids[d / 2]][d % 2];
      }
    }
  }

  // Small bodies (decimated meshes) are factorised outright; large ones try
  // CG first, the factorisation only when it stalls (see the file comment).
  bool solved = false;
  if (K.rows() > kLargestDirectBody)
  {
    Iterative.compute(K);
    Solution = Iterative.solveWithGuess(Rhs, Solution);
    solved = Iterative.info() == Eigen::Success && Solution.allFinite();
  }
  if (!solved)
  {
    if (!Analysed)
    {
      Direct.analyzePattern(K);
      Analysed = true;
    }
    Direct.factorize(K);
    if (Direct.info() == Eigen::Success)
      Solution = Direct.solve(Rhs);
    if (Direct.info() != Eigen::Success || !Solution.allFinite())
    {
      Solution.setZero(); // no guess for the next solve
      return false;
    }
  }
  const Eigen::VectorXd& u = Solution;
  for (std::size_t p = 0; p < x.size(); ++p)
  {
    const std::int64_t f = FreeIndex[p];
    x[p][0] += f >= 0 ? u[2 * f] : increment[p][0];
    x[p][1] += f >= 0 ? u[2 * f + 1] : increment[p][1];
  }
  return true;
}

/// Cells with at least one control point away from its original position.
std::vector<std::size_t> MovedCells(
  const CurvedMesh& mesh, const std::vector<Point2>& x, const std::vector<Point2>& original)
{
  std::vector<std::size_t> moved;
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
    for (std::int64_t id : mesh.Cells[c])
      if (x[id] != original[id])
      {
        moved.push_back(c);
        break;
      }
  return moved;
}

CubicTriangle CellAt(const std::array<std::int64_t, 10>& ids, const std::vector<Point2>& x)
{
  CubicTriangle triangle;
  for (int k = 0; k < 10; ++k)
    triangle.ControlPoints[k] = x[ids[k]];
  return triangle;
}

double MinimumScaledJacobian(const CurvedMesh& mesh, const std::vector<Point2>& x)
{
  double minimum = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
    minimum = std::min(minimum, BoundJacobian(CellAt(mesh.Cells[c], x)).ScaledJacobian());
  return mesh.Cells.empty() ? 0.0 : minimum;
}

/// True when no placement of the free points can make the cell valid: all ten
/// points are constrained, or at a corner the corner point and its two edge
/// neighbours are, with det J <= 0 there (Table 1: det J at P300 is
/// 9 (P210 - P300) x (P201 - P300), the corner control triangle's doubled area).
/// This happens where a smooth interface passes through a cell with two
/// interface edges: its angle there opens to 180 degrees.
bool CannotBecomeValid(
  const std::array<std::int64_t, 10>& ids, const std::vector<Point2>& target, const std::vector<char>& constrained)
{
  if (std::all_of(ids.begin(), ids.end(), [&](std::int64_t id) { return constrained[id] != 0; }))
    return ClassifyValidity(CellAt(ids, target)) != Validity::Valid;
  static const std::array<std::array<int, 3>, 3> corners{ { { CubicControlPointIndex(3, 0, 0),
    CubicControlPointIndex(2, 1, 0), CubicControlPointIndex(2, 0, 1) },
    { CubicControlPointIndex(1, 2, 0), CubicControlPointIndex(0, 3, 0), CubicControlPointIndex(0, 2, 1) },
    { CubicControlPointIndex(1, 0, 2), CubicControlPointIndex(0, 1, 2), CubicControlPointIndex(0, 0, 3) } } };
  for (const auto& t : corners)
  {
    const std::int64_t a = ids[t[0]], b = ids[t[1]], c = ids[t[2]];
    if (!constrained[a] || !constrained[b] || !constrained[c])
      continue;
    const Point2 &p = target[a], &q = target[b], &r = target[c];
    if (!((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]) > 0.0))
      return true;
  }
  return false;
}

struct Solution
{
  int Steps = 0;
  std::vector<Point2> Points;
  std::vector<std::size_t> InvalidCells;
};
} // namespace

UntanglingResult UntangleControlNets(CurvedMesh& mesh,
  const std::vector<std::pair<std::int64_t, Point2>>& prescribed, const UntanglingOptions& options,
  const ProgressObserver& observer)
{
  if (options.MaximumSteps < 1 || options.QualityIterations < 0)
    throw std::invalid_argument("untangling needs MaximumSteps >= 1 and QualityIterations >= 0");
  if (!(options.PoissonRatio >= 0.0 && options.PoissonRatio < 0.5))
    throw std::invalid_argument("the Poisson ratio must lie in [0, 0.5)");
  const auto points = static_cast<std::int64_t>(mesh.ControlPoints.size());
  for (const auto& [id, target] : prescribed)
    if (id < 0 || id >= points)
      throw std::invalid_argument("prescribed control point " + std::to_string(id) + " does not exist");
  if (!observer.Report(Stage, 0.0))
    throw AbortRequested{};

  const std::vector<Point2>& original = mesh.ControlPoints;
  std::vector<Point2> displacement(original.size(), Point2{ 0.0, 0.0 });
  std::vector<char> constrained(original.size(), 0);
  for (std::int64_t v = 0; v < mesh.NumberOfVertices; ++v)
    constrained[v] = 1;
  // An edge point used by one cell lies on a mesh-boundary edge.
  std::vector<unsigned char> uses(original.size(), 0);
  for (const auto& cell : mesh.Cells)
    for (int k = 3; k < 9; ++k)
      uses[cell[k]] = static_cast<unsigned char>(std::min(uses[cell[k]] + 1, 2));
  for (std::size_t p = 0; p < original.size(); ++p)
    constrained[p] |= uses[p] == 1;
  bool moving = false;
  for (const auto& [id, target] : prescribed)
  {
    constrained[id] = 1;
    displacement[id] = { target[0] - original[id][0], target[1] - original[id][1] };
    moving = moving || displacement[id] != Point2{ 0.0, 0.0 };
  }

  // Cells no attempt moves keep their original validity.
  std::vector<char> initiallyValid(mesh.Cells.size());
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
    initiallyValid[c] = ClassifyValidity(mesh.Cell(c)) == Validity::Valid;
  UntanglingResult result;
  if (!moving)
  {
    for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
      if (!initiallyValid[c])
        result.InvalidCells.push_back(c);
    result.Valid = result.InvalidCells.empty();
    result.MinimumScaledJacobian = MinimumScaledJacobian(mesh, original);
    observer.Report(Stage, 1.0);
    return result;
  }

  std::vector<std::int64_t> freeIndex(original.size(), -1);
  std::int64_t numberOfFree = 0;
  for (std::size_t p = 0; p < original.size(); ++p)
    if (!constrained[p])
      freeIndex[p] = numberOfFree++;
  ElasticBody body(mesh, std::move(freeIndex), numberOfFree, options.PoissonRatio);

  // Progress: every step of every attempt the schedule allows.
  int largest = 1;
  while (2 * largest <= options.MaximumSteps)
    largest *= 2;
  const double totalSteps = 2.0 * largest - 1.0;
  double stepsDone = 0.0;

  std::vector<Point2> increment(original.size());
  int lastSteps = 1;
  // Figure 21: apply the displacement in n fractions, each on the body the previous one deformed.
  auto attempt = [&](int n, Solution& solution) {
    solution.Steps = n;
    solution.Points = original;
    solution.InvalidCells.clear();
    body.ScaleGuess(lastSteps / double(n));
    lastSteps = n;
    for (std::size_t p = 0; p < original.size(); ++p)
      increment[p] = { displacement[p][0] / n, displacement[p][1] / n };
    for (int k = 1; k <= n; ++k)
    {
      const bool solved = body.Step(solution.Points, increment);
      stepsDone += 1.0;
      if (!observer.Report(Stage, std::min(stepsDone / totalSteps, 1.0)))
        throw AbortRequested{};
      if (!solved)
        return false;
    }
    // No round-off drift on the targets.
    for (const auto& [id, target] : prescribed)
      solution.Points[id] = target;
    std::vector<char> valid = initiallyValid;
    for (std::size_t c : MovedCells(mesh, solution.Points, original))
      valid[c] = ClassifyValidity(CellAt(mesh.Cells[c], solution.Points)) == Validity::Valid;
    for (std::size_t c = 0; c < valid.size(); ++c)
      if (!valid[c])
        solution.InvalidCells.push_back(c);
    return true;
  };

  // Cells no schedule can fix end the search as soon as they are all that is left.
  std::vector<Point2> target = original;
  for (const auto& [id, point] : prescribed)
    target[id] = point;
  std::vector<char> hopeless(mesh.Cells.size());
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
    hopeless[c] = CannotBecomeValid(mesh.Cells[c], target, constrained);

  Solution best, trial;
  bool haveBest = false;
  int n = 1;
  for (; n <= options.MaximumSteps; n *= 2)
  {
    if (!attempt(n, trial))
      continue;
    if (!haveBest || trial.InvalidCells.size() < best.InvalidCells.size())
    {
      std::swap(best, trial);
      haveBest = true;
    }
    if (std::all_of(best.InvalidCells.begin(), best.InvalidCells.end(), [&](std::size_t c) { return hopeless[c] != 0; }))
      break;
  }

  if (!haveBest)
  {
    // Every solve failed (not seen with the area clamp): the curved boundary alone, Steps 0.
    best.Steps = 0;
    best.Points = target;
    best.InvalidCells.clear();
    for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
      if (ClassifyValidity(CellAt(mesh.Cells[c], target)) != Validity::Valid)
        best.InvalidCells.push_back(c);
  }
  double bestQuality = MinimumScaledJacobian(mesh, best.Points);
  if (haveBest && best.InvalidCells.empty())
  {
    // Finer fractions often leave better-shaped cells; keep them only when the worst cell improves.
    for (int q = 0; q < options.QualityIterations && 2 * n <= options.MaximumSteps; ++q)
    {
      n *= 2;
      if (!attempt(n, trial) || !trial.InvalidCells.empty())
        continue;
      const double quality = MinimumScaledJacobian(mesh, trial.Points);
      if (quality > bestQuality)
      {
        std::swap(best, trial);
        bestQuality = quality;
      }
    }
  }

  mesh.ControlPoints = std::move(best.Points);
  result.Valid = best.InvalidCells.empty();
  result.Steps = best.Steps;
  result.InvalidCells = std::move(best.InvalidCells);
  result.MinimumScaledJacobian = bestQuality;
  observer.Report(Stage, 1.0);
  return result;
}

} // namespace labelmesher
