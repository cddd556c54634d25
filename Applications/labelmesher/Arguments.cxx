// SPDX-License-Identifier: GPL-2.0-or-later
// Parses and validates the labelmesher command line; every mistake becomes one UsageError line.
#include "Arguments.h"

#include "StringUtilities.h"

#include "MeshFiles.h"

#include "vtkLabelMesher.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

namespace labelmesher_cli
{

using labelmesher::io::EndsWith;
using labelmesher::io::Lower;
using labelmesher::io::Trim;
namespace
{

/// `text` read whole by `read` (std::stod or std::stol); false when it is empty,
/// not a number, or has anything after the number.
template <typename Value, typename Read>
bool ReadWhole(const std::string& text, Read read, Value& value)
{
  std::size_t used = 0;
  try
  {
    value = static_cast<Value>(read(text, &used));
  }
  catch (const std::exception&)
  {
    return false;
  }
  return !text.empty() && used == text.size();
}

double ParseDistance(const std::string& option, const std::string& text)
{
  double value = 0.0;
  const auto read = [](const std::string& t, std::size_t* used) { return std::stod(t, used); };
  if (!ReadWhole(text, read, value) || !std::isfinite(value) || value < 0.0)
  {
    throw UsageError(option + " expects a non-negative number of voxels, got '" + text + "'");
  }
  return value;
}

int ParseCount(const std::string& option, const std::string& text, int minimum)
{
  long value = 0;
  const auto read = [](const std::string& t, std::size_t* used) { return std::stol(t, used); };
  if (!ReadWhole(text, read, value) || value < minimum || value > 1000000)
  {
    throw UsageError(option + " expects a whole number >= " + std::to_string(minimum) +
      ", got '" + text + "'");
  }
  return static_cast<int>(value);
}

/// "30" for 30.0: the proven bounds as the help text states them.
std::string ProvenBound(int dimension)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", vtkLabelMesher::GetProvenAngleBound(dimension));
  return text;
}

double ParseAngle(const std::string& text)
{
  double value = -1.0;
  const auto read = [](const std::string& t, std::size_t* used) { return std::stod(t, used); };
  // The largest bound of either dimension here; the filters check the image's own.
  const double largest = std::max(vtkLabelMesher::GetProvenAngleBound(2), vtkLabelMesher::GetProvenAngleBound(3));
  if (!ReadWhole(text, read, value) || !(value > 0.0 && value <= largest))
  {
    throw UsageError("--min-angle expects degrees in (0, " + ProvenBound(3) + "] (3D) or (0, " + ProvenBound(2) +
      "] (2D), got '" + text + "'");
  }
  return value;
}

/// "900M", "1.5G", "2048" (MiB) -> MiB.
double ParseMemory(const std::string& text)
{
  std::string number = text;
  double unit = 1.0;
  if (!number.empty() && (number.back() == 'G' || number.back() == 'g' || number.back() == 'M' || number.back() == 'm'))
  {
    unit = (number.back() == 'G' || number.back() == 'g') ? 1024.0 : 1.0;
    number.pop_back();
  }
  double value = -1.0;
  const auto read = [](const std::string& t, std::size_t* used) { return std::stod(t, used); };
  if (!ReadWhole(number, read, value) || !std::isfinite(value) || !(value > 0.0))
  {
    throw UsageError("--max-memory expects a positive size in MiB, or with M or G (900M, 1.5G), got '" + text + "'");
  }
  return value * unit;
}

/// "4" -> a count of blocks (0 allowed: one part).
long long ParsePartBlocks(const std::string& text)
{
  long long value = -1;
  const auto read = [](const std::string& t, std::size_t* used) { return std::stoll(t, used); };
  if (!ReadWhole(text, read, value) || value < 0 || value > 1000000000LL)
  {
    throw UsageError("--part-blocks expects a whole number of blocks >= 0, got '" + text + "'");
  }
  return value;
}

/// "1000000", "250k", "2M" -> a count of cells (0 allowed: one block).
long long ParseBlockCells(const std::string& text)
{
  std::string number = text;
  long long unit = 1;
  if (!number.empty() && (number.back() == 'k' || number.back() == 'K' || number.back() == 'M' || number.back() == 'm'))
  {
    unit = (number.back() == 'k' || number.back() == 'K') ? 1000 : 1000000;
    number.pop_back();
  }
  long long value = -1;
  const auto read = [](const std::string& t, std::size_t* used) { return std::stoll(t, used); };
  if (!ReadWhole(number, read, value) || value < 0 || value > 1000000000000LL / unit)
  {
    throw UsageError("--block-cells expects a whole number of cells >= 0 (with k or M: 500k, 2M), got '" + text + "'");
  }
  return value * unit;
}

double ParseScaledJacobian(const std::string& text)
{
  double value = -1.0;
  const auto read = [](const std::string& t, std::size_t* used) { return std::stod(t, used); };
  if (!ReadWhole(text, read, value) || !(value >= 0.0 && value < 1.0))
  {
    throw UsageError("--min-scaled-jacobian expects a number in [0, 1), got '" + text + "'");
  }
  return value;
}

double ParseTension(const std::string& text)
{
  double value = -1.0;
  const auto read = [](const std::string& t, std::size_t* used) { return std::stod(t, used); };
  if (!ReadWhole(text, read, value) || !(value >= 0.0 && value <= 1.0))
  {
    throw UsageError("--tension expects a number in [0, 1], got '" + text + "'");
  }
  return value;
}

struct Reading;
void ChooseDecimation(Reading& reading, const std::string& option);

/// What the parser knows while it reads the words: the arguments so far and what was given.
struct Reading
{
  Arguments& Args;
  std::string DecimateOption;     ///< --decimate or --no-decimate, if given
  std::set<std::string> Given;    ///< the long names of the options given
};

/// One option: its names, its value (null for a switch), its help and what it does.
struct Option
{
  const char* Short; ///< "-o", or null
  const char* Long;  ///< "--output"
  const char* Value; ///< "FILE", or null: a switch, which takes no value
  bool CurveOnly;    ///< applies to `curve` only
  std::string Help;  ///< lines, each after the first continued under the first
  void (*Apply)(Reading& reading, const std::string& value);
};

/// Every option, in the order of the help text: the parser and Usage() read this table alone.
const std::vector<Option>& Options()
{
  static const std::vector<Option> options = {
    { "-o", "--output", "FILE", false,
      "output file, format by extension; repeat for several\n"
      "[required]. The mesh with a group per material:\n"
      "  .vtu  VTK XML         .vtk  VTK legacy (binary)\n"
      "  .msh  Gmsh 4.1 ASCII  .inp  Abaqus\n"
      "  .mesh Medit           .pvtu VTK XML, a piece per process\n"
      "the interfaces between materials (mesh only):\n"
      "  .vtp  VTK XML         .stl  binary STL (3D)\n"
      "  .obj  Wavefront OBJ\n"
      "curve writes .vtu or .vtk (Bezier cells) or .msh (10-node triangles)",
      [](Reading& r, const std::string& v) { r.Args.Outputs.push_back(v); } },
    { nullptr, "--msh-version", "4.1|2.2", false, "Gmsh file version                         [default 4.1]",
      [](Reading& r, const std::string& v) {
        if (v != "4.1" && v != "2.2")
          throw UsageError("--msh-version expects 4.1 or 2.2, got '" + v + "'");
        r.Args.GmshVersion22 = v == "2.2";
      } },
    { nullptr, "--stl-per-interface", nullptr, false, "one .stl per pair of materials, STEM_NAMEA_NAMEB.stl",
      [](Reading& r, const std::string&) { r.Args.StlPerInterface = true; } },
    { nullptr, "--labels", "FILE", false,
      "material names (and colours) from an ITK-SNAP label\n"
      "description or a 3D Slicer colour table; without it\n"
      "materials are named label_N (or by the .seg.nrrd)",
      [](Reading& r, const std::string& v) { r.Args.Labels = v; } },
    { nullptr, "--image-to-mesh", "H1", false,
      "h(I,M) bound: image boundary to mesh boundary, in voxels\n"
      "of the smallest spacing                        [default 2]",
      [](Reading& r, const std::string& v) { r.Args.Settings.ImageToMeshDistance = ParseDistance("--image-to-mesh", v); } },
    { nullptr, "--mesh-to-image", "H2", false,
      "h(M,I) bound: mesh boundary to image boundary, in voxels\n"
      "of the smallest spacing                        [default 2]",
      [](Reading& r, const std::string& v) { r.Args.Settings.MeshToImageDistance = ParseDistance("--mesh-to-image", v); } },
    { nullptr, "--hausdorff", "H", false, "set both bounds to H voxels",
      [](Reading& r, const std::string& v) {
        r.Args.Settings.ImageToMeshDistance = r.Args.Settings.MeshToImageDistance = ParseDistance("--hausdorff", v);
      } },
    { nullptr, "--report", "FILE.json", false, "write the summary as JSON",
      [](Reading& r, const std::string& v) { r.Args.Report = v; } },
    { nullptr, "--min-angle", "DEG", false,
      "smallest angle the decimator may create, degrees:\n"
      "(0, " + ProvenBound(3) + "] in 3D, (0, " + ProvenBound(2) + "] in 2D                [default 15];\n"
      "curve, --order 2: also every curved cell's corner angles",
      [](Reading& r, const std::string& v) { r.Args.Settings.MinimumAngle = ParseAngle(v); } },
    { nullptr, "--order", "1|2", false,
      "mesh: element order; 2 also makes quadratic tetrahedra\n"
      "(3D) or triangles (2D) fitted to the image (decimated):\n"
      "certified valid, --min-scaled-jacobian, corners at\n"
      "--min-angle, both distance bounds; written as\n"
      ".vtu .vtk .msh .inp .mesh                   [default 1]",
      [](Reading& r, const std::string& v) {
        r.Args.Settings.Order = ParseCount("--order", v, 1);
        if (r.Args.Settings.Order > 2)
          throw UsageError("--order expects 1 (linear) or 2 (quadratic)");
      } },
    { nullptr, "--no-decimate", nullptr, false,
      "keep the initial mesh (angles >= " + ProvenBound(3) + " 3D, " + ProvenBound(2) + " 2D)",
      [](Reading& r, const std::string&) { ChooseDecimation(r, "--no-decimate"); } },
    { nullptr, "--decimate", nullptr, false, "decimate (the default)",
      [](Reading& r, const std::string&) { ChooseDecimation(r, "--decimate"); } },
    { nullptr, "--no-relocate", nullptr, false,
      "merges only: do not move interior vertices between\n"
      "rounds of merges (more cells; the dissertation's way)",
      [](Reading& r, const std::string&) { r.Args.Settings.RelocateInteriorVertices = false; } },
    { nullptr, "--include-background", nullptr, false, "keep the cells of label 0",
      [](Reading& r, const std::string&) { r.Args.Settings.IncludeBackground = true; } },
    { nullptr, "--no-measure", nullptr, false,
      "do not measure the output (angles, distances,\n"
      "conformity, topology); saves 1-2x the meshing time",
      [](Reading& r, const std::string&) { r.Args.Settings.Measure = false; } },
    { nullptr, "--block-cells", "N", false,
      "initial cells per block: the mesh is made and decimated\n"
      "block by block, so that peak memory follows one block\n"
      "and the output; 0: one block (k, M: 500k, 2M)  [default 1M]",
      [](Reading& r, const std::string& v) { r.Args.Settings.BlockCells = ParseBlockCells(v); } },
    { nullptr, "--part-blocks", "N", false,
      "blocks per part: under mpirun -np P each process meshes\n"
      "its share of the parts, the same mesh for any P;\n"
      "0: one part                                [default 2]",
      [](Reading& r, const std::string& v) { r.Args.Settings.PartBlocks = ParsePartBlocks(v); } },
    { nullptr, "--max-memory", "SIZE", false,
      "the most memory the run may hold, MiB or with M/G\n"
      "(900M, 1.5G); a run estimated not to fit it (or the\n"
      "machine's available memory, ulimit -v) is refused\n"
      "before it starts          [default: the machine's]",
      [](Reading& r, const std::string& v) { r.Args.Settings.MemoryLimit = ParseMemory(v); } },
    { "-q", "--quiet", nullptr, false, "no progress bar, no summary (errors only)",
      [](Reading& r, const std::string&) { r.Args.Quiet = true; } },
    { nullptr, "--smoothness", "1|2", true,
      "continuity of the curved boundaries: C1, fitted\n"
      "to the image, or C2, through the vertices   [default 1]",
      [](Reading& r, const std::string& v) {
        r.Args.Settings.Smoothness = ParseCount("--smoothness", v, 1);
        if (r.Args.Settings.Smoothness > 2)
          throw UsageError("--smoothness expects 1 (C1) or 2 (C2)");
      } },
    { nullptr, "--tension", "T", true,
      "C1 tangent handle length factor in [0, 1] the fit\n"
      "is pulled towards (1/3: Catmull-Rom, 0: straight)\n"
      "                                            [default 0.3333]",
      [](Reading& r, const std::string& v) { r.Args.Settings.Tension = ParseTension(v); } },
    { nullptr, "--max-untangling-steps", "N", true, "most load fractions of the elastic untangling [default 64]",
      [](Reading& r, const std::string& v) {
        r.Args.Settings.MaximumUntanglingSteps = ParseCount("--max-untangling-steps", v, 1);
      } },
    { nullptr, "--max-shortening-rounds", "N", true,
      "most untangling rounds, each after shortening the\n"
      "curves of the cells left invalid            [default 8]",
      [](Reading& r, const std::string& v) {
        r.Args.Settings.MaximumShorteningRounds = ParseCount("--max-shortening-rounds", v, 1);
      } },
    { nullptr, "--min-scaled-jacobian", "R", true,
      "every curved cell's certified min det J / max det J\n"
      "at least R, in [0, 1): curves pulled back until it\n"
      "holds (0: validity alone; also mesh --order 2)\n"
      "                                            [default 0.1]",
      [](Reading& r, const std::string& v) { r.Args.Settings.MinimumScaledJacobian = ParseScaledJacobian(v); } },
    { nullptr, "--quality-iterations", "N", true,
      "further fraction doublings kept when the worst\n"
      "scaled Jacobian improves                    [default 0]",
      [](Reading& r, const std::string& v) {
        r.Args.Settings.QualityIterations = ParseCount("--quality-iterations", v, 0);
      } },
    { "-h", "--help", nullptr, false, "this text", [](Reading& r, const std::string&) { r.Args.Help = true; } },
    { nullptr, "--version", nullptr, false, "print the version",
      [](Reading& r, const std::string&) { r.Args.Version = true; } },
  };
  return options;
}

void ChooseDecimation(Reading& reading, const std::string& option)
{
  if (!reading.DecimateOption.empty() && reading.DecimateOption != option)
  {
    throw UsageError("--decimate and --no-decimate contradict each other");
  }
  reading.DecimateOption = option;
}

const Option* FindOption(const std::string& word)
{
  for (const Option& option : Options())
    if (word == option.Long || (option.Short && word == option.Short))
      return &option;
  return nullptr;
}

} // namespace

std::string Usage()
{
  std::string text = "Usage: labelmesher mesh INPUT -o OUTPUT [options]\n"
                     "       labelmesher curve INPUT2D -o OUTPUT [options]\n"
                     "\n"
                     "mesh:  meshes a label image (integer labels, 0 = background) into labelled\n"
                     "       tetrahedra (3D) or triangles (2D images) with bounded angles, bounded\n"
                     "       Hausdorff distance and the image's topology per material, then decimates\n"
                     "       the mesh within the same bounds (fewer cells).\n"
                     "curve: meshes and decimates a 2D label image as above, then curves the\n"
                     "       triangles into cubic Bezier triangles (VTK_BEZIER_TRIANGLE) with C1\n"
                     "       (fitted to the image) or C2 smooth material boundaries that keep both\n"
                     "       distance bounds, every cell proven valid; reports validity, the scaled\n"
                     "       Jacobian histogram, the curves' distances and crossings, and pixel\n"
                     "       accuracy of the linear vs the curved mesh.\n"
                     "\n"
                     "INPUT   .nrrd/.nhdr, .nii/.nii.gz, .mha/.mhd (ITK), .vti, .png (single channel),\n"
                     "        .seg.nrrd (3D Slicer segmentation: segment names, colours, layers)\n"
                     "\n"
                     "Options:\n";
  constexpr std::size_t column = 29; // where the help starts
  bool curveHeader = false;
  for (const Option& option : Options())
  {
    if (option.CurveOnly && !curveHeader)
    {
      text += "curve options:\n";
      curveHeader = true;
    }
    std::string names = std::string("  ") + (option.Short ? std::string(option.Short) + ", " : "") + option.Long +
      (option.Value ? std::string(" ") + option.Value : "");
    names.resize(std::max(column, names.size() + 1), ' ');
    std::string help = option.Help;
    for (std::size_t at = help.find('\n'); at != std::string::npos; at = help.find('\n', at + 1 + column))
      help.insert(at + 1, column, ' ');
    text += names + help + "\n";
  }
  return text;
}

Arguments ParseArguments(int argc, const char* const* argv)
{
  Arguments args;
  Reading reading{ args, {}, {} };
  std::vector<std::string> words(argv + 1, argv + argc);
  std::vector<std::string> positional;
  for (std::size_t w = 0; w < words.size(); ++w)
  {
    std::string word = words[w];
    std::string value;
    bool hasInlineValue = false;
    if (word.rfind("--", 0) == 0)
    {
      const std::size_t eq = word.find('=');
      if (eq != std::string::npos)
      {
        value = word.substr(eq + 1);
        word = word.substr(0, eq);
        hasInlineValue = true;
      }
    }
    const Option* option = FindOption(word);
    if (!option)
    {
      if (word.size() > 1 && word[0] == '-')
      {
        throw UsageError("unknown option " + word);
      }
      positional.push_back(word);
      continue;
    }
    if (!option->Value && hasInlineValue)
    {
      throw UsageError(word + " takes no value");
    }
    if (option->Value && !hasInlineValue)
    {
      if (w + 1 >= words.size())
      {
        throw UsageError(word + " needs a value");
      }
      value = words[++w];
    }
    reading.Given.insert(option->Long);
    option->Apply(reading, value);
  }
  const auto given = [&](const char* name) { return reading.Given.count(name) > 0; };
  if (args.Help || args.Version)
  {
    return args;
  }
  if (positional.empty())
  {
    throw UsageError("missing command: expected 'mesh' or 'curve'");
  }
  if (positional[0] != "mesh" && positional[0] != "curve")
  {
    throw UsageError("unknown command '" + positional[0] + "': expected 'mesh' or 'curve'");
  }
  args.Command = positional[0];
  args.Settings.Curve = args.Command == "curve";
  args.Settings.Decimate = reading.DecimateOption.empty() || reading.DecimateOption == "--decimate";
  if (given("--no-relocate") && !args.Settings.Decimate)
  {
    throw UsageError("--no-relocate is a decimator option: it cannot go with --no-decimate");
  }
  if (given("--block-cells") && !args.Settings.Decimate)
  {
    throw UsageError("--block-cells streams mesher and decimator: it cannot go with --no-decimate");
  }
  if (given("--part-blocks") && !args.Settings.Decimate)
  {
    throw UsageError("--part-blocks groups the streamed blocks: it cannot go with --no-decimate");
  }
  if (given("--min-angle") && !args.Settings.Decimate)
  {
    throw UsageError("--min-angle is the decimator's bound: it cannot go with --no-decimate");
  }
  if (given("--order") && args.Command == "curve")
  {
    throw UsageError("--order applies to 'mesh' ('curve' makes cubic cells)");
  }
  if (args.Settings.Order == 2 && !args.Settings.Decimate)
  {
    throw UsageError("--order 2 curves the decimated mesh: it cannot go with --no-decimate");
  }
  for (const Option& option : Options())
  {
    // The scaled Jacobian bound applies to the quadratic mesh too; the others to 'curve' alone.
    const bool quadraticOption = args.Settings.Order == 2 && std::string(option.Long) == "--min-scaled-jacobian";
    if (args.Command == "mesh" && option.CurveOnly && given(option.Long) && !quadraticOption)
    {
      throw UsageError(std::string(option.Long) + " applies to 'curve' only");
    }
  }
  if (positional.size() < 2)
  {
    throw UsageError("missing INPUT image");
  }
  if (positional.size() > 2)
  {
    throw UsageError("unexpected argument '" + positional[2] + "'");
  }
  args.Input = positional[1];
  if (args.Outputs.empty())
  {
    throw UsageError("missing -o OUTPUT (" + labelmesher::io::KnownExtensions() + ")");
  }
  bool gmsh = false, stl = false;
  for (std::size_t i = 0; i < args.Outputs.size(); ++i)
  {
    const std::string& output = args.Outputs[i];
    const auto format = labelmesher::io::FormatOfPath(output);
    if (!format)
    {
      throw UsageError("output '" + output + "' has an unknown extension: expected one of " +
        labelmesher::io::KnownExtensions());
    }
    if (args.Command == "curve" && !labelmesher::io::HoldsCurvedCells(*format))
    {
      throw UsageError("output '" + output + "': curved (cubic) cells can be written as .vtu, .pvtu, .vtk or .msh only");
    }
    if (args.Settings.Order == 2 && !labelmesher::io::HoldsQuadraticCells(*format))
    {
      throw UsageError("output '" + output + "': quadratic cells can be written as .vtu, .pvtu, .vtk, .msh, .inp or "
                       ".mesh only");
    }
    if (std::find(args.Outputs.begin(), args.Outputs.begin() + static_cast<std::ptrdiff_t>(i), output) !=
      args.Outputs.begin() + static_cast<std::ptrdiff_t>(i))
    {
      throw UsageError("output '" + output + "' is given twice");
    }
    gmsh = gmsh || *format == labelmesher::io::MeshFormat::Gmsh;
    stl = stl || *format == labelmesher::io::MeshFormat::Stl;
  }
  if (args.GmshVersion22 && !gmsh)
  {
    throw UsageError("--msh-version applies to .msh outputs, and none is given");
  }
  if (args.StlPerInterface && !stl)
  {
    throw UsageError("--stl-per-interface applies to .stl outputs, and none is given");
  }
  if (!args.Report.empty() &&
    std::find(args.Outputs.begin(), args.Outputs.end(), args.Report) != args.Outputs.end())
  {
    throw UsageError("the report '" + args.Report + "' would overwrite an output");
  }
  return args;
}

} // namespace labelmesher_cli
