#include "graspecmf/data/hdf5_file.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <numeric>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"

namespace graspecmf::data {
namespace fs = std::filesystem;

namespace {

// The HDF5 library prints its error stack to stderr by default; we report our own single line.
void silence_hdf5_errors() {
  static const bool silenced = [] {
    H5::Exception::dontPrint();
    return true;
  }();
  (void)silenced;
}

// Reading a dataset whose declared size exceeds kMaxExpansion × its stored bytes + kSmallDataset
// is refused (deflate's best ratio is about 1032:1).
constexpr double kMaxExpansion = 1100.0;
constexpr double kSmallDataset = 1 << 20;

std::size_t element_count(const Shape& shape) {
  return std::accumulate(shape.begin(), shape.end(), std::size_t{1}, std::multiplies<>());
}

std::string describe(const H5::Exception& e) {
  const std::string detail = e.getDetailMsg();
  return detail.empty() ? std::string("HDF5 error") : detail;
}

std::string type_name(const H5::DataSet& ds) {
  const H5T_class_t type_class = ds.getTypeClass();
  if (type_class == H5T_STRING) {
    const H5::StrType type = ds.getStrType();
    return std::string("string-") + (type.getCset() == H5T_CSET_UTF8 ? "utf8" : "ascii") +
           (type.isVariableStr() ? "-vlen" : "-fixed" + std::to_string(type.getSize()));
  }
  const std::string bits = std::to_string(8 * ds.getDataType().getSize());
  if (type_class == H5T_FLOAT) return "float" + bits;
  if (type_class == H5T_INTEGER) {
    return (ds.getIntType().getSign() == H5T_SGN_NONE ? "uint" : "int") + bits;
  }
  return "class" + std::to_string(static_cast<int>(type_class)) + "-" + bits;
}

}  // namespace

bool DatasetLayout::operator==(const DatasetLayout& other) const {
  return shape == other.shape && type == other.type && chunks == other.chunks &&
         deflate_level == other.deflate_level;
}

Shape h5py_chunk_shape(const Shape& shape, std::size_t element_size) {
  // h5py's rule: aim for a chunk of 16 KiB × 2^log10(dataset MiB), clamped to [8 KiB, 1 MiB], by
  // halving the axes in turn until the chunk is below the target or within 50 % of it.
  constexpr double kBase = 16.0 * 1024, kMin = 8.0 * 1024, kMax = 1024.0 * 1024;
  Shape chunk = shape;
  for (auto& c : chunk) c = std::max<std::size_t>(c, 1);
  const double dataset_bytes = static_cast<double>(element_count(chunk) * element_size);
  double target = kBase * std::pow(2.0, std::log10(dataset_bytes / (1024.0 * 1024)));
  target = std::clamp(target, kMin, kMax);
  for (std::size_t i = 0;; ++i) {
    const double chunk_bytes = static_cast<double>(element_count(chunk) * element_size);
    const bool small_enough = chunk_bytes < target || std::abs(chunk_bytes - target) / target < 0.5;
    if ((small_enough && chunk_bytes < kMax) || element_count(chunk) == 1) break;
    std::size_t& axis = chunk[i % chunk.size()];
    axis = (axis + 1) / 2;
  }
  return chunk;
}

// ---------------------------------------------------------------------------------------------
// Reader

struct Hdf5Reader::Impl {
  fs::path path;
  H5::H5File file;

  H5::DataSet open(const std::string& name) const {
    if (!exists(name)) throw Error(path.string() + ": no dataset /" + name);
    try {
      return file.openDataSet(name);
    } catch (const H5::Exception& e) {
      throw Error(path.string() + ": cannot open /" + name + ": " + describe(e));
    }
  }

  // True if every link along the path exists and the last is a dataset.
  bool exists(const std::string& name) const {
    std::size_t pos = 0;
    while ((pos = name.find('/', pos + 1)) != std::string::npos) {
      if (H5Lexists(file.getId(), name.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
    }
    if (H5Lexists(file.getId(), name.c_str(), H5P_DEFAULT) <= 0) return false;
    H5O_info_t info;
    if (H5Oget_info_by_name(file.getId(), name.c_str(), &info, H5P_DEFAULT) < 0) return false;
    return info.type == H5O_TYPE_DATASET;
  }

  template <typename T>
  std::vector<T> read_all(const std::string& name, const H5::PredType& type) const {
    H5::DataSet ds = open(name);
    try {
      if (ds.getTypeClass() != H5T_INTEGER && ds.getTypeClass() != H5T_FLOAT) {
        throw Error(path.string() + ": /" + name + " is not numeric");
      }
      const hssize_t n = ds.getSpace().getSimpleExtentNpoints();
      // Refuse extents the stored bytes cannot hold before allocating: deflate expands at most
      // about 1032:1, and a dataset declared over unallocated chunks would read fill values.
      const double declared =
          static_cast<double>(n) * static_cast<double>(ds.getDataType().getSize());
      const double stored = static_cast<double>(ds.getStorageSize());
      if (declared > kMaxExpansion * stored + kSmallDataset) {
        throw Error(path.string() + ": /" + name + " declares " + std::to_string(n) +
                    " values but stores only " + std::to_string(ds.getStorageSize()) +
                    " bytes; the file is damaged or not what it claims");
      }
      std::vector<T> values(static_cast<std::size_t>(n));
      if (n > 0) ds.read(values.data(), type);
      return values;
    } catch (const H5::Exception& e) {
      throw Error(path.string() + ": cannot read /" + name + ": " + describe(e));
    }
  }
};

Hdf5Reader::Hdf5Reader(const fs::path& path) : impl_(std::make_unique<Impl>()) {
  silence_hdf5_errors();
  impl_->path = path;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path.string() + ": no such file");
  if (!fs::is_regular_file(path, ec)) throw Error(path.string() + ": not a regular file");
  if (H5Fis_hdf5(path.c_str()) <= 0) throw Error(path.string() + ": not an HDF5 file");
  try {
    impl_->file.openFile(path.string(), H5F_ACC_RDONLY);
  } catch (const H5::Exception& e) {
    throw Error(path.string() + ": cannot open HDF5 file: " + describe(e));
  }
}

Hdf5Reader::~Hdf5Reader() = default;

std::vector<std::string> Hdf5Reader::dataset_paths() const {
  std::vector<std::string> paths;
  const auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type == H5O_TYPE_DATASET)
      static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  if (H5Ovisit(impl_->file.getId(), H5_INDEX_NAME, H5_ITER_INC, visit, &paths) < 0) {
    throw Error(impl_->path.string() + ": cannot list the datasets");
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

DatasetLayout Hdf5Reader::layout(const std::string& path) const {
  H5::DataSet ds = impl_->open(path);
  try {
    DatasetLayout layout;
    layout.shape = shape(path);
    layout.type = type_name(ds);
    const H5::DSetCreatPropList creation = ds.getCreatePlist();
    if (creation.getLayout() == H5D_CHUNKED) {
      std::vector<hsize_t> chunks(layout.shape.size());
      creation.getChunk(static_cast<int>(chunks.size()), chunks.data());
      layout.chunks.assign(chunks.begin(), chunks.end());
    }
    for (int i = 0; i < creation.getNfilters(); ++i) {
      unsigned flags = 0, level = 0, config = 0;
      std::size_t num_values = 1;
      char name[32];
      if (creation.getFilter(i, flags, num_values, &level, sizeof(name), name, config) ==
          H5Z_FILTER_DEFLATE) {
        layout.deflate_level = static_cast<int>(level);
      }
    }
    return layout;
  } catch (const H5::Exception& e) {
    throw Error(impl_->path.string() + ": cannot read the layout of /" + path + ": " + describe(e));
  }
}

bool Hdf5Reader::has_dataset(const std::string& path) const {
  return impl_->exists(path);
}

Shape Hdf5Reader::shape(const std::string& path) const {
  H5::DataSpace space = impl_->open(path).getSpace();
  const int rank = space.getSimpleExtentNdims();
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) space.getSimpleExtentDims(dims.data());
  return Shape(dims.begin(), dims.end());
}

std::vector<double> Hdf5Reader::read_doubles(const std::string& path) const {
  return impl_->read_all<double>(path, H5::PredType::NATIVE_DOUBLE);
}

std::vector<std::int64_t> Hdf5Reader::read_int64s(const std::string& path) const {
  return impl_->read_all<std::int64_t>(path, H5::PredType::NATIVE_INT64);
}

double Hdf5Reader::read_double(const std::string& path) const {
  const std::vector<double> values = read_doubles(path);
  if (values.size() != 1) {
    throw Error(impl_->path.string() + ": /" + path + " should hold one number, holds " +
                std::to_string(values.size()));
  }
  return values[0];
}

std::string Hdf5Reader::read_string(const std::string& path) const {
  H5::DataSet ds = impl_->open(path);
  try {
    if (ds.getTypeClass() != H5T_STRING) {
      throw Error(impl_->path.string() + ": /" + path + " is not a string");
    }
    if (ds.getSpace().getSimpleExtentNpoints() != 1) {
      throw Error(impl_->path.string() + ": /" + path + " must hold one string");
    }
    const H5::StrType type = ds.getStrType();
    if (!type.isVariableStr()) {
      std::string value;
      ds.read(value, type);
      return value;
    }
    // A variable-length string may be NULL, which HDF5's std::string overload does not handle.
    char* text = nullptr;
    ds.read(static_cast<void*>(&text), type);
    const std::unique_ptr<char, herr_t (*)(void*)> owned(text, H5free_memory);
    if (text == nullptr) throw Error(impl_->path.string() + ": /" + path + " is a NULL string");
    return std::string(text);
  } catch (const H5::Exception& e) {
    throw Error(impl_->path.string() + ": cannot read /" + path + ": " + describe(e));
  }
}

// ---------------------------------------------------------------------------------------------
// Writer

struct Hdf5Writer::Impl {
  fs::path path;
  H5::H5File file;
  bool open = false;

  // Dataset creation without the modification time HDF5 records by default, so that the same
  // content always gives the same bytes (resumed dataset runs compare byte for byte).
  static H5::DSetCreatPropList untimed_creation() {
    H5::DSetCreatPropList creation;
    H5Pset_obj_track_times(creation.getId(), false);
    return creation;
  }

  H5::LinkCreatPropList link_properties() const {
    H5::LinkCreatPropList properties;
    properties.setCreateIntermediateGroup(true);
    return properties;
  }

  template <typename T>
  void write_array(const std::string& name, const std::vector<T>& values, const Shape& shape,
                   const H5::PredType& file_type, const H5::PredType& memory_type) {
    if (values.size() != element_count(shape) || shape.empty()) {
      throw Error(path.string() + ": /" + name + ": " + std::to_string(values.size()) +
                  " values do not fill the requested shape");
    }
    try {
      const std::vector<hsize_t> dims(shape.begin(), shape.end());
      const Shape chunk_shape = h5py_chunk_shape(shape, sizeof(T));
      const std::vector<hsize_t> chunk(chunk_shape.begin(), chunk_shape.end());
      H5::DSetCreatPropList creation = untimed_creation();
      creation.setChunk(static_cast<int>(chunk.size()), chunk.data());
      creation.setDeflate(4);
      H5::DataSpace space(static_cast<int>(dims.size()), dims.data());
      H5::DataSet ds = file.createDataSet(name, file_type, space, creation,
                                          H5::DSetAccPropList::DEFAULT, link_properties());
      ds.write(values.data(), memory_type);
    } catch (const H5::Exception& e) {
      throw Error(path.string() + ": cannot write /" + name + ": " + describe(e));
    }
  }
};

Hdf5Writer::Hdf5Writer(const fs::path& path) : impl_(std::make_unique<Impl>()) {
  silence_hdf5_errors();
  impl_->path = path;
  try {
    // The file is built in memory (the core driver without a backing store) and written out by
    // close() with checked I/O, so that no disk error ever reaches HDF5's own close.
    H5::FileAccPropList access;
    access.setCore(1 << 20, false);
    impl_->file = H5::H5File(path.string(), H5F_ACC_TRUNC, H5::FileCreatPropList::DEFAULT, access);
    impl_->open = true;
  } catch (const H5::Exception& e) {
    throw Error(path.string() + ": cannot create HDF5 file: " + describe(e));
  }
}

Hdf5Writer::~Hdf5Writer() {
  if (!impl_->open) return;
  try {
    impl_->file.close();
  } catch (const H5::Exception&) {
    // Closing an in-memory file cannot meet a disk error; nothing is written without close().
  }
}

void Hdf5Writer::write_doubles(const std::string& path, const std::vector<double>& values,
                               const Shape& shape) {
  impl_->write_array(path, values, shape, H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE);
}

void Hdf5Writer::write_int64s(const std::string& path, const std::vector<std::int64_t>& values,
                              const Shape& shape) {
  impl_->write_array(path, values, shape, H5::PredType::STD_I64LE, H5::PredType::NATIVE_INT64);
}

void Hdf5Writer::write_double(const std::string& path, double value) {
  try {
    H5::DataSet ds = impl_->file.createDataSet(
        path, H5::PredType::IEEE_F64LE, H5::DataSpace(H5S_SCALAR), Impl::untimed_creation(),
        H5::DSetAccPropList::DEFAULT, impl_->link_properties());
    ds.write(&value, H5::PredType::NATIVE_DOUBLE);
  } catch (const H5::Exception& e) {
    throw Error(impl_->path.string() + ": cannot write /" + path + ": " + describe(e));
  }
}

void Hdf5Writer::write_string(const std::string& path, const std::string& value) {
  try {
    H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
    type.setCset(H5T_CSET_UTF8);
    H5::DataSet ds =
        impl_->file.createDataSet(path, type, H5::DataSpace(H5S_SCALAR), Impl::untimed_creation(),
                                  H5::DSetAccPropList::DEFAULT, impl_->link_properties());
    ds.write(value, type);
  } catch (const H5::Exception& e) {
    throw Error(impl_->path.string() + ": cannot write /" + path + ": " + describe(e));
  }
}

void Hdf5Writer::close() {
  if (!impl_->open) return;
  impl_->open = false;
  std::string image;
  try {
    const hid_t id = impl_->file.getId();
    if (H5Fflush(id, H5F_SCOPE_GLOBAL) < 0) throw H5::FileIException("H5Fflush", "flush failed");
    const ssize_t size = H5Fget_file_image(id, nullptr, 0);
    if (size < 0) throw H5::FileIException("H5Fget_file_image", "no file image");
    image.resize(static_cast<std::size_t>(size));
    if (H5Fget_file_image(id, image.data(), image.size()) != size) {
      throw H5::FileIException("H5Fget_file_image", "short file image");
    }
    impl_->file.close();
  } catch (const H5::Exception& e) {
    throw Error(impl_->path.string() + ": cannot finish HDF5 file: " + describe(e));
  }
  write_file_atomically(impl_->path, image);
}

}  // namespace graspecmf::data
