// SPDX-License-Identifier: GPL-2.0-or-later
// The README's C++ pipeline, compiled and run as a test (Testing/Examples): a label image (.vti)
// through vtkLabelMesher (mesher and decimator, streamed) into a .vtu. The block between the README
// markers is what the README shows; check_examples.py keeps the two the same.
#include "vtkLabelMesher.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: MeshLabelImage LABELS.vti MESH.vtu\n";
    return 2;
  }
  // README:begin
  vtkNew<vtkXMLImageDataReader> reader;            // integer labels, 0 = background
  reader->SetFileName(argv[1]);
  vtkNew<vtkLabelMesher> mesher;                   // mesher and decimator, block by block
  mesher->SetInputConnection(reader->GetOutputPort());
  mesher->SetImageToMeshDistance(1.5);             // voxels of the smallest spacing
  mesher->SetMeshToImageDistance(1.5);
  mesher->SetMinimumAngle(15.0);                   // degrees
  mesher->SetBlockCells(1000000);                  // initial cells a block: the memory in flight
  vtkNew<vtkXMLUnstructuredGridWriter> writer;     // tetrahedra + cell array "Material"
  writer->SetInputConnection(mesher->GetOutputPort(0));
  writer->SetFileName(argv[2]);
  if (writer->Write() != 1)                        // a filter's or the writer's error
  {
    return 1;
  }
  // GetInterfacesOutput(): the material interfaces, cell array "Materials" (2 labels)
  // README:end
  std::cout << mesher->GetOutput()->GetNumberOfCells() << " cells\n";
  return 0;
}
