// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file main.cxx
 * labelmesher: read a label image, run vtkLabelOctreeMesher, write the mesh and
 * the report. Exit status 0 on success, 1 when the input or the run fails, 2 on
 * a bad command line; every failure is reported as one line on stderr.
 */

#include "Arguments.h"
#include "ImageReader.h"
#include "ProgressBar.h"
#include "Report.h"
#include "StringUtilities.h"
#include "VTKMessages.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkLabelOctreeMesher.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridWriter.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <chrono>
#include <fstream>
#include <iostream>
#include <string>

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

void WriteMesh(vtkUnstructuredGrid* mesh, const std::string& path)
{
  const bool xml = EndsWith(path, ".vtu");
  vtkSmartPointer<vtkAlgorithm> writer;
  if (xml)
  {
    auto w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    w->SetFileName(path.c_str());
    w->SetDataModeToAppended();
    w->SetCompressorTypeToZLib();
    writer = w;
  }
  else
  {
    auto w = vtkSmartPointer<vtkUnstructuredGridWriter>::New();
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    writer = w;
  }
  VTKMessages errors(writer, vtkCommand::ErrorEvent);
  writer->SetInputDataObject(mesh);
  writer->Update();
  if (!errors.First().empty())
  {
    throw RunError("cannot write '" + path + "': " + errors.First());
  }
}

int Run(const Arguments& args)
{
  const auto readStart = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkImageData> image = ReadLabelImage(args.Input);
  const double readSeconds = Seconds(readStart);

  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetImageToMeshDistance(args.ImageToMeshDistance);
  mesher->SetMeshToImageDistance(args.MeshToImageDistance);
  mesher->SetIncludeBackground(args.IncludeBackground);
  mesher->SetInputData(image);

  VTKMessages errors(mesher, vtkCommand::ErrorEvent);
  VTKMessages warnings(mesher, vtkCommand::WarningEvent);
  ProgressBar bar(!args.Quiet);
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&bar);
  progress->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
    auto* algorithm = static_cast<vtkAlgorithm*>(caller);
    const char* stage = algorithm->GetProgressText();
    static_cast<ProgressBar*>(clientData)->Update(
      *static_cast<double*>(callData), stage ? stage : "");
  });
  mesher->AddObserver(vtkCommand::ProgressEvent, progress);
  mesher->Update();
  bar.Finish();
  if (!errors.First().empty())
  {
    throw RunError(errors.First());
  }
  vtkUnstructuredGrid* mesh = mesher->GetOutput();
  if (mesh->GetNumberOfCells() == 0)
  {
    throw RunError(warnings.First().empty() ? "the mesher produced no cells" : warnings.First());
  }

  const auto writeStart = std::chrono::steady_clock::now();
  WriteMesh(mesh, args.Output);
  const double writeSeconds = Seconds(writeStart);

  RunReport report = MakeReport(args, image, mesh);
  report.Timings.insert(report.Timings.begin(), { "read", readSeconds });
  report.Timings.emplace_back("write", writeSeconds);
  if (!args.Report.empty())
  {
    std::ofstream json(args.Report);
    if (json)
    {
      WriteJson(report, json);
    }
    if (!json)
    {
      throw RunError("cannot write report '" + args.Report + "'");
    }
  }
  if (!args.Quiet)
  {
    PrintSummary(report, std::cout);
  }
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
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
