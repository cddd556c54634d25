// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_FilterStage_h
#define labelmesher_FilterStage_h

/**
 * @file FilterStage.h
 * Runs one filter as a stage of another (vtkLabelMesher runs vtkLabelOctreeMesher and
 * vtkBezierCurver so): the inner filter's progress becomes a share of the outer one's, a request
 * to stop the outer filter (AbortExecute) reaches the inner one at its next report, and the inner
 * filter's first error and warning are caught as one line each instead of reaching VTK's output
 * window, for the outer filter to report as its own.
 */

#include <string>

class vtkAlgorithm;

namespace labelmesher
{

struct StageMessages
{
  std::string Error;   ///< the inner filter's first error, empty if none
  std::string Warning; ///< its first warning, empty if none
};

/// inner->Update() as the part [start, start + share] of outer's progress.
StageMessages RunAsStage(vtkAlgorithm* outer, vtkAlgorithm* inner, double start, double share);

} // namespace labelmesher

#endif
