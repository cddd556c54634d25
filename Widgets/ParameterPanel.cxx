// SPDX-License-Identifier: GPL-2.0-or-later
#include "ParameterPanel.h"

#include "vtkLabelMesher.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QSpinBox>

#include <cmath>
#include <limits>

namespace labelmesher
{
namespace widgets
{
namespace
{
// The filters accept up to 64 voxels (vtkLabelOctreeMesher's documented range in the plugin).
constexpr double kMaximumDistance = 64.0;

struct PresetValues
{
  double Distance, Angle;
};

PresetValues ValuesOf(ParameterPanel::Preset preset)
{
  switch (preset)
  {
    case ParameterPanel::Preset::Fast:
      return { 3.0, 10.0 };
    case ParameterPanel::Preset::Faithful:
      return { 1.0, 20.0 };
    default:
      return { 2.0, 15.0 };
  }
}
} // namespace

ParameterPanel::ParameterPanel(QWidget* parent)
  : QWidget(parent)
{
  // Queued connections and QSignalSpy need the enums as meta types.
  qRegisterMetaType<Preset>();
  qRegisterMetaType<DistanceUnit>();
  auto* form = new QFormLayout(this);

  this->PresetBox = new QComboBox(this);
  this->PresetBox->setObjectName(QStringLiteral("preset"));
  this->PresetBox->addItems({ tr("Fast"), tr("Balanced"), tr("Faithful"), tr("Custom") });
  this->PresetBox->setToolTip(tr("Fast: 3 voxels, 10 degrees (few cells, quick). Balanced: 2 voxels, "
                                 "15 degrees (the filters' defaults). Faithful: 1 voxel, 20 degrees "
                                 "(close to the image, more cells). Custom: values set by hand."));
  form->addRow(tr("Preset"), this->PresetBox);

  this->UnitBox = new QComboBox(this);
  this->UnitBox->setObjectName(QStringLiteral("distanceUnit"));
  this->UnitBox->addItems({ tr("voxels"), tr("mm") });
  this->UnitBox->setToolTip(tr("Unit of the distances shown: voxels of the image's smallest spacing "
                               "(the filters' unit) or millimetres."));
  form->addRow(tr("Distance unit"), this->UnitBox);

  auto makeDistance = [this](const QString& tip) {
    auto* box = new QDoubleSpinBox(this);
    box->setDecimals(3);
    box->setToolTip(tip);
    return box;
  };
  this->ImageToMeshBox = makeDistance(
    tr("Image to mesh distance h(I,M). Guarantee: every labelled voxel centre lies within this distance "
       "of the mesh's cells of its label (one side of a two-sided Hausdorff bound, certified by an "
       "exact test). 0 to 64 voxels of the smallest spacing."));
  this->MeshToImageBox = makeDistance(
    tr("Mesh to image distance h(M,I). Guarantee: every point of a material's cells lies within this "
       "distance of a voxel of that label. 0 to 64 voxels of the smallest spacing."));
  this->ImageToMeshBox->setObjectName(QStringLiteral("imageToMeshDistance"));
  this->MeshToImageBox->setObjectName(QStringLiteral("meshToImageDistance"));
  form->addRow(tr("Image to mesh"), this->ImageToMeshBox);
  form->addRow(tr("Mesh to image"), this->MeshToImageBox);

  this->DecimateBox = new QCheckBox(tr("Decimate"), this);
  this->DecimateBox->setObjectName(QStringLiteral("decimate"));
  this->DecimateBox->setChecked(true);
  this->DecimateBox->setToolTip(tr("Merge vertices for few cells. Guarantee: the angle bound below, both "
                                   "distance bounds and every material's topology are kept."));
  form->addRow(QString(), this->DecimateBox);

  this->AngleBox = new QDoubleSpinBox(this);
  this->AngleBox->setObjectName(QStringLiteral("minimumAngle"));
  this->AngleBox->setDecimals(1);
  this->AngleBox->setRange(1.0, this->maximumAngle());
  this->AngleBox->setSuffix(QStringLiteral(" °"));
  this->AngleBox->setToolTip(tr("Guarantee after decimation: every dihedral angle (3D) or planar angle "
                                "(2D) is at least this, in degrees; at most %1 in 3D and %2 in 2D. "
                                "Without decimation the proven bounds are %1 (3D) and %2 (2D) degrees.")
                               .arg(vtkLabelMesher::GetProvenAngleBound(3))
                               .arg(vtkLabelMesher::GetProvenAngleBound(2)));
  form->addRow(tr("Minimum angle"), this->AngleBox);

  this->BlockCellsBox = new QSpinBox(this);
  this->BlockCellsBox->setObjectName(QStringLiteral("blockCells"));
  this->BlockCellsBox->setRange(0, std::numeric_limits<int>::max());
  this->BlockCellsBox->setSingleStep(100000);
  this->BlockCellsBox->setValue(1000000);
  this->BlockCellsBox->setSuffix(tr(" cells"));
  this->BlockCellsBox->setSpecialValueText(tr("one block"));
  this->BlockCellsBox->setToolTip(tr("Decimating: mesher and decimator run block by block, each block of "
                                     "about this many initial cells, so that memory follows one block and "
                                     "the output, not the whole initial mesh. 0: one block. The mesh "
                                     "depends on it a little, never on the thread count."));
  form->addRow(tr("Block size"), this->BlockCellsBox);

  this->MemoryLimitBox = new QDoubleSpinBox(this);
  this->MemoryLimitBox->setObjectName(QStringLiteral("memoryLimit"));
  this->MemoryLimitBox->setDecimals(0);
  this->MemoryLimitBox->setRange(0.0, 1.0e7);
  this->MemoryLimitBox->setSingleStep(1024.0);
  this->MemoryLimitBox->setSuffix(tr(" MiB"));
  this->MemoryLimitBox->setSpecialValueText(tr("available memory"));
  this->MemoryLimitBox->setToolTip(tr("The most memory the viewer may hold while meshing, in MiB: a run "
                                      "estimated above it is refused before it starts, with the estimate "
                                      "named. 0: the memory available."));
  form->addRow(tr("Memory limit"), this->MemoryLimitBox);

  this->CurveBox = new QCheckBox(tr("Curve"), this);
  this->CurveBox->setObjectName(QStringLiteral("curve"));
  this->CurveBox->setToolTip(tr("2D images: turn the mesh into cubic Bezier triangles whose interfaces "
                                "follow the image smoothly. Guarantee: every curved cell valid (Bernstein "
                                "bound of its Jacobian), both distance bounds, no crossing interfaces, "
                                "the topology kept. Saved as .vtu, .vtk or .msh only.\n"
                                "3D images (decimated): quadratic tetrahedra whose interfaces are fitted to "
                                "the image. Guarantee: every cell's scaled Jacobian at least 0.1 (Bernstein "
                                "bound of det J), both distance bounds on the curved interfaces, the "
                                "topology kept. Saved as .vtu, .vtk, .msh, .inp or .mesh."));
  form->addRow(QString(), this->CurveBox);

  this->SmoothnessBox = new QComboBox(this);
  this->SmoothnessBox->setObjectName(QStringLiteral("smoothness"));
  this->SmoothnessBox->addItems({ tr("C1 (tangents continuous)"), tr("C2 (curvature continuous)") });
  this->SmoothnessBox->setToolTip(tr("2D curved meshes: continuity of the interface curves where they "
                                     "meet. Guarantee either way: every curved cell valid (Bernstein "
                                     "bound of its Jacobian), both distance bounds, no crossing."));
  form->addRow(tr("Smoothness"), this->SmoothnessBox);

  this->SliceOrderBox = new QComboBox(this);
  this->SliceOrderBox->setObjectName(QStringLiteral("sliceOrder"));
  this->SliceOrderBox->addItems({ tr("cubic Bezier triangles"), tr("quadratic triangles (6 nodes)") });
  this->SliceOrderBox->setToolTip(tr("2D curved meshes: the order of the curved cells. Quadratic "
                                     "triangles (as solvers take them: Abaqus CPS6, Gmsh's 6-node "
                                     "triangle; saved also as .inp or .mesh) have one control point per "
                                     "edge, fitted to the image, and the same guarantees; they need "
                                     "decimation."));
  form->addRow(tr("Curved cells"), this->SliceOrderBox);

  this->TensionBox = new QDoubleSpinBox(this);
  this->TensionBox->setObjectName(QStringLiteral("tension"));
  this->TensionBox->setDecimals(3);
  this->TensionBox->setRange(0.0, 1.0);
  this->TensionBox->setSingleStep(0.05);
  this->TensionBox->setValue(1.0 / 3.0);
  this->TensionBox->setToolTip(tr("2D curved meshes: handle length of the Bezier curves, dimensionless "
                                  "in [0, 1]; 1/3 gives the Catmull-Rom spline, 0 straight edges."));
  form->addRow(tr("Tension"), this->TensionBox);

  connect(this->PresetBox, QOverload<int>::of(&QComboBox::activated), this,
    [this](int index) { this->setPreset(static_cast<Preset>(index)); });
  connect(this->UnitBox, QOverload<int>::of(&QComboBox::activated), this,
    [this](int index) { this->setDistanceUnit(static_cast<DistanceUnit>(index)); });
  for (QDoubleSpinBox* box : { this->ImageToMeshBox, this->MeshToImageBox })
  {
    connect(box, &QDoubleSpinBox::editingFinished, this, &ParameterPanel::onDistanceEdited);
  }
  connect(this->DecimateBox, &QCheckBox::toggled, this, [this](bool on) {
    this->AngleBox->setEnabled(on);
    this->BlockCellsBox->setEnabled(on);
    this->enableCurverControls(); // a 3D image is curved from its decimated mesh only
    emit decimateChanged(on);
    emit parametersChanged();
  });
  connect(this->AngleBox, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double degrees) {
    this->markCustom();
    emit minimumAngleChanged(degrees);
    emit parametersChanged();
  });
  connect(this->BlockCellsBox, QOverload<int>::of(&QSpinBox::valueChanged), this, [this](int cells) {
    emit blockCellsChanged(cells);
    emit parametersChanged();
  });
  connect(this->MemoryLimitBox, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double mib) {
    emit memoryLimitChanged(mib);
    emit parametersChanged();
  });
  connect(this->CurveBox, &QCheckBox::toggled, this, [this](bool on) {
    this->enableCurverControls();
    emit curveChanged(on);
    emit parametersChanged();
  });
  connect(this->SmoothnessBox, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int index) {
    emit smoothnessChanged(index + 1);
    emit parametersChanged();
  });
  connect(this->SliceOrderBox, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int index) {
    emit sliceOrderChanged(index == 0 ? 3 : 2);
    emit parametersChanged();
  });
  connect(this->TensionBox, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double t) {
    emit tensionChanged(t);
    emit parametersChanged();
  });

  this->setImageGeometry(3, 1.0);
  this->setPreset(Preset::Balanced);
}

void ParameterPanel::setImageGeometry(int dimension, double smallestSpacing)
{
  this->Dimension = dimension == 2 ? 2 : 3;
  this->SmallestSpacing = std::isfinite(smallestSpacing) && smallestSpacing > 0.0 ? smallestSpacing : 1.0;
  this->AngleBox->setMaximum(this->maximumAngle()); // clamps (and signals) a 2D bound above 30 in 3D
  this->enableCurverControls();
  this->showDistances();
}

void ParameterPanel::enableCurverControls()
{
  this->CurveBox->setEnabled(this->Dimension == 2 || this->decimate());
  // Smoothness and tension shape the 2D curver's cubic curves; quadratic tetrahedra have neither.
  this->SmoothnessBox->setEnabled(this->Dimension == 2 && this->curve());
  this->TensionBox->setEnabled(this->Dimension == 2 && this->curve());
  this->SliceOrderBox->setEnabled(this->Dimension == 2 && this->CurveBox->isChecked());
}

double ParameterPanel::displayScale() const
{
  return this->Unit == DistanceUnit::Millimetres ? this->SmallestSpacing : 1.0;
}

void ParameterPanel::showDistances()
{
  const double scale = this->displayScale();
  const QString suffix = this->Unit == DistanceUnit::Millimetres ? tr(" mm") : tr(" voxels");
  for (QDoubleSpinBox* box : { this->ImageToMeshBox, this->MeshToImageBox })
  {
    const QSignalBlocker blocker(box);
    box->setRange(0.0, kMaximumDistance * scale);
    box->setSingleStep(0.5 * scale);
    box->setSuffix(suffix);
  }
  const QSignalBlocker b1(this->ImageToMeshBox), b2(this->MeshToImageBox);
  this->ImageToMeshBox->setValue(this->ImageToMesh * scale);
  this->MeshToImageBox->setValue(this->MeshToImage * scale);
}

void ParameterPanel::onDistanceEdited()
{
  // Read both boxes first: each setter redraws both from the stored values.
  const double scale = this->displayScale();
  const double imageToMesh = this->ImageToMeshBox->value() / scale;
  const double meshToImage = this->MeshToImageBox->value() / scale;
  this->setImageToMeshDistance(imageToMesh);
  this->setMeshToImageDistance(meshToImage);
}

void ParameterPanel::markCustom()
{
  if (!this->ApplyingPreset && this->CurrentPreset != Preset::Custom)
  {
    this->CurrentPreset = Preset::Custom;
    this->PresetBox->setCurrentIndex(static_cast<int>(Preset::Custom));
    emit presetChanged(Preset::Custom);
  }
}

void ParameterPanel::setImageToMeshDistance(double voxels)
{
  this->setDistance(this->ImageToMesh, voxels, &ParameterPanel::imageToMeshDistanceChanged);
}

void ParameterPanel::setMeshToImageDistance(double voxels)
{
  this->setDistance(this->MeshToImage, voxels, &ParameterPanel::meshToImageDistanceChanged);
}

void ParameterPanel::setDistance(double& stored, double voxels, void (ParameterPanel::*changed)(double))
{
  // Only finite values within the filters' range are taken; anything else keeps the old value.
  if (!std::isfinite(voxels) || voxels < 0.0 || voxels > kMaximumDistance || voxels == stored)
  {
    this->showDistances();
    return;
  }
  stored = voxels;
  this->showDistances();
  this->markCustom();
  emit(this->*changed)(voxels);
  emit parametersChanged();
}

void ParameterPanel::setDistanceUnit(DistanceUnit unit)
{
  if (unit == this->Unit)
    return;
  this->Unit = unit;
  this->UnitBox->setCurrentIndex(static_cast<int>(unit));
  this->showDistances();
  emit distanceUnitChanged(unit);
}

bool ParameterPanel::decimate() const
{
  return this->DecimateBox->isChecked();
}

void ParameterPanel::setDecimate(bool on)
{
  this->DecimateBox->setChecked(on);
}

double ParameterPanel::minimumAngle() const
{
  return this->AngleBox->value();
}

void ParameterPanel::setMinimumAngle(double degrees)
{
  if (std::isfinite(degrees))
    this->AngleBox->setValue(degrees); // clamped to [1, maximumAngle()]
}

bool ParameterPanel::curve() const
{
  // Quadratic cells are made of the decimated mesh; a slice's cubic ones of either.
  return this->CurveBox->isChecked() && ((this->Dimension == 2 && this->sliceOrder() == 3) || this->decimate());
}

int ParameterPanel::sliceOrder() const
{
  return this->SliceOrderBox->currentIndex() == 0 ? 3 : 2;
}

void ParameterPanel::setSliceOrder(int order)
{
  if (order == 2 || order == 3)
    this->SliceOrderBox->setCurrentIndex(order == 3 ? 0 : 1);
}

void ParameterPanel::setCurve(bool on)
{
  this->CurveBox->setChecked(on);
}

int ParameterPanel::smoothness() const
{
  return this->SmoothnessBox->currentIndex() + 1;
}

void ParameterPanel::setSmoothness(int continuity)
{
  if (continuity == 1 || continuity == 2)
    this->SmoothnessBox->setCurrentIndex(continuity - 1);
}

int ParameterPanel::blockCells() const
{
  return this->BlockCellsBox->value();
}

void ParameterPanel::setBlockCells(int cells)
{
  if (cells >= 0)
    this->BlockCellsBox->setValue(cells);
}

double ParameterPanel::memoryLimit() const
{
  return this->MemoryLimitBox->value();
}

void ParameterPanel::setMemoryLimit(double mib)
{
  if (std::isfinite(mib) && mib >= 0.0)
    this->MemoryLimitBox->setValue(mib); // clamped to 10^7 MiB
}

double ParameterPanel::tension() const
{
  return this->TensionBox->value();
}

void ParameterPanel::setTension(double tension)
{
  if (std::isfinite(tension))
    this->TensionBox->setValue(tension); // clamped to [0, 1]
}

void ParameterPanel::setPreset(Preset preset)
{
  if (preset != Preset::Custom)
  {
    const PresetValues values = ValuesOf(preset);
    this->ApplyingPreset = true;
    this->setImageToMeshDistance(values.Distance);
    this->setMeshToImageDistance(values.Distance);
    this->setMinimumAngle(std::min(values.Angle, this->maximumAngle()));
    this->ApplyingPreset = false;
  }
  this->PresetBox->setCurrentIndex(static_cast<int>(preset));
  if (preset != this->CurrentPreset)
  {
    this->CurrentPreset = preset;
    emit presetChanged(preset);
  }
}

double ParameterPanel::maximumAngle() const
{
  return vtkLabelMesher::GetProvenAngleBound(this->Dimension);
}

} // namespace widgets
} // namespace labelmesher
