#include "graspecmf/core/random.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "graspecmf/core/error.hpp"

namespace graspecmf {

double Rng::uniform() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double Rng::normal() {
  if (has_spare_normal_) {
    has_spare_normal_ = false;
    return spare_normal_;
  }
  const double u1 = 1.0 - uniform();  // (0, 1]: log stays finite
  const double u2 = uniform();
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * M_PI * u2;
  spare_normal_ = radius * std::sin(angle);
  has_spare_normal_ = true;
  return radius * std::cos(angle);
}

std::size_t Rng::index(std::size_t n) {
  const std::uint64_t bound = static_cast<std::uint64_t>(n);
  // Reject the top partial block so every residue is equally likely.
  const std::uint64_t limit =
      std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % bound;
  std::uint64_t x = engine_();
  while (x >= limit) x = engine_();
  return static_cast<std::size_t>(x % bound);
}

std::string Rng::state() const {
  std::ostringstream out;
  out << engine_ << ' ' << has_spare_normal_ << ' ';
  out.precision(17);
  out << std::hexfloat << spare_normal_;
  return out.str();
}

void Rng::restore(const std::string& text) {
  std::istringstream in(text);
  std::mt19937_64 engine;
  bool has_spare = false;
  double spare = 0.0;
  in >> engine >> has_spare;
  // Hex floats are read through strtod, as istream's hexfloat input is not portable.
  std::string spare_text;
  in >> spare_text;
  char* end = nullptr;
  spare = std::strtod(spare_text.c_str(), &end);
  if (!in || end == spare_text.c_str() || *end != '\0')
    throw Error("invalid random generator state");
  engine_ = engine;
  has_spare_normal_ = has_spare;
  spare_normal_ = spare;
}

}  // namespace graspecmf
