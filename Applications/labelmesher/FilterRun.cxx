// SPDX-License-Identifier: GPL-2.0-or-later
#include "FilterRun.h"

#include "VTKMessages.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"

namespace labelmesher_cli
{

using labelmesher::VTKMessages;

FilterMessages UpdateFilter(vtkAlgorithm* algorithm, const FilterProgress& progress)
{
  VTKMessages errors(algorithm, vtkCommand::ErrorEvent);
  VTKMessages warnings(algorithm, vtkCommand::WarningEvent);
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(const_cast<FilterProgress*>(&progress));
  observer->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
    auto* running = static_cast<vtkAlgorithm*>(caller);
    const char* stage = running->GetProgressText();
    (*static_cast<const FilterProgress*>(clientData))(running, *static_cast<double*>(callData), stage ? stage : "");
  });
  unsigned long tag = 0;
  if (progress)
  {
    tag = algorithm->AddObserver(vtkCommand::ProgressEvent, observer);
  }
  algorithm->Update();
  if (progress)
  {
    algorithm->RemoveObserver(tag);
  }
  return { errors.First(), warnings.First() };
}

} // namespace labelmesher_cli
