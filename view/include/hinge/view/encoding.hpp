// hinge/view/encoding.hpp: how the page carries its frames compactly. Positions: 16 bits per coordinate,
// quantized on the bounding box of all frames; per-hinge values: 8 bits on one scale for all frames; both as
// base64 (RFC 4648) of little-endian bytes, which the page decodes into typed arrays.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hinge::view {

using Vec3 = std::array<double, 3>;

// The axis-aligned box that holds every position given.
struct Box {
  Vec3 min{}, max{};
};
Box bounding_box(std::span<const std::vector<Vec3>> frames);

// Coordinate c of a position as the nearest of 65536 levels from box.min[c] to box.max[c]:
// q = round((x - min) / (max - min) * 65535), 0 where max == min. Decoded: min + q (max - min) / 65535, within
// half a level, (max - min) / 131070, of x (plus the rounding of that expression).
constexpr int position_levels = 65536;
std::vector<std::uint16_t> quantize_positions(std::span<const Vec3> vertices, const Box& box);
Vec3 dequantize_position(const std::uint16_t* q, const Box& box);

// A value in [0, scale] as the nearest of the levels 0 .. 254 (value / scale * 254, rounded; clamped to 254);
// NaN as 255, drawn as "no value". Decoded: level * scale / 254.
constexpr std::uint8_t value_levels = 255, no_value = 255;
std::vector<std::uint8_t> quantize_values(std::span<const double> values, double scale);

// Base64 (RFC 4648, with padding) of `bytes`; the 16-bit levels as their little-endian bytes.
std::string base64(std::span<const std::uint8_t> bytes);
std::string base64(std::span<const std::uint16_t> levels);
std::string base64(std::span<const std::int32_t> values);

}  // namespace hinge::view
