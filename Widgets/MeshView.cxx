// SPDX-License-Identifier: GPL-2.0-or-later
#include "MeshView.h"

#include "CurvedEdges.h"

#include "LabelMesherArrayNames.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkExtractGeometry.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkLookupTable.h"
#include "vtkPlane.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVariant.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <array>
#include <set>

namespace labelmesher
{
namespace widgets
{
namespace
{
constexpr int kSliderSteps = 1000;

/// Colours for materials the caller gives none (Paul Tol's "bright" and "muted" sets: told
/// apart by colour-blind readers too).
constexpr std::array<std::array<int, 3>, 14> kPalette{ { { 68, 119, 170 }, { 238, 102, 119 },
  { 34, 136, 51 }, { 204, 187, 68 }, { 102, 204, 238 }, { 170, 51, 119 }, { 187, 187, 187 },
  { 51, 34, 136 }, { 17, 119, 51 }, { 68, 170, 153 }, { 136, 204, 238 }, { 221, 204, 119 },
  { 204, 102, 119 }, { 136, 34, 85 } } };

/// The palette's colours first, then hues a golden angle apart: every material its own colour.
QColor PaletteColour(vtkIdType index)
{
  if (index < static_cast<vtkIdType>(kPalette.size()))
  {
    const auto& c = kPalette[static_cast<std::size_t>(index)];
    return QColor(c[0], c[1], c[2]);
  }
  const double hue = std::fmod(0.1 + 0.6180339887498949 * static_cast<double>(index), 1.0);
  return QColor::fromHsvF(hue, 0.55, 0.85);
}

/// The axis along which the bounds have no extent (a flat 2D mesh), or -1.
int FlatAxis(const double bounds[6])
{
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) + (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  for (int a = 0; a < 3; ++a)
  {
    if (bounds[2 * a + 1] - bounds[2 * a] <= 1e-9 * diagonal)
    {
      return a;
    }
  }
  return -1;
}
} // namespace

MeshView::MeshView(QWidget* parent)
  : QWidget(parent)
{
  this->View = new QVTKOpenGLNativeWidget(this);
  this->View->setRenderWindow(this->Window);
  this->Window->AddRenderer(this->Renderer);
  this->Renderer->SetBackground(1.0, 1.0, 1.0);
  this->Renderer->GradientBackgroundOff();

  // Whole cells on the near side of the plane (crinkle cut): the mesh's own elements stay visible.
  this->Clip->SetImplicitFunction(this->Plane);
  this->Clip->ExtractInsideOn();
  this->Clip->ExtractBoundaryCellsOn();
  this->Surface->SetInputConnection(this->Clip->GetOutputPort());
  this->Mapper->SetInputConnection(this->Surface->GetOutputPort());
  this->Mapper->SetScalarModeToUseCellFieldData();
  this->Mapper->SelectColorArray(labelmesher::arrays::Material);
  this->Mapper->SetColorModeToMapScalars();
  this->Mapper->SetLookupTable(this->Colours);
  this->Mapper->UseLookupTableScalarRangeOn();
  this->Colours->IndexedLookupOn();
  this->Actor->SetMapper(this->Mapper);
  this->Actor->GetProperty()->EdgeVisibilityOn();
  this->Actor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);
  this->Actor->SetVisibility(false);
  this->Renderer->AddActor(this->Actor);
  this->EdgeActor->SetMapper(this->EdgeMapper);
  this->EdgeMapper->ScalarVisibilityOff();
  this->EdgeActor->GetProperty()->SetColor(0.15, 0.15, 0.15);
  this->EdgeActor->SetVisibility(false);
  this->Renderer->AddActor(this->EdgeActor);

  this->ClipBox = new QCheckBox(tr("Clip"), this);
  this->ClipBox->setObjectName("clip");
  this->ClipBox->setToolTip(tr("Hide the cells beyond a plane to see inside the mesh (whole cells are shown)."));
  this->AxisBox = new QComboBox(this);
  this->AxisBox->setObjectName("clipAxis");
  this->AxisBox->addItems({ "x", "y", "z" });
  this->AxisBox->setToolTip(tr("The axis the clipping plane is normal to."));
  this->PositionSlider = new QSlider(Qt::Horizontal, this);
  this->PositionSlider->setObjectName("clipPosition");
  this->PositionSlider->setRange(0, kSliderSteps);
  this->PositionSlider->setValue(kSliderSteps / 2);
  this->PositionSlider->setToolTip(tr("Where the plane lies across the mesh's extent."));
  connect(this->ClipBox, &QCheckBox::toggled, this, &MeshView::setClipping);
  connect(this->AxisBox, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &MeshView::setClipAxis);
  connect(this->PositionSlider, &QSlider::valueChanged, this,
    [this](int value) { this->setClipPosition(static_cast<double>(value) / kSliderSteps); });

  auto* controls = new QHBoxLayout;
  controls->addWidget(this->ClipBox);
  controls->addWidget(new QLabel(tr("normal to"), this));
  controls->addWidget(this->AxisBox);
  controls->addWidget(this->PositionSlider, 1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(this->View, 1);
  layout->addLayout(controls);
  this->setClipping(false);
}

MeshView::~MeshView() = default;

void MeshView::setMesh(vtkUnstructuredGrid* mesh, const std::map<int, QColor>& colours)
{
  this->Mesh = mesh;
  if (!mesh)
  {
    this->clear();
    return;
  }
  // One table entry per material present, in label order (indexed lookup: labels need not be dense).
  std::set<int> labels;
  if (vtkDataArray* material = mesh->GetCellData()->GetArray(labelmesher::arrays::Material))
  {
    for (vtkIdType c = 0; c < material->GetNumberOfTuples(); ++c)
    {
      labels.insert(static_cast<int>(material->GetComponent(c, 0)));
    }
  }
  this->Colours->ResetAnnotations();
  this->Colours->SetNumberOfTableValues(std::max<vtkIdType>(1, static_cast<vtkIdType>(labels.size())));
  vtkIdType index = 0;
  for (int label : labels)
  {
    const auto given = colours.find(label);
    const QColor colour = given != colours.end() && given->second.isValid() ? given->second : PaletteColour(index);
    this->Colours->SetTableValue(index, colour.redF(), colour.greenF(), colour.blueF(), 1.0);
    this->Colours->SetAnnotation(vtkVariant(label), QString::number(label).toStdString());
    ++index;
  }
  this->Colours->Build();
  // A cubic cell subdivided twice (36 flat pieces) looks smooth at any zoom a cell fills; the
  // pieces' own edges are not drawn, the cells' curved edges are (updateCurvedEdges).
  this->Curved = HasCurvedCells(mesh);
  this->Surface->SetNonlinearSubdivisionLevel(this->Curved ? 2 : 1);
  this->Actor->GetProperty()->SetEdgeVisibility(!this->Curved);
  this->Clip->SetInputData(mesh);
  this->updateClipPlane();
  this->Actor->SetVisibility(true);
  this->EdgeActor->SetVisibility(this->Curved);
  // A 3D mesh: an oblique view from the front, so it reads as a solid. A flat (2D) mesh: face-on,
  // along its flat axis, which need not be z (a sagittal or coronal slice).
  double bounds[6];
  mesh->GetBounds(bounds);
  const int flat = FlatAxis(bounds);
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  double position[3] = { 0, 0, 0 }, up[3] = { 0, 0, 0 };
  position[flat < 0 ? 2 : flat] = 1.0;
  up[flat == 1 ? 2 : 1] = 1.0;
  camera->SetPosition(position);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(up);
  if (flat < 0)
  {
    camera->Azimuth(25);
    camera->Elevation(20);
  }
  this->Renderer->ResetCamera(mesh->GetBounds());
  this->render();
}

vtkUnstructuredGrid* MeshView::mesh() const
{
  return this->Mesh;
}

void MeshView::clear()
{
  this->Mesh = nullptr;
  this->Curved = false;
  this->Clip->RemoveAllInputs();
  this->Actor->SetVisibility(false);
  this->EdgeActor->SetVisibility(false);
  this->render();
}

void MeshView::setClipping(bool on)
{
  if (this->ClipBox->isChecked() != on)
  {
    this->ClipBox->setChecked(on); // comes back here through toggled()
    return;
  }
  this->AxisBox->setEnabled(on);
  this->PositionSlider->setEnabled(on);
  this->updateClipPlane();
  this->render();
  emit clippingChanged();
}

void MeshView::setClipAxis(int axis)
{
  axis = std::clamp(axis, 0, 2);
  if (this->AxisBox->currentIndex() != axis)
  {
    this->AxisBox->setCurrentIndex(axis);
    return;
  }
  this->updateClipPlane();
  this->render();
  emit clippingChanged();
}

void MeshView::setClipPosition(double position)
{
  const int value = static_cast<int>(std::clamp(position, 0.0, 1.0) * kSliderSteps + 0.5);
  if (this->PositionSlider->value() != value)
  {
    this->PositionSlider->setValue(value);
    return;
  }
  this->updateClipPlane();
  this->render();
  emit clippingChanged();
}

QColor MeshView::materialColour(int label) const
{
  const vtkIdType index = this->Colours->GetAnnotatedValueIndex(vtkVariant(label));
  if (!this->Mesh || index < 0)
  {
    return {};
  }
  double rgba[4];
  this->Colours->GetTableValue(index, rgba);
  return QColor::fromRgbF(rgba[0], rgba[1], rgba[2]);
}

int MeshView::numberOfMaterials() const
{
  return this->Mesh ? static_cast<int>(this->Colours->GetNumberOfAnnotatedValues()) : 0;
}

bool MeshView::clipping() const
{
  return this->ClipBox->isChecked();
}

void MeshView::updateClipPlane()
{
  double bounds[6] = { 0, 1, 0, 1, 0, 1 };
  if (this->Mesh)
  {
    this->Mesh->GetBounds(bounds);
  }
  const int axis = this->AxisBox->currentIndex();
  double origin[3] = { bounds[0], bounds[2], bounds[4] };
  double normal[3] = { 0, 0, 0 };
  normal[axis] = 1.0;
  // Across the flat axis of a 2D mesh every point lies on the plane: nothing to clip.
  if (this->clipping() && axis != FlatAxis(bounds))
  {
    const double t = static_cast<double>(this->PositionSlider->value()) / kSliderSteps;
    origin[axis] = bounds[2 * axis] + t * (bounds[2 * axis + 1] - bounds[2 * axis]);
  }
  else
  {
    // Off: a plane beyond the far side keeps every cell.
    origin[axis] = bounds[2 * axis + 1] + 1.0 + std::abs(bounds[2 * axis + 1]);
  }
  this->Plane->SetOrigin(origin);
  this->Plane->SetNormal(normal);
  this->updateCurvedEdges();
}

void MeshView::updateCurvedEdges()
{
  if (!this->Mesh || !this->Curved)
  {
    return;
  }
  constexpr int kSegmentsPerEdge = 12;
  this->Clip->Update();
  this->EdgeMapper->SetInputData(CurvedCellEdges(this->Clip->GetOutput(), kSegmentsPerEdge));
}

vtkIdType MeshView::drawnEdges()
{
  if (!this->Mesh || !this->Curved)
  {
    return 0;
  }
  auto* edges = vtkPolyData::SafeDownCast(this->EdgeMapper->GetInput());
  return edges ? edges->GetNumberOfLines() : 0;
}

vtkIdType MeshView::shownCells()
{
  if (!this->Mesh)
  {
    return 0;
  }
  this->Clip->Update();
  return this->Clip->GetOutput()->GetNumberOfCells();
}

QImage MeshView::grabPicture()
{
  this->render();
  return this->View->grabFramebuffer();
}

void MeshView::render()
{
  this->View->renderWindow()->Render();
  this->View->update();
}

} // namespace widgets
} // namespace labelmesher
