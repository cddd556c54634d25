// SPDX-License-Identifier: GPL-2.0-or-later
// The material table and its field-data form.
#include "MaterialTable.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{
namespace io
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
  labels->SetName("MaterialLabel");
  vtkNew<vtkStringArray> names;
  names->SetName("MaterialName");
  vtkNew<vtkDoubleArray> colors;
  colors->SetName("MaterialColor");
  colors->SetNumberOfComponents(3);
  for (const MaterialInfo& m : table.Entries())
  {
    labels->InsertNextValue(m.Label);
    names->InsertNextValue(m.Name);
    colors->InsertNextTuple(m.Color.data());
  }
  fd->RemoveArray("MaterialLabel");
  fd->RemoveArray("MaterialName");
  fd->RemoveArray("MaterialColor");
  fd->AddArray(labels);
  fd->AddArray(names);
  fd->AddArray(colors);
}

} // namespace io
} // namespace labelmesher
