// SPDX-License-Identifier: GPL-2.0-or-later
#include "FilterStage.h"

#include "VTKMessages.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"

#include <algorithm>

namespace labelmesher
{
namespace
{
struct StageShare
{
  vtkAlgorithm* Outer;
  double Start, Share;
};
} // namespace

StageMessages RunAsStage(vtkAlgorithm* outer, vtkAlgorithm* inner, double start, double share)
{
  VTKMessages errors(inner, vtkCommand::ErrorEvent);
  VTKMessages warnings(inner, vtkCommand::WarningEvent);
  StageShare stage{ outer, start, share };
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(&stage);
  forward->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
    const auto* s = static_cast<const StageShare*>(clientData);
    auto* running = static_cast<vtkAlgorithm*>(caller);
    s->Outer->SetProgressText(running->GetProgressText());
    s->Outer->UpdateProgress(s->Start + s->Share * std::clamp(*static_cast<double*>(callData), 0.0, 1.0));
    // The outer filter's observers may have asked it to stop during this report.
    if (s->Outer->GetAbortExecute())
    {
      running->SetAbortExecute(1);
    }
  });
  // VTK clears the inner filter's AbortExecute when it starts: a stop reaches it through its first
  // progress report.
  const unsigned long tag = inner->AddObserver(vtkCommand::ProgressEvent, forward);
  inner->Update();
  inner->RemoveObserver(tag);
  return { errors.First(), warnings.First() };
}

} // namespace labelmesher
