// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file BoundaryShapes.cxx
 * ExtractBoundaries: the image boundary by a scan of the voxel faces (pixel
 * edges) along each axis, including those on the image's outer faces (outside
 * counts as label 0); the mesh boundary from the boundary facet records of
 * MeshIncidence.h, one record per facet and material.
 */

#include "Checks/BoundaryShapes.h"

#include "Checks/MeshIncidence.h"

namespace labelmesher
{
namespace checks_detail
{

namespace
{

/// Voxel faces (pixel edges) between different labels, as flat boxes.
void AddImageBoundary(const LabelImage& image, Boundaries& b)
{
  const int nx = image.Dimensions[0], ny = image.Dimensions[1], nz = image.Dimensions[2];
  const int dim = image.Dimension();
  if (nx <= 0 || ny <= 0 || nz <= 0 || image.NumberOfVoxels() == 0)
    return;
  for (int axis = 0; axis < dim; ++axis)
  {
    const int e[3] = { axis == 0, axis == 1, axis == 2 };
    for (int k = 0; k < nz + e[2]; ++k)
      for (int j = 0; j < ny + e[1]; ++j)
        for (int i = 0; i < nx + e[0]; ++i)
        {
          const std::int32_t A = image.At(i - e[0], j - e[1], k - e[2]);
          const std::int32_t B = image.At(i, j, k);
          if (A == B)
            continue;
          // The face between voxels (i, j, k) - e and (i, j, k), whose centres are integers.
          Shape s;
          s.K = ShapeKind::Box;
          const double c[3] = { double(i), double(j), double(k) };
          for (int a = 0; a < 3; ++a)
          {
            if (a == axis)
              s.P[0][a] = s.P[1][a] = c[a] - 0.5;
            else if (a >= dim)
              s.P[0][a] = s.P[1][a] = 0.0;
            else
            {
              s.P[0][a] = c[a] - 0.5;
              s.P[1][a] = c[a] + 0.5;
            }
          }
          s.P[2] = s.P[1];
          s.Axis = static_cast<std::int8_t>(axis);
          s.Plane = c[axis] - 0.5;
          b.Overall.Image.push_back(s);
          if (A != 0)
            b.PerMaterial[A].Image.push_back(s);
          if (B != 0)
            b.PerMaterial[B].Image.push_back(s);
        }
  }
}

/// Mesh boundary facets: triangles (segments in 2D).
void AddMeshBoundary(const SimplexMesh& mesh, Boundaries& b)
{
  if (mesh.NumberOfCells() == 0)
    return;
  const auto incidence = BuildVertexIncidence(mesh);
  const auto records = ExtractMeshBoundary(mesh, incidence);
  const bool is3D = mesh.Dimension == 3;
  for (const auto& r : records)
  {
    Shape s;
    s.K = is3D ? ShapeKind::Triangle : ShapeKind::Segment;
    s.P[0] = mesh.Points[r.Vertices[0]];
    s.P[1] = mesh.Points[r.Vertices[1]];
    s.P[2] = is3D ? mesh.Points[r.Vertices[2]] : s.P[1];
    SetPlane(s, mesh.Dimension);
    if (r.FirstOfFacet)
      b.Overall.Mesh.push_back(s);
    b.PerMaterial[r.Material].Mesh.push_back(s);
  }
}

/// Given facets: each bounds the non-zero materials of its two sides when they differ.
void AddFacets(const std::vector<BoundaryFacet>& facets, Boundaries& b)
{
  for (const BoundaryFacet& f : facets)
  {
    if (f.First == f.Second)
      continue;
    Shape s;
    s.K = ShapeKind::Triangle;
    for (int k = 0; k < 3; ++k)
      s.P[k] = f.Points[k];
    SetPlane(s, 3);
    b.Overall.Mesh.push_back(s);
    for (std::int32_t m : { f.First, f.Second })
      if (m != 0)
        b.PerMaterial[m].Mesh.push_back(s);
  }
}

} // namespace

Boundaries ExtractBoundaries(const LabelImage& image, const SimplexMesh& mesh)
{
  Boundaries b;
  AddImageBoundary(image, b);
  AddMeshBoundary(mesh, b);
  return b;
}

Boundaries ExtractBoundaries(const LabelImage& image, const std::vector<BoundaryFacet>& facets)
{
  Boundaries b;
  AddImageBoundary(image, b);
  AddFacets(facets, b);
  return b;
}

} // namespace checks_detail
} // namespace labelmesher
