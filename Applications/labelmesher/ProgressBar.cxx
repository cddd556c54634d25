// SPDX-License-Identifier: GPL-2.0-or-later
// Draws the CLI's one-line progress bar on stderr when it is a terminal.
#include "ProgressBar.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace labelmesher_cli
{

ProgressBar::ProgressBar(bool enabled)
  : Enabled(enabled && isatty(fileno(stderr)))
{
}

ProgressBar::~ProgressBar()
{
  this->Finish();
}

void ProgressBar::Update(double fraction, const std::string& stage)
{
  if (!this->Enabled)
  {
    return;
  }
  const int percent = static_cast<int>(100.0 * std::clamp(fraction, 0.0, 1.0));
  if (percent == this->LastPercent && stage == this->LastStage)
  {
    return;
  }
  this->LastPercent = percent;
  this->LastStage = stage;
  constexpr int width = 30;
  const int filled = percent * width / 100;
  std::fprintf(stderr, "\r%3d%% [%.*s%*s] %-24.24s", percent, filled,
    "##############################", width - filled, "", stage.c_str());
  std::fflush(stderr);
  this->Drawn = true;
}

void ProgressBar::Finish()
{
  if (this->Drawn)
  {
    std::fprintf(stderr, "\r%*s\r", 64, "");
    std::fflush(stderr);
    this->Drawn = false;
  }
}

FilterProgress TerminalProgress::Function()
{
  return [this](vtkAlgorithm* running, double fraction, const std::string& stage) {
    if (running != this->Current)
    {
      this->Bar = std::make_unique<ProgressBar>(this->Enabled); // the previous one clears its line
      this->Current = running;
    }
    this->Bar->Update(fraction, stage);
  };
}

void TerminalProgress::Finish()
{
  this->Bar.reset();
  this->Current = nullptr;
}

} // namespace labelmesher_cli
