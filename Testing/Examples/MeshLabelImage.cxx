// SPDX-License-Identifier: GPL-2.0-or-later
// The README's C++ pipeline, compiled and run as a test (Testing/Examples): a label image (.vti)
// through vtkLabelOctreeMesher and vtkMeshDecimator into a .vtu. The block between the README
// markers is what the README shows; check_examples.py keeps the two the same.
#include "vtkLabelOctreeMesher.h"
#include "vtkMeshDecimator.h"
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
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputConnection(reader->GetOutputPort());
  mesher->SetImageToMeshDistance(1.5);             // voxels of the smallest spacing
  mesher->SetMeshToImageDistance(1.5);
  mesher->SetIncludeBackground(true);              // the decimator needs the whole box
  mesher->SetMeasureOutput(false);                 // the decimator measures its own output
  mesher->SetCheckMemoryForDecimation(true);       // refuse up front what the decimator could not hold
  vtkNew<vtkMeshDecimator> decimator;
  decimator->SetInputConnection(0, mesher->GetOutputPort(0));
  decimator->SetInputConnection(1, reader->GetOutputPort());  // the image the mesh came from
  decimator->SetMinimumAngle(15.0);                // degrees; distances: the mesher's by default
  vtkNew<vtkXMLUnstructuredGridWriter> writer;     // tetrahedra + cell array "Material"
  writer->SetInputConnection(decimator->GetOutputPort(0));
  writer->SetFileName(argv[2]);
  if (writer->Write() != 1)                        // a filter's or the writer's error
  {
    return 1;
  }
  // GetBoundaryOutput() of either filter: the material interfaces, cell array "Materials" (2 labels)
  // README:end
  std::cout << decimator->GetOutput()->GetNumberOfCells() << " cells\n";
  return 0;
}
