#include "graspecmf/geometry/ply_body.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/number_text.hpp"

namespace graspecmf::geometry {
namespace {

// How one binary value is stored.
struct ValueType {
  std::size_t size = 0;
  bool floating = false;
  bool is_signed = false;
};

// Reads the values of a PLY body one at a time, in file order; every read is bounds-checked.
class PlyReader {
 public:
  PlyReader(const std::filesystem::path& path, std::string_view data, const std::string& format)
      : path_(path),
        data_(data),
        ascii_(format == "ascii"),
        big_endian_(format == "binary_big_endian") {}

  // The next value, of type type.
  double value(const ValueType& type) {
    if (ascii_) return ascii_value(type);
    if (type.size > data_.size() - at_) fail("the PLY data ends early (truncated?)");
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < type.size; ++i) {
      const std::size_t byte = big_endian_ ? i : type.size - 1 - i;
      bits = (bits << 8) | static_cast<unsigned char>(data_[at_ + byte]);
    }
    at_ += type.size;
    if (type.floating)
      return type.size == 4 ? from_bits<float, std::uint32_t>(bits)
                            : from_bits<double, std::uint64_t>(bits);
    if (type.is_signed && type.size < 8 && (bits >> (8 * type.size - 1)) != 0) {
      return static_cast<double>(bits) - std::ldexp(1.0, static_cast<int>(8 * type.size));
    }
    return static_cast<double>(bits);
  }

  // The next value as a list length: a non-negative integer no larger than the number of items
  // of item_size bytes (binary) or of at least one character and a separator (ascii) left.
  std::size_t length(const ValueType& type, std::size_t item_size) {
    const double n = value(type);
    if (n < 0) fail("a PLY list has a negative length");
    const std::size_t left = data_.size() - at_;
    const double most =
        ascii_ ? static_cast<double>(left / 2 + 1) : static_cast<double>(left / item_size);
    if (n > most) fail("a PLY list is longer than the data left (truncated or damaged?)");
    return static_cast<std::size_t>(n);
  }

  // Passes over n values of type type.
  void skip(std::size_t n, const ValueType& type) {
    if (!ascii_) {
      at_ += n * type.size;  // length() checked that they are there
      return;
    }
    for (std::size_t i = 0; i < n; ++i) ascii_value(type);
  }

  // Fails unless only whitespace (ascii) or nothing (binary) is left.
  void finish() {
    const std::string_view rest = data_.substr(at_);
    if (ascii_ ? rest.find_first_not_of(" \t\r\n") != std::string_view::npos : !rest.empty()) {
      fail("the PLY data goes on after the elements its header declares (damaged header?)");
    }
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

  template <typename Float, typename Bits>
  static double from_bits(std::uint64_t bits) {
    const auto narrow = static_cast<Bits>(bits);
    Float value;
    std::memcpy(&value, &narrow, sizeof value);
    return static_cast<double>(value);
  }

  double ascii_value(const ValueType& type) {
    while (at_ < data_.size() && is_space(data_[at_])) ++at_;
    if (at_ == data_.size()) fail("the PLY data ends early (truncated?)");
    std::size_t end = at_;
    while (end < data_.size() && !is_space(data_[end])) ++end;
    const std::string_view token = data_.substr(at_, end - at_);
    at_ = end;
    double x = 0;
    if (!parse_number(token, x)) {
      fail("the PLY value '" + std::string(token.substr(0, 32)) + "' is not a number");
    }
    if (!type.floating && !(std::isfinite(x) && std::floor(x) == x)) {
      fail("the PLY value '" + std::string(token.substr(0, 32)) + "' is not an integer");
    }
    return x;
  }

  [[noreturn]] void fail(const std::string& why) const { throw Error(path_.string() + ": " + why); }

  const std::filesystem::path& path_;
  std::string_view data_;
  std::size_t at_ = 0;
  bool ascii_;
  bool big_endian_;
};

}  // namespace

const PlyProperty* find_ply_property(const PlyHeader& header, const std::string& element,
                                     const std::string& name) {
  for (const PlyElement& e : header.elements) {
    if (e.name != element) continue;
    for (const PlyProperty& p : e.properties) {
      if (p.name == name) return &p;
    }
  }
  return nullptr;
}

std::vector<PlyColumn> read_ply_columns(
    const std::filesystem::path& path, std::string_view bytes, const PlyHeader& header,
    const std::vector<std::pair<std::string, std::string>>& wanted) {
  std::vector<PlyColumn> columns(wanted.size());
  // slot[e][p]: the column of property p of element e, or -1 when it is not wanted.
  std::vector<std::vector<int>> slot;
  for (const PlyElement& element : header.elements)
    slot.emplace_back(element.properties.size(), -1);
  for (std::size_t i = 0; i < wanted.size(); ++i) {
    const PlyProperty* property = find_ply_property(header, wanted[i].first, wanted[i].second);
    if (property == nullptr) {
      throw Error(path.string() + ": the PLY file has no property '" + wanted[i].second +
                  "' of an element '" + wanted[i].first + "'");
    }
    for (std::size_t e = 0; e < header.elements.size(); ++e) {
      const std::vector<PlyProperty>& properties = header.elements[e].properties;
      if (property >= properties.data() && property < properties.data() + properties.size()) {
        slot[e][static_cast<std::size_t>(property - properties.data())] = static_cast<int>(i);
        if (property->count_size > 0)
          columns[i].starts.push_back(0);
        else
          columns[i].values.reserve(static_cast<std::size_t>(header.elements[e].count));
      }
    }
  }
  PlyReader in(path, bytes.substr(std::min(header.data_start, bytes.size())), header.format);
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    // An element without properties holds no data, however many items it declares.
    if (element.properties.empty()) continue;
    for (std::uint64_t item = 0; item < element.count; ++item) {
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        const ValueType type{property.size, property.floating, property.is_signed};
        PlyColumn* column =
            slot[e][p] < 0 ? nullptr : &columns[static_cast<std::size_t>(slot[e][p])];
        if (property.count_size == 0) {
          const double x = in.value(type);
          if (column != nullptr) column->values.push_back(x);
          continue;
        }
        const std::size_t n =
            in.length({property.count_size, false, property.count_signed}, property.size);
        if (column == nullptr) {
          in.skip(n, type);
          continue;
        }
        for (std::size_t k = 0; k < n; ++k) column->values.push_back(in.value(type));
        column->starts.push_back(column->values.size());
      }
    }
  }
  in.finish();
  return columns;
}

std::vector<std::pair<std::string, std::string>> ply_xyz_names(const std::filesystem::path& path,
                                                               const PlyHeader& header) {
  std::vector<std::pair<std::string, std::string>> names;
  for (const char* axis : {"x", "y", "z"}) {
    const PlyProperty* p = find_ply_property(header, "vertex", axis);
    if (p == nullptr || p->count_size > 0) {
      throw Error(path.string() + ": the PLY vertices have no scalar x, y and z properties");
    }
    names.emplace_back("vertex", axis);
  }
  return names;
}

std::vector<Vec3> ply_points(const std::vector<PlyColumn>& columns) {
  std::vector<Vec3> points(columns.at(0).values.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = {columns[0].values[i], columns[1].values[i], columns[2].values[i]};
  }
  return points;
}

}  // namespace graspecmf::geometry
