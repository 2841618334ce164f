// Small mesh files for the mesh tests, written into a fresh temporary folder per test.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "support/temp_folder.h"

namespace urdfsnap::geometry {

class MeshFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_.emplace(std::string(info->test_suite_name()) + "_" + info->name());
    dir_ = folder_->path();
  }
  void TearDown() override { folder_.reset(); }

  // Writes `bytes` to DIR/relative (creating folders) and returns the path.
  std::string Write(const std::string& relative, const std::string& bytes) const {
    const std::filesystem::path path = dir_ / relative;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }

  std::optional<test::TempFolder> folder_;
  std::filesystem::path dir_;  // folder_'s path
};

}  // namespace urdfsnap::geometry
