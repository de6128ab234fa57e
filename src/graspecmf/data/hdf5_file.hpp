#pragma once
// A small typed view of an HDF5 file for the data layer: read/write whole datasets by path, in the
// style h5py writes them (non-scalar datasets chunked by h5py's size rule + deflate level 4,
// scalars contiguous, strings variable-length UTF-8). Every failure is an Error naming file and
// path.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace graspecmf::data {

// The shape of a dataset; empty for a scalar.
using Shape = std::vector<std::size_t>;

// How a dataset is stored: what a layout comparison between two files needs.
struct DatasetLayout {
  Shape shape;
  std::string type;        // "float64", "int64", "string-utf8-vlen", ... (class, size, variant)
  Shape chunks;            // empty when contiguous
  int deflate_level = -1;  // -1 without a deflate filter

  bool operator==(const DatasetLayout& other) const;
};

// The chunk shape h5py's automatic chunking picks for a dataset of this shape and element size.
Shape h5py_chunk_shape(const Shape& shape, std::size_t element_size);

class Hdf5Reader {
 public:
  // Opens an existing HDF5 file read-only; throws Error if it is missing or not HDF5.
  explicit Hdf5Reader(const std::filesystem::path& path);
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  // Paths of every dataset in the file, sorted (e.g. "grasps/transforms").
  std::vector<std::string> dataset_paths() const;
  // Storage details of a dataset; throws Error if it does not exist.
  DatasetLayout layout(const std::string& path) const;
  // True if a dataset exists at path (e.g. "grasps/transforms").
  bool has_dataset(const std::string& path) const;
  // The dataset's shape; throws Error if it does not exist.
  Shape shape(const std::string& path) const;
  // All values as float64 / int64 (HDF5 converts numeric types), in row-major order.
  std::vector<double> read_doubles(const std::string& path) const;
  std::vector<std::int64_t> read_int64s(const std::string& path) const;
  // A scalar float64 dataset.
  double read_double(const std::string& path) const;
  // A scalar string dataset (variable- or fixed-length).
  std::string read_string(const std::string& path) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class Hdf5Writer {
 public:
  // Starts an HDF5 file in memory; nothing touches path until close(). Throws Error on failure.
  explicit Hdf5Writer(const std::filesystem::path& path);
  // Discards a file that was not closed; never throws.
  ~Hdf5Writer();
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  // Writes an array dataset (chunked + deflate 4); values.size() must equal the shape's product.
  // Parent groups are created as needed.
  void write_doubles(const std::string& path, const std::vector<double>& values,
                     const Shape& shape);
  void write_int64s(const std::string& path, const std::vector<std::int64_t>& values,
                    const Shape& shape);
  // Writes a scalar float64 dataset (contiguous).
  void write_double(const std::string& path, double value);
  // Writes a scalar variable-length UTF-8 string dataset.
  void write_string(const std::string& path, const std::string& value);
  // Writes the finished file to path atomically; throws Error naming path and the system's reason
  // if the write fails, leaving path as it was.
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace graspecmf::data
