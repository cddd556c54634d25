// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ProgressObserver_h
#define labelmesher_ProgressObserver_h

/**
 * @file ProgressObserver.h
 * How long-running core work reports progress and learns that it should stop,
 * without the core knowing about VTK (the adapters forward to UpdateProgress /
 * GetAbortExecute, the CLI to a progress bar).
 */

#include <functional>
#include <string>

namespace labelmesher
{

struct ProgressObserver
{
  /// Called with a stage name and the overall fraction done in [0, 1]. Returns
  /// false when the caller wants the work abandoned.
  std::function<bool(const std::string& stage, double fraction)> Callback;

  bool Report(const std::string& stage, double fraction) const
  {
    return !Callback || Callback(stage, fraction);
  }
};

/// Thrown by core work when a ProgressObserver asked it to stop.
struct AbortRequested
{
};

} // namespace labelmesher

#endif
