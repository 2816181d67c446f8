// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A label map from an INRIMAGE-4 file (.inr, or .inr.gz), the images CGAL's ImageIO and Mesh_3
// read and write. The header is text: the line `#INRIMAGE-4#{`, lines KEY=VALUE, comment lines
// starting with '#', newlines to pad it, the line `##}`; the voxels follow, x fastest. Of the
// keys, XDIM YDIM ZDIM (required), VDIM (1), TYPE and PIXSIZE (required), CPU (the byte order,
// required beyond 8 bits), VX VY VZ (the voxel sizes, 1 by default) and TX TY TZ (the world
// position of voxel (0, 0, 0), 0 by default) are read, up to the first comment or blank line as
// CGAL's ImageIO reads them; the affine is diag(VX, VY, VZ) plus that origin, where CGAL's
// Image_3 puts the voxels. As in CGAL, SCALE, the integers XO YO ZO and the rotation RX RY RZ
// place no voxel and are not read. Every defect is a reason naming it.

#ifndef CONSTRAINED_FAIRING_FRONT_END_INR_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_INR_FILE_H

#include "front_end/Label_map.h"
#include "front_end/Zlib_file.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <locale>
#include <sstream>
#include <string>

namespace Constrained_fairing_front_end {
namespace internal {

struct Inr_header
{
  std::array<std::size_t, 3> size{0, 0, 0}; // 0 where not given
  std::size_t values_per_voxel = 1;         // VDIM
  std::string type;                         // TYPE, empty where not given
  std::size_t bits = 0;                     // PIXSIZE, 0 where not given
  std::string cpu;                          // CPU, empty where not given
  std::array<double, 3> voxel_size{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0};
};

inline std::string trimmed(const std::string& text)
{
  std::size_t first = 0, last = text.size();
  while(first < last && std::isspace(static_cast<unsigned char>(text[first])))
    ++first;
  while(last > first && std::isspace(static_cast<unsigned char>(text[last - 1])))
    --last;
  return text.substr(first, last - first);
}

// A positive whole number written in decimal digits (leading zeros allowed, as in "XDIM=002").
inline bool parse_count(const std::string& text, std::size_t& n)
{
  if(text.empty() || text.size() > 15)
    return false;
  n = 0;
  for(char c : text)
  {
    if(!std::isdigit(static_cast<unsigned char>(c)))
      return false;
    n = 10 * n + std::size_t(c - '0');
  }
  return n > 0;
}

// A finite number, read in the C locale whatever the program's.
inline bool parse_number(const std::string& text, double& x)
{
  std::istringstream stream(text);
  stream.imbue(std::locale::classic());
  stream >> x;
  return !text.empty() && stream && stream.peek() == std::char_traits<char>::eof() && std::isfinite(x);
}

// PIXSIZE's value, "N bits".
inline bool parse_bits(const std::string& text, std::size_t& bits)
{
  const std::size_t end = text.size() >= 4 ? text.size() - 4 : 0;
  return text.size() > 4 && text.compare(end, 4, "bits") == 0 && parse_count(trimmed(text.substr(0, end)), bits);
}

// The field KEY=VALUE of a header line; returns its defect, or an empty string.
inline std::string read_inr_field(const std::string& key, const std::string& text, Inr_header& header)
{
  const std::string value = trimmed(text);
  const std::string field = key + "=" + value;
  const std::string axes = "XYZ";
  const std::size_t axis = key.size() > 0 ? axes.find(key[0]) : std::string::npos;
  if(axis != std::string::npos && key.compare(1, std::string::npos, "DIM") == 0)
    return parse_count(value, header.size[axis]) ? "" : field + " is not a positive whole number";
  if(key == "VDIM")
    return parse_count(value, header.values_per_voxel) ? "" : field + " is not a positive whole number";
  if(key.size() == 2 && key[0] == 'V' && axes.find(key[1]) != std::string::npos)
  {
    double& size = header.voxel_size[axes.find(key[1])];
    return parse_number(value, size) && size > 0 ? "" : field + " is not a positive voxel size";
  }
  if(key.size() == 2 && key[0] == 'T' && axes.find(key[1]) != std::string::npos)
    return parse_number(value, header.origin[axes.find(key[1])]) ? "" : field + " is not a finite number";
  if(key == "PIXSIZE")
    return parse_bits(value, header.bits) ? "" : field + " is not a size in bits (PIXSIZE=8 bits)";
  if(key == "TYPE")
    header.type = value;
  else if(key == "CPU")
    header.cpu = value;
  return {};
}

// The header, from its first line to its last, `##}`; returns its defect, or an empty string.
inline std::string read_inr_header(Zlib_file& file, const std::string& path, Inr_header& header)
{
  std::string line;
  if(!file.read_line(line, 64) || line != "#INRIMAGE-4#{")
    return path + ": not an INRIMAGE-4 file (its first line is not #INRIMAGE-4#{)";
  // Headers are a few blocks of 256 bytes: a file without `##}` in its first MiB is no INR.
  const std::size_t limit = std::size_t(1) << 20;
  // CGAL's ImageIO reads the fields up to the first comment or blank line: a field below them
  // is refused rather than read where CGAL would not.
  bool in_fields = true;
  for(std::size_t read = line.size() + 1;; read += line.size() + 1)
  {
    if(read >= limit || !file.read_line(line, limit - read))
      return path + (read >= limit || line.size() == limit - read ? ": no end of header (##}) in its first MiB"
                                                                  : ": truncated header (no ##} line)");
    if(line.compare(0, 3, "##}") == 0)
      return {};
    if(line.empty() || line[0] == '#')
    {
      in_fields = false;
      continue;
    }
    const std::string quoted = "header line \"" + line.substr(0, 40) + "\"";
    if(!in_fields)
      return path + ": " + quoted + " follows its comments or padding, where CGAL's ImageIO reads no field";
    const std::size_t equals = line.find('=');
    if(equals == std::string::npos)
      return path + ": " + quoted + " is neither KEY=VALUE nor a comment";
    const std::string defect = read_inr_field(line.substr(0, equals), line.substr(equals + 1), header);
    if(!defect.empty())
      return path + ": " + defect;
  }
}

// The voxels' type as the header gives it; returns its defect, or an empty string.
inline std::string inr_voxel_type(const Inr_header& header, Voxel_type& type)
{
  if(header.type.empty() || header.bits == 0)
    return std::string("its header gives no ") + (header.type.empty() ? "TYPE" : "PIXSIZE");
  const std::string field = "TYPE=" + header.type + " with PIXSIZE=" + std::to_string(header.bits) + " bits";
  if(header.type == "unsigned fixed" || header.type == "signed fixed" || header.type == "float")
    type.kind = header.type[0] == 'u' ? 'u' : header.type[0] == 's' ? 'i' : 'f';
  else
    return "unknown TYPE=" + header.type + " (unsigned fixed, signed fixed or float)";
  type.bytes = header.bits / 8;
  if(header.bits % 8 != 0 || !with_voxel_type(type, [](auto) {}))
    return field + ": not a type of voxels (8, 16, 32 or 64 bits, floats of 32 or 64)";
  const std::string& cpu = header.cpu;
  if(cpu == "decm" || cpu == "alpha" || cpu == "pc" || cpu == "sun" || cpu == "sgi")
    type.big_endian = cpu == "sun" || cpu == "sgi";
  else if(!cpu.empty())
    return "unknown CPU=" + cpu + " (decm, alpha, pc: little endian; sun, sgi: big endian)";
  else if(type.bytes > 1)
    return "its header gives no CPU, the byte order of its " + std::to_string(header.bits) + "-bit voxels";
  return {};
}

} // namespace internal

// Reads the INRIMAGE-4 file `path` into `map`; returns the reason it cannot, or an empty string.
inline std::string read_inr_file(const std::string& path, Label_map& map)
{
  Zlib_file file(path);
  if(!file.is_open())
    return "cannot open " + path;
  internal::Inr_header header;
  const std::string header_defect = internal::read_inr_header(file, path, header);
  if(!header_defect.empty())
    return header_defect;
  for(std::size_t axis = 0; axis < 3; ++axis)
    if(header.size[axis] == 0)
      return path + ": its header gives no " + "XYZ"[axis] + "DIM";
  if(header.values_per_voxel != 1)
    return path + ": VDIM=" + std::to_string(header.values_per_voxel) +
           ": a label map has one value per voxel (VDIM=1)";
  Voxel_type type;
  const std::string type_defect = internal::inr_voxel_type(header, type);
  if(!type_defect.empty())
    return path + ": " + type_defect;
  map.size = header.size;
  map.affine = {};
  for(std::size_t r = 0; r < 3; ++r)
  {
    map.affine[r][r] = header.voxel_size[r];
    map.affine[r][3] = header.origin[r];
  }
  return read_voxels(file, type, true, 1, 0, path, map);
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_INR_FILE_H
