// SPDX-License-Identifier: GPL-2.0-or-later
// Interior mid-nodes at the elastic equilibrium of the control nets.
#include "Quadratic/InteriorUntangler.h"

#include "Support/Geometry.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <array>
#include <cmath>

namespace labelmesher
{
using namespace geometry;
namespace
{

/// A control point of a cell: corner k (0..3) or edge e (4 + e), and the eight tetrahedra of the
/// degree-2 control net: four at the corners, four around the octahedron's diagonal 0-2 / 1-3
/// (edges 2 and 4 in kTetraEdges' order).
constexpr int kNetTetra[8][4] = {
  { 0, 4, 6, 7 }, { 1, 4, 5, 8 }, { 2, 5, 6, 9 }, { 3, 7, 8, 9 }, // corners with their three edges
  { 6, 8, 4, 5 }, { 6, 8, 5, 9 }, { 6, 8, 9, 7 }, { 6, 8, 7, 4 }, // 2-0 / 1-3 and the equator 0-1, 1-2, 2-3, 0-3
};

/// The 12 x 12 stiffness of a linear tetrahedron with points x (isotropic, Young's modulus 1),
/// divided by its volume. False when it is degenerate.
bool Stiffness(const Point3 x[4], double nu, Eigen::Matrix<double, 12, 12>& k)
{
  Eigen::Matrix4d m;
  for (int i = 0; i < 4; ++i)
    m.row(i) << 1.0, x[i][0], x[i][1], x[i][2];
  const double det = m.determinant();
  if (std::fabs(det) < 1e-12)
    return false;
  const Eigen::Matrix4d inverse = m.inverse(); // column i: the coefficients of shape function i
  Eigen::Matrix<double, 6, 12> b = Eigen::Matrix<double, 6, 12>::Zero();
  for (int i = 0; i < 4; ++i)
  {
    const double dx = inverse(1, i), dy = inverse(2, i), dz = inverse(3, i);
    b(0, 3 * i) = dx;
    b(1, 3 * i + 1) = dy;
    b(2, 3 * i + 2) = dz;
    b(3, 3 * i) = dy, b(3, 3 * i + 1) = dx;
    b(4, 3 * i + 1) = dz, b(4, 3 * i + 2) = dy;
    b(5, 3 * i) = dz, b(5, 3 * i + 2) = dx;
  }
  const double lambda = nu / ((1 + nu) * (1 - 2 * nu)), mu = 1.0 / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i)
    d(i, i) += 2 * mu, d(3 + i, 3 + i) = mu;
  k = b.transpose() * d * b; // volume × BᵀDB, stiffened by 1 / volume
  return true;
}

/// Conjugate gradients stop at this residual, relative to the right-hand side's norm.
constexpr double kRelativeResidual = 1e-8;

} // namespace

/// The system K_ff u_f = -K_fp u_p over the moving edges' control points (3 dofs each), K_fp
/// over the bounding edges' ones, solved by conjugate gradients (Jacobi preconditioner) from the
/// last solution. A sparse Cholesky factor grows faster than the mesh (digimouse: 2 GB and
/// minutes per factorisation); the iteration needs only K, and the answer need not be exact:
/// every cell is certified afterwards, wherever its mid-nodes are.
struct InteriorUntangler::System
{
  std::vector<int> Unknown;                 ///< per edge: its index among the moving ones, or -1
  std::vector<int> Prescribed;              ///< per edge: its index among the bounding ones next to them, or -1
  Eigen::SparseMatrix<double> Matrix;       ///< K_ff, its upper triangle (it is symmetric)
  Eigen::SparseMatrix<double> Coupling;     ///< K_fp
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Upper> Solver;
  bool Ok = false;
};

InteriorUntangler::InteriorUntangler(const QuadraticMesh& mesh, const std::vector<char>& free, double poissonRatio)
  : Mesh(mesh)
  , Free(free)
  , PoissonRatio(poissonRatio)
  , Moving(mesh.Edges.size(), 0)
  , Displacement(mesh.Edges.size(), Point3{ 0.0, 0.0, 0.0 })
{
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    bool curved = false;
    for (int e = 0; e < 6; ++e)
    {
      const auto id = static_cast<std::size_t>(mesh.CellEdges[c * 6 + e]);
      curved = curved || (!free[id] && mesh.Curved(id));
    }
    if (curved)
      for (int e = 0; e < 6; ++e)
      {
        const auto id = static_cast<std::size_t>(mesh.CellEdges[c * 6 + e]);
        Moving[id] = free[id];
      }
  }
}

InteriorUntangler::~InteriorUntangler() = default;

void InteriorUntangler::Pin(std::size_t e)
{
  Free[e] = 0;
  if (Moving[e])
  {
    Moving[e] = 0;
    Factored.reset();
  }
}

std::size_t InteriorUntangler::Solve(QuadraticMesh& mesh)
{
  const std::size_t edges = mesh.Edges.size();
  for (std::size_t e = 0; e < edges; ++e)
    if (Free[e])
      mesh.Scales[e] = 0.0;
  if (!Factored)
  {
    Factored = std::make_unique<System>();
    System& s = *Factored;
    s.Unknown.assign(edges, -1);
    s.Prescribed.assign(edges, -1);
    int unknowns = 0, prescribed = 0;
    for (std::size_t e = 0; e < edges; ++e)
      if (Moving[e])
        s.Unknown[e] = unknowns++;
    // The bounding edges of cells with a moving edge are the prescribed columns.
    auto touches = [&](std::size_t c) {
      for (int e = 0; e < 6; ++e)
        if (s.Unknown[static_cast<std::size_t>(Mesh.CellEdges[c * 6 + e])] >= 0)
          return true;
      return false;
    };
    for (std::size_t c = 0; c < Mesh.NumberOfCells(); ++c)
      if (touches(c))
        for (int e = 0; e < 6; ++e)
        {
          const auto edge = static_cast<std::size_t>(Mesh.CellEdges[c * 6 + e]);
          if (!Free[edge] && s.Prescribed[edge] < 0)
            s.Prescribed[edge] = prescribed++;
        }
    // Both matrices get their pattern first (the edges of each touching cell couple), then the
    // stiffness is added in place: no triplet lists (all at once took 0.5 GB on totalseg) and no
    // repeated sums of partial matrices (quadratic in the mesh: minutes on digimouse).
    std::vector<std::vector<int>> rowsOfUnknown(static_cast<std::size_t>(unknowns)),
      rowsOfPrescribed(static_cast<std::size_t>(prescribed));
    auto addOnce = [](std::vector<int>& list, int value) {
      if (std::find(list.begin(), list.end(), value) == list.end())
        list.push_back(value);
    };
    for (std::size_t c = 0; c < Mesh.NumberOfCells(); ++c)
    {
      if (!touches(c))
        continue;
      for (int a = 0; a < 6; ++a)
      {
        const int ua = s.Unknown[static_cast<std::size_t>(Mesh.CellEdges[c * 6 + a])];
        if (ua < 0)
          continue;
        for (int b = 0; b < 6; ++b)
        {
          const auto eb = static_cast<std::size_t>(Mesh.CellEdges[c * 6 + b]);
          if (s.Unknown[eb] >= 0 && ua <= s.Unknown[eb]) // K_ff's upper triangle
            addOnce(rowsOfUnknown[static_cast<std::size_t>(s.Unknown[eb])], ua);
          else if (s.Prescribed[eb] >= 0)
            addOnce(rowsOfPrescribed[static_cast<std::size_t>(s.Prescribed[eb])], ua);
        }
      }
    }
    // Column 3 b + j holds rows 3 a + i for the edges a coupled to b, in order.
    auto withPattern = [](Eigen::SparseMatrix<double>& m, std::vector<std::vector<int>>& rowsOf) {
      if (m.cols() == 0)
        return; // Eigen's makeCompressed reads past a reserved matrix of no columns (ASan)
      Eigen::VectorXi sizes(m.cols());
      for (std::size_t b = 0; b < rowsOf.size(); ++b)
        for (int j = 0; j < 3; ++j)
          sizes[static_cast<Eigen::Index>(3 * b + static_cast<std::size_t>(j))] = static_cast<int>(3 * rowsOf[b].size());
      m.reserve(sizes);
      for (std::size_t b = 0; b < rowsOf.size(); ++b)
      {
        std::sort(rowsOf[b].begin(), rowsOf[b].end());
        for (int j = 0; j < 3; ++j)
          for (int a : rowsOf[b])
            for (int i = 0; i < 3; ++i)
              m.insert(3 * a + i, static_cast<Eigen::Index>(3 * b) + j) = 0.0;
        std::vector<int>().swap(rowsOf[b]);
      }
      m.makeCompressed();
    };
    Eigen::SparseMatrix<double> matrix(3 * unknowns, 3 * unknowns);
    s.Coupling.resize(3 * unknowns, 3 * prescribed);
    withPattern(matrix, rowsOfUnknown);
    withPattern(s.Coupling, rowsOfPrescribed);
    for (std::size_t c = 0; c < Mesh.NumberOfCells(); ++c)
    {
      if (!touches(c))
        continue;
      std::int64_t node[10]; // -1 for corners (fixed), else the edge
      for (int k = 0; k < 4; ++k)
        node[k] = -1;
      for (int e = 0; e < 6; ++e)
        node[4 + e] = Mesh.CellEdges[c * 6 + e];
      // The straight net: corners and edge midpoints.
      Point3 net[10];
      const std::int64_t* v = Mesh.Linear.Cell(c);
      for (int k = 0; k < 4; ++k)
        net[k] = Mesh.Linear.Points[static_cast<std::size_t>(v[k])];
      for (int e = 0; e < 6; ++e)
        net[4 + e] = Scale(Add(net[kTetraEdges[e][0]], net[kTetraEdges[e][1]]), 0.5);
      for (const auto& t : kNetTetra)
      {
        const Point3 x[4] = { net[t[0]], net[t[1]], net[t[2]], net[t[3]] };
        Eigen::Matrix<double, 12, 12> k;
        if (!Stiffness(x, PoissonRatio, k))
          continue;
        for (int a = 0; a < 4; ++a)
        {
          const int ua = node[t[a]] < 0 ? -1 : s.Unknown[static_cast<std::size_t>(node[t[a]])];
          if (ua < 0)
            continue;
          for (int b = 0; b < 4; ++b)
          {
            const std::int64_t eb = node[t[b]];
            if (eb < 0)
              continue; // a corner: fixed, no displacement
            const auto edge = static_cast<std::size_t>(eb);
            const int ub = s.Unknown[edge];
            if (ub < 0 && Free[edge])
              continue; // a free edge that does not move: straight
            Eigen::SparseMatrix<double>& target = ub >= 0 ? matrix : s.Coupling;
            const int column = ub >= 0 ? ub : s.Prescribed[edge];
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j)
                if (ub < 0 || 3 * ua + i <= 3 * ub + j) // K_ff: its upper triangle only
                  target.coeffRef(3 * ua + i, 3 * column + j) += k(3 * a + i, 3 * b + j);
          }
        }
      }
    }
    s.Matrix = std::move(matrix);
    if (unknowns > 0)
    {
      s.Solver.setTolerance(kRelativeResidual);
      s.Solver.compute(s.Matrix);
      s.Ok = s.Solver.info() == Eigen::Success;
    }
  }
  System& s = *Factored;
  if (!s.Ok)
    return 0;
  // The prescribed control points' displacements from the straight net: 2 × (mid-node − midpoint).
  Eigen::VectorXd up = Eigen::VectorXd::Zero(s.Coupling.cols());
  for (std::size_t e = 0; e < edges; ++e)
    if (s.Prescribed[e] >= 0 && mesh.Curved(e))
      for (int j = 0; j < 3; ++j)
        up[3 * s.Prescribed[e] + j] = 2.0 * mesh.Scales[e] * mesh.Offset[e][j];
  Eigen::VectorXd guess(s.Matrix.rows());
  for (std::size_t e = 0; e < edges; ++e)
    if (s.Unknown[e] >= 0)
      for (int j = 0; j < 3; ++j)
        guess[3 * s.Unknown[e] + j] = Displacement[e][j];
  const Eigen::VectorXd u = s.Solver.solveWithGuess(-(s.Coupling * up), guess);
  std::size_t moved = 0;
  for (std::size_t e = 0; e < edges; ++e)
  {
    const int k = s.Unknown[e];
    if (k < 0)
      continue;
    const Point3 d{ u[3 * k], u[3 * k + 1], u[3 * k + 2] };
    if (!std::isfinite(d[0] + d[1] + d[2]))
      continue;
    Displacement[e] = d;
    if (Norm(d) < 1e-9)
      continue;
    mesh.Offset[e] = Scale(d, 0.5); // the mid-node moves half its control point's displacement
    mesh.Scales[e] = 1.0;
    ++moved;
  }
  return moved;
}

} // namespace labelmesher
