// SPDX-License-Identifier: GPL-2.0-or-later
// QtTest of labelmesher-gui's window, run under xvfb-run (VTK's view needs OpenGL): it opens a
// shared real image, meshes it in the worker thread and checks the guarantees in the report, the
// angle histogram (its own measure) against the report, clipping, a saved picture
// that is not blank and a saved mesh read back; then it cancels a second run midway and checks the
// window kept the first mesh and meshes again; bad paths give one sentence and change nothing; a
// 3D image is curved into quadratic tetrahedra (their report, det J sampled on every cell shown,
// formats without them refused); a 2D slice is meshed and curved: the curver's guarantees in its
// report, det J sampled on every curved cell shown, the curved mesh saved as .vtu only; a one-row
// image gets the filters' voxel.
#include "AngleHistogram.h"
#include "CurvingChecks.h"
#include "MainWindow.h"
#include "MeshView.h"
#include "MpiSession.h"
#include "ParameterPanel.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkCellType.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkQuadraticTetra.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QProgressBar>
#include <QSet>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <utility>

#include <limits>
#include <memory>

using labelmesher::gui::MainWindow;
using labelmesher::widgets::ParameterPanel;

namespace
{
constexpr int kRunTimeoutMs = 600000; // a hung run fails the test instead of hanging CI

/// Pixels that are not the view's white background, and the distinct colours among them.
std::pair<double, int> Coverage(const QImage& image)
{
  long long coloured = 0;
  QSet<QRgb> colours;
  for (int y = 0; y < image.height(); ++y)
  {
    for (int x = 0; x < image.width(); ++x)
    {
      const QRgb pixel = image.pixel(x, y) & 0xFFFFFF;
      if (pixel != 0xFFFFFF)
      {
        ++coloured;
        colours.insert(pixel);
      }
    }
  }
  return { static_cast<double>(coloured) / (static_cast<double>(image.width()) * image.height()),
    colours.size() };
}
double Determinant(const double m[3][3])
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// The orientation (+1 or -1) of the tetrahedron with these corners.
double Orientation(const double x[10][3])
{
  double corners[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      corners[a][b] = x[a + 1][b] - x[0][b];
  return Determinant(corners) > 0.0 ? 1.0 : -1.0;
}

/// The smallest det J of the quadratic tetrahedron with nodes x (VTK's order) over the points of
/// its barycentric grid of step 1/n, times `sign` (the mesh's orientation): > 0 when it is valid there.
double SampledMinimumQuadraticJacobian(const double x[10][3], int n, double sign)
{
  auto det = Determinant;
  double smallest = std::numeric_limits<double>::max();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      for (int k = 0; i + j + k <= n; ++k)
      {
        const double r[3] = { double(i) / n, double(j) / n, double(k) / n };
        double derivs[30];
        vtkQuadraticTetra::InterpolationDerivs(r, derivs);
        double m[3][3] = {};
        for (int d = 0; d < 3; ++d)
          for (int node = 0; node < 10; ++node)
            for (int c = 0; c < 3; ++c)
              m[d][c] += derivs[10 * d + node] * x[node][c];
        smallest = std::min(smallest, sign * det(m));
      }
  return smallest;
}
} // namespace

class TestViewer : public QObject
{
  Q_OBJECT

  std::unique_ptr<MainWindow> Window;
  QTemporaryDir Folder;
  vtkIdType FirstCells = 0;

  QString image() const { return qEnvironmentVariable("LABELMESHER_DATA") + "/3d/iso2mesh_rat_head.nrrd"; }

private slots:
  void initTestCase()
  {
    QVERIFY(Folder.isValid());
    Folder.setAutoRemove(qEnvironmentVariableIsEmpty("LABELMESHER_KEEP_TEST_FILES")); // to look at the pictures
    if (!Folder.autoRemove())
      qInfo("test files kept in %s", qPrintable(Folder.path()));
    QVERIFY2(QFile::exists(image()), qPrintable("missing shared image " + image()));
    Window = std::make_unique<MainWindow>();
    Window->show();
    QVERIFY(QTest::qWaitForWindowExposed(Window.get()));
    QSignalSpy opened(Window.get(), &MainWindow::imageOpened);
    QVERIFY(Window->openImage(image()));
    QCOMPARE(opened.count(), 1);
    QCOMPARE(Window->parameters()->imageDimension(), 3);
  }

  void meshesTheImageWithItsGuarantees()
  {
    auto* bar = Window->findChild<QProgressBar*>("progress");
    QVERIFY(bar);
    QSignalSpy progress(bar, &QProgressBar::valueChanged);
    QSignalSpy finished(Window.get(), &MainWindow::meshingFinished);
    QSignalSpy errors(Window.get(), &MainWindow::errorOccurred);
    Window->parameters()->setPreset(ParameterPanel::Preset::Balanced); // 2 voxels each way, 15 degrees
    QVERIFY(Window->startMeshing());
    QVERIFY(Window->isMeshing());
    QVERIFY(!Window->startMeshing()); // one run at a time
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, kRunTimeoutMs);
    QCOMPARE(errors.count(), 1); // the refused second start only

    // Progress reached the window while the worker ran, in order, up to the end.
    QVERIFY2(progress.count() >= 5, qPrintable(QString::number(progress.count())));
    int previous = -1;
    for (const QList<QVariant>& value : progress)
    {
      QVERIFY(value.at(0).toInt() >= previous);
      previous = value.at(0).toInt();
    }
    QCOMPARE(previous, bar->maximum());

    // The guarantees, from the report (the CLI's figures).
    QVERIFY(Window->report().has_value());
    const labelmesher::report::RunReport& r = *Window->report();
    QVERIFY(r.Measured());
    QVERIFY(r.Decimation.has_value());
    QVERIFY2(*r.MinimumAngle >= 15.0 - 1e-9, qPrintable(QString::number(*r.MinimumAngle)));
    QCOMPARE(r.InvertedCells.value_or(-1), 0.0);
    QCOMPARE(r.HausdorffCertified.value_or(0), 1.0);
    QVERIFY(*r.MeasuredImageToMesh <= 2.0 + 1e-9);
    QVERIFY(*r.MeasuredMeshToImage <= 2.0 + 1e-9);
    QVERIFY(r.TopologyMatches());
    QVERIFY(r.Cells > 0 && r.Cells < r.Decimation->CellsBefore);
    FirstCells = r.Cells;

    // The histogram measures every shown cell apart from the filters' checks, and agrees with them.
    const auto* histogram = Window->histogram();
    QCOMPARE(histogram->measuredCells(), r.Cells);
    QVERIFY(histogram->smallestAngle() >= 15.0 - 1e-6);
    QVERIFY2(std::abs(histogram->smallestAngle() - *r.MinimumAngle) < 1e-6,
      qPrintable(QString("%1 vs %2").arg(histogram->smallestAngle()).arg(*r.MinimumAngle)));
    vtkIdType binned = 0;
    for (std::size_t bin = 0; bin < histogram->counts().size(); ++bin)
    {
      binned += histogram->counts()[bin];
      if ((bin + 1) * labelmesher::widgets::AngleHistogram::BinWidth <= 15.0)
        QCOMPARE(histogram->counts()[bin], vtkIdType(0)); // nothing below the bound
    }
    QCOMPARE(binned, r.Cells);

    // The summary is the CLI's text; the view shows every cell.
    QVERIFY(Window->summaryText().contains("Both bounds certified"));
    QVERIFY(Window->summaryText().contains("Minimum dihedral angle"));
    QCOMPARE(Window->view()->shownCells(), r.Cells);
  }

  void clippingHidesTheFarSide()
  {
    auto* view = Window->view();
    view->setClipping(true);
    view->setClipAxis(2);
    view->setClipPosition(0.5);
    const vtkIdType clipped = view->shownCells();
    QVERIFY2(clipped > 0 && clipped < FirstCells, qPrintable(QString::number(clipped)));
    view->setClipPosition(0.9);
    QVERIFY(view->shownCells() > clipped); // the plane moved outwards: more cells on the near side
    view->setClipping(false);
    QCOMPARE(view->shownCells(), FirstCells);
  }

  void savedPicturesAreNotBlank()
  {
    const QString whole = Folder.filePath("whole.png");
    const QString clipped = Folder.filePath("clipped.png");
    QVERIFY(Window->savePicture(whole));
    Window->view()->setClipping(true);
    Window->view()->setClipAxis(0);
    Window->view()->setClipPosition(0.5);
    QVERIFY(Window->savePicture(clipped));
    Window->view()->setClipping(false);
    QImage a(whole), b(clipped);
    QVERIFY(!a.isNull() && !b.isNull());
    QVERIFY(a.width() > 100 && a.height() > 100);
    const auto [coverA, coloursA] = Coverage(a);
    const auto [coverB, coloursB] = Coverage(b);
    // The mesh fills a good part of the view, shaded (many colours), and clipping shows less of it.
    QVERIFY2(coverA > 0.05 && coloursA > 20, qPrintable(QString("%1 %2").arg(coverA).arg(coloursA)));
    QVERIFY2(coverB > 0.02 && coverB < coverA, qPrintable(QString("%1 vs %2").arg(coverB).arg(coverA)));

    // Coloured by material: the rat head's one material is drawn in its table colour (shaded:
    // the same hue, darker or lighter), apart from the dark edges.
    QCOMPARE(Window->view()->numberOfMaterials(), 1);
    const QColor material = Window->view()->materialColour(1);
    QVERIFY(material.isValid());
    QVERIFY(!Window->view()->materialColour(2).isValid());
    long long shaded = 0, onHue = 0;
    for (int y = 0; y < a.height(); ++y)
      for (int x = 0; x < a.width(); ++x)
      {
        const QColor pixel = a.pixelColor(x, y);
        if ((pixel.rgb() & 0xFFFFFF) == 0xFFFFFF || pixel.value() < 60 || pixel.saturation() < 40)
          continue;
        ++shaded;
        const int difference = std::abs(pixel.hue() - material.hue());
        onHue += std::min(difference, 360 - difference) <= 12;
      }
    QVERIFY2(shaded > 0 && onHue > 0.9 * shaded, qPrintable(QString("%1 of %2").arg(onHue).arg(shaded)));
  }

  void savesTheMeshAndRefusesBadPaths()
  {
    const QString path = Folder.filePath("mesh.vtu");
    QVERIFY(Window->saveMesh(path));
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.toUtf8().constData());
    reader->Update();
    QCOMPARE(reader->GetOutput()->GetNumberOfCells(), FirstCells);
    QVERIFY(Window->summaryText().contains("mesh.vtu"));

    QSignalSpy errors(Window.get(), &MainWindow::errorOccurred);
    QVERIFY(!Window->saveMesh(Folder.filePath("no-such-folder/mesh.vtu")));
    QVERIFY(!Window->saveMesh(Folder.filePath("mesh.xyz")));
    QVERIFY(!Window->savePicture(Folder.filePath("no-such-folder/a.png")));
    QVERIFY(QDir(Folder.path()).mkdir("folder.vtu"));
    QVERIFY(!Window->saveMesh(Folder.filePath("folder.vtu"))); // a folder with a mesh's name
    QCOMPARE(errors.count(), 4);
    for (const QList<QVariant>& e : errors)
    {
      const QString message = e.at(0).toString();
      QVERIFY2(!message.isEmpty() && !message.contains('\n') && !message.contains("\x1b"), qPrintable(message));
    }
    QVERIFY(!QFile::exists(Folder.filePath("mesh.xyz")));
    QCOMPARE(QDir(Folder.path()).entryList(QDir::Files).size(), 3); // mesh.vtu and the two pictures
    QVERIFY(QDir(Folder.filePath("folder.vtu")).isEmpty());
  }

  void cancelStopsASecondRunMidway()
  {
    QSignalSpy finished(Window.get(), &MainWindow::meshingFinished);
    QSignalSpy cancelled(Window.get(), &MainWindow::meshingCancelled);
    vtkUnstructuredGrid* shown = Window->view()->mesh();
    Window->parameters()->setPreset(ParameterPanel::Preset::Faithful); // 1 voxel, 20 degrees
    // Cancel at the first progress past 40 %: within the decimator's merges (the mesher takes the
    // first 30 %, measuring the last 14 %), whatever the machine's speed.
    auto* bar = Window->findChild<QProgressBar*>("progress");
    double at = -1.0;
    const QMetaObject::Connection cancelMidway = connect(bar, &QProgressBar::valueChanged, this, [&](int value) {
      if (at < 0.0 && value >= 400 && value < 800)
      {
        at = Window->progress();
        Window->cancelMeshing();
      }
    });
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(!Window->isMeshing(), kRunTimeoutMs);
    disconnect(cancelMidway);
    QVERIFY2(at >= 0.4, "no progress report between 40 % and 80 %");
    QCOMPARE(cancelled.count(), 1);
    QCOMPARE(finished.count(), 0);
    QVERIFY2(Window->progress() < 0.86 && Window->progress() >= at, qPrintable(QString::number(Window->progress())));
    // The window kept the first run's mesh and report.
    QCOMPARE(Window->view()->mesh(), shown);
    QCOMPARE(Window->report()->Cells, FirstCells);
    QCOMPARE(Window->report()->Decimation->AngleBound, 15.0);
  }

  void cancelWhileMeasuringKeepsTheCompleteMesh()
  {
    // Measuring (the last 14 % of the progress) cannot stop: a cancel there must not throw away
    // the finished mesh.
    QSignalSpy finished(Window.get(), &MainWindow::meshingFinished);
    QSignalSpy cancelled(Window.get(), &MainWindow::meshingCancelled);
    Window->parameters()->setPreset(ParameterPanel::Preset::Fast);
    auto* bar = Window->findChild<QProgressBar*>("progress");
    bool requested = false;
    const QMetaObject::Connection cancelLate = connect(bar, &QProgressBar::valueChanged, this, [&](int value) {
      if (!requested && value >= 880 && value < 1000)
      {
        requested = true;
        Window->cancelMeshing();
      }
    });
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(!Window->isMeshing(), kRunTimeoutMs);
    disconnect(cancelLate);
    QVERIFY2(requested, "no progress report within the measuring stage");
    QCOMPARE(cancelled.count(), 0);
    QCOMPARE(finished.count(), 1);
    QVERIFY(*Window->report()->MinimumAngle >= 10.0 - 1e-9);
    QCOMPARE(Window->report()->HausdorffCertified.value_or(0), 1.0);
    QVERIFY(Window->report()->TopologyMatches());
    QVERIFY(Window->report()->Cells != FirstCells);
    QCOMPARE(Window->view()->shownCells(), Window->report()->Cells);
  }

  void curvesA3DImageIntoQuadraticTetrahedra()
  {
    // The rat head is still open: curving a volume makes quadratic tetrahedra of the decimated mesh.
    QCOMPARE(Window->parameters()->imageDimension(), 3);
    QSignalSpy finished(Window.get(), &MainWindow::meshingFinished);
    QSignalSpy errors(Window.get(), &MainWindow::errorOccurred);
    Window->parameters()->setPreset(ParameterPanel::Preset::Balanced);
    Window->parameters()->setCurve(true);
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, kRunTimeoutMs);
    QCOMPARE(errors.count(), 0);

    // The quadratic stage's guarantees, from the report (the CLI's `mesh --order 2` figures).
    QVERIFY(Window->report().has_value() && Window->report()->Quadratic.has_value());
    QVERIFY(!Window->curveReport().has_value()); // no Bezier curve report for tetrahedra
    const labelmesher::report::RunReport& r = *Window->report();
    const labelmesher::report::QuadraticEntry& q = *r.Quadratic;
    QCOMPARE(q.ScaledJacobianBound, 0.1);
    QVERIFY2(q.CertifiedMinimumScaledJacobian >= q.ScaledJacobianBound,
      qPrintable(QString::number(q.CertifiedMinimumScaledJacobian)));
    const double slack = q.MeasureResolution.value_or(0.0) + 1e-9;
    QVERIFY(q.MeasuredImageToMesh && *q.MeasuredImageToMesh <= 2.0 + slack);
    QVERIFY(q.MeasuredMeshToImage && *q.MeasuredMeshToImage <= 2.0 + slack);
    QVERIFY(q.CurvedEdges > 0);
    QVERIFY(labelmesher::report::QuadraticHolds(r));
    QVERIFY(Window->summaryText().contains("quadratic tetrahedra"));

    // The view shows the quadratic tetrahedra themselves, each valid by det J sampled on a
    // barycentric grid (apart from the curver's Bernstein bound), with their curved edges.
    vtkUnstructuredGrid* shown = Window->view()->mesh();
    QVERIFY(shown);
    QCOMPARE(static_cast<long long>(shown->GetNumberOfCells()), q.Cells);
    QVERIFY(Window->view()->showsCurvedCells());
    QVERIFY(Window->view()->drawnEdges() > 0);
    vtkNew<vtkIdList> ids;
    double orientation = 0.0; // the mesh's, the first cell's: every cell must share it
    for (vtkIdType cell = 0; cell < shown->GetNumberOfCells(); ++cell)
    {
      QCOMPARE(shown->GetCellType(cell), static_cast<int>(VTK_QUADRATIC_TETRA));
      shown->GetCellPoints(cell, ids);
      double x[10][3];
      for (int k = 0; k < 10; ++k)
        shown->GetPoint(ids->GetId(k), x[k]);
      if (orientation == 0.0)
        orientation = Orientation(x);
      const double jacobian = SampledMinimumQuadraticJacobian(x, 6, orientation);
      QVERIFY2(jacobian > 0.0, qPrintable(QString("cell %1: sampled det J %2").arg(cell).arg(jacobian)));
    }
    const QImage picture = Window->view()->grabPicture();
    QVERIFY(Coverage(picture).first > 0.02);
    if (!Folder.autoRemove())
      QVERIFY(picture.save(Folder.filePath("quadratic.png")));

    // Saved as the CLI writes it; formats without quadratic tetrahedra refused, nothing written.
    QVERIFY(!Window->saveMesh(Folder.filePath("quadratic.stl")));
    QVERIFY(errors.last().at(0).toString().contains(".inp or .mesh only"));
    QVERIFY(!QFile::exists(Folder.filePath("quadratic.stl")));
    QVERIFY(Window->saveMesh(Folder.filePath("quadratic.inp")));
    QVERIFY(Window->saveMesh(Folder.filePath("quadratic.vtu")));
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(qPrintable(Folder.filePath("quadratic.vtu")));
    reader->Update();
    QCOMPARE(reader->GetOutput()->GetNumberOfCells(), shown->GetNumberOfCells());
    QCOMPARE(reader->GetOutput()->GetCellType(0), static_cast<int>(VTK_QUADRATIC_TETRA));

    // Curving off again: the linear mesh.
    Window->parameters()->setCurve(false);
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 2, kRunTimeoutMs);
    QVERIFY(!Window->report()->Quadratic.has_value());
    QVERIFY(!Window->view()->showsCurvedCells());
  }

  void badImagesChangeNothing()
  {
    QSignalSpy errors(Window.get(), &MainWindow::errorOccurred);
    const long long cells = Window->report()->Cells;
    QVERIFY(!Window->openImage(Folder.filePath("missing.nrrd")));
    QFile text(Folder.filePath("not-an-image.nrrd"));
    QVERIFY(text.open(QIODevice::WriteOnly));
    text.write("NRRD0004\ntype: float\n");
    text.close();
    QVERIFY(!Window->openImage(text.fileName()));
    QCOMPARE(errors.count(), 2);
    for (const QList<QVariant>& e : errors)
      QVERIFY2(!e.at(0).toString().isEmpty() && !e.at(0).toString().contains('\n'), qPrintable(e.at(0).toString()));
    QCOMPARE(Window->report()->Cells, cells);
    QVERIFY(Window->view()->mesh() != nullptr);
  }

  void meshesA2DImageOfManyMaterials()
  {
    QSignalSpy finished(Window.get(), &MainWindow::meshingFinished);
    const QString slice = qEnvironmentVariable("LABELMESHER_DATA") + "/2d/digimouse_sagittal.png";
    QVERIFY(Window->openImage(slice));
    QCOMPARE(Window->parameters()->imageDimension(), 2);
    QVERIFY(!Window->report().has_value()); // the 3D run's report went with its image
    QVERIFY(!Window->saveMesh(Folder.filePath("nothing.vtu")));
    Window->parameters()->setPreset(ParameterPanel::Preset::Balanced);
    Window->parameters()->setMinimumAngle(40.0); // 2D allows up to 45 degrees
    QCOMPARE(Window->parameters()->minimumAngle(), 40.0);
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, kRunTimeoutMs);
    const labelmesher::report::RunReport& r = *Window->report();
    QCOMPARE(r.MeshDimension, 2);
    QVERIFY2(*r.MinimumAngle >= 40.0 - 1e-9, qPrintable(QString::number(*r.MinimumAngle)));
    QCOMPARE(r.HausdorffCertified.value_or(0), 1.0);
    QVERIFY(r.TopologyMatches());
    QVERIFY(Window->summaryText().contains("Minimum planar angle"));
    QCOMPARE(Window->histogram()->measuredCells(), r.Cells);
    QVERIFY(std::abs(Window->histogram()->smallestAngle() - *r.MinimumAngle) < 1e-6);
    // Every material present is drawn, each in its own colour.
    const int materials = static_cast<int>(r.CellsPerMaterial.size());
    QCOMPARE(materials, 17);
    QCOMPARE(Window->view()->numberOfMaterials(), materials);
    QSet<QRgb> colours;
    for (const auto& entry : r.CellsPerMaterial)
      colours.insert(Window->view()->materialColour(entry.first).rgb());
    QCOMPARE(colours.size(), materials);
    // On screen: face-on, many materials' hues (shading keeps a hue; one colour for all would give
    // one or two buckets of 10 degrees).
    const QImage picture = Window->view()->grabPicture();
    QVERIFY(Coverage(picture).first > 0.02);
    QSet<int> hues;
    for (int y = 0; y < picture.height(); ++y)
      for (int x = 0; x < picture.width(); ++x)
      {
        const QColor pixel = picture.pixelColor(x, y);
        if (pixel.saturation() >= 60 && pixel.value() >= 60)
          hues.insert(pixel.hue() / 10);
      }
    QVERIFY2(hues.size() >= 8, qPrintable(QString::number(hues.size())));
  }

  void curvesA2DImage()
  {
    // The digimouse slice of the test above is still open.
    QCOMPARE(Window->parameters()->imageDimension(), 2);
    QSignalSpy finished(Window.get(), &MainWindow::meshingFinished);
    QSignalSpy errors(Window.get(), &MainWindow::errorOccurred);
    Window->parameters()->setPreset(ParameterPanel::Preset::Balanced);
    Window->parameters()->setCurve(true);
    Window->parameters()->setSmoothness(2);
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, kRunTimeoutMs);
    QCOMPARE(errors.count(), 0);

    // The curver's guarantees, from the report (the CLI's curve figures).
    QVERIFY(Window->curveReport().has_value());
    const labelmesher::report::CurveReport& c = *Window->curveReport();
    QCOMPARE(c.Smoothness, 2);
    QVERIFY(c.Valid());
    QCOMPARE(c.InvalidCells, 0LL);
    QVERIFY2(c.MinimumScaledJacobian > 0.0, qPrintable(QString::number(c.MinimumScaledJacobian)));
    QVERIFY(c.CurvedEdges > 0);
    QCOMPARE(c.InterfaceCrossings.value_or(-1), 0LL);
    QVERIFY(c.TopologyMatches.value_or(false));
    QVERIFY2(c.MeasuredImageToMesh && *c.MeasuredImageToMesh <= 2.0 + c.CurveResolution.value_or(0.0) + 1e-9,
      qPrintable(QString::number(c.MeasuredImageToMesh.value_or(-1))));
    QVERIFY2(c.MeasuredMeshToImage && *c.MeasuredMeshToImage <= 2.0 + c.CurveResolution.value_or(0.0) + 1e-9,
      qPrintable(QString::number(c.MeasuredMeshToImage.value_or(-1))));
    QVERIFY(c.CurvesFaithful());
    QVERIFY(Window->summaryText().contains("cubic Bezier triangles"));
    QVERIFY(Window->summaryText().contains("every cell proven valid"));
    // The histogram is the linear mesh's, the one curved (its corners are the curved cells').
    QCOMPARE(Window->histogram()->measuredCells(), Window->report()->Cells);
    QVERIFY(Window->histogram()->smallestAngle() >= 15.0 - 1e-9);

    // The view shows the curved cells themselves: cubic Bezier triangles, each valid by det J
    // sampled densely on a barycentric grid (not the curver's Bernstein bound).
    vtkUnstructuredGrid* shown = Window->view()->mesh();
    QVERIFY(shown);
    QCOMPARE(static_cast<long long>(shown->GetNumberOfCells()), c.Cells);
    QVERIFY(Window->view()->showsCurvedCells());
    QCOMPARE(Window->view()->shownCells(), shown->GetNumberOfCells());
    // Every edge drawn once: E = (3 T + boundary edges) / 2, so 3T/2 <= E <= 3T.
    const vtkIdType edges = Window->view()->drawnEdges();
    QVERIFY2(2 * edges >= 3 * shown->GetNumberOfCells() && edges <= 3 * shown->GetNumberOfCells(),
      qPrintable(QString::number(edges)));
    double bounds[6];
    shown->GetBounds(bounds);
    QCOMPARE(bounds[5] - bounds[4], 0.0); // the PNG's slice lies in z = 0
    vtkNew<vtkIdList> ids;
    double orientation = 0.0;
    for (vtkIdType cell = 0; cell < shown->GetNumberOfCells(); ++cell)
    {
      QCOMPARE(shown->GetCellType(cell), static_cast<int>(VTK_BEZIER_TRIANGLE));
      shown->GetCellPoints(cell, ids);
      QCOMPARE(ids->GetNumberOfIds(), static_cast<vtkIdType>(10));
      labelmesher::CubicTriangle triangle;
      for (int k = 0; k < 10; ++k)
      {
        double p[3];
        shown->GetPoint(ids->GetId(k), p);
        triangle.ControlPoints[static_cast<std::size_t>(k)] = { p[0], p[1] };
      }
      const auto& q = triangle.ControlPoints;
      const double corners = (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
      if (orientation == 0.0)
        orientation = corners > 0.0 ? 1.0 : -1.0; // the mesh's orientation, the same for every cell
      if (orientation < 0.0)
        for (auto& point : triangle.ControlPoints)
          point[0] = -point[0];
      const double jacobian = labelmesher::testing::SampledMinimumJacobian(triangle, 24);
      QVERIFY2(jacobian > 0.0, qPrintable(QString("cell %1: sampled det J %2").arg(cell).arg(jacobian)));
    }
    const QImage picture = Window->view()->grabPicture();
    QVERIFY(Coverage(picture).first > 0.02);
    if (!Folder.autoRemove())
      QVERIFY(picture.save(Folder.filePath("curved.png")));

    // Saved as the CLI writes it: .vtu/.vtk (read back with the same Bezier cells) or .msh (Gmsh's
    // 10-node triangles); formats without cubic cells refused.
    QVERIFY(!Window->saveMesh(Folder.filePath("curved.inp")));
    QVERIFY(errors.last().at(0).toString().contains(".vtu, .vtk or .msh"));
    QVERIFY(!QFile::exists(Folder.filePath("curved.inp")));
    QVERIFY(Window->saveMesh(Folder.filePath("curved.msh")));
    QVERIFY(Window->saveMesh(Folder.filePath("curved.vtu")));
    QCOMPARE(Window->curveReport()->Linear.Outputs.size(), std::size_t{ 1 });
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(qPrintable(Folder.filePath("curved.vtu")));
    reader->Update();
    QCOMPARE(reader->GetOutput()->GetNumberOfCells(), shown->GetNumberOfCells());
    QCOMPARE(reader->GetOutput()->GetCellType(0), static_cast<int>(VTK_BEZIER_TRIANGLE));

    // Curving off again: the same image gives the linear mesh.
    Window->parameters()->setCurve(false);
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 2, kRunTimeoutMs);
    QVERIFY(!Window->curveReport().has_value());
    QVERIFY(!Window->view()->showsCurvedCells());
    QCOMPARE(Window->view()->drawnEdges(), static_cast<vtkIdType>(0));
  }

  void curvesA2DImageIntoQuadraticTriangles()
  {
    // The digimouse slice is still open; the panel's Curved cells choice makes 6-node triangles.
    QCOMPARE(Window->parameters()->imageDimension(), 2);
    QSignalSpy finished(Window.get(), &MainWindow::meshingFinished);
    QSignalSpy errors(Window.get(), &MainWindow::errorOccurred);
    Window->parameters()->setCurve(true);
    Window->parameters()->setSmoothness(1);
    Window->parameters()->setSliceOrder(2);
    QCOMPARE(Window->parameters()->sliceOrder(), 2);
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, kRunTimeoutMs);
    QCOMPARE(errors.count(), 0);
    QVERIFY(Window->curveReport().has_value());
    const labelmesher::report::CurveReport& c = *Window->curveReport();
    QCOMPARE(c.Order, 2);
    QVERIFY(c.Valid() && c.ScaledJacobianHolds() && c.CornerAnglesHold() && c.CurvesFaithful());
    QVERIFY(Window->summaryText().contains("quadratic triangles"));
    vtkUnstructuredGrid* shown = Window->view()->mesh();
    QVERIFY(shown);
    QVERIFY(Window->view()->showsCurvedCells());
    QVERIFY(Window->view()->drawnEdges() > 0);
    // Each shown cell: six nodes whose det J (the quadratic's, from its nodes) keeps one sign.
    vtkNew<vtkIdList> ids;
    double orientation = 0.0;
    for (vtkIdType cell = 0; cell < shown->GetNumberOfCells(); ++cell)
    {
      QCOMPARE(shown->GetCellType(cell), static_cast<int>(VTK_QUADRATIC_TRIANGLE));
      shown->GetCellPoints(cell, ids);
      QCOMPARE(ids->GetNumberOfIds(), static_cast<vtkIdType>(6));
      std::array<std::array<double, 3>, 6> n{};
      for (int k = 0; k < 6; ++k)
        shown->GetPoint(ids->GetId(k), n[static_cast<std::size_t>(k)].data());
      for (const auto& [r, t] : { std::pair{ 0.1, 0.1 }, std::pair{ 0.8, 0.1 }, std::pair{ 0.1, 0.8 }, std::pair{ 0.4, 0.4 } })
      {
        const double u = 1.0 - r - t;
        const double dr[6] = { 1 - 4 * u, 4 * r - 1, 0, 4 * (u - r), 4 * t, -4 * t };
        const double dt[6] = { 1 - 4 * u, 0, 4 * t - 1, -4 * r, 4 * r, 4 * (u - t) };
        double xr[2] = { 0, 0 }, xt[2] = { 0, 0 };
        for (int k = 0; k < 6; ++k)
          for (int a = 0; a < 2; ++a)
          {
            xr[a] += dr[k] * n[static_cast<std::size_t>(k)][static_cast<std::size_t>(a)];
            xt[a] += dt[k] * n[static_cast<std::size_t>(k)][static_cast<std::size_t>(a)];
          }
        const double det = xr[0] * xt[1] - xr[1] * xt[0];
        if (orientation == 0.0)
          orientation = det > 0.0 ? 1.0 : -1.0;
        QVERIFY2(det * orientation > 0.0, qPrintable(QString("cell %1: det J %2").arg(cell).arg(det)));
      }
    }
    // Saved as the CLI writes quadratic cells: .inp and .mesh too; surface formats refused.
    QVERIFY(Window->saveMesh(Folder.filePath("quadratic.inp")));
    QVERIFY(Window->saveMesh(Folder.filePath("quadratic.msh")));
    QVERIFY(!Window->saveMesh(Folder.filePath("quadratic.obj")));
    QVERIFY(!QFile::exists(Folder.filePath("quadratic.obj")));
    // Without decimation a slice's quadratic cells cannot be made: curve() is off, as for volumes.
    Window->parameters()->setDecimate(false);
    QVERIFY(!Window->parameters()->curve());
    Window->parameters()->setDecimate(true);
    Window->parameters()->setSliceOrder(3);
    Window->parameters()->setCurve(false);
  }

  void oneRowImageHasTheFiltersVoxel()
  {
    // A 6 x 1 x 1 image is meshed across its last single-slice axis (z), as LabelImageConversion
    // places it, so its voxel is the smaller of the x and y spacings (0.25 mm), though y too has a
    // single slice; the panel's millimetres must use that voxel, the report's VoxelSize.
    const QString path = Folder.filePath("row.nrrd");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    const QByteArray header = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 6 1 1\n"
                              "spacings: 1 0.25 1\nencoding: raw\n\n";
    QVERIFY(file.write(header + QByteArray("\0\1\1\1\1\0", 6)) == header.size() + 6);
    file.close();
    QSignalSpy finished(Window.get(), &MainWindow::meshingFinished);
    QVERIFY(Window->openImage(path));
    QCOMPARE(Window->parameters()->imageDimension(), 2);
    QCOMPARE(Window->parameters()->smallestSpacing(), 0.25);
    Window->parameters()->setCurve(false);
    QVERIFY(Window->startMeshing());
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, kRunTimeoutMs);
    QCOMPARE(Window->report()->VoxelSize, Window->parameters()->smallestSpacing());
  }

  void cleanupTestCase() { Window.reset(); }
};

int main(int argc, char* argv[])
{
  const labelmesher::gui::MpiSession mpi; // as labelmesher-gui's main()
  // VTK's OpenGL needs its surface format set before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  TestViewer test;
  return QTest::qExec(&test, argc, argv);
}

#include "TestViewer.moc"
