// SPDX-License-Identifier: GPL-2.0-or-later
#include "MainWindow.h"

#include "AngleHistogram.h"
#include "ImageReader.h"
#include "MeshView.h"
#include "ParameterPanel.h"

#include "MeshFiles.h"
#include "SafeFile.h"

#include "vtkImageData.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <QAction>
#include <QApplication>
#include <QBuffer>
#include <QCloseEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QStatusBar>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace labelmesher
{
namespace gui
{
namespace
{
constexpr int kProgressSteps = 1000;

/// The run the panel describes (the panel sets what a user can choose; the rest are the CLI's
/// defaults).
labelmesher_cli::MeshingSettings SettingsOf(const widgets::ParameterPanel& panel)
{
  labelmesher_cli::MeshingSettings settings;
  settings.ImageToMeshDistance = panel.imageToMeshDistance();
  settings.MeshToImageDistance = panel.meshToImageDistance();
  settings.Decimate = panel.decimate();
  settings.MinimumAngle = panel.minimumAngle();
  // Curving a 2D image makes cubic Bezier triangles or quadratic ones, a 3D one quadratic tetrahedra.
  const bool flat = panel.imageDimension() == 2;
  settings.Curve = panel.curve() && flat && panel.sliceOrder() == 3;
  settings.Order = panel.curve() && !settings.Curve ? 2 : 1;
  settings.Smoothness = panel.smoothness();
  settings.Tension = panel.tension();
  settings.BlockCells = panel.blockCells();
  settings.MemoryLimit = panel.memoryLimit();
  return settings;
}
} // namespace

MainWindow::MainWindow(QWidget* parent)
  : QMainWindow(parent)
{
  this->setWindowTitle(tr("LabelMesher"));
  this->Panel = new widgets::ParameterPanel(this);
  this->MeshButton = new QPushButton(tr("Mesh"), this);
  this->MeshButton->setObjectName("mesh");
  this->MeshButton->setToolTip(tr("Mesh the open image with these parameters (in the background)."));
  this->CancelButton = new QPushButton(tr("Cancel"), this);
  this->CancelButton->setObjectName("cancel");
  this->CancelButton->setToolTip(tr("Stop the run under way; the mesh shown stays."));
  connect(this->MeshButton, &QPushButton::clicked, this, [this]() { this->startMeshing(); });
  connect(this->CancelButton, &QPushButton::clicked, this, &MainWindow::cancelMeshing);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(this->MeshButton);
  buttons->addWidget(this->CancelButton);

  this->Histogram = new widgets::AngleHistogram(this);
  this->Summary = new QPlainTextEdit(this);
  this->Summary->setObjectName("summary");
  this->Summary->setReadOnly(true);
  this->Summary->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  this->Summary->setPlaceholderText(tr("Open a label image (File > Open), then Mesh."));

  auto* side = new QWidget(this);
  auto* sideLayout = new QVBoxLayout(side);
  sideLayout->addWidget(this->Panel);
  sideLayout->addLayout(buttons);
  sideLayout->addWidget(this->Histogram);
  sideLayout->addWidget(this->Summary, 1);

  this->View = new widgets::MeshView(this);
  auto* splitter = new QSplitter(this);
  splitter->addWidget(side);
  splitter->addWidget(this->View);
  splitter->setStretchFactor(1, 1);
  this->setCentralWidget(splitter);

  this->Progress = new QProgressBar(this);
  this->Progress->setObjectName("progress");
  this->Progress->setRange(0, kProgressSteps);
  this->Progress->setValue(0);
  this->Stage = new QLabel(this);
  this->statusBar()->addWidget(this->Stage, 1);
  this->statusBar()->addPermanentWidget(this->Progress);

  connect(&this->Job, &MeshingJob::progressed, this, &MainWindow::onProgress);
  connect(&this->Job, &MeshingJob::finished, this, &MainWindow::onFinished);
  connect(&this->Job, &MeshingJob::cancelled, this, &MainWindow::onCancelled);
  connect(&this->Job, &MeshingJob::failed, this, &MainWindow::onFailed);
  this->buildMenus();
  this->setMeshingState(false);
  this->resize(1200, 760);
}

MainWindow::~MainWindow() = default;

void MainWindow::buildMenus()
{
  QMenu* file = this->menuBar()->addMenu(tr("&File"));
  this->OpenAction = file->addAction(tr("&Open label image..."), this, &MainWindow::chooseImage, QKeySequence::Open);
  this->SaveMeshAction = file->addAction(tr("&Save mesh..."), this, &MainWindow::chooseMeshFile, QKeySequence::Save);
  this->SavePictureAction = file->addAction(tr("Save &picture..."), this, &MainWindow::choosePictureFile);
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);
}

void MainWindow::fail(const QString& message)
{
  this->statusBar()->showMessage(message);
  emit errorOccurred(message);
}

bool MainWindow::openImage(const QString& path)
{
  if (this->Job.isRunning())
  {
    this->fail(tr("cannot open an image while meshing; cancel the run first"));
    return false;
  }
  io::LabeledImage input;
  try
  {
    input = io::ReadLabeledImage(path.toStdString());
  }
  catch (const std::exception& e)
  {
    this->fail(QString::fromStdString(e.what()));
    return false;
  }
  this->Image = input.Image;
  this->Materials = input.Materials;
  if (!this->Materials.Empty())
  {
    // As vtkLabelImageReader puts it: the filter passes it to the mesh, where the report finds it.
    labelmesher::StoreMaterialTable(this->Image->GetFieldData(), this->Materials);
  }
  this->Notes.clear();
  for (const std::string& note : input.Notes)
  {
    this->Notes << QString::fromStdString(note);
  }
  this->ImagePath = path;
  int dims[3];
  double spacing[3];
  this->Image->GetDimensions(dims);
  this->Image->GetSpacing(spacing);
  // The filters' voxel (LabelImageConversion's PlaceLabels): a 2D image is meshed across its last
  // single-slice axis, and the voxel is the smallest spacing over the other axes.
  int normal = -1;
  for (int a = 2; a >= 0 && normal < 0; --a)
  {
    normal = dims[a] == 1 ? a : -1;
  }
  double smallest = std::numeric_limits<double>::max();
  for (int a = 0; a < 3; ++a)
  {
    smallest = a == normal ? smallest : std::min(smallest, std::abs(spacing[a]));
  }
  this->Panel->setImageGeometry(normal < 0 ? 3 : 2, smallest);
  this->Report.reset();
  this->Curves.reset();
  this->View->clear();
  this->Histogram->clear();
  this->Summary->setPlainText(tr("%1: %2 x %3 x %4 voxels, spacing %5 x %6 x %7 mm. Press Mesh.")
                                .arg(QFileInfo(path).fileName())
                                .arg(dims[0]).arg(dims[1]).arg(dims[2])
                                .arg(spacing[0]).arg(spacing[1]).arg(spacing[2]));
  this->setWindowTitle(tr("LabelMesher - %1").arg(QFileInfo(path).fileName()));
  this->setMeshingState(false);
  emit imageOpened(path);
  return true;
}

bool MainWindow::startMeshing()
{
  if (!this->Image)
  {
    this->fail(tr("no label image is open (File > Open)"));
    return false;
  }
  if (this->Job.isRunning())
  {
    this->fail(tr("a run is already under way"));
    return false;
  }
  const labelmesher_cli::MeshingSettings settings = SettingsOf(*this->Panel);
  if (!this->Job.start(this->Image, settings))
  {
    this->fail(tr("the run could not be started"));
    return false;
  }
  this->RunSettings = settings;
  this->Progress->setValue(0);
  this->Stage->setText(tr("meshing..."));
  this->setMeshingState(true);
  return true;
}

void MainWindow::cancelMeshing()
{
  if (this->Job.isRunning())
  {
    this->Job.cancel();
    this->Stage->setText(tr("cancelling..."));
    this->CancelButton->setEnabled(false);
  }
}

bool MainWindow::isMeshing() const
{
  return this->Job.isRunning();
}

double MainWindow::progress() const
{
  return static_cast<double>(this->Progress->value()) / kProgressSteps;
}

void MainWindow::setMeshingState(bool running)
{
  this->MeshButton->setEnabled(!running && this->Image);
  this->CancelButton->setEnabled(running);
  this->Panel->setEnabled(!running);
  this->OpenAction->setEnabled(!running);
  const bool haveMesh = !running && this->View->mesh() != nullptr;
  this->SaveMeshAction->setEnabled(haveMesh);
  this->SavePictureAction->setEnabled(haveMesh);
}

void MainWindow::onProgress(double fraction, const QString& stage)
{
  this->Progress->setValue(static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kProgressSteps + 0.5));
  if (!stage.isEmpty())
  {
    this->Stage->setText(stage);
  }
}

void MainWindow::onFinished()
{
  const labelmesher_cli::MeshingOutcome& out = this->Job.outcome();
  labelmesher::report::RunContext context;
  context.Input = this->ImagePath.toStdString();
  context.Outputs = { "(not saved)" };
  for (const QString& note : this->Notes)
  {
    context.Notes.push_back(note.toStdString());
  }
  labelmesher::report::RunReports reports =
    labelmesher::report::MakeRunReports(context, this->Image, out.Mesh, out.Curved);
  this->Report = std::move(reports.Linear);
  this->Curves = std::move(reports.Curved);

  std::map<int, QColor> colours;
  for (const labelmesher::MaterialInfo& m : this->Materials.Entries())
  {
    if (m.HasColor())
    {
      colours[m.Label] = QColor::fromRgbF(m.Color[0], m.Color[1], m.Color[2]);
    }
  }
  this->View->setMesh(out.Curved ? out.Curved : out.Mesh, colours);
  // The line marks the decimator's bound; without decimation none is drawn (the mesher's proven
  // bound, 30 or 45 degrees, is stated in the summary's angle line, not chosen here).
  const double bound = this->RunSettings.Decimate ? this->RunSettings.MinimumAngle : 0.0;
  this->Histogram->setMesh(out.Mesh, bound);
  this->showReport();
  this->Progress->setValue(kProgressSteps);
  const bool quadratic = this->Report && this->Report->Quadratic;
  const bool quadraticTriangles = this->Curves && this->Curves->Order == 2;
  QString done = out.Curved
    ? tr("meshed and curved in %1 s: %2 %3")
        .arg(this->Job.seconds(), 0, 'f', 1)
        .arg(out.Curved->GetNumberOfCells())
        .arg(quadratic ? tr("quadratic tetrahedra") : quadraticTriangles ? tr("quadratic triangles") : tr("curved cells"))
    : tr("meshed in %1 s: %2 cells").arg(this->Job.seconds(), 0, 'f', 1).arg(out.Mesh->GetNumberOfCells());
  // A failed or unfaithful curving is shown (the marked mesh, for inspection) and said plainly.
  if (!out.CurveError.empty())
  {
    done += tr("; CURVING FAILED: %1").arg(QString::fromStdString(out.CurveError));
  }
  else if (this->Curves && (!this->Curves->CurvesFaithful() || !this->Curves->ScaledJacobianHolds() ||
             !this->Curves->CornerAnglesHold()))
  {
    done += tr("; THE CURVES BREAK A BOUND (see the summary)");
  }
  else if (quadratic && !labelmesher::report::QuadraticHolds(*this->Report))
  {
    done += tr("; THE QUADRATIC MESH BREAKS A BOUND (see the summary)");
  }
  else if (!out.Warning.empty())
  {
    done += tr("; warning: %1").arg(QString::fromStdString(out.Warning));
  }
  this->Stage->setText(done);
  this->setMeshingState(false);
  emit meshingFinished();
}

void MainWindow::onCancelled(double fraction)
{
  this->Stage->setText(this->View->mesh() ? tr("cancelled at %1 %; the mesh shown is the previous one").arg(fraction * 100.0, 0, 'f', 0)
                                          : tr("cancelled at %1 %").arg(fraction * 100.0, 0, 'f', 0));
  this->setMeshingState(false);
  emit meshingCancelled();
}

void MainWindow::onFailed(const QString& message)
{
  this->setMeshingState(false);
  this->fail(message);
  emit meshingFailed(message);
}

void MainWindow::showReport()
{
  if (!this->Report)
  {
    return;
  }
  std::ostringstream text;
  // The CLI's own summary.
  if (this->Curves)
  {
    labelmesher::report::PrintCurveSummary(*this->Curves, text);
  }
  else
  {
    labelmesher::report::PrintSummary(*this->Report, text);
  }
  this->Summary->setPlainText(QString::fromStdString(text.str()));
}

QString MainWindow::summaryText() const
{
  return this->Summary->toPlainText();
}

bool MainWindow::saveMesh(const QString& path)
{
  const labelmesher_cli::MeshingOutcome& out = this->Job.outcome();
  if (!out.Mesh || !this->Report)
  {
    this->fail(tr("there is no mesh to save yet"));
    return false;
  }
  const std::optional<labelmesher::io::MeshFormat> format = labelmesher::io::FormatOfPath(path.toStdString());
  const bool quadratic = this->Report->Quadratic.has_value() || (this->Curves && this->Curves->Order == 2);
  if (out.Curved && quadratic && format && !labelmesher::io::HoldsQuadraticCells(*format))
  {
    this->fail(tr("cannot save '%1': quadratic cells can be saved as .vtu, .vtk, .msh, .inp or .mesh only").arg(path));
    return false;
  }
  if (out.Curved && !quadratic && format && !labelmesher::io::HoldsCurvedCells(*format))
  {
    this->fail(tr("cannot save '%1': curved (Bezier) cells can be saved as .vtu, .vtk or .msh only").arg(path));
    return false;
  }
  try
  {
    // A curved or quadratic mesh is saved without the linear interface surface, as the CLI writes
    // it (a quadratic one's interfaces come from its cells, ExportMesh.h).
    labelmesher::io::MeshFileWriter writer(out.Curved ? out.Curved : out.Mesh,
      out.Curved ? nullptr : out.Interfaces.GetPointer(), this->Materials, {});
    const std::vector<std::string> written = writer.Write(path.toStdString());
    this->Report->Outputs = written;
    if (this->Curves)
    {
      this->Curves->Linear.Outputs = written;
    }
  }
  catch (const std::exception& e)
  {
    this->fail(QString::fromStdString(e.what()));
    return false;
  }
  this->showReport();
  this->statusBar()->showMessage(tr("saved %1").arg(path));
  return true;
}

bool MainWindow::savePicture(const QString& path)
{
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  if (!this->View->grabPicture().save(&buffer, "PNG"))
  {
    this->fail(tr("the view could not be encoded as PNG"));
    return false;
  }
  try
  {
    labelmesher::io::SafeFile file(path.toStdString());
    file.Stream().write(png.constData(), png.size());
    file.Commit();
  }
  catch (const std::exception& e)
  {
    this->fail(QString::fromStdString(e.what()));
    return false;
  }
  this->statusBar()->showMessage(tr("saved %1").arg(path));
  return true;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
  if (this->Job.isRunning())
  {
    // The filter stops at its next progress report; measuring cannot stop, so this may take a while.
    this->Stage->setText(tr("stopping the run..."));
    this->Job.cancel();
    QApplication::setOverrideCursor(Qt::WaitCursor);
    this->Job.wait();
    QApplication::restoreOverrideCursor();
  }
  QMainWindow::closeEvent(event);
}

void MainWindow::chooseImage()
{
  const QString path = QFileDialog::getOpenFileName(this, tr("Open label image"), QString(),
    tr("Label images (*.nrrd *.nhdr *.nii *.nii.gz *.mha *.mhd *.vti *.png);;All files (*)"));
  if (!path.isEmpty())
  {
    this->openImage(path);
  }
}

void MainWindow::chooseMeshFile()
{
  const QString path = QFileDialog::getSaveFileName(this, tr("Save mesh"), QString(),
    tr("Meshes (*.vtu *.vtk *.msh *.inp *.mesh *.vtp *.stl *.obj)"));
  if (!path.isEmpty())
  {
    this->saveMesh(path);
  }
}

void MainWindow::choosePictureFile()
{
  const QString path = QFileDialog::getSaveFileName(this, tr("Save picture"), QString(), tr("PNG images (*.png)"));
  if (!path.isEmpty())
  {
    this->savePicture(path);
  }
}

} // namespace gui
} // namespace labelmesher
