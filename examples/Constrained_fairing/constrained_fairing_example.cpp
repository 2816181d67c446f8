// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fairs a mesh while keeping every vertex within epsilon of its input position.
//
//   constrained_fairing_example [IN] [EPS] [OUT]
//
// IN   a triangle mesh in any format CGAL reads (OFF, OBJ, PLY, STL); default: the bundled
//      noisy elephant
// EPS  the tolerance: absolute (0.002), or relative to the mean edge length h when it ends
//      with h (0.25h); default 0.25h
// OUT  where to write the faired mesh (.off, .obj, .ply or .stl), full precision; default:
//      faired.off
//
// On bad input or any failure, prints one line starting with "error:" and returns non-zero,
// and writes nothing: the output is written to a temporary file, renamed to OUT once complete.

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for(auto e : edges(mesh))
    sum += PMP::edge_length(e, mesh);
  return sum / double(num_edges(mesh));
}

// "0.002" is absolute, "0.25h" is 0.25 times the mean edge length. Returns false if malformed.
bool parse_epsilon(const std::string& text, const Mesh& mesh, double& epsilon)
{
  const bool relative = !text.empty() && text.back() == 'h';
  const std::string number = relative ? text.substr(0, text.size() - 1) : text;
  std::size_t used = 0;
  try
  {
    epsilon = std::stod(number, &used);
  }
  catch(const std::exception&)
  {
    return false;
  }
  if(used != number.size())
    return false;
  if(relative)
    epsilon *= mean_edge_length(mesh);
  return true;
}

using Polygon = std::vector<std::size_t>;

// CGAL's readers and writers explain failures on std::cerr; this keeps their words for our
// one-line message.
class Captured_cerr
{
public:
  Captured_cerr() : m_saved(std::cerr.rdbuf(m_text.rdbuf())) {}
  ~Captured_cerr() { std::cerr.rdbuf(m_saved); }
  // ": what CGAL said", on one line, or nothing
  std::string reason() const
  {
    std::string text = m_text.str();
    std::replace(text.begin(), text.end(), '\n', ' ');
    while(!text.empty() && text.back() == ' ')
      text.pop_back();
    return text.empty() ? text : " (" + text + ")";
  }

private:
  std::ostringstream m_text;
  std::streambuf* m_saved;
};

// Why a polygon soup that reads fine is no polygon mesh.
std::string soup_defect(const std::vector<Polygon>& polygons)
{
  std::vector<std::array<std::size_t, 3> > edges; // (smaller, larger, direction) of each side
  for(const Polygon& p : polygons)
  {
    if(p.size() < 3)
      return "a face has fewer than 3 vertices";
    for(std::size_t k = 0; k < p.size(); ++k)
    {
      const std::size_t a = p[k], b = p[(k + 1) % p.size()];
      if(std::count(p.begin(), p.end(), a) > 1)
        return "a face uses vertex " + std::to_string(a) + " twice";
      edges.push_back({(std::min)(a, b), (std::max)(a, b), std::size_t(a < b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  for(std::size_t i = 0, j = 0; i < edges.size(); i = j)
  {
    while(j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1])
      ++j;
    const std::string edge = "the edge between vertices " + std::to_string(edges[i][0]) + " and " + std::to_string(edges[i][1]);
    if(j - i > 2)
      return edge + " has " + std::to_string(j - i) + " faces (a non-manifold edge)";
    if(j - i == 2 && edges[i][2] == edges[i + 1][2])
      return "two faces run along " + edge + " in the same direction (inconsistent orientation)";
  }
  return "the faces around some vertex form more than one fan (a non-manifold vertex)";
}

// Reads a mesh from any format CGAL reads. Returns an empty string or the reason it failed.
std::string read_mesh(const std::string& in, Mesh& mesh)
{
  std::vector<K::Point_3> points;
  std::vector<Polygon> polygons;
  Captured_cerr cgal;
  if(!CGAL::IO::read_polygon_soup(in, points, polygons))
    return "cannot read " + in + " as an OFF, OBJ, PLY or STL mesh" + cgal.reason();
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t i : polygons[f])
      if(i >= points.size())
        return "face " + std::to_string(f) + " of " + in + " refers to vertex " + std::to_string(i) + ", but there are " +
               std::to_string(points.size()) + " vertices";
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    return in + " is not a manifold, consistently oriented mesh: " + soup_defect(polygons);
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return std::string();
}

bool writable_format(const std::string& out)
{
  const std::string ext = std::filesystem::path(out).extension().string();
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl";
}

// Writes to a temporary file beside `out`, renamed to `out` once complete. Returns an empty
// string or the reason it failed.
std::string write_mesh(const std::string& out, const Mesh& mesh)
{
  std::filesystem::path partial(out);
  partial.replace_filename("." + partial.stem().string() + ".partial" + partial.extension().string());
  std::error_code error;
  Captured_cerr cgal;
  if(CGAL::IO::write_polygon_mesh(partial.string(), mesh, CGAL::parameters::stream_precision(17)))
  {
    std::filesystem::rename(partial, out, error);
    if(!error)
      return std::string();
  }
  std::error_code ignored;
  std::filesystem::remove(partial, ignored);
  return "cannot write " + out + (error ? " (" + error.message() + ")" : cgal.reason());
}

int main(int argc, char* argv[])
{
  const std::string in = argc > 1 ? argv[1] : CGAL_CONSTRAINED_FAIRING_DATA_DIR "/elephant_noisy.off";
  const std::string eps_text = argc > 2 ? argv[2] : "0.25h";
  const std::string out = argc > 3 ? argv[3] : "faired.off";

  if(!writable_format(out))
  {
    std::cerr << "error: OUT must end with .off, .obj, .ply or .stl (got " << out << ")" << std::endl;
    return EXIT_FAILURE;
  }
  Mesh mesh;
  const std::string read_error = read_mesh(in, mesh);
  if(!read_error.empty())
  {
    std::cerr << "error: " << read_error << std::endl;
    return EXIT_FAILURE;
  }
  double epsilon = 0;
  if(!parse_epsilon(eps_text, mesh, epsilon))
  {
    std::cerr << "error: EPS must be a number, or a number followed by h (got " << eps_text << ")" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "input:       " << in << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces" << std::endl;
  std::cout << "epsilon:     " << epsilon << " (" << eps_text << ")" << std::endl;

  const auto start = std::chrono::steady_clock::now();
  const PMP::Constrained_fairing_result result = PMP::constrained_fairing(mesh, epsilon);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;

  if(!result)
  {
    std::cerr << "error: " << result.message << "; nothing written" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "iterations:  " << result.number_of_iterations << " ("
            << (result.status == PMP::Constrained_fairing_status::CONVERGED ? "converged" : "iteration limit")
            << ", " << result.number_of_energy_evaluations << " energy evaluations)" << std::endl;
  std::cout << "energy:      " << result.initial_energy << " -> " << result.final_energy << std::endl;
  if(result.number_of_degenerate_edges > 0)
    std::cout << "degenerate:  " << result.number_of_degenerate_edges
              << " edges with a degenerate triangle, left out of the energy" << std::endl;
  std::cout << "deviation:   " << result.max_deviation << " at most (bound " << epsilon << ")" << std::endl;
  std::cout << "time:        " << seconds.count() << " s" << std::endl;

  const std::string write_error = write_mesh(out, mesh);
  if(!write_error.empty())
  {
    std::cerr << "error: " << write_error << "; nothing written" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "output:      " << out << std::endl;
  return EXIT_SUCCESS;
}
