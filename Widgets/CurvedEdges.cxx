// SPDX-License-Identifier: GPL-2.0-or-later
#include "CurvedEdges.h"

#include "vtkCell.h"
#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <set>
#include <utility>

namespace labelmesher
{
namespace widgets
{
namespace
{
/// Control points of the three edges of a degree-3 VTK_BEZIER_TRIANGLE, from corner to corner
/// (Filters/Core/Curving/CubicTriangle.h: corners 0-2, then two points per edge 0-1, 1-2, 2-0).
constexpr int kCubicEdges[3][4] = { { 0, 3, 4, 1 }, { 1, 5, 6, 2 }, { 2, 7, 8, 0 } };

void AddCubicCurve(vtkPoints* input, const vtkIdType ids[4], int segments, vtkPoints* points, vtkCellArray* lines)
{
  double p[4][3];
  for (int k = 0; k < 4; ++k)
  {
    input->GetPoint(ids[k], p[k]);
  }
  lines->InsertNextCell(segments + 1);
  for (int s = 0; s <= segments; ++s)
  {
    const double t = static_cast<double>(s) / segments, u = 1.0 - t;
    const double b[4] = { u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t };
    double x[3];
    for (int a = 0; a < 3; ++a)
    {
      x[a] = b[0] * p[0][a] + b[1] * p[1][a] + b[2] * p[2][a] + b[3] * p[3][a];
    }
    lines->InsertCellPoint(points->InsertNextPoint(x));
  }
}
/// A quadratic edge (VTK_QUADRATIC_EDGE: ends 0 and 1, mid-node 2) sampled along its parabola.
void AddQuadraticCurve(vtkPoints* input, const vtkIdType ids[3], int segments, vtkPoints* points, vtkCellArray* lines)
{
  double p[3][3];
  for (int k = 0; k < 3; ++k)
  {
    input->GetPoint(ids[k], p[k]);
  }
  lines->InsertNextCell(segments + 1);
  for (int s = 0; s <= segments; ++s)
  {
    const double t = static_cast<double>(s) / segments;
    const double b[3] = { (1.0 - t) * (1.0 - 2.0 * t), t * (2.0 * t - 1.0), 4.0 * t * (1.0 - t) };
    double x[3];
    for (int a = 0; a < 3; ++a)
    {
      x[a] = b[0] * p[0][a] + b[1] * p[1][a] + b[2] * p[2][a];
    }
    lines->InsertCellPoint(points->InsertNextPoint(x));
  }
}
} // namespace

vtkSmartPointer<vtkPolyData> CurvedCellEdges(vtkUnstructuredGrid* mesh, int segments)
{
  segments = std::max(1, segments);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  std::set<std::pair<vtkIdType, vtkIdType>> drawn; // corner pairs: a shared edge is drawn once
  auto firstTime = [&drawn](vtkIdType a, vtkIdType b) { return drawn.insert(std::minmax(a, b)).second; };
  vtkNew<vtkIdList> cellPoints;
  for (vtkIdType c = 0; mesh && c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, cellPoints);
    if (mesh->GetCellType(c) == VTK_BEZIER_TRIANGLE && cellPoints->GetNumberOfIds() == 10)
    {
      for (const auto& edge : kCubicEdges)
      {
        const vtkIdType ids[4] = { cellPoints->GetId(edge[0]), cellPoints->GetId(edge[1]),
          cellPoints->GetId(edge[2]), cellPoints->GetId(edge[3]) };
        if (firstTime(ids[0], ids[3]))
        {
          AddCubicCurve(mesh->GetPoints(), ids, segments, points, lines);
        }
      }
      continue;
    }
    vtkCell* cell = mesh->GetCell(c);
    for (int e = 0; e < cell->GetNumberOfEdges(); ++e)
    {
      vtkCell* edge = cell->GetEdge(e);
      vtkIdList* ends = edge->GetPointIds();
      if (edge->GetCellType() == VTK_QUADRATIC_EDGE && ends->GetNumberOfIds() == 3)
      {
        const vtkIdType ids[3] = { ends->GetId(0), ends->GetId(1), ends->GetId(2) };
        if (firstTime(ids[0], ids[1]))
        {
          AddQuadraticCurve(mesh->GetPoints(), ids, segments, points, lines);
        }
        continue;
      }
      if (firstTime(ends->GetId(0), ends->GetId(1)))
      {
        lines->InsertNextCell(2);
        lines->InsertCellPoint(points->InsertNextPoint(mesh->GetPoint(ends->GetId(0))));
        lines->InsertCellPoint(points->InsertNextPoint(mesh->GetPoint(ends->GetId(1))));
      }
    }
  }
  auto edges = vtkSmartPointer<vtkPolyData>::New();
  edges->SetPoints(points);
  edges->SetLines(lines);
  return edges;
}

bool HasCurvedCells(vtkUnstructuredGrid* mesh)
{
  for (vtkIdType c = 0; mesh && c < mesh->GetNumberOfCells(); ++c)
  {
    if (!vtkCellTypes::IsLinear(mesh->GetCellType(c)))
    {
      return true;
    }
  }
  return false;
}

} // namespace widgets
} // namespace labelmesher
