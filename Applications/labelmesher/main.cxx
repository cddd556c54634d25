// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file main.cxx
 * labelmesher: read a label image, run vtkLabelMesher (mesh, decimate, and for
 * `curve` curve the 2D mesh), write the mesh and the report (RunReport,
 * CurveReport). Exit status 0 on success, 1 when the input or the run fails, 2
 * on a bad command line; every failure is reported as one line on stderr.
 */

#include "Arguments.h"
#include "ColorTableReader.h"
#include "Report/CurveReport.h"
#include "ImageReader.h"
#include "MeshingPipeline.h"
#include "ProgressBar.h"
#include "Report/RunReport.h"
#include "StringUtilities.h"
#include "VTKMessages.h"

#include "MPIPartExchange.h"
#include "MPIStartup.h"
#include "MemoryBudget.h"
#include "MeshFiles.h"
#include "SafeFile.h"

#include "itkObject.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLabelImageReader.h"
#include "vtkLabelMesher.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkPointData.h"
#include "vtkDataArray.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <cstdlib>
#include <cstdint>
#include <iostream>
#include <new>
#include <string>
#include <vector>

using namespace labelmesher_cli;
using namespace labelmesher::io;
using namespace labelmesher::report;

namespace
{

struct RunError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// Every output of the run, each whole or not at all; returns the files written.
std::vector<std::string> WriteOutputs(const Arguments& args, vtkUnstructuredGrid* mesh, vtkPolyData* interfaces,
  const labelmesher::MaterialTable& table)
{
  labelmesher::io::WriteOptions options;
  options.GmshVersion22 = args.GmshVersion22;
  options.StlPerInterface = args.StlPerInterface;
  labelmesher::io::MeshFileWriter writer(mesh, interfaces, table, options);
  std::vector<std::string> written;
  for (const std::string& path : args.Outputs)
  {
    for (const std::string& file : writer.Write(path))
    {
      written.push_back(file);
    }
  }
  return written;
}

/// Fails before any work when an output (or the report) cannot be written.
void CheckOutputPaths(const Arguments& args)
{
  for (const std::string& path : args.Outputs)
  {
    labelmesher::io::CheckMeshOutputPath(path);
  }
  if (!args.Report.empty())
  {
    labelmesher::io::CheckOutputPath(args.Report);
  }
}

template <typename Report, typename Writer>
void WriteReport(const std::string& path, const Report& report, Writer write)
{
  if (path.empty())
  {
    return;
  }
  labelmesher::io::SafeFile file(path);
  write(report, file.Stream());
  file.Commit();
}

/// The image read and checked against the command line.
struct PreparedRun
{
  LabeledImage Input; ///< with a Source, the image's geometry alone
  /// On a process other than rank 0 of a distributed run: the reader that has read the header,
  /// from which the filter reads the slab this process's parts need.
  vtkSmartPointer<vtkLabelImageReader> Source;
  labelmesher::MaterialTable Table;
  double ReadSeconds = 0.0;
};

PreparedRun Prepare(const Arguments& args, bool writes, bool readsSlabOnly)
{
  if (writes)
  {
    CheckOutputPaths(args);
  }
  PreparedRun run;
  const auto readStart = std::chrono::steady_clock::now();
  if (readsSlabOnly && labelmesher::io::ReadsByExtent(args.Input))
  {
    run.Source = vtkSmartPointer<vtkLabelImageReader>::New();
    run.Source->SetFileName(args.Input.c_str());
    run.Source->UpdateInformation();
    if (*run.Source->GetErrorText())
    {
      throw RunError(run.Source->GetErrorText());
    }
    vtkInformation* information = run.Source->GetOutputInformation(0);
    run.Input.Image = vtkSmartPointer<vtkImageData>::New();
    run.Input.Image->SetExtent(information->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()));
    int dims[3];
    run.Input.Image->GetDimensions(dims);
    if (!vtkLabelMesher::ReadsSlabsOf(dims, information->Get(vtkDataObject::SPACING())))
    {
      run.Source = nullptr; // resampled or permuted: Label Mesher needs it whole, read here with its checks
    }
  }
  if (!run.Source)
  {
    run.Input = ReadLabeledImage(args.Input);
  }
  LabeledImage& input = run.Input;
  vtkImageData* image = input.Image;
  labelmesher::MaterialTable& table = run.Table;
  table = input.Materials;
  if (!args.Labels.empty())
  {
    // The colour table names what it lists; other names (a .seg.nrrd's) stay.
    const labelmesher::MaterialTable named = ReadColorTable(args.Labels);
    for (const labelmesher::MaterialInfo& m : named.Entries())
    {
      table.Set(m);
    }
  }
  // On the image, as vtkLabelImageReader puts it: the filter passes it to the mesh, where the
  // report finds the names.
  if (!table.Empty())
  {
    labelmesher::StoreMaterialTable(image->GetFieldData(), table);
  }
  run.ReadSeconds = Seconds(readStart);
  if (args.Settings.Curve && !IsTwoDimensional(image))
  {
    throw RunError("'curve' needs a 2D image (one extent of a single slice); '" + args.Input +
      "' is 3D");
  }
  for (const std::string& output : args.Outputs)
  {
    if (IsTwoDimensional(image) && labelmesher::io::FormatOfPath(output) == labelmesher::io::MeshFormat::Stl)
    {
      throw RunError("cannot write '" + output + "': STL holds triangles, the interfaces of a 2D mesh are "
                     "segments (use .obj or .vtp)");
    }
  }
  return run;
}

int Run(const Arguments& args)
{
  // Under `mpirun -np N` (N > 1) every process reads the image and meshes its share of the
  // blocks; rank 0 gathers, writes and reports (vtkLabelMesher::Distributed).
  const bool distributed = labelmesher::LaunchedOnSeveralProcesses();
  if (distributed)
  {
    labelmesher::StartMPI();
    if (labelmesher::WorldSize() == 1)
    {
      // Launched as several processes, but each one's MPI starts alone: labelmesher's MPI is not
      // the launcher's (MPICH's mpiexec running an Open MPI build, say). Each would mesh the whole
      // image and write the same files.
      throw RunError("launched as " + std::to_string(labelmesher::LaunchedProcesses()) +
        " processes, but this process's MPI sees only itself: run it with the mpirun of the MPI it was built "
        "with");
    }
  }
  const bool root = labelmesher::WorldRank() == 0;
  PreparedRun prepared;
  std::string failure;
  try
  {
    if (distributed && !args.Settings.Decimate)
    {
      throw RunError("under mpirun the processes share out the decimated pipeline's parts; --no-decimate runs on "
                     "one process");
    }
    // A process other than rank 0 reads the image's header; Label Mesher reads its slab later.
    prepared = Prepare(args, root, distributed && !root);
  }
  catch (const std::exception& e)
  {
    if (!distributed)
    {
      throw;
    }
    failure = e.what();
  }
  if (distributed)
  {
    // None may mesh while another has given up (rank 0 would wait for its parts). That every
    // process was given the same image and meshing parameters, Label Mesher checks first.
    failure = labelmesher::FirstFailure(failure);
    if (!failure.empty())
    {
      throw RunError(failure);
    }
  }
  LabeledImage& input = prepared.Input;
  vtkSmartPointer<vtkImageData> image = input.Image;
  const labelmesher::MaterialTable& table = prepared.Table;
  const double readSeconds = prepared.ReadSeconds;
  const bool curve = args.Settings.Curve;
  const bool quadratic = args.Settings.Order == 2;

  MeshingSettings settings = args.Settings;
  settings.Distributed = distributed;
  const double startMemory = labelmesher::ResidentBytes() / 1048576.0;
  TerminalProgress bars(!args.Quiet && root);
  const MeshingOutcome meshed = RunMeshingPipeline(image, settings, bars.Function(), prepared.Source);
  bars.Finish();
  if (!root)
  {
    return 0; // its parts went to rank 0, which writes and reports
  }
  if (meshed.Aborted || !meshed.Mesh)
  {
    throw RunError("meshing was aborted");
  }

  const auto writeStart = std::chrono::steady_clock::now();
  // The curved and quadratic meshes are written without the linear interface surface: a cubic
  // mesh has no interfaces in the files, a quadratic one has them from its cells (ExportMesh.h).
  if (quadratic && (!meshed.Curved || meshed.Curved->GetNumberOfCells() == 0))
  {
    throw RunError("making quadratic cells produced no cells");
  }
  const std::vector<std::string> written = curve || quadratic
    ? WriteOutputs(args, meshed.Curved, nullptr, table)
    : WriteOutputs(args, meshed.Mesh, meshed.Interfaces, table);
  RunContext context;
  context.Input = args.Input;
  context.Outputs = written;
  context.Notes = input.Notes;
  context.StartMemory = startMemory;
  context.PeakMemory = labelmesher::PeakResidentBytes() / 1048576.0;
  context.TimingsBefore = { { "read", readSeconds } };
  context.TimingsAfter = { { "write", Seconds(writeStart) } };
  const RunReports reports =
    MakeRunReports(context, image, meshed.Mesh, curve || quadratic ? meshed.Curved.GetPointer() : nullptr);
  if (!reports.Curved)
  {
    WriteReport(args.Report, reports.Linear, WriteJson);
    if (!args.Quiet)
    {
      PrintSummary(reports.Linear, std::cout);
    }
    if (!QuadraticHolds(reports.Linear))
    {
      throw RunError("the quadratic mesh breaks its scaled Jacobian or a distance bound as measured (see the "
                     "report); it is written for inspection");
    }
    return 0;
  }

  const CurveReport& curved = *reports.Curved;
  WriteReport(args.Report, curved, WriteCurveJson);
  if (!args.Quiet)
  {
    PrintCurveSummary(curved, std::cout);
  }
  // An untangling failure leaves the marked mesh, written above for inspection.
  if (!meshed.CurveError.empty())
  {
    throw RunError(meshed.CurveError);
  }
  if (!curved.ScaledJacobianHolds())
  {
    throw RunError("a curved cell's scaled Jacobian is below " + FormatFixed(curved.ScaledJacobianBound, 3) +
      " (see the report); the mesh is written for inspection");
  }
  if (!curved.CornerAnglesHold())
  {
    throw RunError("a curved cell's corner angle is below " + FormatFixed(curved.CornerAngleBound, 2) +
      " degrees (see the report); the mesh is written for inspection");
  }
  if (!curved.CurvesFaithful())
  {
    throw RunError("the curved mesh breaks a distance bound, crosses an interface or changes the topology "
                   "(see the report); it is written for inspection");
  }
  return 0;
}

/// False on the processes other than the first of an mpirun (read before MPI starts): they
/// leave help, version and usage errors to it.
bool FirstOfItsRun()
{
  return labelmesher::LaunchedRank() == 0;
}

} // namespace

int main(int argc, char* argv[])
{
  labelmesher::SilenceVTKOutputWindow();
  itk::Object::GlobalWarningDisplayOff(); // ITK's warnings; its errors arrive as exceptions
  Arguments args;
  try
  {
    args = ParseArguments(argc, argv);
  }
  catch (const UsageError& e)
  {
    if (FirstOfItsRun())
    {
      std::cerr << "labelmesher: " << e.what() << " (see labelmesher --help)\n";
    }
    return 2;
  }
  if (args.Help)
  {
    std::cout << (FirstOfItsRun() ? Usage() : std::string());
    return 0;
  }
  if (args.Version)
  {
    if (FirstOfItsRun())
    {
      std::cout << "labelmesher " << LABELMESHER_VERSION << "\n";
    }
    return 0;
  }
  try
  {
    return Run(args);
  }
  catch (const std::bad_alloc&)
  {
    if (labelmesher::WorldRank() != 0)
    {
      return 1; // rank 0 of a distributed run says why
    }
    // An allocation outside the filters' guarded runs (reading, packing, writing): say what it is.
    std::cerr << "labelmesher: error: out of memory while reading the image or handling the mesh (the "
                 "meshing checks its own need beforehand): free memory, or raise --max-memory or ulimit -v\n";
    return 1;
  }
  catch (const std::exception& e)
  {
    if (labelmesher::WorldRank() == 0)
    {
      std::cerr << "labelmesher: error: " << e.what() << "\n"; // rank 0 of a distributed run names the process
    }
    return 1;
  }
}
