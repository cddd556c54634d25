// SPDX-License-Identifier: GPL-2.0-or-later
#include "MeshingJob.h"

#include "VTKMessages.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkLabelOctreeMesher.h"
#include "vtkMeshDecimator.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <QThread>

#include <chrono>
#include <cmath>

namespace labelmesher
{
namespace gui
{

/// The state one worker thread owns; the window's thread reads it only after the thread ended.
struct MeshingJob::Run
{
  MeshingSettings Settings;
  vtkSmartPointer<vtkImageData> Image;
  std::atomic<bool> CancelRequested{ false };
  std::atomic<double> Fraction{ 0.0 };
  bool Aborted = false;
  QString Error;
  MeshingOutcome Outcome;
};

namespace
{
/// Share of the whole run's progress the mesher takes when the decimator follows (the
/// decimator's merges and checks take most of the time).
constexpr double kMesherShare = 0.3;

struct ProgressContext
{
  MeshingJob* Job;
  std::atomic<bool>* CancelRequested;
  std::atomic<double>* Fraction;
  double Start, Share;
  double LastSent = -1.0;
};

/// Runs `algorithm`, forwarding its progress; returns its first error (empty if none) and keeps
/// its first warning in `warning` (VTK's output window sees neither).
QString UpdateFilter(vtkAlgorithm* algorithm, ProgressContext& context, QString& warning)
{
  labelmesher_cli::VTKMessages errors(algorithm, vtkCommand::ErrorEvent);
  labelmesher_cli::VTKMessages warnings(algorithm, vtkCommand::WarningEvent);
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&context);
  observer->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
    auto* c = static_cast<ProgressContext*>(clientData);
    auto* running = static_cast<vtkAlgorithm*>(caller);
    if (c->CancelRequested->load())
    {
      running->SetAbortExecute(1); // read by the filter right after this report
    }
    const double fraction = c->Start + c->Share * *static_cast<double*>(callData);
    c->Fraction->store(fraction);
    // Queued to the window's thread; a few hundred events per run at most.
    if (fraction - c->LastSent >= 0.005 || fraction >= 1.0)
    {
      c->LastSent = fraction;
      const char* stage = running->GetProgressText();
      emit c->Job->progressed(fraction, QString::fromUtf8(stage ? stage : ""));
    }
  });
  algorithm->AddObserver(vtkCommand::ProgressEvent, observer);
  algorithm->Update();
  if (warning.isEmpty())
  {
    warning = QString::fromStdString(warnings.First());
  }
  return QString::fromStdString(errors.First());
}

template <typename T>
vtkSmartPointer<T> CopyOf(T* data)
{
  auto copy = vtkSmartPointer<T>::New();
  copy->ShallowCopy(data);
  return copy;
}
} // namespace

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

bool MeshingJob::start(vtkImageData* image, const MeshingSettings& settings)
{
  if (this->Thread || !image)
  {
    return false;
  }
  auto run = std::make_shared<Run>();
  run->Settings = settings;
  run->Image = CopyOf(image); // the filters' pipeline information stays off the window's image
  this->Current = run;
  this->Thread = QThread::create([this, run]() {
    const auto start = std::chrono::steady_clock::now();
    const MeshingSettings& s = run->Settings;
    // The decimator needs the whole box (background cells) and measures the final mesh itself.
    vtkNew<vtkLabelOctreeMesher> mesher;
    mesher->SetImageToMeshDistance(s.ImageToMeshDistance);
    mesher->SetMeshToImageDistance(s.MeshToImageDistance);
    mesher->SetIncludeBackground(s.Decimate);
    mesher->SetMeasureOutput(!s.Decimate);
    mesher->SetInputData(run->Image);
    ProgressContext context{ this, &run->CancelRequested, &run->Fraction, 0.0, s.Decimate ? kMesherShare : 1.0 };
    run->Error = UpdateFilter(mesher, context, run->Outcome.Warning);
    run->Aborted = mesher->GetAbortExecute() != 0;
    if (!run->Error.isEmpty() || run->Aborted)
    {
      return;
    }
    MeshingOutcome& out = run->Outcome;
    out.Initial = CopyOf(mesher->GetOutput());
    out.Mesh = out.Initial;
    out.Interfaces = CopyOf(mesher->GetBoundaryOutput());
    if (s.Decimate)
    {
      vtkNew<vtkMeshDecimator> decimator;
      decimator->SetMinimumAngle(s.MinimumAngle);
      decimator->SetIncludeBackground(false);
      decimator->SetMeasureOutput(true);
      decimator->SetInputDataObject(0, out.Initial);
      decimator->SetInputDataObject(1, run->Image);
      context.Start = kMesherShare;
      context.Share = 1.0 - kMesherShare;
      run->Error = UpdateFilter(decimator, context, out.Warning);
      run->Aborted = decimator->GetAbortExecute() != 0;
      if (!run->Error.isEmpty() || run->Aborted)
      {
        return;
      }
      out.Mesh = CopyOf(decimator->GetOutput());
      out.Interfaces = CopyOf(decimator->GetBoundaryOutput());
    }
    if (out.Mesh->GetNumberOfCells() == 0)
    {
      run->Error = tr("the filters produced no cells (is every voxel background?)");
    }
    out.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
  if (run->Aborted)
  {
    emit cancelled(run->Fraction.load());
  }
  else if (!run->Error.isEmpty())
  {
    emit failed(run->Error);
  }
  else
  {
    this->Last = run->Outcome;
    emit finished();
  }
}

} // namespace gui
} // namespace labelmesher
