// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_VTKMessages_h
#define labelmesher_VTKMessages_h

/**
 * @file VTKMessages.h
 * Catches the error (or warning) events of one VTK object instead of letting VTK
 * print them, and keeps the first message as one line, without VTK's
 * "ERROR: In file, line ... Class (0x...): " prefix.
 */

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkWeakPointer.h"

#include <string>

class vtkObject;

namespace labelmesher
{

class VTKMessages
{
public:
  /// `event`: vtkCommand::ErrorEvent or vtkCommand::WarningEvent.
  VTKMessages(vtkObject* object, unsigned long event);
  /// Stops observing (the object may outlive this catcher).
  ~VTKMessages();
  VTKMessages(const VTKMessages&) = delete;
  VTKMessages& operator=(const VTKMessages&) = delete;

  /// The first message caught; empty if none.
  const std::string& First() const { return this->FirstMessage; }

private:
  std::string FirstMessage;
  vtkNew<vtkCallbackCommand> Command;
  vtkWeakPointer<vtkObject> Observed;
  unsigned long Tag = 0;
};

/// Replaces VTK's output window by one that drops everything and turns off
/// vtkLogger's stderr output: VTK's log records (file, line, object address,
/// colours) never reach the user; the errors and warnings that matter are
/// caught by VTKMessages and reported as one line.
void SilenceVTKOutputWindow();

} // namespace labelmesher

#endif
