#pragma once
// Shared by all test suites: paths of the bundled ACRONYM sample (data/acronym-sample), a scratch
// folder per test, whole-file read/write helpers, and an expectation on graspecmf::Error.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "graspecmf/core/error.hpp"

namespace graspecmf::testing {

inline std::filesystem::path sample_root() {
  return std::filesystem::path(GRASPECMF_DATA_DIR) / "acronym-sample";
}
inline std::filesystem::path sample_grasp_file() {
  return sample_root() / "grasps" / "Mug_10f6e09036350e92b3f21f1137c3c347_0.0002682457830986903.h5";
}
inline std::filesystem::path sample_mesh_file() {
  return sample_root() / "meshes" / "Mug" / "10f6e09036350e92b3f21f1137c3c347.obj";
}
// An input a fuzz target found (or a hand-made one beside them): fuzz/regressions/TARGET/NAME.
inline std::filesystem::path fuzz_regression(const std::string& target, const std::string& name) {
  return std::filesystem::path(GRASPECMF_DATA_DIR).parent_path() / "fuzz" / "regressions" / target /
         name;
}
// The bundled model's weights (models/mugs/model.pt), a LibTorch archive of stored and deflated
// entries.
inline std::filesystem::path bundled_weights_file() {
  return std::filesystem::path(GRASPECMF_DATA_DIR).parent_path() / "models" / "mugs" / "model.pt";
}
// A seed of a fuzz target's corpus: fuzz/corpus/TARGET/NAME.
inline std::filesystem::path fuzz_seed(const std::string& target, const std::string& name) {
  return std::filesystem::path(GRASPECMF_DATA_DIR).parent_path() / "fuzz" / "corpus" / target /
         name;
}
inline std::filesystem::path gripper_mesh_file() {
  return sample_root() / "franka_gripper_collision_mesh.stl";
}

// Expects `call` to throw graspecmf::Error whose message contains `fragment`.
template <typename F>
void expect_error(F&& call, const std::string& fragment) {
  try {
    call();
    ADD_FAILURE() << "expected an Error containing '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

// A fresh, empty folder named after the running test and process; removed with the object.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::path(::testing::TempDir()) /
            ("graspecmf_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Number of entries in the folder.
  std::size_t num_files() const {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(path_), {}));
  }

 private:
  std::filesystem::path path_;
};

inline void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace graspecmf::testing
