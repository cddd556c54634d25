// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_gui_MainWindow_h
#define labelmesher_gui_MainWindow_h

/**
 * @file MainWindow.h
 * labelmesher-gui's window: open a label image (the CLI's checked readers), set
 * the parameters (ParameterPanel), mesh in a worker thread (MeshingJob) with a
 * progress bar and Cancel, look at the mesh (MeshView, clipping plane) and its
 * quality (AngleHistogram and the CLI's own summary text), save the mesh in any
 * of the CLI's formats and the picture as PNG. A 2D image can be curved
 * (vtkBezierCurver): the view then shows the cubic Bezier cells, the summary
 * is the CLI's curve report, and the mesh is saved as .vtu, .vtk or .msh (the formats
 * that hold Bezier cells); the histogram stays that of the linear mesh the
 * curves were made from (its corners are the curved cells'). The public methods are what the
 * menus and buttons call, so a test drives the window exactly as a user does.
 */

#include "Report/CurveReport.h"
#include "MeshingJob.h"
#include "Report/RunReport.h"

#include "MaterialTable.h"

#include "vtkSmartPointer.h"

#include <QMainWindow>
#include <QString>
#include <QStringList>

#include <optional>

class QAction;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class vtkImageData;

namespace labelmesher
{
namespace widgets
{
class AngleHistogram;
class MeshView;
class ParameterPanel;
}

namespace gui
{

class MainWindow : public QMainWindow
{
  Q_OBJECT

public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Reads a label image (NRRD/NHDR, NIfTI, MetaImage, VTI, PNG, .seg.nrrd); on failure
  /// errorOccurred() and the window keeps what it had.
  bool openImage(const QString& path);
  /// Meshes the open image with the panel's parameters; false (and errorOccurred) without an
  /// image or while a run is under way.
  bool startMeshing();
  /// Stops the run under way (meshingCancelled() follows); nothing without one.
  void cancelMeshing();
  bool isMeshing() const;
  /// Writes the shown mesh; the format is the extension's (.vtu, .vtk, .msh, .inp, .mesh, .vtp,
  /// .stl, .obj; a curved mesh .vtu, .vtk or .msh only), the file whole or not at all.
  bool saveMesh(const QString& path);
  /// Writes the view as PNG, whole or not at all.
  bool savePicture(const QString& path);

  widgets::ParameterPanel* parameters() const { return this->Panel; }
  widgets::MeshView* view() const { return this->View; }
  widgets::AngleHistogram* histogram() const { return this->Histogram; }
  /// The last finished run's report (the CLI's figures), if any.
  const std::optional<labelmesher::report::RunReport>& report() const { return this->Report; }
  /// The last finished run's curve report, when it curved the mesh.
  const std::optional<labelmesher::report::CurveReport>& curveReport() const { return this->Curves; }
  QString summaryText() const;
  double progress() const; ///< of the run under way (or the last), [0, 1]

signals:
  /// A failure the user must see, in one sentence (main() shows it in a message box).
  void errorOccurred(const QString& message);
  void imageOpened(const QString& path);
  void meshingFinished();
  void meshingCancelled();
  void meshingFailed(const QString& message);

private:
  void buildMenus();
  void setMeshingState(bool running);
  void showReport();
  void onProgress(double fraction, const QString& stage);
  void onFinished();
  void onCancelled(double fraction);
  void onFailed(const QString& message);
  void chooseImage();
  void chooseMeshFile();
  void choosePictureFile();
  void fail(const QString& message);
  void closeEvent(QCloseEvent* event) override;

  MeshingJob Job;
  vtkSmartPointer<vtkImageData> Image;
  labelmesher::MaterialTable Materials;
  QStringList Notes;
  QString ImagePath;
  labelmesher_cli::MeshingSettings RunSettings; ///< those of the run under way (or the last)
  std::optional<labelmesher::report::RunReport> Report;
  std::optional<labelmesher::report::CurveReport> Curves;

  widgets::ParameterPanel* Panel = nullptr;
  widgets::MeshView* View = nullptr;
  widgets::AngleHistogram* Histogram = nullptr;
  QPlainTextEdit* Summary = nullptr;
  QPushButton* MeshButton = nullptr;
  QPushButton* CancelButton = nullptr;
  QProgressBar* Progress = nullptr;
  QLabel* Stage = nullptr;
  QAction* OpenAction = nullptr;
  QAction* SaveMeshAction = nullptr;
  QAction* SavePictureAction = nullptr;
};

} // namespace gui
} // namespace labelmesher

#endif
