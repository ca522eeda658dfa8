// A test's own store of runs (experiments/frame/run_store.hpp): a fresh temporary directory, the store allowed
// for the test binary's dirty build, switched on and off with the environment the drivers read; removed after.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

class RunStoreTest : public ::testing::Test {
 protected:
  explicit RunStoreTest(const std::string& name)
      : dir_(std::filesystem::temp_directory_path() / ("sph_" + name + "_" + std::to_string(::getpid()))) {}
  void SetUp() override {
    std::filesystem::remove_all(dir_);
    setenv("SPH_RUN_CACHE_ALLOW_DIRTY", "1", 1);
  }
  void TearDown() override {
    unsetenv("SPH_RUN_CACHE");
    unsetenv("SPH_RUN_CACHE_ALLOW_DIRTY");
    std::filesystem::remove_all(dir_);
  }
  void store_on() { setenv("SPH_RUN_CACHE", dir_.c_str(), 1); }
  void store_off() { unsetenv("SPH_RUN_CACHE"); }
  std::filesystem::path dir_;
};
