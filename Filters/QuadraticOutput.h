// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_QuadraticOutput_h
#define labelmesher_QuadraticOutput_h

/**
 * @file QuadraticOutput.h
 * VTK plumbing of the quadratic 3D mesh (Quadratic/QuadraticCurver.h):
 * VTK_QUADRATIC_TETRA cells in physical space with cell data Material and
 * ScaledJacobian (certified), the curver's counts as field data, and, when
 * measured, the independent checks of Checks/QuadraticVolume.h.
 */

#include "LabelImageConversion.h"
#include "Quadratic/QuadraticCurver.h"

class vtkFieldData;
class vtkUnstructuredGrid;

namespace labelmesher
{

/// The cells of `result` (background ones only with includeBackground), their
/// corners and the mid-nodes of their edges.
void PackQuadraticMesh(
  const QuadraticResult& result, bool includeBackground, const ImagePlacement& placement, vtkUnstructuredGrid* output);

/// Order, MinimumScaledJacobianBound, CertifiedMinimumScaledJacobian, FittedEdges, CurvedEdges,
/// PulledBackEdges, CellsFailedScaledJacobian, FacesFailedDistance.
void AddQuadraticFields(vtkFieldData* fd, const QuadraticResult& result, double minimumScaledJacobian);

/// Measured, independently of the curver: both distances overall on the boundary faces flattened
/// at step 1/8 (MeasuredImageToMeshDistance, MeasuredMeshToImageDistance, CurvedMeasureResolution:
/// how far they may exceed the true ones), det J sampled on every curved cell
/// (SampledMinimumScaledJacobian), and Voxels, MisclassifiedVoxelsLinear and
/// MisclassifiedVoxelsQuadratic (the cells refined at step 1/4), over the whole box.
void AddQuadraticMeasurements(vtkFieldData* fd, const LabelImage& image, const QuadraticResult& result);

} // namespace labelmesher

#endif
