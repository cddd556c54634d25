// SPDX-License-Identifier: GPL-2.0-or-later
//
// labelmesher_property_scan: the property tests' assertions (MesherGuarantees.h)
// over as many seeded random images as one asks for, outside ctest. The CI
// suites run 3,400 images; the bugs they missed showed up at rates of 1 in
// 3,000 to 1 in 10,000, so run this with tens of thousands before trusting a
// change to the per-leaf tests. Prints every failing seed; exit status 1 if any.
//
//   labelmesher_property_scan smooth|boxes 2|3 FIRST_SEED COUNT [SIZE]
//
// smooth: GenerateRandomLabelImageWithDescription(seed, dimension) (the images
// of TestMesherProperties' MesherProperties suites); boxes:
// GenerateRandomBoxImage(seed, dimension, SIZE) (default 24 in 2D, 14 in 3D).
// Distance bounds: DrawDistanceBounds(seed), as in the tests.

#include "MesherGuarantees.h"
#include "RandomLabelImages.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

using namespace labelmesher;

int main(int argc, char** argv)
{
  if (argc < 5)
  {
    std::fprintf(stderr, "usage: %s smooth|boxes 2|3 FIRST_SEED COUNT [SIZE]\n", argv[0]);
    return 2;
  }
  const std::string family = argv[1];
  const int dimension = std::atoi(argv[2]);
  const std::uint64_t first = std::strtoull(argv[3], nullptr, 10);
  const std::uint64_t count = std::strtoull(argv[4], nullptr, 10);
  const int size = argc > 5 ? std::atoi(argv[5]) : (dimension == 3 ? 14 : 24);
  if ((family != "smooth" && family != "boxes") || (dimension != 2 && dimension != 3) || size < 2)
  {
    std::fprintf(stderr, "bad arguments: family smooth or boxes, dimension 2 or 3, size >= 2\n");
    return 2;
  }
  std::uint64_t failures = 0;
  for (std::uint64_t seed = first; seed < first + count; ++seed)
  {
    const testing::RandomLabelImage random = family == "smooth"
      ? testing::GenerateRandomLabelImageWithDescription(seed, dimension)
      : testing::GenerateRandomBoxImage(seed, dimension, size);
    const MesherParameters parameters = testing::DrawDistanceBounds(seed);
    const auto problems = testing::ViolatedMesherGuarantees(random.Image, parameters);
    if (problems.empty())
      continue;
    ++failures;
    std::printf("seed %llu FAILS (h(I,M) <= %g, h(M,I) <= %g)\n", static_cast<unsigned long long>(seed),
      parameters.ImageToMeshDistance, parameters.MeshToImageDistance);
    for (const auto& problem : problems)
      std::printf("  %s\n", problem.c_str());
    std::printf("%s", random.Describe().c_str());
    std::fflush(stdout);
  }
  std::printf("%s %dD seeds %llu..%llu: %llu of %llu images violate a guarantee\n", family.c_str(), dimension,
    static_cast<unsigned long long>(first), static_cast<unsigned long long>(first + count - 1),
    static_cast<unsigned long long>(failures), static_cast<unsigned long long>(count));
  return failures == 0 ? 0 : 1;
}
