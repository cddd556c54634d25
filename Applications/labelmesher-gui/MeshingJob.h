// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_gui_MeshingJob_h
#define labelmesher_gui_MeshingJob_h

/**
 * @file MeshingJob.h
 * One run of the meshing pipeline (MeshingPipeline.h: vtkLabelOctreeMesher,
 * vtkMeshDecimator and, for 2D images on request, vtkBezierCurver) in a worker
 * thread, so the window stays live: progress arrives as signals in the
 * window's thread, cancel() makes the running filter
 * stop at its next progress report (AbortExecute, set from the worker's own
 * progress observer), and the meshes are handed over only when the thread has
 * finished with them.
 */

#include "MeshingPipeline.h"

#include <QObject>
#include <QString>

#include <memory>

class QThread;
class vtkImageData;

namespace labelmesher
{
namespace gui
{

class MeshingJob : public QObject
{
  Q_OBJECT

public:
  explicit MeshingJob(QObject* parent = nullptr);
  /// Cancels a run under way and waits for its thread.
  ~MeshingJob() override;

  /// Starts meshing `image` (label scalars) with `settings`; false when a run is under way.
  bool start(vtkImageData* image, const labelmesher_cli::MeshingSettings& settings);
  /// Asks the running filter to stop; cancelled() follows once it has (or finished() when the
  /// request came during a stage that cannot stop, measuring, and the mesh is complete).
  void cancel();
  bool isRunning() const;
  /// Blocks until the worker has finished (its signal still arrives through the event loop).
  void wait();
  /// The last finished run's meshes (empty before the first); Initial keeps only the mesher's
  /// field data (its timings) when the mesh was decimated.
  const labelmesher_cli::MeshingOutcome& outcome() const { return this->Last; }
  double seconds() const { return this->LastSeconds; } ///< of the last finished run

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
  labelmesher_cli::MeshingOutcome Last;
  double LastSeconds = 0.0;
};

} // namespace gui
} // namespace labelmesher

#endif
