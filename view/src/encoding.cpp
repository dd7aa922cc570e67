// The page's compact encoding of frames and values (hinge/view/encoding.hpp).
#include "hinge/view/encoding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hinge::view {

Box bounding_box(std::span<const std::vector<Vec3>> frames) {
  Box b;
  b.min.fill(std::numeric_limits<double>::infinity());
  b.max.fill(-std::numeric_limits<double>::infinity());
  for (const auto& frame : frames)
    for (const Vec3& p : frame)
      for (std::size_t c = 0; c < 3; ++c) {
        b.min[c] = std::min(b.min[c], p[c]);
        b.max[c] = std::max(b.max[c], p[c]);
      }
  return b;
}

std::vector<std::uint16_t> quantize_positions(std::span<const Vec3> vertices, const Box& box) {
  std::vector<std::uint16_t> q(3 * vertices.size());
  constexpr double top = position_levels - 1;
  for (std::size_t v = 0; v < vertices.size(); ++v)
    for (std::size_t c = 0; c < 3; ++c) {
      const double extent = box.max[c] - box.min[c];
      const double level = extent > 0 ? std::round((vertices[v][c] - box.min[c]) / extent * top) : 0.0;
      q[3 * v + c] = static_cast<std::uint16_t>(std::clamp(level, 0.0, top));
    }
  return q;
}

Vec3 dequantize_position(const std::uint16_t* q, const Box& box) {
  constexpr double top = position_levels - 1;
  Vec3 p{};
  for (std::size_t c = 0; c < 3; ++c) p[c] = box.min[c] + q[c] * ((box.max[c] - box.min[c]) / top);
  return p;
}

std::vector<std::uint8_t> quantize_values(std::span<const double> values, double scale) {
  std::vector<std::uint8_t> q(values.size());
  constexpr double top = value_levels - 1;
  for (std::size_t i = 0; i < values.size(); ++i)
    q[i] = std::isnan(values[i]) ? no_value
                                 : static_cast<std::uint8_t>(std::clamp(std::round(values[i] / scale * top), 0.0, top));
  return q;
}

std::string base64(std::span<const std::uint8_t> bytes) {
  static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const unsigned word = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    for (int shift = 18; shift >= 0; shift -= 6) out += digits[(word >> shift) & 63];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    const unsigned word = (bytes[i] << 16) | (rest == 2 ? bytes[i + 1] << 8 : 0);
    out += digits[(word >> 18) & 63];
    out += digits[(word >> 12) & 63];
    out += rest == 2 ? digits[(word >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

namespace {

template <class Int>
std::string base64_little_endian(std::span<const Int> values) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(sizeof(Int) * values.size());
  for (const Int value : values) {
    const auto u = static_cast<std::make_unsigned_t<Int>>(value);
    for (std::size_t b = 0; b < sizeof(Int); ++b) bytes.push_back(static_cast<std::uint8_t>(u >> (8 * b)));
  }
  return base64(bytes);
}

}  // namespace

std::string base64(std::span<const std::uint16_t> levels) { return base64_little_endian(levels); }
std::string base64(std::span<const std::int32_t> values) { return base64_little_endian(values); }

}  // namespace hinge::view
