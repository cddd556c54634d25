// SPDX-License-Identifier: GPL-2.0-or-later
// vtkLabelMeshWriter: the materials' names reach the finite-element files through the filters'
// field data; the VTK files read back with the same cells; every failed write returns 0, says one
// line and leaves nothing under the target's name. (meshio and gmsh read every format back in
// Testing/Python/test_labelmesher_io.py.)
#include "vtkLabelMeshWriter.h"

#include "FilterTestSupport.h"
#include "MaterialTable.h"
#include "ScratchFolder.h"
#include "vtkBezierCurver.h"
#include "vtkLabelMesher.h"
#include "vtkLabelOctreeMesher.h"
#include "vtkMeshDecimator.h"

#include "LabelMesherArrayNames.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLPUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>

namespace
{
namespace fs = std::filesystem;
using labelmesher::testing::MessageRecorder;

std::string Slurp(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

std::set<std::string> Listing(const fs::path& folder)
{
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder))
    names.insert(entry.path().filename().string());
  return names;
}

/// A ball of label 1 in a 14^3 image named "outer shell", meshed by vtkLabelMesher once.
class WriterTest : public labelmesher::testing::ScratchFolder
{
protected:
  static void SetUpTestSuite()
  {
    vtkSmartPointer<vtkImageData> image = labelmesher::testing::MakeVtkImage(labelmesher::testing::MakeBallLabels(14, 5.0));
    labelmesher::testing::NameMaterial(image, 1, "outer shell", { 0.8, 0.3, 0.1 });
    Mesher = vtkLabelMesher::New();
    Mesher->SetInputData(image);
    Mesher->Update();
  }
  static void TearDownTestSuite() { Mesher->Delete(); }

  /// Write()'s result, with the error events in `errors`.
  static int Write(const std::string& path, std::vector<std::string>& errors, bool interfaces = true)
  {
    vtkNew<vtkLabelMeshWriter> writer;
    MessageRecorder recorder(writer, vtkCommand::ErrorEvent);
    writer->SetInputConnection(Mesher->GetOutputPort(0));
    if (interfaces)
      writer->SetInterfacesConnection(Mesher->GetOutputPort(1));
    writer->SetFileName(path.c_str());
    const int ok = writer->Write();
    errors = recorder.Messages;
    if (!errors.empty())
    {
      const std::string text = writer->GetErrorText();
      EXPECT_EQ(text.find('\n'), std::string::npos) << text;
      EXPECT_NE(errors[0].find(text), std::string::npos) << errors[0];
    }
    return ok;
  }

  static vtkLabelMesher* Mesher;
};
vtkLabelMesher* WriterTest::Mesher = nullptr;

TEST(MaterialTable, FieldDataRoundTrip)
{
  labelmesher::MaterialTable table;
  labelmesher::MaterialInfo a;
  a.Label = 7;
  a.Name = "bone";
  a.Color = { 1, 0.5, 0 };
  labelmesher::MaterialInfo b;
  b.Label = 2; // no name, no colour
  table.Set(a);
  table.Set(b);
  vtkNew<vtkFieldData> fd;
  labelmesher::StoreMaterialTable(fd, table);
  const labelmesher::MaterialTable back = labelmesher::ReadMaterialTable(fd);
  ASSERT_EQ(back.Entries().size(), 2u);
  EXPECT_EQ(back.NameOf(7), "bone");
  EXPECT_EQ(back.NameOf(2), "label_2");
  EXPECT_FALSE(back.Find(2)->HasColor());
  EXPECT_DOUBLE_EQ(back.Find(7)->Color[1], 0.5);
  EXPECT_TRUE(labelmesher::ReadMaterialTable(nullptr).Empty());
}

TEST_F(WriterTest, NamesReachEveryFiniteElementFormat)
{
  std::vector<std::string> errors;
  for (const char* name : { "m.msh", "m.inp", "m.mesh", "m.vtu" })
  {
    ASSERT_EQ(Write(this->Path(name), errors), 1) << name;
    ASSERT_TRUE(errors.empty()) << errors[0];
  }
  EXPECT_NE(Slurp(this->Path("m.msh")).find("\"outer shell\""), std::string::npos);
  EXPECT_NE(Slurp(this->Path("m.inp")).find("ELSET=outer_shell"), std::string::npos);
  EXPECT_NE(Slurp(this->Path("m.mesh")).find("= outer shell"), std::string::npos);

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(this->Path("m.vtu").c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), Mesher->GetOutput()->GetNumberOfCells());
  EXPECT_GT(reader->GetOutput()->GetNumberOfCells(), 0);
  const labelmesher::MaterialTable table = labelmesher::ReadMaterialTable(reader->GetOutput()->GetFieldData());
  EXPECT_EQ(table.NameOf(1), "outer shell");
  EXPECT_DOUBLE_EQ(table.Find(1)->Color[0], 0.8);
}

TEST_F(WriterTest, EveryFilterPassesTheMaterialTable)
{
  // The image's table through the mesher and the decimator (3D), and through the curver (2D);
  // the decimator takes the mesh's table over the image's.
  vtkSmartPointer<vtkImageData> image = labelmesher::testing::MakeVtkImage(labelmesher::testing::MakeBallLabels(12, 4.0));
  labelmesher::MaterialTable table;
  labelmesher::MaterialInfo ball;
  ball.Label = 1;
  ball.Name = "ball";
  table.Set(ball);
  labelmesher::StoreMaterialTable(image->GetFieldData(), table);
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  mesher->IncludeBackgroundOn();
  vtkSmartPointer<vtkImageData> other = vtkSmartPointer<vtkImageData>::New();
  other->DeepCopy(image);
  ball.Name = "not this one";
  labelmesher::MaterialTable otherTable;
  otherTable.Set(ball);
  labelmesher::StoreMaterialTable(other->GetFieldData(), otherTable);
  vtkNew<vtkMeshDecimator> decimator;
  decimator->SetInputConnection(0, mesher->GetOutputPort(0));
  decimator->SetInputDataObject(1, other);
  decimator->Update();
  for (vtkDataObject* out : { mesher->GetOutputDataObject(0), mesher->GetOutputDataObject(1),
         decimator->GetOutputDataObject(0), decimator->GetOutputDataObject(1) })
  {
    EXPECT_EQ(labelmesher::ReadMaterialTable(out->GetFieldData()).NameOf(1), "ball");
  }
  vtkSmartPointer<vtkImageData> slice = labelmesher::testing::MakeVtkImage(labelmesher::testing::MakeDiscSliceXZ(12, 4.0));
  labelmesher::StoreMaterialTable(slice->GetFieldData(), table);
  vtkNew<vtkLabelOctreeMesher> mesher2D;
  mesher2D->SetInputData(slice);
  vtkNew<vtkBezierCurver> curver;
  curver->SetInputConnection(mesher2D->GetOutputPort(0));
  curver->Update();
  EXPECT_EQ(labelmesher::ReadMaterialTable(curver->GetOutput()->GetFieldData()).NameOf(1), "ball");
  // Nothing to pass: no table appears.
  vtkNew<vtkLabelOctreeMesher> plain;
  plain->SetInputData(labelmesher::testing::MakeVtkImage(labelmesher::testing::MakeBallLabels(8, 2.5)));
  plain->Update();
  EXPECT_EQ(plain->GetOutput()->GetFieldData()->GetAbstractArray("MaterialLabel"), nullptr);
}

TEST_F(WriterTest, AnEmptyMeshFromAFailedFilterWritesNoFile)
{
  vtkNew<vtkLabelMesher> failed;
  failed->SetInputData(labelmesher::testing::MakeVtkImage(labelmesher::testing::MakeBallLabels(8, 2.5)));
  failed->SetMinimumAngle(40.0); // above the 3D bound: an error and an empty output
  vtkNew<vtkLabelMeshWriter> writer;
  writer->SetInputConnection(failed->GetOutputPort(0));
  MessageRecorder errors(writer, vtkCommand::ErrorEvent);
  for (const char* name : { "m.vtu", "m.msh" })
  {
    writer->SetFileName(this->Path(name).c_str());
    EXPECT_EQ(writer->Write(), 0) << name;
    EXPECT_NE(std::string(writer->GetErrorText()).find("no cells"), std::string::npos) << writer->GetErrorText();
    EXPECT_FALSE(std::filesystem::exists(this->Path(name))) << name;
  }
  EXPECT_EQ(errors.Messages.size(), 2u);
}

/// Surface formats hold straight faces: a quadratic mesh (port 2 of a 2D Order 2 run) with an
/// interface surface is refused in one line rather than written with its mid-nodes as corners.
TEST_F(WriterTest, SurfaceFormatsRefuseQuadraticCells)
{
  vtkNew<vtkLabelMesher> quadratic;
  quadratic->SetInputData(labelmesher::testing::MakeVtkImage2D(labelmesher::testing::MakeDiscSliceXZ(24, 8.0), 24, 24));
  quadratic->SetOrder(2);
  vtkNew<vtkLabelMeshWriter> writer;
  writer->SetInputConnection(quadratic->GetOutputPort(2));
  writer->SetInterfacesConnection(quadratic->GetOutputPort(1));
  MessageRecorder errors(writer, vtkCommand::ErrorEvent);
  for (const char* name : { "q.obj", "q.stl" })
  {
    writer->SetFileName(this->Path(name).c_str());
    EXPECT_EQ(writer->Write(), 0) << name;
    EXPECT_NE(std::string(writer->GetErrorText()).find("straight faces"), std::string::npos) << writer->GetErrorText();
    EXPECT_FALSE(std::filesystem::exists(this->Path(name))) << name;
  }
  writer->SetFileName(this->Path("q.msh").c_str());
  EXPECT_EQ(writer->Write(), 1) << writer->GetErrorText();
}

TEST_F(WriterTest, GmshVersionChoice)
{
  vtkNew<vtkLabelMeshWriter> writer;
  writer->SetInputConnection(Mesher->GetOutputPort(0));
  writer->SetFileName(this->Path("m.msh").c_str());
  writer->GmshVersion22On();
  ASSERT_EQ(writer->Write(), 1) << writer->GetErrorText();
  EXPECT_EQ(Slurp(this->Path("m.msh")).rfind("$MeshFormat\n2.2 0 8\n", 0), 0u);
  writer->GmshVersion22Off();
  ASSERT_EQ(writer->Write(), 1) << writer->GetErrorText();
  EXPECT_EQ(Slurp(this->Path("m.msh")).rfind("$MeshFormat\n4.1 0 8\n", 0), 0u);
}

TEST_F(WriterTest, AFileReachedThroughALinkIsWrittenThroughIt)
{
  // The link stays a link (relative, through a second link, or dangling) and its target gets
  // the mesh, its temporary beside the target, none left anywhere.
  fs::create_directories(this->Folder / "out");
  std::ofstream(this->Folder / "out/old.msh") << "an earlier mesh";
  fs::create_symlink("out/old.msh", this->Folder / "m.msh");
  fs::create_symlink("m.msh", this->Folder / "twice.msh");
  fs::create_symlink("out/new.msh", this->Folder / "dangling.msh");
  fs::create_symlink("loop.msh", this->Folder / "loop.msh");
  const std::set<std::string> links = Listing(this->Folder);
  for (const char* name : { "twice.msh", "m.msh", "dangling.msh" }) // through two links first
  {
    std::vector<std::string> errors;
    ASSERT_EQ(Write(this->Path(name), errors), 1) << name << ": " << (errors.empty() ? "" : errors[0]);
    for (const char* link : { "m.msh", "twice.msh", "dangling.msh", "loop.msh" })
      EXPECT_TRUE(fs::is_symlink(this->Path(link))) << link << " after writing " << name;
    EXPECT_EQ(Listing(this->Folder), links) << name;
  }
  EXPECT_EQ(Slurp((this->Folder / "out/old.msh").string()).rfind("$MeshFormat", 0), 0u);
  EXPECT_EQ(Slurp((this->Folder / "out/new.msh").string()).rfind("$MeshFormat", 0), 0u);
  EXPECT_EQ(Listing(this->Folder / "out"), (std::set<std::string>{ "new.msh", "old.msh" }));
  std::vector<std::string> errors;
  EXPECT_EQ(Write(this->Path("loop.msh"), errors), 0);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("symbolic links"), std::string::npos) << errors[0];
}

TEST_F(WriterTest, FailedWritesReturnZeroSayOneLineAndLeaveNothing)
{
  fs::create_directories(this->Folder / "taken.msh");
  fs::create_symlink("/dev/full", this->Folder / "full.inp");
  const std::pair<std::string, std::string> cases[] = {
    { this->Path("missing/m.msh"), "missing" },
    { this->Path("taken.msh"), "folder" },
    { this->Path("full.inp"), "No space left on device" },
    { this->Path("m.xyz"), "unknown extension" },
  };
  for (const auto& [path, fragment] : cases)
  {
    const std::set<std::string> before = Listing(this->Folder);
    std::vector<std::string> errors;
    EXPECT_EQ(Write(path, errors), 0) << path;
    ASSERT_EQ(errors.size(), 1u) << path;
    EXPECT_NE(errors[0].find(fragment), std::string::npos) << errors[0];
    EXPECT_EQ(Listing(this->Folder), before) << path;
  }
  // A surface format without the interfaces on port 1.
  std::vector<std::string> errors;
  EXPECT_EQ(Write(this->Path("s.stl"), errors, false), 0);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("interface"), std::string::npos) << errors[0];
  EXPECT_FALSE(fs::exists(this->Path("s.stl")));
}

/// The mesher's output with its cells given to `processes` processes in runs, as a
/// distributed run's "Process" array gives them.
vtkSmartPointer<vtkUnstructuredGrid> WithProcesses(vtkUnstructuredGrid* mesh, int processes)
{
  auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
  copy->ShallowCopy(mesh);
  vtkNew<vtkIntArray> process;
  process->SetName(labelmesher::arrays::Process);
  const vtkIdType n = mesh->GetNumberOfCells();
  for (vtkIdType c = 0; c < n; ++c)
    process->InsertNextValue(static_cast<int>(c * processes / n));
  copy->GetCellData()->AddArray(process);
  return copy;
}

int WriteGrid(vtkUnstructuredGrid* mesh, const std::string& path, std::vector<std::string>& errors)
{
  vtkNew<vtkLabelMeshWriter> writer;
  MessageRecorder recorder(writer, vtkCommand::ErrorEvent);
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  const int ok = writer->Write();
  errors = recorder.Messages;
  return ok;
}

TEST_F(WriterTest, PvtuHasOnePiecePerProcess)
{
  vtkUnstructuredGrid* mesh = Mesher->GetOutput();
  ASSERT_GT(mesh->GetNumberOfCells(), 30);
  std::vector<std::string> errors;
  ASSERT_EQ(WriteGrid(WithProcesses(mesh, 3), this->Path("m.pvtu"), errors), 1) << (errors.empty() ? "" : errors[0]);
  EXPECT_EQ(Listing(this->Folder), (std::set<std::string>{ "m.pvtu", "m_0.vtu", "m_1.vtu", "m_2.vtu" }));
  vtkIdType cells = 0;
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkXMLUnstructuredGridReader> piece;
    piece->SetFileName(this->Path("m_" + std::to_string(k) + ".vtu").c_str());
    piece->Update();
    vtkDataArray* process = piece->GetOutput()->GetCellData()->GetArray(labelmesher::arrays::Process);
    ASSERT_NE(process, nullptr);
    ASSERT_GT(process->GetNumberOfTuples(), 0);
    for (vtkIdType c = 0; c < process->GetNumberOfTuples(); ++c)
      ASSERT_EQ(process->GetComponent(c, 0), k) << "piece " << k;
    EXPECT_EQ(labelmesher::ReadMaterialTable(piece->GetOutput()->GetFieldData()).NameOf(1), "outer shell");
    cells += piece->GetOutput()->GetNumberOfCells();
  }
  EXPECT_EQ(cells, mesh->GetNumberOfCells());
  vtkNew<vtkXMLPUnstructuredGridReader> whole;
  whole->SetFileName(this->Path("m.pvtu").c_str());
  whole->Update();
  EXPECT_EQ(whole->GetOutput()->GetNumberOfCells(), mesh->GetNumberOfCells());
  EXPECT_NE(whole->GetOutput()->GetCellData()->GetArray(labelmesher::arrays::Material), nullptr);

  // One process (no "Process" array): one piece.
  ASSERT_EQ(WriteGrid(mesh, this->Path("one.pvtu"), errors), 1);
  EXPECT_TRUE(fs::exists(this->Path("one_0.vtu")));
  EXPECT_FALSE(fs::exists(this->Path("one_1.vtu")));
}

TEST_F(WriterTest, ARewriteOnFewerProcessesLeavesNoStalePiece)
{
  vtkUnstructuredGrid* mesh = Mesher->GetOutput();
  std::vector<std::string> errors;
  ASSERT_EQ(WriteGrid(WithProcesses(mesh, 4), this->Path("m.pvtu"), errors), 1);
  // The earlier summary also names files that are not pieces VTK would name: they stay.
  std::string summary;
  {
    std::ifstream in(this->Path("m.pvtu"));
    summary.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string extra =
    "<Piece Source=\"m_x.vtu\"/><Piece Source=\"m_02.vtu\"/><Piece Source=\"other_5.vtu\"/>"
    "<Piece Source=\"m_2.vtu.bak\"/><Piece Source=\"sub/m_5.vtu\"/>";
  const std::size_t at = summary.rfind("</PUnstructuredGrid>");
  ASSERT_NE(at, std::string::npos);
  summary.insert(at, extra);
  std::ofstream(this->Path("m.pvtu")) << summary;
  fs::create_directories(this->Folder / "sub");
  for (const char* kept : { "m_x.vtu", "m_02.vtu", "other_5.vtu", "m_2.vtu.bak", "sub/m_5.vtu" })
    std::ofstream(this->Folder / kept) << "kept";
  ASSERT_EQ(WriteGrid(WithProcesses(mesh, 2), this->Path("m.pvtu"), errors), 1) << (errors.empty() ? "" : errors[0]);
  EXPECT_EQ(Listing(this->Folder), (std::set<std::string>{ "m.pvtu", "m_0.vtu", "m_1.vtu", "m_x.vtu", "m_02.vtu",
                                     "other_5.vtu", "m_2.vtu.bak", "sub" }));
  EXPECT_TRUE(fs::exists(this->Folder / "sub/m_5.vtu"));
  // A summary reached through a link is refused (VTK would look for its pieces beside the
  // link, or beside its target, never both), one line naming where it leads; nothing changes.
  fs::create_directories(this->Folder / "target");
  ASSERT_EQ(WriteGrid(WithProcesses(mesh, 3), (this->Folder / "target/l.pvtu").string(), errors), 1);
  fs::create_symlink("target/l.pvtu", this->Folder / "l.pvtu");
  const std::set<std::string> here = Listing(this->Folder), there = Listing(this->Folder / "target");
  const std::string targetSummary = Slurp((this->Folder / "target/l.pvtu").string());
  errors.clear();
  EXPECT_EQ(WriteGrid(WithProcesses(mesh, 2), this->Path("l.pvtu"), errors), 0);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("symbolic link"), std::string::npos) << errors[0];
  EXPECT_NE(errors[0].find("target/l.pvtu"), std::string::npos) << errors[0];
  EXPECT_TRUE(fs::is_symlink(this->Path("l.pvtu")));
  EXPECT_EQ(Listing(this->Folder), here);
  EXPECT_EQ(Listing(this->Folder / "target"), there);
  EXPECT_EQ(Slurp((this->Folder / "target/l.pvtu").string()), targetSummary);
  vtkNew<vtkXMLPUnstructuredGridReader> whole;
  whole->SetFileName(this->Path("m.pvtu").c_str());
  whole->Update();
  EXPECT_EQ(whole->GetOutput()->GetNumberOfCells(), mesh->GetNumberOfCells());
}

TEST_F(WriterTest, AFailedPvtuLeavesNoPiece)
{
  const vtkSmartPointer<vtkUnstructuredGrid> mesh = WithProcesses(Mesher->GetOutput(), 3);
  fs::create_directories(this->Folder / "taken_1.vtu"); // the second piece cannot be written
  fs::create_symlink("/dev/full", this->Folder / "full.pvtu"); // the summary, written last, cannot
  const std::pair<std::string, std::string> cases[] = {
    { this->Path("missing/m.pvtu"), "missing" },
    { this->Path("taken.pvtu"), "taken_1.vtu" },
    { this->Path("full.pvtu"), "No space left on device" },
  };
  // A Process array that holds no ranks.
  const vtkSmartPointer<vtkUnstructuredGrid> fractional = WithProcesses(Mesher->GetOutput(), 3);
  vtkDataArray* process = fractional->GetCellData()->GetArray(labelmesher::arrays::Process);
  vtkNew<vtkDoubleArray> half;
  half->DeepCopy(process);
  half->SetName(labelmesher::arrays::Process);
  half->SetValue(0, 0.5);
  fractional->GetCellData()->AddArray(half);
  std::vector<std::string> badErrors;
  EXPECT_EQ(WriteGrid(fractional, this->Path("bad.pvtu"), badErrors), 0);
  ASSERT_EQ(badErrors.size(), 1u);
  EXPECT_NE(badErrors[0].find("cell 0 has Process 0.5, not a process rank below"), std::string::npos) << badErrors[0];
  EXPECT_FALSE(fs::exists(this->Path("bad.pvtu")));
  for (const auto& [path, fragment] : cases)
  {
    const std::set<std::string> before = Listing(this->Folder);
    std::vector<std::string> errors;
    EXPECT_EQ(WriteGrid(mesh, path, errors), 0) << path;
    ASSERT_EQ(errors.size(), 1u) << path;
    EXPECT_NE(errors[0].find(fragment), std::string::npos) << errors[0];
    EXPECT_EQ(Listing(this->Folder), before) << path;
  }
}

} // namespace
