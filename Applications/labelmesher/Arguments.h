// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_cli_Arguments_h
#define labelmesher_cli_Arguments_h

/**
 * @file Arguments.h
 * Command line of `labelmesher mesh|curve INPUT -o OUTPUT [options]`.
 */

#include <stdexcept>
#include <string>
#include <vector>

namespace labelmesher_cli
{

/// A command line that cannot be run; main prints it with the usage hint.
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Arguments
{
  std::string Command;             ///< "mesh" or "curve"
  std::string Input;
  std::vector<std::string> Outputs; ///< one or more, format by extension (labelmesher::io::FormatOfPath)
  std::string Labels;               ///< --labels colour table (ITK-SNAP or 3D Slicer); empty: none
  bool GmshVersion22 = false;       ///< --msh-version 2.2
  bool StlPerInterface = false;     ///< --stl-per-interface
  std::string Report;              ///< JSON report path; empty: none
  double ImageToMeshDistance = 2.0; ///< voxels of the smallest spacing
  double MeshToImageDistance = 2.0; ///< voxels of the smallest spacing
  bool IncludeBackground = false;
  bool Measure = true;              ///< measure the output (angles, distances, topology)
  bool Decimate = true;             ///< run vtkMeshDecimator after the mesher (default: mesh yes, curve no)
  bool Relocate = true;             ///< the decimator moves interior vertices between rounds of merges
  double MinimumAngle = 15.0;       ///< degrees, the decimator's angle bound; (0, 30] in 3D, (0, 45] in 2D
  // curve only
  int Smoothness = 1;               ///< 1 (C1, fitted to the image) or 2 (C2)
  double Tension = 1.0 / 3.0;       ///< C1 handle length factor, dimensionless
  int MaximumUntanglingSteps = 64;
  int MaximumShorteningRounds = 8;
  int QualityIterations = 0;
  bool Quiet = false;
  bool Help = false;
  bool Version = false;
};

/// Parses argv; throws UsageError with a one-line reason.
Arguments ParseArguments(int argc, const char* const* argv);

/// The help text.
std::string Usage();

} // namespace labelmesher_cli

#endif
