// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: arbitrary bytes, saved as an OFF, PLY, STL or OBJ file (guessed from the
// first bytes), read by CGAL::IO::read_polygon_mesh and faired for a few iterations. Beyond
// crashes and sanitizer reports, it aborts when a promise breaks: the soup check must accept
// exactly what CGAL's builder accepts, a failed call must leave the mesh bit-identical, a
// successful one must give finite points within the bound exactly.

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/constrained_fairing_input_check.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;

// Larger meshes only slow the search down.
constexpr std::size_t max_vertices = 2000;

std::string extension(const std::uint8_t* data, std::size_t size)
{
  const std::string head(reinterpret_cast<const char*>(data), std::min<std::size_t>(size, 8));
  if(head.rfind("ply", 0) == 0)
    return ".ply";
  if(head.rfind("solid", 0) == 0 || (size >= 84 && (size - 84) % 50 == 0))
    return ".stl";
  if(head.find("OFF") != std::string::npos)
    return ".off";
  return ".obj";
}

// CGAL 5.5's PLY reader appends a property to the last element without checking that an
// element was declared, dereferences a null pointer when a vertex element ("vertex" or
// "vertices") lacks one of x, y, z
// or has one of another type than float or double, and goes on reading past the end of the
// file as many items as an element announces (billions, for a mutated count).
bool is_sane_ply_header(const std::uint8_t* data, std::size_t size)
{
  std::istringstream header(std::string(reinterpret_cast<const char*>(data), size));
  std::string element;
  int coordinates = 7; // x, y, z of the current vertex element (bits 1, 2, 4) as float or double
  for(std::string line; std::getline(header, line);)
  {
    std::istringstream words(line);
    std::string keyword, type, name, count;
    words >> keyword; // the first word, as the reader splits it
    if(keyword == "end_header" || keyword == "element")
    {
      if((element == "vertex" || element == "vertices") && coordinates != 7)
        return false;
      if(keyword == "end_header")
        return true;
      if(!(words >> element >> count && count.size() <= 9 && count.find_first_not_of("0123456789") == std::string::npos &&
           std::stoul(count) <= size))
        return false;
      coordinates = 0;
    }
    else if(keyword == "property")
    {
      if(element.empty())
        return false;
      words >> type >> name;
      const int bit = name == "x" ? 1 : name == "y" ? 2 : name == "z" ? 4 : 0;
      if((element == "vertex" || element == "vertices") && bit != 0)
      {
        if((coordinates & bit) || !(type == "float" || type == "float32" || type == "double" || type == "float64"))
          return false;
        coordinates |= bit;
      }
    }
  }
  return true;
}

// CGAL 5.5's OFF scanner overflows its buffer on some malformed colour entries: OFF files
// are read only in their plain form (an "OFF" line, the counts, then lines of exactly three
// numbers and of a count followed by that many indices; no colour, no normal).
bool is_plain_off(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<std::vector<std::string> > lines;
  for(std::string line; std::getline(in, line);)
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::vector<std::string> tokens;
    for(std::string token; words >> token;)
      tokens.push_back(token);
    if(!tokens.empty())
      lines.push_back(tokens);
  }
  auto is_count = [&](const std::string& t) {
    return !t.empty() && t.size() <= 9 && t.find_first_not_of("0123456789") == std::string::npos && std::stoul(t) <= size;
  };
  auto is_number = [](const std::string& t) {
    char* end = nullptr;
    std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size();
  };
  if(lines.size() < 2 || lines[0] != std::vector<std::string>{"OFF"} || lines[1].size() != 3 ||
     !(is_count(lines[1][0]) && is_count(lines[1][1]) && is_count(lines[1][2])))
    return false;
  const std::size_t nv = std::stoul(lines[1][0]), nf = std::stoul(lines[1][1]);
  if(lines.size() != 2 + nv + nf)
    return false;
  for(std::size_t i = 2; i < 2 + nv; ++i)
    if(lines[i].size() != 3 || !(is_number(lines[i][0]) && is_number(lines[i][1]) && is_number(lines[i][2])))
      return false;
  for(std::size_t i = 2 + nv; i < lines.size(); ++i)
    if(!is_count(lines[i][0]) || lines[i].size() != 1 + std::stoul(lines[i][0]) ||
       !std::all_of(lines[i].begin() + 1, lines[i].end(), is_count))
      return false;
  return true;
}

void require(bool condition, const char* promise)
{
  if(!condition)
  {
    std::cerr << "broken promise: " << promise << std::endl;
    std::abort();
  }
}

// Inputs that meet a known defect of CGAL 5.5's readers are left out, the search being about
// what comes after reading. The mesh builder (Generic_facegraph_builder) does not check that
// face indices are below the number of vertices, and reads out of bounds when they are not.
bool is_readable(const std::string& path, const std::uint8_t* data, std::size_t size)
{
  const std::string extension = path.substr(path.size() - 4);
  if((extension == ".ply" && !is_sane_ply_header(data, size)) || (extension == ".off" && !is_plain_off(data, size)))
    return false;
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons))
    return false;
  for(const auto& polygon : polygons)
    for(std::size_t i : polygon)
      if(i >= points.size())
        return false;
  // The soup check that the command-line tool and the Python module make guards CGAL's mesh
  // builder: it must accept exactly the soups that CGAL's own test accepts.
  const bool accepted = !PMP::constrained_fairing_polygon_soup_error(points.size(), polygons);
  require(accepted == PMP::is_polygon_soup_a_polygon_mesh(polygons),
          "the soup check agrees with is_polygon_soup_a_polygon_mesh()");
  return true;
}

std::vector<double> coordinates(const Mesh& m)
{
  std::vector<double> result;
  for(auto v : vertices(m))
    for(int c = 0; c < 3; ++c)
      result.push_back(m.point(v)[c]);
  return result;
}

} // namespace

// The readers allocate what a header announces before reading it; a huge count must fail
// (operator new throws std::bad_alloc) rather than end the search. AddressSanitizer's own
// operator new aborts when it cannot allocate, its malloc may return null: new goes through
// malloc, which still checks every access (new and free may then pair up).
extern "C" const char* __asan_default_options() { return "max_allocation_size_mb=512:allocator_may_return_null=1:alloc_dealloc_mismatch=0"; }

void* operator new(std::size_t size)
{
  if(void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = "/tmp/fuzz_constrained_fairing_" + std::to_string(getpid()) + extension(data, size);
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  Mesh m;
  std::streambuf* saved = std::cerr.rdbuf(nullptr); // the readers' complaints
  bool read = false;
  try
  {
    read = is_readable(path, data, size) && CGAL::IO::read_polygon_mesh(path, m);
  }
  catch(const std::exception&) // std::bad_alloc, or std::length_error from a negative count
  {
  }
  std::cerr.rdbuf(saved);
  std::remove(path.c_str());
  if(!read || num_vertices(m) > max_vertices)
    return 0;

  // epsilon: a quarter of the mean edge length, or from the last input byte extreme values
  // (tiny, huge, zero, negative, NaN).
  double sum = 0;
  for(auto e : edges(m))
    sum += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  const double choices[] = {0.25 * sum / double(num_edges(m)), 1e-300, 1e300, 0, -1, std::nan("")};
  const double eps = choices[size == 0 ? 0 : data[size - 1] % 6];
  const auto shape = size % 2 == 0 ? PMP::Deviation_bound::BALL : PMP::Deviation_bound::BOX;

  const std::vector<double> input = coordinates(m);
  const auto result = PMP::constrained_fairing(m, eps, CFP::deviation_bound(shape).number_of_iterations(4));
  const std::vector<double> output = coordinates(m);
  if(!result)
  {
    require(input.empty() || std::memcmp(input.data(), output.data(), input.size() * sizeof(double)) == 0,
            "a failed call leaves the mesh bit-identical");
    return 0;
  }
  for(std::size_t i = 0; i < input.size(); i += 3)
  {
    double d2 = 0;
    for(std::size_t c = i; c < i + 3; ++c)
    {
      require(std::isfinite(output[c]), "the output is finite");
      const double d = output[c] - input[c];
      d2 += d * d;
      require(shape == PMP::Deviation_bound::BALL || std::abs(d) <= eps, "the box bound holds");
    }
    require(shape == PMP::Deviation_bound::BOX || (d2 <= eps * eps && std::sqrt(d2) <= eps), "the ball bound holds");
  }
  require(result.final_energy <= result.initial_energy, "the energy does not rise");
  return 0;
}
