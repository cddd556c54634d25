// SPDX-License-Identifier: GPL-2.0-or-later
// vtkLabelMesher's stages: mesh and decimate (the block-streamed core pipeline) or mesh alone
// (vtkLabelOctreeMesher), then curve (vtkBezierCurver); one progress and one abort over them all.
#include "vtkLabelMesher.h"

#include "FilterStage.h"
#include "FilterSupport.h"
#include "ImageFingerprint.h"
#include "MPIPartExchange.h"
#include "MPIStartup.h"
#include "Streaming/PartExchange.h"
#include "LabelImageConversion.h"
#include "PieceHandOut.h"
#include "LabelMesherArrayNames.h"
#include "MemoryBudget.h"
#include "Mesh/MeshSelection.h"
#include "QuadraticOutput.h"
#include "Streaming/StreamedPipeline.h"
#include "Support/MemoryEstimate.h"
#include "VTKMessages.h"
#include "vtkBezierCurver.h"
#include "vtkLabelOctreeMesher.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkAlgorithmOutput.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <memory>
#include <exception>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLabelMesher);

/*
 * Design. RequestData runs the stages, none of which knows the algorithm:
 *   - mesh and decimate (MeshAndDecimate): the label image as the core's LabelImage
 *     (LabelImageConversion.h), the streamed run's memory estimate against the budget,
 *     labelmesher::MeshAndDecimate with progress and abort forwarded, then pack and measure as the
 *     mesher and the decimator do (FilterSupport.h);
 *   - or mesh alone (MeshOnly): vtkLabelOctreeMesher run as a stage (FilterStage.h);
 *   - curve (CurveMesh): vtkBezierCurver run as a stage on the linear mesh and the image.
 */

namespace arrays = labelmesher::arrays;

namespace
{
/// Asks for `extent` exactly, as piece 0 of 1: a piece request left by the filter's own
/// consumers would make a producer that can give sub-extents cut the extent again.
void RequestExtentAlone(vtkInformation* request, const int extent[6])
{
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent, 6);
  request->Set(vtkStreamingDemandDrivenPipeline::EXACT_EXTENT(), 1);
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
}

/// What ParaView's post filter `producer` passes on (ParaView places a vtkPVPostFilter after
/// every source: it passes extent requests on, but not CAN_PRODUCE_SUB_EXTENT, and its source's
/// errors are the reason it fails), or null when `producer` is not one.
vtkAlgorithmOutput* BehindPostFilter(vtkAlgorithm* producer)
{
  if (!producer || !producer->IsA("vtkPVPostFilter") || producer->GetNumberOfInputPorts() < 1 ||
    producer->GetNumberOfInputConnections(0) != 1)
  {
    return nullptr;
  }
  return producer->GetInputConnection(0, 0);
}

/// The image on `connection` comes from a producer that gives any extent asked for: so it says
/// (CAN_PRODUCE_SUB_EXTENT), or the source before ParaView's post filter does.
bool ProducesAnyExtent(vtkAlgorithmOutput* connection)
{
  for (; connection && connection->GetProducer(); connection = BehindPostFilter(connection->GetProducer()))
  {
    vtkInformation* information = connection->GetProducer()->GetOutputInformation(connection->GetIndex());
    if (information && information->Has(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT()) &&
      information->Get(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT()) != 0)
    {
      return true;
    }
  }
  return false;
}

/// Throws unless a process that holds `slices` slices of an image of `dims` voxels fits its
/// memory limit (MemoryBudget.h): the fixed floor and its slab, a byte a voxel at least.
void RefuseSlabBeyondMemory(const int dims[3], int slices, double memoryLimit)
{
  const std::uint64_t voxels = static_cast<std::uint64_t>(slices) * static_cast<std::uint64_t>(dims[0]) *
    static_cast<std::uint64_t>(dims[2] == 1 ? 1 : dims[1]);
  const std::string refused = labelmesher::RefuseIfTooLarge(labelmesher::SlabProcessFloorBytes() + voxels,
    "its slab of " + labelmesher::WithThousandsSeparators(voxels) + " voxels",
    labelmesher::AvailableMemory(memoryLimit, /*startsMPI=*/true));
  if (!refused.empty())
  {
    throw std::runtime_error(refused);
  }
}

/// The extent of slices [first, end) of the image whose extent is `whole`: along its last axis
/// (y for a 2D image), every voxel across.
void SlabExtent(const int whole[6], int first, int end, int extent[6])
{
  const int axis = whole[5] == whole[4] ? 1 : 2;
  std::copy(whole, whole + 6, extent);
  extent[2 * axis] = whole[2 * axis] + first;
  extent[2 * axis + 1] = whole[2 * axis] + end - 1;
}

/// The stages' rough weights in a run's time on real images (meshing alone is a small part of
/// meshing and decimating); each stage's progress fills its share of the whole run's.
constexpr double kMeshWeight = 0.3, kMeshAndDecimateWeight = 1.0, kCurveWeight = 0.3;

/// Order 2: `linear` (the whole decimated mesh, index space) made quadratic into `quadratic`.
bool MakeQuadratic(vtkLabelMesher* self, const labelmesher::LabelImage& image, const labelmesher::SimplexMesh& linear,
  const labelmesher::ImagePlacement& placement, vtkUnstructuredGrid* quadratic, double start, double share,
  std::vector<labelmesher::StageTiming>& timings)
{
  self->SetProgressText("quadratic cells");
  self->UpdateProgress(start);
  labelmesher::QuadraticParameters parameters;
  parameters.ImageToMeshDistance = self->GetImageToMeshDistance();
  parameters.MeshToImageDistance = self->GetMeshToImageDistance();
  parameters.MinimumScaledJacobian = self->GetMinimumScaledJacobian();
  // The corners keep the angle the linear mesh was decimated to.
  parameters.MinimumCornerAngle = self->GetMinimumAngle();
  labelmesher::QuadraticResult result;
  try
  {
    // The whole box, background included: the curves keep their guarantees only with every cell
    // certified (QuadraticCurver.h).
    result = labelmesher::CurveQuadratic(linear, image, parameters,
      labelmesher::ForwardProgress(self, start, self->GetMeasureOutput() ? 0.5 * share : share));
  }
  catch (const labelmesher::AbortRequested&)
  {
    vtkWarningWithObjectMacro(self, "Meshing aborted on request: output is empty.");
    return false;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(self, "Making quadratic cells failed: out of memory.");
    return false;
  }
  catch (const std::exception& e)
  {
    vtkErrorWithObjectMacro(self, "Making quadratic cells failed: " << e.what() << ".");
    return false;
  }
  timings.push_back({ "quadratic fit", result.FitSeconds });
  timings.push_back({ "quadratic certify", result.CertifySeconds });
  labelmesher::PackQuadraticMesh(result, self->GetIncludeBackground(), placement, quadratic);
  vtkFieldData* fd = quadratic->GetFieldData();
  labelmesher::AddQuadraticFields(fd, result, self->GetMinimumScaledJacobian());
  labelmesher::AddScalarField(fd, arrays::ImageToMeshDistance, self->GetImageToMeshDistance());
  labelmesher::AddScalarField(fd, arrays::MeshToImageDistance, self->GetMeshToImageDistance());
  labelmesher::AddScalarField(fd, arrays::VoxelSize, placement.VoxelSize);
  labelmesher::AddScalarField(fd, arrays::IncludeBackground, self->GetIncludeBackground() ? 1.0 : 0.0);
  labelmesher::PassMaterialTable(self->GetInputDataObject(0, 0)->GetFieldData(), fd);
  if (self->GetMeasureOutput())
  {
    self->SetProgressText("measure quadratic cells");
    self->UpdateProgress(start + 0.5 * share);
    try
    {
      labelmesher::StageClock clock(timings);
      labelmesher::AddQuadraticMeasurements(fd, image, result);
      clock.Finish("measure: quadratic");
    }
    catch (const std::exception& e)
    {
      vtkWarningWithObjectMacro(self, "Measuring the quadratic mesh failed: " << e.what());
    }
  }
  self->UpdateProgress(start + share);
  return true;
}

} // namespace

//------------------------------------------------------------------------------
int vtkLabelMesher::GetImageDimension(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  return (dims[0] == 1 || dims[1] == 1 || dims[2] == 1) ? 2 : 3;
}

//------------------------------------------------------------------------------
double vtkLabelMesher::GetProvenAngleBound(int dimension)
{
  return vtkLabelOctreeMesher::GetProvenAngleBound(dimension);
}

//------------------------------------------------------------------------------
bool vtkLabelMesher::ReadsSlabsOf(const int dims[3], const double spacing[3])
{
  return dims[0] > 0 && dims[1] > 0 && dims[2] > 0 && labelmesher::ConvertsAsIs(dims, spacing);
}

//------------------------------------------------------------------------------
const char* vtkLabelMesher::GetMaterialArrayName()
{
  return arrays::Material;
}
const char* vtkLabelMesher::GetMaterialLabelArrayName()
{
  return arrays::MaterialLabel;
}
const char* vtkLabelMesher::GetMaterialNameArrayName()
{
  return arrays::MaterialName;
}
const char* vtkLabelMesher::GetMaterialColorArrayName()
{
  return arrays::MaterialColor;
}

//------------------------------------------------------------------------------
void vtkLabelMesher::SetMinimumAngle(double degrees)
{
  const double clamped = labelmesher::ClampToProvenAngleBounds(degrees);
  if (clamped != this->MinimumAngle)
  {
    this->MinimumAngle = clamped;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLabelMesher::vtkLabelMesher()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLabelMesher::GetInterfacesOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
vtkUnstructuredGrid* vtkLabelMesher::GetCurvedOutput()
{
  return vtkUnstructuredGrid::SafeDownCast(this->GetOutputDataObject(2));
}

//------------------------------------------------------------------------------
int vtkLabelMesher::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLabelMesher::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkLabelMesher::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  vtkInformation* inputInformation = inputVector[0]->GetInformationObject(0);
  if (inputInformation && this->ReadsItsSlabOnly(inputInformation))
  {
    // No voxels yet: rank 0 has to plan the parts before this process knows its slab.
    const int none[6] = { 0, -1, 0, -1, 0, -1 };
    RequestExtentAlone(inputInformation, none);
    return 1;
  }
  labelmesher::RequestWholeImages(inputVector[0]);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLabelMesher::ReadsItsSlabOnly(vtkInformation* in) const
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (!this->SharesOutAcrossProcesses() || labelmesher::WorldRank() == 0 || !in->Has(SDDP::WHOLE_EXTENT()) ||
    !in->Has(vtkDataObject::SPACING()) || !ProducesAnyExtent(const_cast<vtkLabelMesher*>(this)->GetInputConnection(0, 0)))
  {
    return false;
  }
  const int* whole = in->Get(SDDP::WHOLE_EXTENT());
  const int dims[3] = { whole[1] - whole[0] + 1, whole[3] - whole[2] + 1, whole[5] - whole[4] + 1 };
  return ReadsSlabsOf(dims, in->Get(vtkDataObject::SPACING()));
}

//------------------------------------------------------------------------------
vtkImageData* vtkLabelMesher::UpdateInputExtent(const int extent[6], vtkDataArray*& labels, std::string& problem)
{
  labels = nullptr;
  problem.clear();
  vtkAlgorithmOutput* connection = this->GetInputConnection(0, 0);
  vtkAlgorithm* producer = connection ? connection->GetProducer() : nullptr;
  if (!producer)
  {
    return nullptr;
  }
  const int port = connection->GetIndex();
  vtkNew<vtkInformationVector> requests;
  requests->SetNumberOfInformationObjects(producer->GetNumberOfOutputPorts());
  RequestExtentAlone(requests->GetInformationObject(port), extent);
  // The producer's error (or its source's, behind ParaView's post filter) is this process's
  // reason, sent to rank 0: caught, not printed here.
  std::vector<std::unique_ptr<labelmesher::VTKMessages>> errors;
  for (vtkAlgorithmOutput* c = connection; c && c->GetProducer(); c = BehindPostFilter(c->GetProducer()))
  {
    vtkAlgorithm* source = c->GetProducer();
    errors.push_back(std::make_unique<labelmesher::VTKMessages>(source, vtkCommand::ErrorEvent));
    errors.push_back(std::make_unique<labelmesher::VTKMessages>(source->GetExecutive(), vtkCommand::ErrorEvent));
  }
  const bool updated = producer->Update(port, requests) != 0;
  for (auto it = errors.rbegin(); it != errors.rend() && problem.empty(); ++it)
  {
    problem = (*it)->First(); // the source's first: what the others failed on
  }
  if (!updated && problem.empty())
  {
    problem = "its input failed to update";
  }
  vtkImageData* piece = vtkImageData::SafeDownCast(producer->GetOutputDataObject(port));
  if (piece)
  {
    labels = this->GetInputArrayToProcess(0, piece);
  }
  return piece;
}

//------------------------------------------------------------------------------
bool vtkLabelMesher::SharesOutAcrossProcesses() const
{
  return this->Distributed && this->Decimate && labelmesher::MPIRunning() && labelmesher::WorldSize() > 1;
}

//------------------------------------------------------------------------------
int vtkLabelMesher::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* interfaces = vtkPolyData::GetData(outputVector, 1);
  vtkUnstructuredGrid* curved = vtkUnstructuredGrid::GetData(outputVector, 2);
  if (!input || !output || !interfaces || !curved)
  {
    vtkErrorMacro("Missing input image or outputs.");
    return 0;
  }
  // A process that reads only its slab has no voxels yet: the image's geometry stands in for it
  // until its slab is read (MeshAndDecimate).
  vtkInformation* inputInformation = inputVector[0]->GetInformationObject(0);
  // Decided once: meshing starts MPI when the application has not (MeshAndDecimate).
  const bool shares = this->SharesOutAcrossProcesses();
  this->StoppedOnEveryProcess = false;
  const bool slabOnly = this->ReadsItsSlabOnly(inputInformation);
  // A parallel pipeline (ParaView's) asks each process for its own piece: each then gets the
  // cells of the parts it meshed (PieceHandOut.h).
  vtkInformation* outputInformation = outputVector->GetInformationObject(0);
  const bool handsOutPieces = shares &&
    outputInformation->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) == labelmesher::WorldSize() &&
    outputInformation->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) == labelmesher::WorldRank();
  vtkNew<vtkImageData> geometry;
  if (slabOnly)
  {
    geometry->SetExtent(inputInformation->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()));
    geometry->SetSpacing(inputInformation->Get(vtkDataObject::SPACING()));
    if (inputInformation->Has(vtkDataObject::ORIGIN()))
    {
      geometry->SetOrigin(inputInformation->Get(vtkDataObject::ORIGIN()));
    }
    if (inputInformation->Has(vtkDataObject::DIRECTION()))
    {
      geometry->SetDirectionMatrix(inputInformation->Get(vtkDataObject::DIRECTION()));
    }
    geometry->GetFieldData()->ShallowCopy(input->GetFieldData());
    input = geometry;
  }
  if (shares)
  {
    const std::string failure = this->FirstDifferenceBetweenProcesses(input, slabOnly, handsOutPieces);
    if (!failure.empty())
    {
      vtkErrorMacro(<< failure << ".");
      return 1;
    }
  }
  if (this->Curve && GetImageDimension(input) != 2)
  {
    vtkErrorMacro("Curving needs a 2D image (one extent of a single slice); this image is 3D.");
    return 1;
  }
  if (this->Order == 2 && (!this->Decimate || this->Curve))
  {
    vtkErrorMacro("Quadratic cells (Order 2) curve the decimated mesh: they need Decimate, and not Curve (which "
                  "makes cubic cells).");
    return 1;
  }

  // Order 2 of a 2D image is the curver's, making quadratic triangles.
  const bool curve = this->Curve || (this->Order == 2 && GetImageDimension(input) == 2);
  const double meshWeight = this->Decimate ? kMeshAndDecimateWeight : kMeshWeight;
  const double meshShare = meshWeight / (meshWeight + (curve ? kCurveWeight : 0.0));
  try
  {
    const bool meshed = this->Decimate
      ? this->MeshAndDecimate(
          input, this->GetInputArrayToProcess(0, inputVector), slabOnly, output, interfaces, curved, meshShare)
      : this->MeshOnly(input, output, interfaces, meshShare);
    if (meshed && curve && !this->CurveMesh(input, output, curved, meshShare))
    {
      // Stopped or failed while curving: the run is not done, and a linear mesh alone is not what
      // was asked for.
      output->Initialize();
      interfaces->Initialize();
    }
  }
  catch (const std::exception& e)
  {
    if (!handsOutPieces)
    {
      throw;
    }
    // The other processes wait for their pieces: they get none, and this process says why.
    output->Initialize();
    interfaces->Initialize();
    vtkErrorMacro("Meshing failed: " << e.what() << ".");
  }
  if (handsOutPieces && !this->StoppedOnEveryProcess)
  {
    // Rank 0 without a mesh failed or stopped after the part every process takes together, and
    // has said why; the others learn it here.
    const bool saidWhy = labelmesher::WorldRank() == 0 && output->GetNumberOfCells() == 0;
    const std::string failure = labelmesher::HandOutPieces(output);
    if (!failure.empty())
    {
      interfaces->Initialize(); // no output of a run whose mesh is lost
      curved->Initialize();
      if (!saidWhy)
      {
        vtkErrorMacro(<< failure << ".");
      }
    }
  }
  this->SetProgressText(nullptr);
  if (!this->GetAbortExecute())
  {
    this->UpdateProgress(1.0); // a stopped run's progress stays where it stopped
  }
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkLabelMesher::FirstDifferenceBetweenProcesses(vtkImageData* input, bool slabOnly, bool handsOutPieces)
{
  // Every process must mesh the same (rank 0 joins their parts: parts of different images or
  // parameters make no mesh), checked before anything that could stop one process and not the
  // others (they would wait for it in the next step they take together). The labels are
  // compared slab by slab, as each process takes its slab (StreamedPipeline.cxx).
  std::ostringstream parameters;
  parameters.precision(17);
  parameters << this->ImageToMeshDistance << ' ' << this->MeshToImageDistance << ' ' << this->MinimumAngle << ' '
             << this->RelocateInteriorVertices << ' ' << this->IncludeBackground << ' ' << this->BlockCells << ' '
             << this->PartBlocks << ' ' << this->Order << ' ' << this->Curve; // not MemoryLimit: each process's own
  // Both comparisons are made on every process: each is a step they take together.
  const bool sameRun = labelmesher::SameAsRankZero(labelmesher::ImageFingerprint(input) + parameters.str());
  // So that all or none take HandOutPieces' steps.
  const bool sameRequest = labelmesher::SameAsRankZero(handsOutPieces ? "pieces" : "whole");
  std::string problem;
  if (!slabOnly && input->GetNumberOfPoints() == 0)
  {
    // A process whose reader failed has an empty image, which differs from rank 0's too: its
    // reason is that it has none (the reader's own error is in that process's output).
    problem = labelmesher::WorldRank() == 0
      ? "The input image is empty"
      : "its input image is empty (its reader's error, if it failed, is in that process's output)";
  }
  else if (!sameRun)
  {
    problem = "it was given another image or other meshing parameters than process 0 (every process must mesh the "
              "same)";
  }
  else if (!sameRequest)
  {
    problem = std::string("its pipeline asked for ") + (handsOutPieces ? "its own piece" : "the whole mesh") +
      " where process 0's asked for " + (handsOutPieces ? "the whole mesh" : "each process's piece") +
      " (every process must ask alike)";
  }
  return labelmesher::FirstFailure(problem);
}

//------------------------------------------------------------------------------
bool vtkLabelMesher::MeshOnly(vtkImageData* input, vtkUnstructuredGrid* output, vtkPolyData* interfaces, double share)
{
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetImageToMeshDistance(this->ImageToMeshDistance);
  mesher->SetMeshToImageDistance(this->MeshToImageDistance);
  mesher->SetIncludeBackground(this->IncludeBackground);
  mesher->SetMeasureOutput(this->MeasureOutput);
  mesher->SetMemoryLimit(this->MemoryLimit);
  mesher->SetInputArrayToProcess(0, this->GetInputArrayInformation(0));
  // A copy, so that the inner pipeline leaves the input's pipeline information alone.
  vtkNew<vtkImageData> image;
  image->ShallowCopy(input);
  mesher->SetInputData(image);
  const labelmesher::StageMessages messages = labelmesher::RunAsStage(this, mesher, 0.0, share);
  if (!messages.Error.empty())
  {
    vtkErrorMacro(<< messages.Error);
    return false;
  }
  if (!messages.Warning.empty())
  {
    vtkWarningMacro(<< messages.Warning);
  }
  if (this->GetAbortExecute() || mesher->GetOutput()->GetNumberOfCells() == 0)
  {
    return false;
  }
  output->ShallowCopy(mesher->GetOutput());
  interfaces->ShallowCopy(mesher->GetInterfacesOutput());
  return true;
}

//------------------------------------------------------------------------------
bool vtkLabelMesher::CurveMesh(vtkImageData* input, vtkUnstructuredGrid* linear, vtkUnstructuredGrid* curved, double start)
{
  vtkNew<vtkBezierCurver> curver;
  curver->SetSmoothness(this->Smoothness);
  curver->SetTension(this->Tension);
  curver->SetMaximumUntanglingSteps(this->MaximumUntanglingSteps);
  curver->SetMaximumShorteningRounds(this->MaximumShorteningRounds);
  curver->SetQualityIterations(this->QualityIterations);
  curver->SetMinimumScaledJacobian(this->MinimumScaledJacobian);
  // The corners keep the angle the linear mesh was asked for (the mesher's own mesh holds more).
  curver->SetMinimumCornerAngle(this->MinimumAngle);
  curver->SetOrder(this->Order == 2 ? 2 : 3);
  // Copies, so that the inner pipeline leaves this filter's output and input alone.
  vtkNew<vtkUnstructuredGrid> mesh;
  mesh->ShallowCopy(linear);
  vtkNew<vtkImageData> image;
  image->ShallowCopy(input);
  curver->SetInputDataObject(0, mesh);
  curver->SetInputDataObject(1, image);
  // The labels the mesh was made from, not the image's active scalars: the same array, on the
  // curver's image port.
  vtkNew<vtkInformation> labels;
  labels->Copy(this->GetInputArrayInformation(0));
  labels->Set(vtkAlgorithm::INPUT_PORT(), 1);
  curver->SetInputArrayToProcess(0, labels);
  const labelmesher::StageMessages messages = labelmesher::RunAsStage(this, curver, start, 1.0 - start);
  if (!messages.Warning.empty())
  {
    vtkWarningMacro(<< messages.Warning);
  }
  vtkUnstructuredGrid* made = curver->GetOutput();
  if (!messages.Error.empty())
  {
    vtkErrorMacro(<< messages.Error);
  }
  else if (made->GetNumberOfCells() == 0 && !this->GetAbortExecute())
  {
    vtkErrorMacro("The curver produced no cells.");
  }
  // An untangling failure still outputs the marked mesh: kept, with the error and the linear mesh.
  // Any other failure (or a stop) leaves no curves: the run did not finish.
  curved->ShallowCopy(made);
  return made->GetNumberOfCells() > 0;
}

//------------------------------------------------------------------------------
bool vtkLabelMesher::MeshAndDecimate(vtkImageData* input, vtkDataArray* labels, bool slabOnly,
  vtkUnstructuredGrid* output, vtkPolyData* boundary, vtkUnstructuredGrid* quadratic, double share)
{
  labelmesher::ImagePlacement placement;
  labelmesher::LabelImage image;
  std::string problem;
  const auto blockCells = static_cast<std::uint64_t>(std::max<vtkIdType>(0, this->BlockCells));
  labelmesher::MemoryEstimate estimate;
  labelmesher::MemoryBudget budget;
  const bool quadratic3D = this->Order == 2 && GetImageDimension(input) == 3;
  int dims[3];
  input->GetDimensions(dims);
  if (slabOnly)
  {
    // Its labels come with its slab; until then it knows only the least it will need. Rank 0
    // estimated the whole run, of which this process holds a share.
    image.Dimensions = { dims[0], dims[1], dims[2] };
    estimate.RunBytes = labelmesher::SlabProcessFloorBytes();
    budget = labelmesher::AvailableMemory(this->MemoryLimit, /*startsMPI=*/true);
    problem = labelmesher::RefuseIfTooLarge(
      estimate.RunBytes, "the least a process that reads its slab of the image holds", budget);
  }
  else if (labelmesher::ConvertLabelImage(input, labels, image, placement, problem))
  {
    estimate = labelmesher::EstimateStreamedMemory(image, blockCells);
    if (quadratic3D)
    {
      estimate = labelmesher::WithQuadraticStage(estimate, this->MeasureOutput);
    }
    budget = labelmesher::AvailableMemory(this->MemoryLimit, /*startsMPI=*/true);
    problem = labelmesher::RefuseIfTooLarge(estimate.RunBytes, labelmesher::DescribeEstimate(estimate), budget);
  }
  // Under mpirun the application has started MPI; a plain process starts it only once the run
  // is known to fit (its start takes address space, MemoryBudget.h).
  const std::unique_ptr<labelmesher::PartExchange> exchange =
    this->Distributed && labelmesher::MPIRunning() ? labelmesher::WorldPartExchange() : nullptr;
  if (exchange)
  {
    // Every process goes on or none does: rank 0 would wait for the parts of one that stopped.
    // (That all were given the same image and parameters RequestData checked first.)
    problem = labelmesher::FirstFailure(problem);
  }
  if (!problem.empty())
  {
    this->StoppedOnEveryProcess = exchange != nullptr;
    vtkErrorMacro(<< problem << ".");
    return false;
  }
  labelmesher::StartMPI(); // p4est's forest needs MPI; starting it is the application's (MPIStartup.h)

  labelmesher::MesherParameters mesher;
  mesher.ImageToMeshDistance = this->ImageToMeshDistance;
  mesher.MeshToImageDistance = this->MeshToImageDistance;
  labelmesher::DecimationParameters decimation;
  decimation.MinimumAngle = this->MinimumAngle;
  decimation.ImageToMeshDistance = this->ImageToMeshDistance;
  decimation.MeshToImageDistance = this->MeshToImageDistance;
  decimation.RelocateInteriorVertices = this->RelocateInteriorVertices;
  labelmesher::StreamingParameters streaming;
  streaming.BlockCells = blockCells;
  streaming.PartBlocks = static_cast<std::size_t>(std::max<vtkIdType>(0, this->PartBlocks));

  // Quadratic cells (and their measurement) take a share of the run after the decimation.
  // In order: meshing and decimating, the quadratic cells (Order 2), measuring the linear mesh.
  const double quadraticShare = quadratic3D ? share * 0.2 : 0.0;
  const double runShare = (share - quadraticShare) * (this->MeasureOutput ? 0.8 : 1.0);
  const double measureStart = runShare + quadraticShare;
  // A process other than rank 0 keeps only the slab of the image its parts need, taken once
  // rank 0 has assigned them; the rest of the converted image is released then.
  labelmesher::SlabSource slabs;
  if (slabOnly)
  {
    slabs = [this, input, dims](int first, int end) {
      if (first >= end)
      {
        return labelmesher::LabelImage::EmptySlab({ dims[0], dims[1], dims[2] }, first, first); // reads no voxel
      }
      RefuseSlabBeyondMemory(dims, end - first, this->MemoryLimit);
      int whole[6], extent[6];
      input->GetExtent(whole);
      SlabExtent(whole, first, end, extent);
      vtkDataArray* pieceLabels = nullptr;
      std::string error;
      vtkImageData* piece = this->UpdateInputExtent(extent, pieceLabels, error);
      labelmesher::LabelImage slab;
      if (!error.empty() || !piece || !labelmesher::ConvertLabelSlab(piece, pieceLabels, whole, first, end, slab, error))
      {
        throw std::runtime_error("reading slices " + std::to_string(first) + " to " + std::to_string(end - 1) +
          " of its image failed" + (error.empty() ? std::string() : ": " + error));
      }
      piece->ReleaseData(); // converted: the slab is the only copy this process keeps
      return slab;
    };
  }
  else if (exchange && exchange->Rank() != 0)
  {
    slabs = [whole = std::make_shared<labelmesher::LabelImage>(std::move(image))](int first, int end) mutable {
      if (!whole)
      {
        throw std::logic_error("the image's slab was asked for twice");
      }
      labelmesher::LabelImage slab = labelmesher::LabelImage::Slab(*whole, first, end);
      whole.reset();
      return slab;
    };
  }
  labelmesher::StreamedResult result;
  try
  {
    result = labelmesher::MeshAndDecimate(image, mesher, decimation, streaming,
      labelmesher::ForwardProgress(this, 0.0, runShare), exchange.get(), slabs);
  }
  // The streamed pipeline's failures and stops are agreed: under MPI every process is here.
  catch (const labelmesher::AbortRequested&)
  {
    this->StoppedOnEveryProcess = exchange != nullptr;
    vtkWarningMacro("Meshing aborted on request: output is empty.");
    return false;
  }
  catch (const std::bad_alloc&)
  {
    this->StoppedOnEveryProcess = exchange != nullptr;
    vtkErrorMacro("Meshing failed: out of memory (estimated beforehand to need "
      << labelmesher::FormatMiB(estimate.RunBytes) << " more; " << labelmesher::FormatMiB(budget.Bytes)
      << " were available: " << budget.Source << ").");
    return false;
  }
  catch (const std::exception& e)
  {
    this->StoppedOnEveryProcess = exchange != nullptr;
    vtkErrorMacro("Meshing failed: " << e.what() << ".");
    return false;
  }

  if (!result.HoldsMesh)
  {
    return false; // a process other than rank 0 of a distributed run: its parts went to rank 0
  }
  labelmesher::DecimationResult& decimated = result.Decimated;
  if (quadratic3D && !MakeQuadratic(this, image, decimated.Mesh, placement, quadratic, runShare, quadraticShare, decimated.Timings))
  {
    return false;
  }
  const labelmesher::SimplexMesh kept = labelmesher::SelectMaterials(std::move(decimated.Mesh), this->IncludeBackground);
  labelmesher::PackVolumeMesh(kept, placement, output);
  labelmesher::PackInterfaces(decimated.Interfaces, decimated.InterfaceMaterials, placement, boundary);
  if (!result.Parts.StartKeys.empty())
  {
    // Who meshed what: the pieces of a .pvtu, and a colouring that shows the partition.
    const std::vector<std::int32_t> process = labelmesher::CellProcesses(kept, result.Parts);
    vtkNew<vtkIntArray> processArray;
    processArray->SetName(arrays::Process);
    processArray->SetNumberOfValues(static_cast<vtkIdType>(process.size()));
    std::copy(process.begin(), process.end(), processArray->GetPointer(0));
    output->GetCellData()->AddArray(processArray);
  }

  vtkFieldData* fd = output->GetFieldData();
  const std::size_t before =
    this->IncludeBackground ? decimated.Counts.CellsBefore : result.Streaming.ForegroundCellsBefore;
  labelmesher::AddDecimationFields(fd, decimation, decimated.Counts, before, kept.NumberOfCells());
  labelmesher::AddScalarField(fd, arrays::IncludeBackground, this->IncludeBackground ? 1.0 : 0.0);
  labelmesher::AddScalarField(fd, arrays::VoxelSize, placement.VoxelSize);
  labelmesher::AddScalarField(fd, arrays::NumberOfLeaves, static_cast<double>(result.Streaming.Leaves));
  labelmesher::AddScalarField(fd, arrays::EstimatedMemory, static_cast<double>(estimate.RunBytes) / (1 << 20));
  labelmesher::AddScalarField(fd, arrays::InterfaceFaces, static_cast<double>(estimate.InterfaceFaces));
  labelmesher::AddScalarField(fd, arrays::Blocks, static_cast<double>(result.Streaming.Blocks));
  labelmesher::AddScalarField(fd, arrays::LargestBlockCells, static_cast<double>(result.Streaming.LargestBlockCells));
  labelmesher::AddScalarField(fd, arrays::Parts, static_cast<double>(result.Streaming.Parts));
  labelmesher::AddScalarField(fd, arrays::Processes, static_cast<double>(result.Streaming.Processes));
  labelmesher::AddScalarField(fd, arrays::AssembledCells, static_cast<double>(result.Streaming.AssembledCells));
  labelmesher::AddScalarField(fd, arrays::BorderPasses, static_cast<double>(result.Streaming.BorderPasses));
  labelmesher::AddScalarField(
    fd, arrays::LargestAssembledCells, static_cast<double>(result.Streaming.LargestAssembledCells));
  labelmesher::PassMaterialTable(input->GetFieldData(), fd);
  labelmesher::PassMaterialTable(input->GetFieldData(), boundary->GetFieldData());
  if (this->MeasureOutput)
  {
    this->SetProgressText("measure");
    this->UpdateProgress(measureStart);
    try
    {
      labelmesher::AddMeasurements(fd, image, kept, this->ImageToMeshDistance, this->MeshToImageDistance,
        decimated.Timings, [&](int checksDone) { this->UpdateProgress(measureStart + (share - measureStart) * checksDone / 4.0); });
    }
    catch (const std::exception& e)
    {
      vtkWarningMacro("Measuring the mesh failed: " << e.what());
    }
  }
  labelmesher::AddStageTimings(fd, decimated.Timings);
  return output->GetNumberOfCells() > 0;
}

//------------------------------------------------------------------------------
void vtkLabelMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImageToMeshDistance: " << this->ImageToMeshDistance << " voxels\n";
  os << indent << "MeshToImageDistance: " << this->MeshToImageDistance << " voxels\n";
  os << indent << "MinimumAngle: " << this->MinimumAngle << " degrees\n";
  os << indent << "RelocateInteriorVertices: " << (this->RelocateInteriorVertices ? "On" : "Off") << "\n";
  os << indent << "BlockCells: " << this->BlockCells << " initial cells\n";
  os << indent << "PartBlocks: " << this->PartBlocks << " blocks\n";
  os << indent << "Distributed: " << this->Distributed << "\n";
  os << indent << "IncludeBackground: " << (this->IncludeBackground ? "On" : "Off") << "\n";
  os << indent << "MeasureOutput: " << (this->MeasureOutput ? "On" : "Off") << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB (0: the available memory)\n";
  os << indent << "Decimate: " << (this->Decimate ? "On" : "Off") << "\n";
  os << indent << "Curve: " << (this->Curve ? "On" : "Off") << "\n";
  os << indent << "Smoothness: C" << this->Smoothness << "\n";
  os << indent << "Tension: " << this->Tension << "\n";
  os << indent << "MaximumUntanglingSteps: " << this->MaximumUntanglingSteps << "\n";
  os << indent << "MaximumShorteningRounds: " << this->MaximumShorteningRounds << "\n";
  os << indent << "QualityIterations: " << this->QualityIterations << "\n";
  os << indent << "MinimumScaledJacobian: " << this->MinimumScaledJacobian << "\n";
  os << indent << "Order: " << this->Order << "\n";
}
