// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_widgets_CurvedEdges_h
#define labelmesher_widgets_CurvedEdges_h

/**
 * @file CurvedEdges.h
 * The edges of a curved mesh's cells as polylines, for MeshView to draw over
 * the cells: the surface filter subdivides each curved cell (cubic Bezier
 * triangle, quadratic tetrahedron) into flat pieces, whose own edges would
 * hide the cells' (curved) ones.
 */

#include "vtkSmartPointer.h"

class vtkPolyData;
class vtkUnstructuredGrid;

namespace labelmesher
{
namespace widgets
{

/// Each edge of `mesh`'s cells once: a cubic Bezier triangle's (VTK_BEZIER_TRIANGLE, 10 points)
/// or a quadratic cell's (VTK_QUADRATIC_EDGE edges, e.g. VTK_QUADRATIC_TETRA) sampled at
/// `segments` + 1 points along its curve, any other cell's edges straight.
vtkSmartPointer<vtkPolyData> CurvedCellEdges(vtkUnstructuredGrid* mesh, int segments);

/// True when `mesh` holds a cell that is not linear (VTK's IsLinear).
bool HasCurvedCells(vtkUnstructuredGrid* mesh);

} // namespace widgets
} // namespace labelmesher

#endif
