// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_widgets_MeshView_h
#define labelmesher_widgets_MeshView_h

/**
 * @file MeshView.h
 * A 3D view of a labelled mesh (the filters' output): the surface of its cells
 * coloured by the cell array Material, edges drawn, and a clipping plane
 * across one axis that shows whole cells (a crinkle cut, so the tetrahedra
 * inside are seen as they are, not sliced). Curved cells (vtkBezierCurver's
 * cubic Bezier triangles, vtkLabelMesher's quadratic tetrahedra) are drawn
 * subdivided, with their curved edges.
 */

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <QColor>
#include <QImage>
#include <QWidget>

#include <map>

class QCheckBox;
class QComboBox;
class QSlider;
class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkDataSetSurfaceFilter;
class vtkExtractGeometry;
class vtkGenericOpenGLRenderWindow;
class vtkLookupTable;
class vtkPlane;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkUnstructuredGrid;

namespace labelmesher
{
namespace widgets
{

class MeshView : public QWidget
{
  Q_OBJECT

public:
  explicit MeshView(QWidget* parent = nullptr);
  ~MeshView() override;

  /// Shows `mesh` (cell array Material); `colours` gives a material's colour, the others get
  /// a fixed palette. The camera is reset to the mesh.
  void setMesh(vtkUnstructuredGrid* mesh, const std::map<int, QColor>& colours = {});
  void clear();
  vtkUnstructuredGrid* mesh() const;
  /// The colour material `label` is drawn in (invalid when the shown mesh has no such material).
  QColor materialColour(int label) const;
  int numberOfMaterials() const; ///< in the shown mesh

  /// The clipping plane: off, or normal to `axis` (0, 1, 2) at `position` in [0, 1] of the
  /// mesh's extent; cells on the far side of the plane are hidden.
  void setClipping(bool on);
  void setClipAxis(int axis);
  void setClipPosition(double position);
  bool clipping() const;
  /// Cells drawn after clipping (all of them when the plane is off).
  vtkIdType shownCells();
  /// The shown mesh has curved (non-linear) cells, drawn with their curved edges.
  bool showsCurvedCells() const { return this->Curved; }
  /// Edges drawn over a curved mesh's cells, each a polyline once (0 for a linear mesh, whose
  /// edges the cells' surface shows).
  vtkIdType drawnEdges();

  /// The picture as it is on screen (renders first).
  QImage grabPicture();

signals:
  void clippingChanged();

private:
  void updateClipPlane();
  void updateCurvedEdges();
  void render();

  QVTKOpenGLNativeWidget* View = nullptr;
  QCheckBox* ClipBox = nullptr;
  QComboBox* AxisBox = nullptr;
  QSlider* PositionSlider = nullptr;

  vtkSmartPointer<vtkUnstructuredGrid> Mesh;
  vtkNew<vtkGenericOpenGLRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkPlane> Plane;
  vtkNew<vtkExtractGeometry> Clip;
  vtkNew<vtkDataSetSurfaceFilter> Surface;
  vtkNew<vtkPolyDataMapper> Mapper;
  vtkNew<vtkLookupTable> Colours;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkPolyDataMapper> EdgeMapper; ///< curved meshes: their cells' edges, sampled
  vtkNew<vtkActor> EdgeActor;
  bool Curved = false;
};

} // namespace widgets
} // namespace labelmesher

#endif
