// Damaged or hostile HDF5 files: sizes a file declares but cannot hold are refused before any
// allocation.

#include <gtest/gtest.h>
#include <hdf5.h>

#include "graspecmf/data/acronym_file.hpp"
#include "test_support.hpp"

namespace {
using graspecmf::data::read_acronym_file;
using graspecmf::testing::expect_error;
using graspecmf::testing::ScratchDir;

// A 50-million-grasp /grasps/transforms over unallocated chunks: a few kilobytes on disk, 6.4 GB
// if read.
TEST(Hdf5Damage, DeclaredExtentBeyondTheStoredBytesIsRefused) {
  ScratchDir dir;
  const std::string path = (dir / "huge.h5").string();
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t dims[3] = {50'000'000, 4, 4}, chunk[3] = {1024, 4, 4};
  const hid_t space = H5Screate_simple(3, dims, nullptr);
  const hid_t create = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(create, 3, chunk);
  const hid_t links = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(links, 1);
  const hid_t ds =
      H5Dcreate2(file, "grasps/transforms", H5T_IEEE_F64LE, space, links, create, H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  H5Dclose(ds);
  const hid_t scalar = H5Screate(H5S_SCALAR);
  const double scale = 1.0;
  const hid_t scale_ds =
      H5Dcreate2(file, "object/scale", H5T_IEEE_F64LE, scalar, links, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(scale_ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &scale);
  H5Dclose(scale_ds);
  const hid_t text = H5Tcopy(H5T_C_S1);
  H5Tset_size(text, H5T_VARIABLE);
  const char* mesh = "meshes/x.obj";
  const hid_t file_ds =
      H5Dcreate2(file, "object/file", text, scalar, links, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(file_ds, text, H5S_ALL, H5S_ALL, H5P_DEFAULT, &mesh);
  H5Dclose(file_ds);
  H5Tclose(text);
  H5Sclose(scalar);
  H5Pclose(links);
  H5Pclose(create);
  H5Sclose(space);
  H5Fclose(file);
  expect_error([&] { read_acronym_file(path); }, "declares 800000000 values but stores only");
}

}  // namespace

namespace graspecmf::data {
namespace {

// Found by fuzz_acronym: a NULL variable-length string crashed HDF5's std::string read, and a
// string array overran the one pointer it was read into.
TEST(FuzzRegressions, AcronymStringsMustBeOneNonNullString) {
  testing::expect_error(
      [] {
        read_acronym_file(testing::fuzz_regression("acronym", "null_vlen_string_object_file.h5"));
      },
      "is a NULL string");
  testing::expect_error(
      [] { read_acronym_file(testing::fuzz_regression("acronym", "object_file_string_array.h5")); },
      "/object/file must hold one string");
}

// Found by fuzz_acronym: damaged files on which libhdf5 itself hangs, or (with AddressSanitizer)
// asks for an impossible allocation. They are read in a child process first, so they end in one
// error line and the caller lives on.
TEST(FuzzRegressions, LibHdf5HangsAndCrashesAreErrors) {
  testing::expect_error(
      [] {
        read_acronym_file(testing::fuzz_regression("acronym", "hdf5_global_heap_hang.h5"),
                          std::chrono::seconds(2));
      },
      "hdf5_global_heap_hang.h5: damaged HDF5 file (the HDF5 library did not finish within 2 s");
  testing::expect_error(
      [] {
        read_acronym_file(testing::fuzz_regression("acronym", "hdf5_allocation_size_too_big.h5"));
      },
      "hdf5_allocation_size_too_big.h5: ");
}

// A batch read calls back for every file in order: good files with their record, the damaged and
// the missing one with their error, and the good file after a damaged one is still read.
TEST(FuzzRegressions, BatchReadsGoOnPastDamagedFiles) {
  const std::vector<std::filesystem::path> files = {
      testing::sample_grasp_file(),
      testing::fuzz_regression("acronym", "hdf5_allocation_size_too_big.h5"), "no-such-file.h5",
      testing::sample_grasp_file()};
  std::vector<std::string> calls;
  read_acronym_files(
      files,
      [&](std::size_t i, AcronymGraspFile&& record) {
        calls.push_back(std::to_string(i) + " " + std::to_string(record.size()));
      },
      [&](std::size_t i, const std::string& error) {
        calls.push_back(std::to_string(i) + " " + error.substr(0, error.find(':')));
      });
  ASSERT_EQ(calls.size(), 4U);
  EXPECT_EQ(calls[0], "0 2000");
  EXPECT_EQ(calls[1], "1 " + files[1].string());
  EXPECT_EQ(calls[2].rfind("2 ", 0), 0U) << calls[2];
  EXPECT_NE(calls[2].find("no-such-file.h5"), std::string::npos) << calls[2];
  EXPECT_EQ(calls[3], "3 2000");
}

}  // namespace
}  // namespace graspecmf::data
