// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_ScratchFolder_h
#define labelmesher_testing_ScratchFolder_h

/**
 * @file ScratchFolder.h
 * A GoogleTest fixture with a fresh, empty folder of its own (named after the test and the
 * process, under the system's temporary folder, so that two builds' tests never share one),
 * removed after the test: the I/O tests write real files there.
 */

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace labelmesher
{
namespace testing
{

class ScratchFolder : public ::testing::Test
{
protected:
  void SetUp() override
  {
    this->Folder = std::filesystem::temp_directory_path() /
      ("labelmesher_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name()) +
        "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(this->Folder);
    std::filesystem::create_directories(this->Folder);
  }
  void TearDown() override { std::filesystem::remove_all(this->Folder); }
  /// `name` inside the folder.
  std::string Path(const std::string& name) const { return (this->Folder / name).string(); }

  std::filesystem::path Folder;
};

} // namespace testing
} // namespace labelmesher

#endif
