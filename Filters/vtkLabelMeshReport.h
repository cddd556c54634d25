// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkLabelMeshReport
 * @brief   the report of a vtkLabelMesher run: what it made, what it measured,
 *          whether every guarantee holds, as JSON and as a text summary
 *
 * One report for every front end: the labelmesher CLI writes its JSON
 * (`--report`) and prints its summary, the desktop viewer shows the summary,
 * the 3D Slicer module and Python scripts read both. Everything comes from the
 * outputs of vtkLabelMesher (their field data record the parameters, the
 * measurements, the material table and the stage timings) and the image's
 * dimensions and spacing; the caller may add the file names and the memory the
 * process used, which only it knows.
 *
 * The JSON is that of `labelmesher mesh --report` (keys `input`, `outputs`,
 * `material_table`, `image`, `parameters`, `mesh`, `decimation`, `measured`,
 * `quality`, `conformity`, `fidelity`, `topology`, `timings`, `memory`), or
 * with a curved mesh that of `labelmesher curve --report` (`parameters`,
 * `linear_mesh`, `curved_mesh`, `validity`, `accuracy`, `timings`). Distances
 * are in voxels of the smallest spacing, angles in degrees, times in seconds,
 * memory in MiB.
 *
 * Python:
 * @code
 * report = labelmesher.vtkLabelMeshReport()
 * report.SetImage(image); report.SetMesh(mesher.GetOutput())
 * figures = json.loads(report.GetMeshJSON()); print(report.GetSummary())
 * @endcode
 *
 * @sa vtkLabelMesher
 */

#ifndef vtkLabelMeshReport_h
#define vtkLabelMeshReport_h

#include "LabelMesherFiltersModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For the inputs held

#include <functional> // For the report's writers
#include <ostream>    // For the report's writers
#include <string>     // For the texts
#include <utility> // For the timings
#include <vector>  // For the file names and notes

class vtkImageData;
class vtkUnstructuredGrid;

class LABELMESHERFILTERS_EXPORT vtkLabelMeshReport : public vtkObject
{
public:
  static vtkLabelMeshReport* New();
  vtkTypeMacro(vtkLabelMeshReport, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The label image the run meshed (its dimensions and spacing are reported).
   */
  void SetImage(vtkImageData* image);

  /**
   * The linear mesh: vtkLabelMesher's output port 0 (decimated, or the initial
   * mesh without decimation). Required.
   */
  void SetMesh(vtkUnstructuredGrid* mesh);

  /**
   * The curved mesh: vtkLabelMesher's output port 2 when Curve was on (cubic
   * Bezier triangles: the curve report) or Order was 2 (quadratic tetrahedra:
   * the mesh report's `quadratic` part); null or empty otherwise.
   */
  void SetCurvedMesh(vtkUnstructuredGrid* curved);

  ///@{
  /**
   * What the report names the input (a file name; default empty).
   */
  vtkSetStdStringFromCharMacro(InputName);
  vtkGetCharFromStdStringMacro(InputName);
  ///@}

  /**
   * Names a file the mesh was written to (in the order written).
   */
  void AddOutputName(const char* name);
  /**
   * Adds a remark of the reader's (for example, renumbered segments).
   */
  void AddNote(const char* note);
  /**
   * Adds a stage the caller timed (reading, writing), in seconds: first
   * (before the filters' stages) or last.
   */
  void AddTiming(const char* stage, double seconds, bool first);

  /**
   * Resident memory of the process, MiB: when the run started (after reading)
   * and at its peak. Not reported while the peak is 0 (the default).
   */
  void SetMemory(double startMiB, double peakMiB);

  /**
   * The linear mesh's report, as `labelmesher mesh --report` writes it.
   */
  std::string GetMeshJSON();
  /**
   * The curved mesh's report, as `labelmesher curve --report` writes it; empty
   * without a curved mesh.
   */
  std::string GetCurveJSON();
  /**
   * The curve report with a Bezier mesh, the mesh report otherwise (with a
   * quadratic mesh, its `quadratic` object included).
   */
  std::string GetJSON();
  /**
   * The text summary the CLI prints (the curved mesh's part included).
   */
  std::string GetSummary();

  /**
   * True when the linear mesh was measured and every guarantee holds as
   * measured: the angle bound, both distances certified, no inverted cell,
   * the topology of every material; with a curved mesh also every curved cell
   * proven valid with its certified scaled Jacobian at least the bound asked
   * for, and the curves within the bounds with the topology kept; with a
   * quadratic mesh, its certified smallest scaled Jacobian at least the bound
   * (and, where measured, the sampled one and both distances within their bounds).
   */
  bool GetGuaranteesHold();

protected:
  vtkLabelMeshReport();
  ~vtkLabelMeshReport() override;

private:
  vtkLabelMeshReport(const vtkLabelMeshReport&) = delete;
  void operator=(const vtkLabelMeshReport&) = delete;

  struct Figures;
  /// The reports of the meshes set; throws std::invalid_argument without an image or a mesh.
  Figures Gather();
  /// What `write` makes of the reports; empty, after one error, when there are none.
  std::string Text(const std::function<void(const Figures&, std::ostream&)>& write);

  vtkSmartPointer<vtkImageData> Image;
  vtkSmartPointer<vtkUnstructuredGrid> Mesh;
  vtkSmartPointer<vtkUnstructuredGrid> Curved;
  std::string InputName;
  std::vector<std::string> OutputNames, Notes;
  std::vector<std::pair<std::string, double>> FirstTimings, LastTimings;
  double StartMemory = 0.0, PeakMemory = 0.0;
};

#endif
