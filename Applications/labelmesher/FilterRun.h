// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_cli_FilterRun_h
#define labelmesher_cli_FilterRun_h

/**
 * @file FilterRun.h
 * Runs one VTK filter as both front ends need it: its progress events handed to
 * a function (a terminal bar, a Qt signal, a cancel check), its first error and
 * first warning kept as one line each instead of reaching VTK's output window.
 */

#include <functional>
#include <string>

class vtkAlgorithm;

namespace labelmesher_cli
{

/// Called on each progress event: the running filter, its own fraction in [0, 1], its stage
/// text (may be empty). Setting AbortExecute on the filter here stops it at this report.
using FilterProgress = std::function<void(vtkAlgorithm* running, double fraction, const std::string& stage)>;

struct FilterMessages
{
  std::string Error;   ///< the first error, empty if none
  std::string Warning; ///< the first warning, empty if none
};

/// algorithm->Update() with `progress` (may be empty) observing it.
FilterMessages UpdateFilter(vtkAlgorithm* algorithm, const FilterProgress& progress);

} // namespace labelmesher_cli

#endif
