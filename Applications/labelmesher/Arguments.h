// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_cli_Arguments_h
#define labelmesher_cli_Arguments_h

/**
 * @file Arguments.h
 * Command line of `labelmesher mesh|curve INPUT -o OUTPUT [options]`.
 */

#include "MeshingPipeline.h"

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
  /// The pipeline's parameters, with their units and defaults (Curve: the command is "curve").
  MeshingSettings Settings;
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
