// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkLabelMeshWriter
 * @brief   write a labelled mesh in the format its file name's extension
 *          names (Gmsh, Abaqus, Medit, VTK, STL, OBJ), whole or not at all
 *
 * vtkLabelMeshWriter writes what `labelmesher mesh -o FILE` writes, chosen by
 * FileName's extension (case-insensitive):
 *
 * | extension | format                          | holds                  |
 * |-----------|---------------------------------|------------------------|
 * | .msh      | Gmsh MSH 4.1 (or 2.2) ASCII     | cells, interfaces      |
 * | .inp      | Abaqus input                    | cells, interface nodes |
 * | .mesh     | Medit, MeshVersionFormatted 2   | cells, interfaces      |
 * | .vtu      | VTK XML unstructured grid       | cells, all arrays      |
 * | .vtk      | VTK legacy, binary              | cells, all arrays      |
 * | .vtp      | VTK XML polydata                | interfaces             |
 * | .stl      | binary STL (3D)                 | interfaces             |
 * | .obj      | Wavefront OBJ                   | interfaces             |
 *
 * Input port 0: the mesh (vtkUnstructuredGrid of triangles or tetrahedra,
 * cell array `Material`), as the LabelMesher filters give it. Input port 1
 * (optional): the interface surface (vtkPolyData, cell array `Materials`),
 * their output port 1; without it the finite-element formats carry no
 * interface faces and the surface formats cannot be written. Material names
 * and colours come from the mesh's field data (`MaterialLabel`,
 * `MaterialName`, `MaterialColor`, which vtkLabelImageReader reads from a
 * 3D Slicer segmentation and the filters pass on); a material without a name
 * is `label_N`.
 *
 * Every file is written to a temporary beside the target, each write checked,
 * and renamed over the target at the end: a failed write (full disk, missing
 * folder, a folder in the way) leaves no partial file, reports one line
 * (ErrorEvent and GetErrorText()) and makes Write() return 0. So does a mesh
 * with no cells (what a filter that failed upstream leaves) or without the
 * `Material` array. (With StlPerInterface each interface's file is written
 * whole, but a failure at one leaves those written before it.)
 *
 * @sa
 * vtkLabelImageReader vtkLabelMesher
 */

#ifndef vtkLabelMeshWriter_h
#define vtkLabelMeshWriter_h

#include "LabelMesherIOModule.h" // For export macro
#include "vtkWriter.h"

#include <string> // For the error

class vtkPolyData;
class vtkUnstructuredGrid;

class LABELMESHERIO_EXPORT vtkLabelMeshWriter : public vtkWriter
{
public:
  static vtkLabelMeshWriter* New();
  vtkTypeMacro(vtkLabelMeshWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to write; its extension chooses the format (table above).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * .msh only: write Gmsh MSH 2.2 (what FEniCS' dolfin-convert, Elmer and
   * older FEBio read) instead of 4.1. Default off.
   */
  vtkSetMacro(GmshVersion22, bool);
  vtkGetMacro(GmshVersion22, bool);
  vtkBooleanMacro(GmshVersion22, bool);
  ///@}

  ///@{
  /**
   * .stl only: one file per interface, `NAME_a_b.stl` beside FileName,
   * instead of one file. Default off.
   */
  vtkSetMacro(StlPerInterface, bool);
  vtkGetMacro(StlPerInterface, bool);
  vtkBooleanMacro(StlPerInterface, bool);
  ///@}

  /// The interface surface on port 1 (may be omitted).
  void SetInterfacesData(vtkPolyData* interfaces);
  void SetInterfacesConnection(vtkAlgorithmOutput* output);

  /// The last write's error, one line; empty after a write that succeeded.
  const char* GetErrorText() { return this->ErrorText.c_str(); }

  /// ".vtu, .vtk, .msh, .inp, .mesh, .vtp, .stl, .obj"
  static std::string GetKnownExtensions();

protected:
  vtkLabelMeshWriter();
  ~vtkLabelMeshWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

private:
  vtkLabelMeshWriter(const vtkLabelMeshWriter&) = delete;
  void operator=(const vtkLabelMeshWriter&) = delete;

  char* FileName = nullptr;
  bool GmshVersion22 = false;
  bool StlPerInterface = false;
  std::string ErrorText;
};

#endif
