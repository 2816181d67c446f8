// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The PLY format as the front ends parse it, for a soup's vertex and face properties: CGAL reads
// a soup's positions and faces publicly (CGAL::IO::read_PLY()), but the parser that would give
// their other properties is CGAL's own detail, no interface, and differs between 5.5 and 6.x.
// This parser reads what CGAL 5.5's does, value for value: the header line by line (the first
// "ply", the second a format, then elements, properties, comments, other lines ignored, up to
// end_header or the file's end), ASCII values by the stream's operator>> (one-byte types through
// a short, so that they are read as numbers), binary ones as their bytes, swapped where the
// file's byte order is not the machine's. It refuses, as not a PLY file, the headers CGAL's
// parser would misread: a type it does not know, a property before any element.

#ifndef CONSTRAINED_FAIRING_FRONT_END_PLY_READER_H
#define CONSTRAINED_FAIRING_FRONT_END_PLY_READER_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace Constrained_fairing_front_end {

// f(T(), name) for the C++ type T of the PLY type `type` (either spelling, "uchar" or
// "uint8"), with the name CGAL's writer gives it; false for another type.
template <typename F>
bool with_ply_type(const std::string& type, const F& f)
{
  if(type == "char" || type == "int8")
    f(std::int8_t(), "char");
  else if(type == "uchar" || type == "uint8")
    f(std::uint8_t(), "uchar");
  else if(type == "short" || type == "int16")
    f(std::int16_t(), "short");
  else if(type == "ushort" || type == "uint16")
    f(std::uint16_t(), "ushort");
  else if(type == "int" || type == "int32")
    f(std::int32_t(), "int");
  else if(type == "uint" || type == "uint32")
    f(std::uint32_t(), "uint");
  else if(type == "float" || type == "float32")
    f(float(), "float");
  else if(type == "double" || type == "float64")
    f(double(), "double");
  else
    return false;
  return true;
}

enum class Ply_format
{
  ASCII,
  BINARY_LITTLE_ENDIAN,
  BINARY_BIG_ENDIAN
};

namespace internal {

inline bool host_is_little_endian()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// A value of type T as CGAL's parser reads it; on a failure the stream fails.
template <typename T>
double read_ply_number(std::istream& stream, Ply_format format)
{
  T value = T();
  if(format == Ply_format::ASCII)
  {
    // A one-byte type is read as a number, not a character.
    using Read = std::conditional_t<sizeof(T) == 1, std::conditional_t<std::is_signed_v<T>, short, unsigned short>, T>;
    Read read = Read();
    if(stream >> read)
      value = static_cast<T>(read);
    else
      stream.clear(std::ios::badbit);
    return double(value);
  }
  char bytes[sizeof(T)];
  stream.read(bytes, sizeof(T));
  if((format == Ply_format::BINARY_BIG_ENDIAN) == host_is_little_endian())
    std::reverse(bytes, bytes + sizeof(T));
  std::memcpy(&value, bytes, sizeof(T));
  return double(value);
}

} // namespace internal

// A property of an element: a scalar, or a list of scalars after its size.
struct Ply_property_layout
{
  std::string name;
  std::string type; // the scalar's or the list items' type, as CGAL writes it (char, uchar, ...)
  bool is_list = false;
  double (*read_size)(std::istream&, Ply_format) = nullptr; // a list's
  double (*read_value)(std::istream&, Ply_format) = nullptr;
};

struct Ply_element_layout
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property_layout> properties;

  static constexpr std::size_t none = std::size_t(-1);

  // The first property called `name`, the one CGAL's parser finds, or `none`.
  std::size_t index_of(const std::string& property) const
  {
    for(std::size_t k = 0; k < properties.size(); ++k)
      if(properties[k].name == property)
        return k;
    return none;
  }
};

struct Ply_header
{
  Ply_format format = Ply_format::ASCII;
  std::vector<Ply_element_layout> elements;
  std::string comments; // the text of each comment line, ended by a newline
};

namespace internal {

// A property line's words after "property"; false for a type CGAL's parser does not know or a
// property before any element.
inline bool read_ply_property(std::istringstream& words, Ply_header& header)
{
  std::string type, name, item_type;
  if(!(words >> type >> name) || header.elements.empty())
    return false;
  Ply_property_layout property;
  if(type == "list")
  {
    property.is_list = true;
    const std::string size_type = name;
    if(!(words >> item_type >> name) || size_type == "float" || size_type == "float32" || size_type == "double" ||
       size_type == "float64" ||
       !with_ply_type(size_type, [&](auto zero, const char*) { property.read_size = &read_ply_number<decltype(zero)>; }))
      return false;
    type = item_type;
  }
  property.name = name;
  header.elements.back().properties.push_back(property);
  return with_ply_type(type, [&](auto zero, const char* spelled) {
    header.elements.back().properties.back().type = spelled;
    header.elements.back().properties.back().read_value = &read_ply_number<decltype(zero)>;
  });
}

// The second line's format.
inline bool read_ply_format(std::istringstream& words, Ply_format& format)
{
  std::string tag, name, version;
  if(!(words >> tag >> name >> version))
    return false;
  if(name == "ascii")
    format = Ply_format::ASCII;
  else if(name == "binary_little_endian")
    format = Ply_format::BINARY_LITTLE_ENDIAN;
  else if(name == "binary_big_endian")
    format = Ply_format::BINARY_BIG_ENDIAN;
  else
    return false;
  return true;
}

} // namespace internal

// Reads the header of a PLY file from `stream`, which is left at the first item; false if it is
// not one.
inline bool read_ply_header(std::istream& stream, Ply_header& header)
{
  std::string line;
  for(std::size_t number = 1; std::getline(stream, line); ++number)
  {
    std::istringstream words(line);
    std::string keyword;
    if(number == 1)
    {
      if(!(words >> keyword) || keyword != "ply")
        return false;
      continue;
    }
    if(number == 2)
    {
      if(!internal::read_ply_format(words, header.format))
        return false;
      continue;
    }
    if(!(words >> keyword))
      return false;
    if(keyword == "property" && !internal::read_ply_property(words, header))
      return false;
    if(keyword == "comment" && line.size() > 8)
      header.comments += line.substr(8) + "\n";
    if(keyword == "element")
    {
      header.elements.emplace_back();
      if(!(words >> header.elements.back().name >> header.elements.back().count))
        return false;
    }
    if(keyword == "end_header")
      break;
  }
  return true;
}

// An item of an element as read: each property's values, one for a scalar, the items of a list;
// a double holds each PLY type exactly.
struct Ply_item
{
  std::vector<std::vector<double> > values;
};

// Reads the next item of `element` into `item`; false if the stream ends before it does.
inline bool read_ply_item(std::istream& stream, Ply_format format, const Ply_element_layout& element, Ply_item& item)
{
  item.values.resize(element.properties.size());
  for(std::size_t k = 0; k < element.properties.size() && stream; ++k)
  {
    const Ply_property_layout& property = element.properties[k];
    std::vector<double>& values = item.values[k];
    values.clear();
    const double size = property.is_list ? property.read_size(stream, format) : 1;
    // A negative size is no size; a large one is read as long as the stream lasts.
    if(!(size >= 0))
      stream.setstate(std::ios::failbit);
    for(double i = 0; i < size && stream; ++i)
      values.push_back(property.read_value(stream, format));
  }
  return !stream.fail();
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_PLY_READER_H
