// SPDX-License-Identifier: GPL-2.0-or-later
// QtTest of the parameter panel (Widgets/ParameterPanel), headless (QT_QPA_PLATFORM=offscreen):
// presets, the voxel/mm display, refused input, the 2D/3D angle limit, signals, tooltips, and the
// values reaching the filters.
#include "ParameterPanel.h"

#include "vtkNew.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QSpinBox>
#include <QtTest>

#include <limits>

using labelmesher::widgets::ParameterPanel;

class TestParameterPanel : public QObject
{
  Q_OBJECT

  template <typename T>
  static T* child(ParameterPanel& panel, const char* name)
  {
    T* widget = panel.findChild<T*>(QString::fromLatin1(name));
    if (!widget)
      qFatal("no child widget %s", name);
    return widget;
  }

private slots:
  void defaultsAreTheFiltersDefaults()
  {
    ParameterPanel panel;
    QCOMPARE(panel.preset(), ParameterPanel::Preset::Balanced);
    QCOMPARE(panel.imageToMeshDistance(), 2.0);
    QCOMPARE(panel.meshToImageDistance(), 2.0);
    QCOMPARE(panel.minimumAngle(), 15.0);
    QVERIFY(panel.decimate());
    QVERIFY(!panel.curve()); // curving is asked for, not a default
    QCOMPARE(panel.smoothness(), 1);
    QCOMPARE(panel.sliceOrder(), 3); // a slice's curved cells: cubic Bezier triangles
    QCOMPARE(panel.tension(), 0.333);
    QCOMPARE(panel.property("minimumAngle").toDouble(), 15.0); // a Q_PROPERTY
    QCOMPARE(panel.blockCells(), 1000000); // vtkLabelMesher's and the CLI's default
    QCOMPARE(panel.memoryLimit(), 0.0);    // the memory available
  }

  void blockSizeAndMemoryLimit()
  {
    ParameterPanel panel;
    QSignalSpy blocks(&panel, &ParameterPanel::blockCellsChanged);
    QSignalSpy limit(&panel, &ParameterPanel::memoryLimitChanged);
    panel.setBlockCells(250000);
    panel.setMemoryLimit(4096.0);
    QCOMPARE(panel.blockCells(), 250000);
    QCOMPARE(panel.memoryLimit(), 4096.0);
    QCOMPARE(blocks.count(), 1);
    QCOMPARE(limit.count(), 1);
    panel.setBlockCells(-1);
    panel.setMemoryLimit(-5.0);
    panel.setMemoryLimit(std::numeric_limits<double>::quiet_NaN());
    QCOMPARE(panel.blockCells(), 250000);
    QCOMPARE(panel.memoryLimit(), 4096.0);
    panel.setBlockCells(0);
    QCOMPARE(child<QSpinBox>(panel, "blockCells")->text(), QStringLiteral("one block"));
    QVERIFY(child<QSpinBox>(panel, "blockCells")->toolTip().contains("initial cells"));
    QVERIFY(child<QDoubleSpinBox>(panel, "memoryLimit")->toolTip().contains("MiB"));
    panel.setDecimate(false); // blocks stream the decimator: nothing to set without it
    QVERIFY(!child<QSpinBox>(panel, "blockCells")->isEnabled());
  }

  void presetsSetValuesAndSignal()
  {
    ParameterPanel panel;
    QSignalSpy preset(&panel, &ParameterPanel::presetChanged);
    QSignalSpy distance(&panel, &ParameterPanel::imageToMeshDistanceChanged);
    QSignalSpy any(&panel, &ParameterPanel::parametersChanged);
    panel.setPreset(ParameterPanel::Preset::Fast);
    QCOMPARE(panel.imageToMeshDistance(), 3.0);
    QCOMPARE(panel.meshToImageDistance(), 3.0);
    QCOMPARE(panel.minimumAngle(), 10.0);
    QCOMPARE(panel.preset(), ParameterPanel::Preset::Fast);
    QCOMPARE(preset.count(), 1);
    QCOMPARE(distance.count(), 1);
    QCOMPARE(distance.at(0).at(0).toDouble(), 3.0);
    QVERIFY(any.count() >= 3);
    panel.setPreset(ParameterPanel::Preset::Faithful);
    QCOMPARE(panel.imageToMeshDistance(), 1.0);
    QCOMPARE(panel.minimumAngle(), 20.0);
    // A value changed by hand makes the preset Custom, in the property and the combo box.
    panel.setMinimumAngle(22.0);
    QCOMPARE(panel.preset(), ParameterPanel::Preset::Custom);
    QCOMPARE(child<QComboBox>(panel, "preset")->currentIndex(), static_cast<int>(ParameterPanel::Preset::Custom));
  }

  void millimetresAreShownAndReadBackAsVoxels()
  {
    ParameterPanel panel;
    panel.setImageGeometry(3, 0.5);
    auto* box = child<QDoubleSpinBox>(panel, "imageToMeshDistance");
    QCOMPARE(box->value(), 2.0);
    QSignalSpy unit(&panel, &ParameterPanel::distanceUnitChanged);
    panel.setDistanceUnit(ParameterPanel::DistanceUnit::Millimetres);
    QCOMPARE(unit.count(), 1);
    QCOMPARE(box->value(), 1.0); // 2 voxels of 0.5 mm
    QVERIFY(box->suffix().contains("mm"));
    QCOMPARE(box->maximum(), 32.0); // 64 voxels
    QCOMPARE(panel.imageToMeshDistance(), 2.0); // the property stays in voxels
    // The user types 1.5 mm: the property becomes 3 voxels.
    box->setValue(1.5);
    emit box->editingFinished();
    QCOMPARE(panel.imageToMeshDistance(), 3.0);
    panel.setDistanceUnit(ParameterPanel::DistanceUnit::Voxels);
    QCOMPARE(box->value(), 3.0);
  }

  void badValuesAreRefused()
  {
    ParameterPanel panel;
    QSignalSpy any(&panel, &ParameterPanel::parametersChanged);
    for (double bad : { -1.0, 64.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
    {
      panel.setImageToMeshDistance(bad);
      panel.setMeshToImageDistance(bad);
    }
    QCOMPARE(panel.imageToMeshDistance(), 2.0);
    QCOMPARE(panel.meshToImageDistance(), 2.0);
    QCOMPARE(any.count(), 0);
    auto* box = child<QDoubleSpinBox>(panel, "meshToImageDistance");
    box->setValue(-3.0); // the spin box itself cannot go below 0
    emit box->editingFinished();
    QCOMPARE(panel.meshToImageDistance(), 0.0);
    panel.setTension(7.0);
    QCOMPARE(panel.tension(), 1.0);
    panel.setSmoothness(3);
    QCOMPARE(panel.smoothness(), 1);
    panel.setSliceOrder(4);
    QCOMPARE(panel.sliceOrder(), 3);
  }

  void angleLimitFollowsTheImageDimension()
  {
    ParameterPanel panel;
    panel.setImageGeometry(2, 1.0);
    QCOMPARE(panel.maximumAngle(), 45.0);
    panel.setMinimumAngle(40.0);
    QCOMPARE(panel.minimumAngle(), 40.0);
    // The curver's controls apply to 2D images once curving is on.
    QVERIFY(child<QCheckBox>(panel, "curve")->isEnabled());
    QVERIFY(!child<QComboBox>(panel, "smoothness")->isEnabled());
    QSignalSpy curve(&panel, &ParameterPanel::curveChanged);
    panel.setCurve(true);
    QCOMPARE(curve.count(), 1);
    QVERIFY(panel.curve());
    QVERIFY(child<QComboBox>(panel, "smoothness")->isEnabled());
    QVERIFY(child<QDoubleSpinBox>(panel, "tension")->isEnabled());
    QSignalSpy angle(&panel, &ParameterPanel::minimumAngleChanged);
    panel.setImageGeometry(3, 1.0);
    QCOMPARE(panel.minimumAngle(), 30.0); // clamped to the 3D bound, and said so
    QCOMPARE(angle.count(), 1);
    panel.setMinimumAngle(35.0);
    QCOMPARE(panel.minimumAngle(), 30.0);
    // A 3D image is curved into quadratic tetrahedra: no smoothness or tension, and only from
    // the decimated mesh.
    QVERIFY(!child<QComboBox>(panel, "smoothness")->isEnabled());
    QVERIFY(!child<QDoubleSpinBox>(panel, "tension")->isEnabled());
    QVERIFY(child<QCheckBox>(panel, "curve")->isEnabled());
    QVERIFY(panel.curve());
    panel.setDecimate(false);
    QVERIFY(!child<QDoubleSpinBox>(panel, "minimumAngle")->isEnabled());
    QVERIFY(!child<QCheckBox>(panel, "curve")->isEnabled());
    QVERIFY(!panel.curve()); // no quadratic tetrahedra without decimation, whatever the box says
    panel.setImageGeometry(2, 1.0);
    QVERIFY(panel.curve()); // the choice is kept: a 2D image is curved without decimation too
    QVERIFY(child<QComboBox>(panel, "smoothness")->isEnabled());
    // Quadratic triangles are made of the decimated mesh only, as quadratic tetrahedra are.
    QVERIFY(child<QComboBox>(panel, "sliceOrder")->isEnabled());
    QSignalSpy order(&panel, &ParameterPanel::sliceOrderChanged);
    panel.setSliceOrder(2);
    QCOMPARE(order.count(), 1);
    QCOMPARE(order.at(0).at(0).toInt(), 2);
    QVERIFY(!panel.curve());
    panel.setDecimate(true);
    QVERIFY(panel.curve());
    panel.setSliceOrder(3);
    panel.setImageGeometry(3, 1.0);
    QVERIFY(!child<QComboBox>(panel, "sliceOrder")->isEnabled()); // a volume's cells are tetrahedra
    QVERIFY(panel.curve());
  }

  void tooltipsExplainTheGuarantees()
  {
    ParameterPanel panel;
    for (const char* name : { "imageToMeshDistance", "meshToImageDistance", "decimate", "minimumAngle", "curve", "smoothness" })
    {
      const QString tip = panel.findChild<QWidget*>(QString::fromLatin1(name))->toolTip();
      QVERIFY2(tip.contains("Guarantee"), name);
    }
    QVERIFY(child<QDoubleSpinBox>(panel, "imageToMeshDistance")->toolTip().contains("voxels"));
    QVERIFY(child<QDoubleSpinBox>(panel, "minimumAngle")->toolTip().contains("degrees"));
    QVERIFY(child<QDoubleSpinBox>(panel, "tension")->toolTip().contains("[0, 1]"));
  }
};

QTEST_MAIN(TestParameterPanel)
#include "TestParameterPanel.moc"
