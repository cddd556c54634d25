// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_TwoColumnImage_h
#define labelmesher_testing_TwoColumnImage_h

/**
 * @file TwoColumnImage.h
 * A 4 x 2 image of two labels split at x = 1.5 and a hand-made mesh of its box whose interface
 * runs where the caller says: the fixture of the distance checks' unit tests (FidelityCheck,
 * ImageBoundaryAnchors), where the distances of every merge are known.
 */

#include "Decimation/EditableMesh.h"
#include "HandMadeMeshes.h"
#include "Support/LabelImage.h"

namespace labelmesher
{
namespace testing
{

/// 4 x 2 pixels: label 1 for x < 2, label 2 for x >= 2; the image interface is x = 1.5.
inline LabelImage TwoColumns()
{
  LabelImage image(4, 2, 1);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i)
      image(i, j, 0) = i < 2 ? 1 : 2;
  return image;
}

/// The image's box [-0.5, 3.5] x [-0.5, 1.5] in six triangles around 6 = (interfaceX, 0.5):
///   3 ---- 4 ---- 5
///   |  \   |   /  |
///   |    - 6 -    |
///   |  /   |   \  |
///   0 ---- 1 ---- 2     (1 and 4 at x = interfaceX; label 1 left, 2 right)
inline EditableMesh Mesh(double interfaceX)
{
  return EditableMesh(Triangles2D({ { -0.5, -0.5 }, { interfaceX, -0.5 }, { 3.5, -0.5 }, { -0.5, 1.5 }, { interfaceX, 1.5 },
                                    { 3.5, 1.5 }, { interfaceX, 0.5 } },
    { { 0, 1, 6 }, { 0, 6, 3 }, { 3, 6, 4 }, { 1, 2, 6 }, { 2, 5, 6 }, { 6, 5, 4 } }, { 1, 1, 1, 2, 2, 2 }));
}

} // namespace testing
} // namespace labelmesher

#endif
