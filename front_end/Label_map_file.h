// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A label map from a NIfTI-1 file (.nii, or .nii.gz through zlib, which also reads an
// uncompressed file): its voxels as 64-bit integers in C order (labels[(i * J + j) * K + k] for
// voxel (i, j, k), as label_surface_nets() takes them; the file stores i fastest) and the map
// from voxel indices to world coordinates. The map is the one the Python package's
// read_label_map() gives: the sform if its code is set, else the qform if its code is set, else
// the voxel sizes alone (the standard's method 1). Every defect is a reason, never a crash: a
// file that is not NIfTI-1, a .hdr/.img pair, an image that is not 3-D (or 4-D of one volume),
// an unsupported data type, a truncated file, or voxels that are not whole numbers.

#ifndef CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_FILE_H

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
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

inline bool is_label_map_file(const std::string& path)
{
  const auto ends_with = [&path](const char* suffix) {
    const std::size_t n = std::strlen(suffix);
    if(path.size() <= n)
      return false;
    for(std::size_t c = 0; c < n; ++c)
      if(std::tolower(static_cast<unsigned char>(path[path.size() - n + c])) != suffix[c])
        return false;
    return true;
  };
  return ends_with(".nii") || ends_with(".nii.gz");
}

namespace internal {

// The bytes of a NIfTI-1 header field, in the file's byte order.
class Nifti_header
{
public:
  explicit Nifti_header(const unsigned char* bytes) : m_bytes(bytes)
  {
    std::int32_t size;
    std::memcpy(&size, bytes, 4);
    m_swapped = size != 348;
  }

  bool is_valid() const { return int32(0) == 348; }

  template <typename T>
  T get(std::size_t offset) const
  {
    unsigned char b[sizeof(T)];
    std::memcpy(b, m_bytes + offset, sizeof(T));
    if(m_swapped)
      std::reverse(b, b + sizeof(T));
    T value;
    std::memcpy(&value, b, sizeof(T));
    return value;
  }
  std::int32_t int32(std::size_t offset) const { return get<std::int32_t>(offset); }
  std::int16_t int16(std::size_t offset) const { return get<std::int16_t>(offset); }
  double float32(std::size_t offset) const { return double(get<float>(offset)); }
  bool swapped() const { return m_swapped; }

private:
  const unsigned char* m_bytes;
  bool m_swapped;
};

// f(T()) for the C++ type T of NIfTI data type `code`; false if a label map cannot have it.
template <typename F>
bool with_voxel_type(int code, const F& f)
{
  switch(code)
  {
  case 2: f(std::uint8_t()); return true;
  case 4: f(std::int16_t()); return true;
  case 8: f(std::int32_t()); return true;
  case 16: f(float()); return true;
  case 64: f(double()); return true;
  case 256: f(std::int8_t()); return true;
  case 512: f(std::uint16_t()); return true;
  case 768: f(std::uint32_t()); return true;
  case 1024: f(std::int64_t()); return true;
  case 1280: f(std::uint64_t()); return true;
  default: return false;
  }
}

// One voxel of type T, scaled; false if it is not a whole number.
template <typename T>
bool voxel_value(const unsigned char* p, bool swapped, double slope, double intercept, std::int64_t& value)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if(swapped)
    std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  double x = double(v);
  if constexpr(std::is_integral_v<T> && sizeof(T) == 8)
  {
    // Exact where a double is not.
    if(slope == 1 && intercept == 0)
    {
      value = std::int64_t(v);
      return true;
    }
    x = double(std::int64_t(v));
  }
  x = slope * x + intercept;
  if(!std::isfinite(x) || x != std::round(x) || std::abs(x) > 9e15)
    return false;
  value = std::int64_t(x);
  return true;
}

// Slab k of an I x J x K map, voxels of type T in x-fastest order, into `labels` (z fastest);
// the first voxel (i, j) that is not a whole number, if any.
template <typename T>
bool read_slab(const unsigned char* slab, const std::array<std::size_t, 3>& size, std::size_t k, bool swapped,
               double slope, double intercept, std::vector<std::int64_t>& labels, std::array<std::size_t, 2>& bad)
{
  const std::size_t I = size[0], J = size[1], K = size[2];
  for(std::size_t j = 0; j < J; ++j)
    for(std::size_t i = 0; i < I; ++i)
      if(!voxel_value<T>(slab + (j * I + i) * sizeof(T), swapped, slope, intercept, labels[(i * J + j) * K + k]))
      {
        bad = {i, j};
        return false;
      }
  return true;
}

} // namespace internal

// Reads `path` into `map`; returns the reason it cannot, or an empty string.
inline std::string read_label_map(const std::string& path, Label_map& map)
{
  std::unique_ptr<gzFile_s, int (*)(gzFile)> file(gzopen(path.c_str(), "rb"), &gzclose);
  if(!file)
    return "cannot open " + path;
  const auto read = [&](void* into, std::size_t n) {
    return gzread(file.get(), into, static_cast<unsigned>(n)) == static_cast<int>(n);
  };
  unsigned char bytes[352];
  if(!read(bytes, 348))
    return path + ": not a NIfTI-1 file (too short for its header)";
  const internal::Nifti_header header(bytes);
  if(!header.is_valid())
    return path + ": not a NIfTI-1 file (its header does not start with 348)";
  if(std::memcmp(bytes + 344, "n+1", 4) != 0)
    return path + (std::memcmp(bytes + 344, "ni1", 4) == 0
                     ? ": a NIfTI-1 header without its image (.hdr/.img pair); convert it to a single .nii"
                     : ": not a single-file NIfTI-1 image (magic \"n+1\")");
  const int dims = header.int16(40);
  std::array<std::int64_t, 7> dim{};
  for(int d = 0; d < 7; ++d)
    dim[std::size_t(d)] = d < dims ? header.int16(42 + 2 * std::size_t(d)) : 1;
  if(dims < 3 || dims > 7 || std::any_of(dim.begin() + 3, dim.end(), [](std::int64_t n) { return n != 1; }))
    return path + ": a label map must be a 3-D image (dim[0] = " + std::to_string(dims) + ")";
  if(std::any_of(dim.begin(), dim.begin() + 3, [](std::int64_t n) { return n < 1; }))
    return path + ": an image dimension is not positive";
  const int code = header.int16(70);
  std::size_t bytes_per_voxel = 0;
  if(!internal::with_voxel_type(code, [&](auto zero) { bytes_per_voxel = sizeof(zero); }))
    return path + ": unsupported NIfTI data type " + std::to_string(code) + " for a label map";
  double slope = header.float32(112), intercept = header.float32(116);
  if(slope == 0 || !std::isfinite(slope))
    slope = 1, intercept = 0;
  const double offset = header.float32(108);
  if(!(offset >= 348))
    return path + ": invalid vox_offset";
  // Skip the extensions up to the data.
  std::vector<unsigned char> skip(std::size_t(offset) - 348);
  if(!skip.empty() && !read(skip.data(), skip.size()))
    return path + ": truncated before its data";

  const std::size_t I = std::size_t(dim[0]), J = std::size_t(dim[1]), K = std::size_t(dim[2]);
  map.size = {I, J, K};
  map.labels.assign(I * J * K, 0);
  std::vector<unsigned char> slab(I * J * bytes_per_voxel);
  for(std::size_t k = 0; k < K; ++k)
  {
    if(!read(slab.data(), slab.size()))
      return path + ": truncated (" + std::to_string(I) + " x " + std::to_string(J) + " x " + std::to_string(K) +
             " voxels announced)";
    std::array<std::size_t, 2> bad{0, 0};
    bool whole = true;
    internal::with_voxel_type(code, [&](auto zero) {
      whole = internal::read_slab<decltype(zero)>(slab.data(), map.size, k, header.swapped(), slope, intercept,
                                                  map.labels, bad);
    });
    if(!whole)
      return path + ": voxel (" + std::to_string(bad[0]) + ", " + std::to_string(bad[1]) + ", " + std::to_string(k) +
             ") is not a whole number: not a label map";
  }

  const double pixdim[4] = {header.float32(76), header.float32(80), header.float32(84), header.float32(88)};
  if(header.int16(254) > 0)
  {
    for(std::size_t r = 0; r < 3; ++r)
      for(std::size_t c = 0; c < 4; ++c)
        map.affine[r][c] = header.float32(280 + 16 * r + 4 * c);
  }
  else if(header.int16(252) > 0)
  {
    // The qform: a rotation from the quaternion (b, c, d), qfac = pixdim[0] mirroring k.
    const double b = header.float32(256), c = header.float32(260), d = header.float32(264);
    const double a = std::sqrt((std::max)(0., 1 - (b * b + c * c + d * d)));
    const double R[3][3] = {{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
                            {2 * (b * c + a * d), a * a + c * c - b * b - d * d, 2 * (c * d - a * b)},
                            {2 * (b * d - a * c), 2 * (c * d + a * b), a * a + d * d - b * b - c * c}};
    const double scale[3] = {pixdim[1], pixdim[2], (pixdim[0] < 0 ? -1 : 1) * pixdim[3]};
    for(std::size_t r = 0; r < 3; ++r)
    {
      for(std::size_t col = 0; col < 3; ++col)
        map.affine[r][col] = R[r][col] * scale[col];
      map.affine[r][3] = header.float32(268 + 4 * r);
    }
  }
  else
  {
    for(std::size_t r = 0; r < 3; ++r)
    {
      map.affine[r] = {0, 0, 0, 0};
      map.affine[r][r] = pixdim[r + 1];
    }
  }
  return {};
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_FILE_H
