// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_cli_ProgressBar_h
#define labelmesher_cli_ProgressBar_h

/**
 * @file ProgressBar.h
 * A one-line progress bar on stderr, drawn only when stderr is a terminal.
 */

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

} // namespace labelmesher_cli

#endif
