// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A label map as the file readers give it (Label_map_file.h): its voxels as 64-bit integers in
// C order (labels[(i * J + j) * K + k] for voxel (i, j, k), as label_surface_nets() takes them)
// and the map from voxel indices to world coordinates; and the reading of the voxels that the
// readers share: the stored type, its byte order, x or z fastest, each voxel a whole number.

#ifndef CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_H
#define CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_H

#include "front_end/Zlib_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace Constrained_fairing_front_end {

struct Label_map
{
  std::array<std::size_t, 3> size{0, 0, 0};
  std::vector<std::int64_t> labels;
  // world = affine[r] . (i, j, k, 1) for rows r = 0, 1, 2
  std::array<std::array<double, 4>, 3> affine{};
};

// How a file stores its voxels: 'u' unsigned, 'i' signed, 'f' floating point or 'b' bool (one
// byte, any non-zero byte true), of `bytes` bytes each.
struct Voxel_type
{
  char kind = 0;
  std::size_t bytes = 0;
  bool big_endian = false;
};

namespace internal {

inline bool host_is_big_endian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

// f(T()) for the C++ type T of `type`; false if a label map cannot have it.
template <typename F>
bool with_voxel_type(const Voxel_type& type, const F& f)
{
  const char kind = type.kind;
  const std::size_t n = type.bytes;
  if(kind == 'b' && n == 1)
    f(bool());
  else if(kind == 'u' && n == 1)
    f(std::uint8_t());
  else if(kind == 'u' && n == 2)
    f(std::uint16_t());
  else if(kind == 'u' && n == 4)
    f(std::uint32_t());
  else if(kind == 'u' && n == 8)
    f(std::uint64_t());
  else if(kind == 'i' && n == 1)
    f(std::int8_t());
  else if(kind == 'i' && n == 2)
    f(std::int16_t());
  else if(kind == 'i' && n == 4)
    f(std::int32_t());
  else if(kind == 'i' && n == 8)
    f(std::int64_t());
  else if(kind == 'f' && n == 4)
    f(float());
  else if(kind == 'f' && n == 8)
    f(double());
  else
    return false;
  return true;
}

enum class Voxel_status { WHOLE, FRACTION, OUT_OF_RANGE };

// One voxel of type T, scaled (NIfTI's slope and intercept).
template <typename T>
Voxel_status voxel_value(const unsigned char* p, bool swapped, double slope, double intercept, std::int64_t& value)
{
  if constexpr(std::is_same_v<T, bool>)
  {
    value = *p != 0;
    return Voxel_status::WHOLE;
  }
  else
  {
    unsigned char b[sizeof(T)];
    std::memcpy(b, p, sizeof(T));
    if(swapped)
      std::reverse(b, b + sizeof(T));
    T v;
    std::memcpy(&v, b, sizeof(T));
    if constexpr(std::is_integral_v<T>)
      if(slope == 1 && intercept == 0) // exact where a double is not
      {
        if constexpr(std::is_same_v<T, std::uint64_t>)
          if(v > std::uint64_t((std::numeric_limits<std::int64_t>::max)()))
            return Voxel_status::OUT_OF_RANGE;
        value = std::int64_t(v);
        return Voxel_status::WHOLE;
      }
    const double x = slope * double(v) + intercept;
    if(!std::isfinite(x) || x != std::round(x))
      return Voxel_status::FRACTION;
    // Beyond 2^53 a double holds no fractions: whole numbers there say nothing.
    if(std::abs(x) > 9e15)
      return Voxel_status::OUT_OF_RANGE;
    value = std::int64_t(x);
    return Voxel_status::WHOLE;
  }
}

// The voxels of type T in `bytes`, x fastest (i + I * (j + J * k)) or z fastest (C order), into
// `labels`; the index in `bytes` of the first voxel that is not a label, if any.
template <typename T>
Voxel_status decode_voxels(const std::vector<unsigned char>& bytes, const std::array<std::size_t, 3>& size,
                           bool x_fastest, bool swapped, double slope, double intercept,
                           std::vector<std::int64_t>& labels, std::size_t& bad)
{
  const std::size_t I = size[0], J = size[1], K = size[2], n = sizeof(T);
  std::size_t at = 0;
  for(std::size_t a = 0; a < (x_fastest ? K : I); ++a)
    for(std::size_t b = 0; b < J; ++b)
      for(std::size_t c = 0; c < (x_fastest ? I : K); ++c, ++at)
      {
        std::int64_t& label = x_fastest ? labels[(c * J + b) * K + a] : labels[at];
        const Voxel_status status = voxel_value<T>(bytes.data() + at * n, swapped, slope, intercept, label);
        if(status != Voxel_status::WHOLE)
        {
          bad = at;
          return status;
        }
      }
  return Voxel_status::WHOLE;
}

} // namespace internal

inline std::string size_text(const std::array<std::size_t, 3>& size)
{
  return std::to_string(size[0]) + " x " + std::to_string(size[1]) + " x " + std::to_string(size[2]);
}

// The voxels of `map.size`, of a type with_voxel_type() takes, from the rest of `file` into
// `map.labels`, x fastest or z fastest (C order); returns the reason it cannot, or an empty string.
inline std::string read_voxels(Zlib_file& file, const Voxel_type& type, bool x_fastest, double slope,
                               double intercept, const std::string& path, Label_map& map)
{
  const std::array<std::size_t, 3>& size = map.size;
  if(std::any_of(size.begin(), size.end(), [](std::size_t n) { return n == 0; }))
    return path + ": an image dimension is not positive (" + size_text(size) + ")";
  const std::size_t most = (std::numeric_limits<std::size_t>::max)() / 8;
  if(size[1] > most / size[0] || size[2] > most / (size[0] * size[1]))
    return path + ": " + size_text(size) + " voxels announced, more than any memory holds";
  const std::size_t count = size[0] * size[1] * size[2];
  std::vector<unsigned char> bytes;
  if(!file.read(count * type.bytes, bytes))
    return path + ": truncated (" + size_text(size) + " voxels announced)";
  map.labels.assign(count, 0);
  const bool swapped = type.bytes > 1 && type.big_endian != internal::host_is_big_endian();
  internal::Voxel_status status = internal::Voxel_status::WHOLE;
  std::size_t bad = 0;
  internal::with_voxel_type(type, [&](auto zero) {
    status = internal::decode_voxels<decltype(zero)>(bytes, size, x_fastest, swapped, slope, intercept, map.labels, bad);
  });
  if(status == internal::Voxel_status::WHOLE)
    return {};
  const std::size_t fast = x_fastest ? 0 : 2, slow = 2 - fast;
  std::array<std::size_t, 3> voxel;
  voxel[fast] = bad % size[fast];
  voxel[1] = bad / size[fast] % size[1];
  voxel[slow] = bad / (size[fast] * size[1]);
  return path + ": voxel (" + std::to_string(voxel[0]) + ", " + std::to_string(voxel[1]) + ", " +
         std::to_string(voxel[2]) + ") is " +
         (status == internal::Voxel_status::FRACTION ? "not a whole number: not a label map"
                                                     : "beyond the labels' range (64-bit integers, 9e15 as a float)");
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_H
