// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MaterialTable_h
#define labelmesher_MaterialTable_h

/**
 * @file MaterialTable.h
 * The names and colours of a label image's materials, as a 3D Slicer
 * segmentation (.seg.nrrd), an ITK-SNAP / Slicer colour table (--labels) or
 * nothing at all gives them. Every writer names a material through NameOf:
 * its own name, or `label_N` for a label the table does not know.
 *
 * On a mesh the table is field data (StoreMaterialTable): int
 * `MaterialLabel`, string `MaterialName` and double x 3 `MaterialColor`
 * (RGB in [0, 1]; -1 when the source gave none), one tuple per entry.
 */

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class vtkFieldData;

namespace labelmesher
{

struct MaterialInfo
{
  std::int32_t Label = 0;
  std::string Name;                           ///< as the source spelled it (UTF-8); may be empty
  std::array<double, 3> Color{ -1, -1, -1 };  ///< RGB in [0, 1]; -1: none given
  bool HasColor() const { return this->Color[0] >= 0.0; }
};

class MaterialTable
{
public:
  /// Adds or replaces the entry of `info.Label`.
  void Set(const MaterialInfo& info);
  /// The entry of `label`, or null.
  const MaterialInfo* Find(std::int32_t label) const;
  /// The entry's name when it has one, else `label_N` (`background` is never
  /// invented: label 0 is `label_0` unless the table names it).
  std::string NameOf(std::int32_t label) const;
  const std::vector<MaterialInfo>& Entries() const { return this->Items; }
  bool Empty() const { return this->Items.empty(); }

private:
  std::vector<MaterialInfo> Items; ///< sorted by label
};

/// Writes `table` as MaterialLabel / MaterialName / MaterialColor (replacing them).
void StoreMaterialTable(vtkFieldData* fd, const MaterialTable& table);
/// The table StoreMaterialTable wrote into `fd`, or a VTK file of ours holds (names as NUL-ended
/// bytes); empty when `fd` has none; names or colours whose arrays are missing or of another
/// length are left out.
MaterialTable ReadMaterialTable(vtkFieldData* fd);

} // namespace labelmesher

#endif
