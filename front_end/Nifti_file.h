// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A label map from a NIfTI-1 file (.nii, or .nii.gz; the file stores i fastest). The affine is
// the one the Python package's read_label_map() gives through nibabel: the sform if its code is
// set, else the qform if its code is set, else the voxel sizes alone (the standard's method 1).
// Every defect is a reason, never a crash: a file that is not NIfTI-1, a .hdr/.img pair, an
// image that is not 3-D (or 4-D of one volume), an unsupported data type, a truncated file, or
// voxels that are not whole numbers.

#ifndef CONSTRAINED_FAIRING_FRONT_END_NIFTI_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_NIFTI_FILE_H

#include "front_end/Label_map.h"
#include "front_end/Zlib_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace Constrained_fairing_front_end {
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

// The voxel type of NIfTI data type `code`, kind 0 if a label map cannot have it.
inline Voxel_type nifti_voxel_type(int code, bool swapped)
{
  const bool big_endian = swapped != host_is_big_endian();
  switch(code)
  {
  case 2: return {'u', 1, big_endian};
  case 4: return {'i', 2, big_endian};
  case 8: return {'i', 4, big_endian};
  case 16: return {'f', 4, big_endian};
  case 64: return {'f', 8, big_endian};
  case 256: return {'i', 1, big_endian};
  case 512: return {'u', 2, big_endian};
  case 768: return {'u', 4, big_endian};
  case 1024: return {'i', 8, big_endian};
  case 1280: return {'u', 8, big_endian};
  default: return {};
  }
}

// The sform if its code is set, else the qform if its code is set, else the voxel sizes.
inline std::array<std::array<double, 4>, 3> nifti_affine(const Nifti_header& header)
{
  std::array<std::array<double, 4>, 3> affine{};
  const double pixdim[4] = {header.float32(76), header.float32(80), header.float32(84), header.float32(88)};
  if(header.int16(254) > 0)
  {
    for(std::size_t r = 0; r < 3; ++r)
      for(std::size_t c = 0; c < 4; ++c)
        affine[r][c] = header.float32(280 + 16 * r + 4 * c);
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
        affine[r][col] = R[r][col] * scale[col];
      affine[r][3] = header.float32(268 + 4 * r);
    }
  }
  else
  {
    for(std::size_t r = 0; r < 3; ++r)
      affine[r][r] = pixdim[r + 1];
  }
  return affine;
}

} // namespace internal

// Reads the NIfTI-1 file `path` into `map`; returns the reason it cannot, or an empty string.
inline std::string read_nifti_file(const std::string& path, Label_map& map)
{
  Zlib_file file(path);
  if(!file.is_open())
    return "cannot open " + path;
  unsigned char bytes[348];
  if(!file.read(bytes, 348))
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
  const Voxel_type type = internal::nifti_voxel_type(code, header.swapped());
  if(type.kind == 0)
    return path + ": unsupported NIfTI data type " + std::to_string(code) + " for a label map";
  double slope = header.float32(112), intercept = header.float32(116);
  if(slope == 0 || !std::isfinite(slope))
    slope = 1, intercept = 0;
  const double offset = header.float32(108);
  if(!(offset >= 348 && offset < 9e15))
    return path + ": invalid vox_offset";
  // Past the extensions, to the data.
  if(!file.skip(std::size_t(offset) - 348))
    return path + ": truncated before its data";
  map.size = {std::size_t(dim[0]), std::size_t(dim[1]), std::size_t(dim[2])};
  map.affine = internal::nifti_affine(header);
  return read_voxels(file, type, true, slope, intercept, path, map);
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_NIFTI_FILE_H
