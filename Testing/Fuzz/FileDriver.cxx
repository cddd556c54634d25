// SPDX-License-Identifier: GPL-2.0-or-later
// main() for the AFL++ targets built with afl-g++ (afl-as instrumentation, which has neither
// persistent mode nor AFL++'s libFuzzer driver): each file named on the command line (afl-fuzz
// passes one, `@@`) is read and given to the target's LLVMFuzzerTestOneInput once, so the same
// harness runs under libFuzzer, under afl-fuzz and by hand on a pinned input.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv);
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: %s INPUT...\n", argv[0]);
    return 2;
  }
  LLVMFuzzerInitialize(&argc, &argv);
  for (int a = 1; a < argc; ++a)
  {
    std::ifstream in(argv[a], std::ios::binary);
    if (!in)
    {
      std::fprintf(stderr, "%s: cannot read %s\n", argv[0], argv[a]);
      return 2;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
  }
  return 0;
}
