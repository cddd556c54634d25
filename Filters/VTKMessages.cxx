// SPDX-License-Identifier: GPL-2.0-or-later
// Turns a VTK object's error and warning events into one plain line instead of VTK's log records.
#include "VTKMessages.h"

#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

#include <algorithm>

namespace labelmesher
{

VTKMessages::VTKMessages(vtkObject* object, unsigned long event)
{
  this->Command->SetClientData(this);
  this->Command->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto* self = static_cast<VTKMessages*>(clientData);
    if (!self->FirstMessage.empty() || !callData)
    {
      return;
    }
    std::string text = static_cast<const char*>(callData);
    const std::size_t at = text.find("): ");
    text = at == std::string::npos ? text : text.substr(at + 3);
    text.erase(std::remove(text.begin(), text.end(), '\n'), text.end());
    self->FirstMessage = text.empty() ? "unknown VTK error" : text;
  });
  this->Observed = object;
  this->Tag = object->AddObserver(event, this->Command);
}

VTKMessages::~VTKMessages()
{
  if (this->Observed)
  {
    this->Observed->RemoveObserver(this->Tag);
  }
}

namespace
{
class SilentOutputWindow : public vtkOutputWindow
{
public:
  static SilentOutputWindow* New();
  vtkTypeMacro(SilentOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
};
vtkStandardNewMacro(SilentOutputWindow);
} // namespace

void SilenceVTKOutputWindow()
{
  vtkNew<SilentOutputWindow> silent;
  vtkOutputWindow::SetInstance(silent); // keeps its own reference
  // VTK 9.1 also logs every vtkErrorMacro through vtkLogger (loguru), which writes straight to
  // stderr, past the output window: found by fuzzing the VTI reader ("vtkXMLDataParser.cxx:889
  // ERR| ... ReadCompressionHeader failed" in red before the CLI's own line).
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

} // namespace labelmesher
