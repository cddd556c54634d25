// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_VtkFileWriters_h
#define labelmesher_io_VtkFileWriters_h

/**
 * @file VtkFileWriters.h
 * VTK's own formats through VTK's writers, into a checked stream: .vtu (XML,
 * appended, zlib level 1), legacy .vtk (binary) and .vtp (the interface
 * surface). String arrays of the field data (StageName, MaterialName) are
 * written as unsigned-char arrays of the same name holding the UTF-8 strings
 * one after another, each ended by a NUL byte: readers without VTK's String
 * type (meshio) then read the file (`bytes(a).split(b"\\0")[:-1]` in Python).
 */

#include "vtkCallbackCommand.h"
#include "vtkNew.h"

#include <ostream>
#include <string>
#include <vector>

class vtkDataObject;
class vtkObject;

namespace labelmesher
{
namespace io
{

/// The first error event of a VTK object (a writer), kept from construction on.
class FirstVtkError
{
public:
  explicit FirstVtkError(vtkObject* object);
  ~FirstVtkError();
  FirstVtkError(const FirstVtkError&) = delete; // the callback holds this object's address
  FirstVtkError& operator=(const FirstVtkError&) = delete;
  /// "" while none; else VTK's message without its log prefix ("ERROR: In file, line N ...): ").
  std::string Message() const;

private:
  std::string Text;
  vtkObject* Object;
  unsigned long Tag;
  vtkNew<vtkCallbackCommand> Callback;
};

void WriteVtu(vtkDataObject* mesh, std::ostream& out);
void WriteLegacyVtk(vtkDataObject* mesh, std::ostream& out);
void WriteVtp(vtkDataObject* surface, std::ostream& out);

} // namespace io
} // namespace labelmesher

#endif
