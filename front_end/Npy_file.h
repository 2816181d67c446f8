// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A label map from numpy's .npy file (format 1.0, 2.0 or 3.0): the magic "\x93NUMPY", the
// version, the header's length, and the header, a Python dict of 'descr' (the dtype),
// 'fortran_order' and 'shape', then the array. A label map's dtype is bool, an integer or a
// float holding whole numbers, either byte order; its shape 3-D, or 4-D of one volume, as the
// Python package's read_label_map() takes it; its affine the identity, as there (voxel
// (i, j, k) at (i, j, k)). Every defect is a reason naming it.

#ifndef CONSTRAINED_FAIRING_FRONT_END_NPY_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_NPY_FILE_H

#include "front_end/Label_map.h"
#include "front_end/Zlib_file.h"

#include <cctype>
#include <cstddef>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace Constrained_fairing_front_end {
namespace internal {

// A value of the header's dict: a string, True or False, or a tuple of whole numbers.
struct Npy_value
{
  char kind = 0; // 's', 'b' or 't'
  std::string text;
  bool flag = false;
  std::vector<std::size_t> numbers;
};

// The header's dict, the Python literal numpy writes; each defect a reason.
class Npy_header_parser
{
public:
  explicit Npy_header_parser(const std::string& text) : m_text(text) {}

  // The dict's entries; returns its defect, or an empty string.
  std::string parse(std::map<std::string, Npy_value>& entries)
  {
    const std::string defect = "its header does not read as a dict of 'key': value";
    if(!take('{'))
      return defect;
    for(;;)
    {
      if(take('}'))
        break;
      Npy_value key, value;
      if(!parse_value(key) || key.kind != 's' || !take(':'))
        return defect;
      if(!parse_value(value))
        return "its header's '" + key.text + "' is not a string, True, False or a tuple of whole numbers";
      entries[key.text] = value;
      if(!take(',') && !take('}'))
        return defect;
      if(m_text[m_at - 1] == '}')
        break;
    }
    skip_spaces();
    return m_at == m_text.size() ? "" : "its header holds more than a dict";
  }

private:
  void skip_spaces()
  {
    while(m_at < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_at])))
      ++m_at;
  }

  bool take(char c)
  {
    skip_spaces();
    if(m_at == m_text.size() || m_text[m_at] != c)
      return false;
    ++m_at;
    return true;
  }

  bool take(const std::string& word)
  {
    skip_spaces();
    if(m_text.compare(m_at, word.size(), word) != 0)
      return false;
    m_at += word.size();
    return true;
  }

  bool parse_value(Npy_value& value)
  {
    if(take('\'') || take('"'))
    {
      const std::size_t end = m_text.find(m_text[m_at - 1], m_at);
      if(end == std::string::npos)
        return false;
      value.kind = 's';
      value.text = m_text.substr(m_at, end - m_at);
      m_at = end + 1;
      return true;
    }
    value.kind = 'b';
    value.flag = take(std::string("True"));
    if(value.flag || take(std::string("False")))
      return true;
    value.kind = 't';
    return take('(') && parse_numbers(value.numbers);
  }

  // A tuple's whole numbers, up to its ')'.
  bool parse_numbers(std::vector<std::size_t>& numbers)
  {
    for(;;)
    {
      if(take(')'))
        return true;
      skip_spaces();
      std::size_t n = 0, digits = 0;
      for(; m_at < m_text.size() && std::isdigit(static_cast<unsigned char>(m_text[m_at])); ++m_at, ++digits)
        n = 10 * n + std::size_t(m_text[m_at] - '0');
      if(digits == 0 || digits > 15)
        return false;
      numbers.push_back(n);
      if(!take(','))
        return take(')');
    }
  }

  const std::string& m_text;
  std::size_t m_at = 0;
};

// The voxel type of dtype `descr` ('<u2', '|b1', '>f8', ...), kind 0 if a label map cannot have it.
inline Voxel_type npy_voxel_type(const std::string& descr)
{
  Voxel_type type;
  if(descr.size() != 3 || std::string("<>|=").find(descr[0]) == std::string::npos ||
     std::string("biuf").find(descr[1]) == std::string::npos || !std::isdigit(static_cast<unsigned char>(descr[2])))
    return type;
  type = {descr[1], std::size_t(descr[2] - '0'),
          descr[0] == '>' || (descr[0] == '=' && host_is_big_endian())};
  if(!with_voxel_type(type, [](auto) {}) || (descr[0] == '|' && type.bytes > 1))
    type.kind = 0;
  return type;
}

// The header's dict; returns its defect, or an empty string.
inline std::string read_npy_header(Zlib_file& file, std::map<std::string, Npy_value>& entries)
{
  unsigned char start[8];
  if(!file.read(start, 8) || std::memcmp(start, "\x93NUMPY", 6) != 0)
    return "not a .npy file (it does not start with \\x93NUMPY)";
  if(start[6] < 1 || start[6] > 3)
    return "unsupported .npy format " + std::to_string(start[6]) + "." + std::to_string(start[7]) +
           " (1.0, 2.0 and 3.0 are read)";
  unsigned char length_bytes[4] = {0, 0, 0, 0};
  const std::size_t length_size = start[6] == 1 ? 2 : 4;
  if(!file.read(length_bytes, length_size))
    return "truncated header";
  std::size_t length = 0;
  for(std::size_t b = length_size; b-- > 0;)
    length = 256 * length + length_bytes[b];
  if(length > (std::size_t(1) << 20))
    return "a header of " + std::to_string(length) + " bytes: no .npy header is so long";
  std::string text(length, '\0');
  if(!file.read(&text[0], length))
    return "truncated header";
  const std::string defect = Npy_header_parser(text).parse(entries);
  if(!defect.empty())
    return defect;
  for(const auto& [key, kind] : {std::pair<const char*, char>{"descr", 's'}, {"fortran_order", 'b'}, {"shape", 't'}})
  {
    const auto entry = entries.find(key);
    if(entry == entries.end())
      return std::string("its header gives no '") + key + "'";
    if(entry->second.kind != kind)
      return std::string("its header's '") + key + "' is not " +
             (kind == 's' ? "a dtype string" : kind == 'b' ? "True or False" : "a tuple");
  }
  if(entries.size() != 3)
    return "its header has keys other than 'descr', 'fortran_order' and 'shape'";
  return {};
}

} // namespace internal

// Reads the .npy file `path` into `map`; returns the reason it cannot, or an empty string.
inline std::string read_npy_file(const std::string& path, Label_map& map)
{
  Zlib_file file(path);
  if(!file.is_open())
    return "cannot open " + path;
  std::map<std::string, internal::Npy_value> entries;
  const std::string defect = internal::read_npy_header(file, entries);
  if(!defect.empty())
    return path + ": " + defect;
  const std::string& descr = entries["descr"].text;
  const Voxel_type type = internal::npy_voxel_type(descr);
  if(type.kind == 0)
    return path + ": dtype '" + descr + "' is not a label map's (bool, integers, floats of 4 or 8 bytes)";
  const std::vector<std::size_t>& shape = entries["shape"].numbers;
  if(!(shape.size() == 3 || (shape.size() == 4 && shape[3] == 1)))
  {
    std::string text;
    for(std::size_t n : shape)
      text += (text.empty() ? "" : ", ") + std::to_string(n);
    return path + ": a label map must be 3-D (shape (" + text + (shape.size() == 1 ? ",))" : "))");
  }
  map.size = {shape[0], shape[1], shape[2]};
  map.affine = {};
  for(std::size_t r = 0; r < 3; ++r)
    map.affine[r][r] = 1;
  return read_voxels(file, type, entries["fortran_order"].flag, 1, 0, path, map);
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_NPY_FILE_H
