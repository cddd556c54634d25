// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file main.cxx
 * labelmesher: read a label image, run vtkLabelOctreeMesher and vtkMeshDecimator
 * (and for `curve` vtkBezierCurver on the 2D mesh), write the mesh and the report. Exit status 0 on success, 1 when the input or the run fails, 2 on
 * a bad command line; every failure is reported as one line on stderr.
 */

#include "Arguments.h"
#include "ColorTableReader.h"
#include "CurveReport.h"
#include "FilterRun.h"
#include "ImageReader.h"
#include "MeshingPipeline.h"
#include "ProgressBar.h"
#include "Report.h"
#include "StringUtilities.h"
#include "VTKMessages.h"

#include "MeshFiles.h"
#include "SafeFile.h"

#include "itkObject.h"

#include "vtkBezierCurver.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <iostream>
#include <string>
#include <vector>

using namespace labelmesher_cli;

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
  const labelmesher::io::MaterialTable& table)
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
    labelmesher::io::CheckOutputPath(path);
  }
  if (!args.Report.empty())
  {
    labelmesher::io::CheckOutputPath(args.Report);
  }
}

/// Runs `algorithm` with a progress bar; throws RunError with its first error.
/// Returns its first warning (empty if none).
std::string UpdateWithProgress(vtkAlgorithm* algorithm, bool quiet)
{
  TerminalProgress bar(!quiet);
  const FilterMessages messages = UpdateFilter(algorithm, bar.Function());
  bar.Finish();
  if (!messages.Error.empty())
  {
    throw RunError(messages.Error);
  }
  return messages.Warning;
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

bool IsTwoDimensional(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  return dims[0] == 1 || dims[1] == 1 || dims[2] == 1;
}

int Run(const Arguments& args)
{
  CheckOutputPaths(args);
  const auto readStart = std::chrono::steady_clock::now();
  LabeledImage input = ReadLabeledImage(args.Input);
  vtkSmartPointer<vtkImageData> image = input.Image;
  labelmesher::io::MaterialTable table = input.Materials;
  if (!args.Labels.empty())
  {
    // The colour table names what it lists; other names (a .seg.nrrd's) stay.
    const labelmesher::io::MaterialTable named = ReadColorTable(args.Labels);
    for (const labelmesher::io::MaterialInfo& m : named.Entries())
    {
      table.Set(m);
    }
  }
  const double readSeconds = Seconds(readStart);
  const bool curve = args.Command == "curve";
  if (curve && !IsTwoDimensional(image))
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

  MeshingSettings settings;
  settings.ImageToMeshDistance = args.ImageToMeshDistance;
  settings.MeshToImageDistance = args.MeshToImageDistance;
  settings.Decimate = args.Decimate;
  settings.MinimumAngle = args.MinimumAngle;
  settings.RelocateInteriorVertices = args.Relocate;
  settings.IncludeBackground = args.IncludeBackground;
  settings.Measure = args.Measure;
  TerminalProgress bars(!args.Quiet);
  const MeshingOutcome meshed = RunMeshingPipeline(image, settings, bars.Function());
  bars.Finish();
  vtkUnstructuredGrid* initial = meshed.Initial;
  vtkUnstructuredGrid* mesh = meshed.Mesh;
  vtkPolyData* interfaces = meshed.Interfaces;
  if (meshed.Aborted || !mesh)
  {
    throw RunError("meshing was aborted");
  }

  if (!curve)
  {
    const auto writeStart = std::chrono::steady_clock::now();
    const std::vector<std::string> written = WriteOutputs(args, mesh, interfaces, table);
    RunReport report = MakeReport(args, image, mesh, initial);
    report.Outputs = written;
    report.Materials = table;
    report.Notes = input.Notes;
    report.Timings.insert(report.Timings.begin(), { "read", readSeconds });
    report.Timings.emplace_back("write", Seconds(writeStart));
    WriteReport(args.Report, report, WriteJson);
    if (!args.Quiet)
    {
      PrintSummary(report, std::cout);
    }
    return 0;
  }

  vtkNew<vtkBezierCurver> curver;
  curver->SetSmoothness(args.Smoothness);
  curver->SetTension(args.Tension);
  curver->SetMaximumUntanglingSteps(args.MaximumUntanglingSteps);
  curver->SetMaximumShorteningRounds(args.MaximumShorteningRounds);
  curver->SetQualityIterations(args.QualityIterations);
  curver->SetInputData(mesh);
  curver->SetInputDataObject(1, image);
  // An untangling failure is an error of the filter that still outputs the
  // marked mesh: write it and the report, then fail.
  std::string failure;
  try
  {
    UpdateWithProgress(curver, args.Quiet);
  }
  catch (const RunError& e)
  {
    failure = e.what();
  }
  vtkUnstructuredGrid* curved = curver->GetOutput();
  if (curved->GetNumberOfCells() == 0)
  {
    throw RunError(failure.empty() ? "the curver produced no cells" : failure);
  }
  const auto writeStart = std::chrono::steady_clock::now();
  const std::vector<std::string> written = WriteOutputs(args, curved, nullptr, table);
  RunReport linear = MakeReport(args, image, mesh, initial);
  linear.Outputs = written;
  linear.Materials = table;
  linear.Notes = input.Notes;
  linear.Timings.insert(linear.Timings.begin(), { "read", readSeconds });
  CurveReport report = MakeCurveReport(linear, args, curved);
  report.Timings.emplace_back("write", Seconds(writeStart));
  WriteReport(args.Report, report, WriteCurveJson);
  if (!args.Quiet)
  {
    PrintCurveSummary(report, std::cout);
  }
  if (!failure.empty())
  {
    throw RunError(failure);
  }
  if (!report.CurvesFaithful())
  {
    throw RunError("the curved mesh breaks a distance bound, crosses an interface or changes the topology "
                   "(see the report); it is written for inspection");
  }
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  SilenceVTKOutputWindow();
  itk::Object::GlobalWarningDisplayOff(); // ITK's warnings; its errors arrive as exceptions
  Arguments args;
  try
  {
    args = ParseArguments(argc, argv);
  }
  catch (const UsageError& e)
  {
    std::cerr << "labelmesher: " << e.what() << " (see labelmesher --help)\n";
    return 2;
  }
  if (args.Help)
  {
    std::cout << Usage();
    return 0;
  }
  if (args.Version)
  {
    std::cout << "labelmesher " << LABELMESHER_VERSION << "\n";
    return 0;
  }
  try
  {
    return Run(args);
  }
  catch (const std::exception& e)
  {
    std::cerr << "labelmesher: error: " << e.what() << "\n";
    return 1;
  }
}
