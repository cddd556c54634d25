// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_widgets_ParameterPanel_h
#define labelmesher_widgets_ParameterPanel_h

/**
 * @file ParameterPanel.h
 * A Qt5 panel for the parameters of vtkLabelMesher (mesher, decimator and
 * curver in one pipeline): the two distance bounds (shown in voxels of the smallest
 * spacing or in mm), the decimator's angle bound, whether to curve (2D images:
 * cubic Bezier or quadratic triangles, with the curver's smoothness and tension; 3D images:
 * quadratic tetrahedra from the decimated mesh), and presets. Every value is a Q_PROPERTY with a change signal; the
 * distance properties are always in voxels (the filters' unit), whatever the
 * display unit. Each control's tooltip states the guarantee it sets.
 */

#include <QString>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace labelmesher
{
namespace widgets
{

class ParameterPanel : public QWidget
{
  Q_OBJECT
  Q_PROPERTY(double imageToMeshDistance READ imageToMeshDistance WRITE setImageToMeshDistance NOTIFY imageToMeshDistanceChanged)
  Q_PROPERTY(double meshToImageDistance READ meshToImageDistance WRITE setMeshToImageDistance NOTIFY meshToImageDistanceChanged)
  Q_PROPERTY(DistanceUnit distanceUnit READ distanceUnit WRITE setDistanceUnit NOTIFY distanceUnitChanged)
  Q_PROPERTY(bool decimate READ decimate WRITE setDecimate NOTIFY decimateChanged)
  Q_PROPERTY(double minimumAngle READ minimumAngle WRITE setMinimumAngle NOTIFY minimumAngleChanged)
  Q_PROPERTY(int blockCells READ blockCells WRITE setBlockCells NOTIFY blockCellsChanged)
  Q_PROPERTY(double memoryLimit READ memoryLimit WRITE setMemoryLimit NOTIFY memoryLimitChanged)
  Q_PROPERTY(bool curve READ curve WRITE setCurve NOTIFY curveChanged)
  Q_PROPERTY(int smoothness READ smoothness WRITE setSmoothness NOTIFY smoothnessChanged)
  Q_PROPERTY(int sliceOrder READ sliceOrder WRITE setSliceOrder NOTIFY sliceOrderChanged)
  Q_PROPERTY(double tension READ tension WRITE setTension NOTIFY tensionChanged)
  Q_PROPERTY(Preset preset READ preset WRITE setPreset NOTIFY presetChanged)

public:
  enum class DistanceUnit { Voxels, Millimetres };
  Q_ENUM(DistanceUnit)
  /// Fast: coarse (3 voxels, 10 degrees); Balanced: the filters' defaults (2 voxels, 15 degrees);
  /// Faithful: close to the image (1 voxel, 20 degrees). Custom: any value changed by hand.
  enum class Preset { Fast, Balanced, Faithful, Custom };
  Q_ENUM(Preset)

  explicit ParameterPanel(QWidget* parent = nullptr);

  /// The image the panel will mesh: its dimension (2 or 3) sets the angle limit (45 or 30 degrees)
  /// and whether the curver's controls apply; its smallest spacing (mm) converts distances to mm.
  void setImageGeometry(int dimension, double smallestSpacing);
  int imageDimension() const { return this->Dimension; }
  double smallestSpacing() const { return this->SmallestSpacing; } ///< mm: one distance voxel

  double imageToMeshDistance() const { return this->ImageToMesh; } ///< voxels of the smallest spacing
  double meshToImageDistance() const { return this->MeshToImage; } ///< voxels of the smallest spacing
  DistanceUnit distanceUnit() const { return this->Unit; }
  bool decimate() const;
  double minimumAngle() const; ///< degrees
  /// Decimating: initial cells per block of the streamed mesher and decimator (vtkLabelMesher's
  /// BlockCells); 0: one block.
  int blockCells() const;
  /// MiB the process may hold at most; a run estimated above it is refused before it starts. 0: the
  /// memory available.
  double memoryLimit() const;
  /// Curve the mesh: a 2D image into cubic Bezier triangles (vtkBezierCurver) or quadratic
  /// triangles (sliceOrder 2), a 3D one into quadratic tetrahedra (vtkLabelMesher's Order 2);
  /// quadratic cells need decimation (false without it).
  bool curve() const;
  int smoothness() const;      ///< 1 (C1) or 2 (C2)
  /// A 2D image's curved cells: 3, cubic Bezier triangles; 2, quadratic (6-node) triangles.
  int sliceOrder() const;
  double tension() const;      ///< dimensionless, [0, 1]
  Preset preset() const { return this->CurrentPreset; }
  /// The largest angle bound allowed for the image dimension (degrees).
  double maximumAngle() const;


public slots:
  void setImageToMeshDistance(double voxels);
  void setMeshToImageDistance(double voxels);
  void setDistanceUnit(DistanceUnit unit);
  void setDecimate(bool on);
  void setMinimumAngle(double degrees);
  void setBlockCells(int cells);    ///< negative values are refused
  void setMemoryLimit(double mib);  ///< negative and non-finite values are refused
  void setCurve(bool on); ///< kept across images, and for a 3D image while decimation is off
  void setSmoothness(int continuity);
  void setSliceOrder(int order); ///< 2 or 3; other values are refused
  void setTension(double tension);
  void setPreset(Preset preset);

signals:
  void imageToMeshDistanceChanged(double voxels);
  void meshToImageDistanceChanged(double voxels);
  void distanceUnitChanged(DistanceUnit unit);
  void decimateChanged(bool on);
  void minimumAngleChanged(double degrees);
  void blockCellsChanged(int cells);
  void memoryLimitChanged(double mib);
  void curveChanged(bool on);
  void smoothnessChanged(int continuity);
  void sliceOrderChanged(int order);
  void tensionChanged(double tension);
  void presetChanged(Preset preset);
  /// Any value above changed.
  void parametersChanged();

private:
  double displayScale() const; ///< displayed value = voxels * displayScale()
  void showDistances();
  void onDistanceEdited();
  /// Stores `voxels` in `stored` and emits `changed` when it is a new valid distance.
  void setDistance(double& stored, double voxels, void (ParameterPanel::*changed)(double));
  void markCustom();
  void enableCurverControls();

  int Dimension = 3;
  double SmallestSpacing = 1.0;
  double ImageToMesh = 2.0, MeshToImage = 2.0;
  DistanceUnit Unit = DistanceUnit::Voxels;
  Preset CurrentPreset = Preset::Balanced;
  bool ApplyingPreset = false;

  QComboBox* PresetBox = nullptr;
  QComboBox* UnitBox = nullptr;
  QDoubleSpinBox* ImageToMeshBox = nullptr;
  QDoubleSpinBox* MeshToImageBox = nullptr;
  QCheckBox* DecimateBox = nullptr;
  QDoubleSpinBox* AngleBox = nullptr;
  QSpinBox* BlockCellsBox = nullptr;
  QDoubleSpinBox* MemoryLimitBox = nullptr;
  QCheckBox* CurveBox = nullptr;
  QComboBox* SmoothnessBox = nullptr;
  QComboBox* SliceOrderBox = nullptr;
  QDoubleSpinBox* TensionBox = nullptr;
};

} // namespace widgets
} // namespace labelmesher

#endif
