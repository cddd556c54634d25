// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkLabelImageReader
 * @brief   read a label image (NRRD, NIfTI, MetaImage, VTI, PNG, 3D Slicer
 *          segmentation) with every check the labelmesher CLI makes
 *
 * vtkLabelImageReader reads what `labelmesher mesh` reads, the same way:
 * NRRD (gzip too), NIfTI (.nii, .nii.gz) and MetaImage (.mha, .mhd) through
 * ITK, since VTK's NRRD reader misreads gzip-compressed NRRD; VTI and PNG
 * through VTK. Origin, spacing and direction are kept. It refuses, with one
 * error message naming the file and the problem, what lenient readers let
 * through: more than one component (RGB), NaN or non-integer values, labels
 * beyond 32 bits, non-positive or non-finite spacing, data shorter than the
 * header says, damaged headers.
 *
 * A 3D Slicer segmentation (`.seg.nrrd`) becomes one label image; the
 * segments' names and colours go into the output's field data as
 * `MaterialLabel` (int), `MaterialName` (string) and `MaterialColor`
 * (double x 3, RGB in [0, 1], -1 when none was given), one tuple per
 * material, which the LabelMesher filters pass on to the mesh and
 * vtkLabelMeshWriter writes into Gmsh physical names, Abaqus element sets and
 * the VTK files. LabelTableFileName adds (or replaces) names and colours from
 * an ITK-SNAP label description or a 3D Slicer colour table.
 *
 * Output: vtkImageData whose point scalars are named `Labels`.
 *
 * Streaming: NRRD, NIfTI and MetaImage files give any extent asked for (VTK's
 * UPDATE_EXTENT), reading only its voxels: raw and gzip NRRD slice by slice,
 * one slice held at a time; raw MetaImage and NIfTI through ITK's streamed
 * reads (other encodings are read whole by ITK, and the rest released at
 * once). What was read is held only as the output. Segmentations, VTI and PNG
 * files are read whole in RequestInformation and held until a setting changes.
 * The header's errors come with UpdateInformation, those of the values with
 * the read of the voxels (Update).
 *
 * @warning On an error the output is empty and the error (ErrorEvent, and
 * GetErrorText()) is one line.
 *
 * @sa
 * vtkLabelMeshWriter vtkLabelMesher
 */

#ifndef vtkLabelImageReader_h
#define vtkLabelImageReader_h

#include "LabelMesherIOModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // For the image read

#include <string> // For the notes and the error
#include <vector> // For the notes

class vtkImageData;

class LABELMESHERIO_EXPORT vtkLabelImageReader : public vtkImageAlgorithm
{
public:
  static vtkLabelImageReader* New();
  vtkTypeMacro(vtkLabelImageReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The label image: .nrrd, .nhdr, .seg.nrrd, .nii, .nii.gz, .mha, .mhd, .vti or .png.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Optional colour table naming the labels (ITK-SNAP label description, or a
   * 3D Slicer colour table `.ctbl` / `.txt`); empty or null: none. Its
   * entries replace those of a segmentation file for the same labels.
   */
  vtkSetStringMacro(LabelTableFileName);
  vtkGetStringMacro(LabelTableFileName);
  ///@}

  /// 1 when the name has an extension this reader reads, else 0 (the content is checked on reading).
  static int CanReadFile(const char* fileName);

  /// The last read's error, one line; empty after a read that succeeded.
  const char* GetErrorText() { return this->ErrorText.c_str(); }

  ///@{
  /// Remarks of the last read for the user (e.g. that a segmentation's labels were renumbered).
  int GetNumberOfNotes() { return static_cast<int>(this->Notes.size()); }
  const char* GetNote(int i);
  ///@}

protected:
  vtkLabelImageReader();
  ~vtkLabelImageReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLabelImageReader(const vtkLabelImageReader&) = delete;
  void operator=(const vtkLabelImageReader&) = delete;

  /// Reads the files unless the image of the same settings is held; false on an error.
  bool ReadIfChanged();

  char* FileName = nullptr;
  char* LabelTableFileName = nullptr;
  /// The last image read, with its field data: the whole image (segmentations, VTI, PNG), or
  /// its geometry alone and an empty label array (files read by extent).
  vtkSmartPointer<vtkImageData> Image;
  bool HoldsVoxels = false; ///< Image holds the voxels
  vtkMTimeType ImageTime = 0;          ///< this->GetMTime() at the last read, whether or not it failed
  std::string ErrorText;
  std::vector<std::string> Notes;
};

#endif
