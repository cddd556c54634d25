// SPDX-License-Identifier: GPL-2.0-or-later
#include "MeshingJob.h"

#include "vtkAlgorithm.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <QThread>

#include <atomic>
#include <chrono>

namespace labelmesher
{
namespace gui
{
/// The state one worker owns; the window's thread reads it only after the thread ended.
struct MeshingJob::Run
{
  labelmesher_cli::MeshingSettings Settings;
  vtkSmartPointer<vtkImageData> Image;
  std::atomic<bool> CancelRequested{ false };
  double Fraction = 0.0, LastSent = -1.0;
  labelmesher_cli::MeshingOutcome Outcome;
  QString Error;
  double Seconds = 0.0;
};

MeshingJob::MeshingJob(QObject* parent)
  : QObject(parent)
{
}

MeshingJob::~MeshingJob()
{
  if (this->Thread)
  {
    this->cancel();
    this->Thread->wait();
    delete this->Thread; // its finished() is not delivered any more
  }
}

bool MeshingJob::isRunning() const
{
  return this->Thread != nullptr;
}

void MeshingJob::cancel()
{
  if (this->Current)
  {
    this->Current->CancelRequested.store(true);
  }
}

void MeshingJob::wait()
{
  if (this->Thread)
  {
    this->Thread->wait();
  }
}

bool MeshingJob::start(vtkImageData* image, const labelmesher_cli::MeshingSettings& settings)
{
  if (this->Thread || !image)
  {
    return false;
  }
  auto run = std::make_shared<Run>();
  run->Settings = settings;
  run->Image = vtkSmartPointer<vtkImageData>::New();
  run->Image->ShallowCopy(image); // the filters' pipeline information stays off the window's image
  this->Current = run;
  this->Thread = QThread::create([this, run]() {
    const auto start = std::chrono::steady_clock::now();
    // Runs in this worker thread, on each progress report of vtkLabelMesher (over the whole run).
    const labelmesher_cli::FilterProgress progress = [this, run](
                                                       vtkAlgorithm* running, double fraction, const std::string& stage) {
      if (run->CancelRequested.load())
      {
        running->SetAbortExecute(1); // read by the filter right after this report
      }
      run->Fraction = fraction;
      // Queued to the window's thread; a few hundred signals per run at most.
      if (fraction - run->LastSent >= 0.005 || fraction >= 1.0)
      {
        run->LastSent = fraction;
        emit this->progressed(fraction, QString::fromStdString(stage));
      }
    };
    try
    {
      run->Outcome = labelmesher_cli::RunMeshingPipeline(run->Image, run->Settings, progress);
    }
    catch (const std::exception& e)
    {
      run->Error = QString::fromStdString(e.what());
    }
    run->Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  connect(this->Thread, &QThread::finished, this, &MeshingJob::onThreadFinished);
  this->Thread->start();
  return true;
}

void MeshingJob::onThreadFinished()
{
  std::shared_ptr<Run> run = std::move(this->Current);
  this->Thread->deleteLater();
  this->Thread = nullptr;
  if (!run->Error.isEmpty())
  {
    emit failed(run->Error);
    return;
  }
  if (run->Outcome.Aborted)
  {
    emit cancelled(run->Fraction);
    return;
  }
  this->Last = run->Outcome;
  this->LastSeconds = run->Seconds;
  emit finished();
}

} // namespace gui
} // namespace labelmesher
