// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_gui_MeshingJob_h
#define labelmesher_gui_MeshingJob_h

/**
 * @file MeshingJob.h
 * One run of vtkLabelOctreeMesher (and vtkMeshDecimator) in a worker thread, so
 * the window stays live: progress arrives as signals in the window's thread,
 * cancel() makes the running filter stop at its next progress report
 * (AbortExecute, set from the worker's own progress observer), and the meshes
 * are handed over only when the thread has finished with them.
 */

#include "vtkSmartPointer.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

class QThread;
class vtkImageData;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace labelmesher
{
namespace gui
{

/// What a run uses: the filters' parameters (distances in voxels of the smallest spacing).
struct MeshingSettings
{
  double ImageToMeshDistance = 2.0;
  double MeshToImageDistance = 2.0;
  bool Decimate = true;
  double MinimumAngle = 15.0; ///< degrees, the decimator's bound
};

/// What a finished run made.
struct MeshingOutcome
{
  vtkSmartPointer<vtkUnstructuredGrid> Mesh;    ///< what is shown and saved
  vtkSmartPointer<vtkUnstructuredGrid> Initial; ///< the mesher's output (its timings)
  vtkSmartPointer<vtkPolyData> Interfaces;      ///< faces between materials, on Mesh's points
  double Seconds = 0.0;
  QString Warning; ///< the filters' first warning (e.g. a label left out), empty if none
};

class MeshingJob : public QObject
{
  Q_OBJECT

public:
  explicit MeshingJob(QObject* parent = nullptr);
  /// Cancels a run under way and waits for its thread.
  ~MeshingJob() override;

  /// Starts meshing `image` (label scalars) with `settings`; false when a run is under way.
  bool start(vtkImageData* image, const MeshingSettings& settings);
  /// Asks the running filter to stop; cancelled() follows once it has.
  void cancel();
  bool isRunning() const;
  /// Blocks until the thread has finished (its signal still arrives through the event loop).
  void wait();
  /// The last finished run's meshes (empty before the first).
  const MeshingOutcome& outcome() const { return this->Last; }

signals:
  /// fraction in [0, 1] of the whole run; stage: the running filter's stage.
  void progressed(double fraction, const QString& stage);
  void finished();
  void failed(const QString& message);
  /// The run stopped on request at `fraction` of its progress; the previous outcome stays.
  void cancelled(double fraction);

private:
  struct Run;
  void onThreadFinished();

  QThread* Thread = nullptr;
  std::shared_ptr<Run> Current;
  MeshingOutcome Last;
};

} // namespace gui
} // namespace labelmesher

#endif
