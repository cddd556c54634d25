// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_cli_ProgressBar_h
#define labelmesher_cli_ProgressBar_h

/**
 * @file ProgressBar.h
 * A one-line progress bar on stderr, drawn only when stderr is a terminal.
 */

#include "FilterRun.h"

#include <memory>
#include <string>

namespace labelmesher_cli
{

class ProgressBar
{
public:
  /// Draws only if `enabled` and stderr is a terminal.
  explicit ProgressBar(bool enabled);
  ~ProgressBar();
  void Update(double fraction, const std::string& stage);
  /// Clears the line (also done by the destructor).
  void Finish();

private:
  bool Enabled;
  bool Drawn = false;
  int LastPercent = -1;
  std::string LastStage;
};

/// Progress of a run of filters on the terminal: one bar per filter, cleared when the next
/// filter reports or at Finish().
class TerminalProgress
{
public:
  explicit TerminalProgress(bool enabled)
    : Enabled(enabled)
  {
  }
  /// What UpdateFilter / RunMeshingPipeline call; valid while this object lives.
  FilterProgress Function();
  void Finish();

private:
  bool Enabled;
  const void* Current = nullptr; ///< the filter the bar shows
  std::unique_ptr<ProgressBar> Bar;
};

} // namespace labelmesher_cli

#endif
