// SPDX-License-Identifier: GPL-2.0-or-later
// The summary from VTK's parallel writer (run on an empty grid with the mesh's arrays, in a
// scratch folder), the pieces through SafeFile: VTK's file output does not report a failed
// final flush, and writing the pieces ourselves keeps every byte checked.
#include "PvtuWriter.h"

#include "OutputPieces.h"
#include "SafeFile.h"
#include "VtkFileWriters.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLPUnstructuredGridWriter.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace labelmesher
{
namespace io
{
namespace
{

namespace fs = std::filesystem;

/// A scratch folder, removed with everything in it when this goes.
class ScratchFolder
{
public:
  ScratchFolder()
  {
    std::string pattern = (fs::temp_directory_path() / "labelmesher-pvtu-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw WriteError("cannot make a scratch folder in " + fs::temp_directory_path().string());
    this->Path = pattern;
  }
  ~ScratchFolder()
  {
    std::error_code ignored;
    fs::remove_all(this->Path, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  fs::path Path;
};

/// More pieces than any run has processes: a "Process" array asking for more is not one.
constexpr int kMostPieces = 1 << 16;

/// VTK's summary for `pieces` pieces of `mesh` named after `path`, as text.
std::string SummaryText(vtkUnstructuredGrid* mesh, const std::string& path, int pieces)
{
  // The summary lists the arrays of its input and a piece for each piece VTK writes beside it
  // (none for an empty one): its input is the mesh's first cell, every piece that cell, all
  // thrown away with the scratch folder.
  const vtkSmartPointer<vtkUnstructuredGrid> sample = MeshPiece(mesh, std::vector<vtkIdType>{ 0 });
  const ScratchFolder scratch;
  const fs::path summary = scratch.Path / fs::path(path).filename();
  vtkNew<vtkXMLPUnstructuredGridWriter> writer;
  // No controller: under MPI VTK would give it the global one and wait in a collective step
  // for processes that write nothing (this process writes every piece).
  writer->SetController(nullptr);
  const FirstVtkError error(writer);
  writer->SetInputData(sample);
  writer->SetFileName(summary.string().c_str());
  writer->SetNumberOfPieces(pieces);
  writer->SetStartPiece(0);
  writer->SetEndPiece(pieces - 1);
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  std::ifstream in;
  if (writer->Write())
    in.open(summary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  if (!error.Message().empty() || !in || s.find("</VTKFile>") == std::string::npos)
  {
    throw WriteError("VTK's parallel writer failed" + (error.Message().empty() ? std::string() : ": " + error.Message()));
  }
  return s;
}

/// The Source="..." of every piece in `summary`, in order.
std::vector<std::string> PieceSources(const std::string& summary)
{
  std::vector<std::string> sources;
  const std::string tag = "Source=\"";
  for (std::size_t at = summary.find(tag); at != std::string::npos; at = summary.find(tag, at))
  {
    at += tag.size();
    const std::size_t end = summary.find('"', at);
    if (end == std::string::npos)
      break;
    sources.push_back(summary.substr(at, end - at));
  }
  return sources;
}

/// The pieces an earlier summary at `path` names (none when there is none or
/// it cannot be read: it only serves to tidy up).
std::vector<std::string> EarlierPieces(const std::string& path)
{
  std::error_code error;
  if (!fs::is_regular_file(path, error) ||
    fs::file_size(path, error) > (std::uintmax_t(1) << 24))
    return {};
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return PieceSources(text.str());
}

/// The earlier run's pieces that this run's summary no longer names: those
/// of piece numbers beyond this run's, named as VTK names them (`sources`'
/// first name with another number). Only such files are removed: an earlier
/// summary naming anything else (edited by hand, say) loses nothing.
void RemoveStalePieces(const fs::path& folder, const std::vector<std::string>& earlier,
  const std::vector<std::string>& sources)
{
  const std::string first = sources.front(), suffix = "0.vtu";
  if (first.size() < suffix.size() || first.compare(first.size() - suffix.size(), suffix.size(), suffix) != 0)
    return;
  const std::string stem = first.substr(0, first.size() - suffix.size());
  for (const std::string& name : earlier)
  {
    if (name.size() <= stem.size() + 4 || name.compare(0, stem.size(), stem) != 0 ||
      name.compare(name.size() - 4, 4, ".vtu") != 0)
      continue;
    const std::string number = name.substr(stem.size(), name.size() - stem.size() - 4);
    if (number.find_first_not_of("0123456789") != std::string::npos || (number.size() > 1 && number[0] == '0') ||
      number.size() > 6 || std::stoi(number) < static_cast<int>(sources.size()))
      continue;
    std::error_code ignored; // a piece left over is named by no summary: untidy, not wrong
    fs::remove(folder / name, ignored);
  }
}

/// Throws WriteError when `path` is a link to a file (WrittenPath leaves a
/// device or a pipe as named: those are written directly).
void RefuseLinkedSummary(const std::string& path)
{
  const std::string leadsTo = WrittenPath(path);
  if (leadsTo != path)
    throw WriteError("cannot write '" + path + "': it is a symbolic link, and a .pvtu's pieces are read "
                     "beside the name it is opened by: write to '" + leadsTo + "' instead");
}

/// `bytes` into a temporary beside `path`, not yet under its name (SafeFile).
std::unique_ptr<SafeFile> Written(const std::string& path, const std::string& bytes)
{
  auto file = std::make_unique<SafeFile>(path);
  file->Stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!file->Stream().flush())
    file->Commit(); // a write failed (a full disk): Commit throws its reason and renames nothing
  return file;
}

} // namespace

void CheckPvtuPath(const std::string& path)
{
  CheckOutputPath(path);
  RefuseLinkedSummary(path);
}

std::vector<std::string> WritePvtu(vtkUnstructuredGrid* mesh, const std::string& path)
{
  if (mesh->GetNumberOfCells() == 0)
    throw WriteError("cannot write '" + path + "': the mesh has no cells");
  std::vector<std::string> written, renamed;
  try
  {
    const std::vector<int> pieceOfCell = PieceOfCells(mesh, kMostPieces);
    const int pieces = 1 + *std::max_element(pieceOfCell.begin(), pieceOfCell.end());
    RefuseLinkedSummary(path); // SafeFile checks the rest
    const std::string summary = SummaryText(mesh, path, pieces);
    const std::vector<std::string> sources = PieceSources(summary);
    if (static_cast<int>(sources.size()) != pieces)
      throw WriteError("VTK's summary lists " + std::to_string(sources.size()) + " pieces, not " +
        std::to_string(pieces));
    // Every file is written to its temporary first and only then are they all renamed, the
    // summary last: a failure while writing leaves the files of an earlier run as they were.
    const fs::path folder = fs::path(path).parent_path();
    const std::vector<std::string> earlier = EarlierPieces(path);
    std::vector<std::unique_ptr<SafeFile>> files;
    const std::vector<std::vector<vtkIdType>> cellsOf = CellsOfPieces(pieceOfCell, pieces);
    for (int p = 0; p < pieces; ++p)
    {
      std::ostringstream bytes;
      WriteVtu(MeshPiece(mesh, cellsOf[static_cast<std::size_t>(p)]), bytes);
      files.push_back(Written((folder / sources[static_cast<std::size_t>(p)]).string(), bytes.str()));
    }
    files.push_back(Written(path, summary));
    for (const std::unique_ptr<SafeFile>& file : files)
    {
      file->Commit();
      written.push_back(file->Target());
      if (!file->WritesDevice())
        renamed.push_back(file->DestinationPath()); // a piece's name may be a link: what it leads to
    }
    try
    {
      RemoveStalePieces(folder, earlier, sources);
    }
    catch (...)
    {
      // Tidying only: the run's files are whole and in place, and must stay.
    }
  }
  catch (const std::exception& e)
  {
    // Only a rename that failed after all were written gets here with files renamed: take
    // those back too, so that no summary of this run names a piece of another.
    for (const std::string& file : renamed)
      std::remove(file.c_str());
    const std::string reason = e.what();
    // SafeFile's errors name the file (a piece or the summary); the others are the summary's.
    throw WriteError(reason.rfind("cannot write '", 0) == 0 ? reason : "cannot write '" + path + "': " + reason);
  }
  std::rotate(written.begin(), written.end() - 1, written.end()); // the summary first
  return written;
}

} // namespace io
} // namespace labelmesher
