// SPDX-License-Identifier: GPL-2.0-or-later
// The material table and its field-data form.
#include "MaterialTable.h"

#include "LabelMesherArrayNames.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace labelmesher
{

void MaterialTable::Set(const MaterialInfo& info)
{
  auto at = std::lower_bound(this->Items.begin(), this->Items.end(), info.Label,
    [](const MaterialInfo& m, std::int32_t label) { return m.Label < label; });
  if (at != this->Items.end() && at->Label == info.Label)
  {
    *at = info;
  }
  else
  {
    this->Items.insert(at, info);
  }
}

const MaterialInfo* MaterialTable::Find(std::int32_t label) const
{
  auto at = std::lower_bound(this->Items.begin(), this->Items.end(), label,
    [](const MaterialInfo& m, std::int32_t l) { return m.Label < l; });
  return at != this->Items.end() && at->Label == label ? &*at : nullptr;
}

std::string MaterialTable::NameOf(std::int32_t label) const
{
  const MaterialInfo* info = this->Find(label);
  return info && !info->Name.empty() ? info->Name : "label_" + std::to_string(label);
}

void StoreMaterialTable(vtkFieldData* fd, const MaterialTable& table)
{
  vtkNew<vtkIntArray> labels;
  labels->SetName(arrays::MaterialLabel);
  vtkNew<vtkStringArray> names;
  names->SetName(arrays::MaterialName);
  vtkNew<vtkDoubleArray> colors;
  colors->SetName(arrays::MaterialColor);
  colors->SetNumberOfComponents(3);
  for (const MaterialInfo& m : table.Entries())
  {
    labels->InsertNextValue(m.Label);
    names->InsertNextValue(m.Name);
    colors->InsertNextTuple(m.Color.data());
  }
  fd->RemoveArray(arrays::MaterialLabel);
  fd->RemoveArray(arrays::MaterialName);
  fd->RemoveArray(arrays::MaterialColor);
  fd->AddArray(labels);
  fd->AddArray(names);
  fd->AddArray(colors);
}

MaterialTable ReadMaterialTable(vtkFieldData* fd)
{
  MaterialTable table;
  auto* labels = fd ? vtkIntArray::SafeDownCast(fd->GetAbstractArray(arrays::MaterialLabel)) : nullptr;
  if (!labels || labels->GetNumberOfComponents() != 1)
  {
    return table;
  }
  const vtkIdType n = labels->GetNumberOfTuples();
  std::vector<std::string> names;
  if (auto* strings = vtkStringArray::SafeDownCast(fd->GetAbstractArray(arrays::MaterialName)))
  {
    for (vtkIdType i = 0; i < strings->GetNumberOfValues(); ++i)
      names.push_back(strings->GetValue(i));
  }
  else if (auto* bytes = vtkUnsignedCharArray::SafeDownCast(fd->GetAbstractArray(arrays::MaterialName)))
  {
    // The VTK files' form (VtkFileWriters.cxx): each name's UTF-8 bytes and a NUL.
    std::string name;
    for (vtkIdType i = 0; i < bytes->GetNumberOfValues(); ++i)
    {
      const unsigned char c = bytes->GetValue(i);
      c == 0 ? (names.push_back(name), name.clear()) : name.push_back(static_cast<char>(c));
    }
  }
  auto* colors = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray(arrays::MaterialColor));
  const bool haveNames = names.size() == static_cast<std::size_t>(n);
  const bool haveColors = colors && colors->GetNumberOfComponents() == 3 && colors->GetNumberOfTuples() == n;
  for (vtkIdType i = 0; i < n; ++i)
  {
    MaterialInfo info;
    info.Label = labels->GetValue(i);
    if (haveNames)
    {
      info.Name = names[static_cast<std::size_t>(i)];
    }
    if (haveColors)
    {
      colors->GetTypedTuple(i, info.Color.data());
    }
    table.Set(info);
  }
  return table;
}

} // namespace labelmesher
