#include "graspecmf/core/npy.hpp"

#include <cstdint>
#include <cstring>
#include <functional>
#include <numeric>

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace {

// The little-endian number of type T stored at data, as a double.
template <typename T>
double load(const char* data) {
  T value;
  std::memcpy(&value, data, sizeof(T));
  return static_cast<double>(value);
}

// An element type NumPy writes, by its descr: bytes per value and how to read one.
struct NpyType {
  std::size_t width = 0;  // 0: not a type graspecmf reads
  bool integral = false;
  double (*load)(const char*) = nullptr;
};

NpyType npy_type(const std::string& descr) {
  struct Entry {
    const char* descr;
    NpyType type;
  };
  static const Entry kTypes[] = {
      {"'<f4'", {4, false, load<float>}},       {"'<f8'", {8, false, load<double>}},
      {"'|b1'", {1, true, load<std::uint8_t>}}, {"'|u1'", {1, true, load<std::uint8_t>}},
      {"'|i1'", {1, true, load<std::int8_t>}},  {"'<u2'", {2, true, load<std::uint16_t>}},
      {"'<i2'", {2, true, load<std::int16_t>}}, {"'<u4'", {4, true, load<std::uint32_t>}},
      {"'<i4'", {4, true, load<std::int32_t>}}, {"'<u8'", {8, true, load<std::uint64_t>}},
      {"'<i8'", {8, true, load<std::int64_t>}},
  };
  for (const Entry& entry : kTypes) {
    if (descr == entry.descr) return entry.type;
  }
  return {};
}

// The value of `key` in a header dictionary such as "{'descr': '<f8', ...}": the text after
// "'key': " up to the next top-level comma or closing brace.
std::string header_value(const std::string& header, const std::string& key) {
  const std::size_t at = header.find("'" + key + "':");
  if (at == std::string::npos) return {};
  std::size_t begin = at + key.size() + 3, end = begin;
  int depth = 0;
  for (; end < header.size(); ++end) {
    const char c = header[end];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth == 0 && (c == ',' || c == '}')) break;
  }
  while (begin < end && header[begin] == ' ') ++begin;
  return header.substr(begin, end - begin);
}

// The dimensions of a shape tuple such as "(3, 4, 4)", "(5,)" or "()".
std::vector<std::size_t> parse_shape(const std::string& text,
                                     const std::function<Error(const std::string&)>& fail) {
  if (text.size() < 2 || text.front() != '(' || text.back() != ')') throw fail("no array shape");
  std::vector<std::size_t> shape;
  std::size_t at = 1;
  while (at < text.size() - 1) {
    while (at < text.size() - 1 && (text[at] == ' ' || text[at] == ',')) ++at;
    if (at == text.size() - 1) break;
    std::size_t value = 0, digits = 0;
    for (; at < text.size() - 1 && text[at] >= '0' && text[at] <= '9'; ++at, ++digits) {
      if (value > (SIZE_MAX - 9) / 10) throw fail("an array dimension is too large");
      value = value * 10 + static_cast<std::size_t>(text[at] - '0');
    }
    if (digits == 0) throw fail("malformed array shape " + text);
    shape.push_back(value);
  }
  return shape;
}

}  // namespace

NpyArray parse_npy(std::string_view bytes, const std::string& what) {
  const auto fail = [&](const std::string& why) { return Error(what + ": " + why); };
  if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0) throw fail("not a .npy array");
  const int major = static_cast<unsigned char>(bytes[6]);
  if (major < 1 || major > 3) throw fail("unknown .npy format version " + std::to_string(major));
  const std::size_t length_bytes = major == 1 ? 2 : 4;
  if (bytes.size() < 8 + length_bytes) throw fail("truncated .npy header");
  std::size_t header_length = 0;
  for (std::size_t i = 0; i < length_bytes; ++i) {
    header_length |= static_cast<std::size_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
  }
  const std::size_t data_start = 8 + length_bytes + header_length;
  if (header_length > bytes.size() || bytes.size() < data_start) {
    throw fail("truncated .npy header");
  }
  const std::string header(bytes.substr(8 + length_bytes, header_length));
  const std::string descr = header_value(header, "descr");
  if (descr == "'|O'") {
    throw fail("holds pickled Python objects, not numbers (graspecmf reads only numeric arrays)");
  }
  const NpyType type = npy_type(descr);
  const std::size_t width = type.width;
  if (width == 0) {
    throw fail(".npy data must be little-endian numbers (float, integer or bool), not " +
               (descr.empty() ? std::string("an unnamed type") : descr));
  }
  if (header_value(header, "fortran_order") != "False") throw fail(".npy data must be in C order");
  NpyArray array;
  array.integral = type.integral;
  array.shape = parse_shape(header_value(header, "shape"), fail);
  const std::size_t data_bytes = bytes.size() - data_start;
  std::size_t count = 1;
  bool overflow = false;
  for (const std::size_t n : array.shape) {
    overflow = overflow || (n != 0 && count > SIZE_MAX / n);
    count *= n;
  }
  if (overflow || data_bytes % width != 0 || data_bytes / width != count) {
    throw fail(".npy data size does not match its shape");
  }
  array.values.resize(data_bytes / width);
  const char* data = bytes.data() + data_start;
  for (std::size_t i = 0; i < array.values.size(); ++i) {
    array.values[i] = type.load(data + width * i);
  }
  return array;
}

std::string npy_bytes(const NpyArray& array) {
  const std::size_t count =
      std::accumulate(array.shape.begin(), array.shape.end(), std::size_t{1}, std::multiplies<>());
  if (count != array.values.size()) {
    throw Error(".npy array of " + std::to_string(array.values.size()) +
                " values does not match its shape");
  }
  std::string shape = "(";
  for (const std::size_t n : array.shape) shape += std::to_string(n) + ", ";
  if (array.shape.size() > 1) shape.resize(shape.size() - 2);
  if (array.shape.size() == 1) shape.resize(shape.size() - 1);
  shape += ")";
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': " + shape + ", }";
  // NumPy pads the header with spaces and a newline so the data starts on a 64-byte boundary.
  const std::size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  std::string out = "\x93NUMPY\x01";
  out.push_back('\0');
  out.push_back(static_cast<char>(header.size() & 0xff));
  out.push_back(static_cast<char>(header.size() >> 8));
  out += header;
  const std::size_t start = out.size();
  out.resize(start + 8 * count);
  std::memcpy(out.data() + start, array.values.data(), 8 * count);
  return out;
}

}  // namespace graspecmf
