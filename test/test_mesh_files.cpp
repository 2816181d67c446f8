// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh files as the front ends read them (front_end/Mesh_file.h), from several threads at once,
// as the Python module does when a Dask worker runs several tasks: every read gives what the same
// read gives alone, message and all, while another thread writes to std::cerr. Reading must not
// touch process-wide state: a reader that swapped std::cerr's buffer for its own would mix the
// threads' messages, and a writer could write into a buffer already destroyed (which the
// sanitizer build reports). Also the messages of files that cannot be read.

#include "test_support.h"

#include "front_end/Mesh_file.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <atomic>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace FE = Constrained_fairing_front_end;
using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

// What one read gives: its message, and the size of the mesh made of it.
struct Outcome
{
  std::string error;
  std::size_t vertices = 0, faces = 0, values = 0;

  bool operator==(const Outcome& o) const
  {
    return error == o.error && vertices == o.vertices && faces == o.faces && values == o.values;
  }
};

Outcome read(const std::string& path, const std::string& property)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<double> values;
  FE::Ply_properties properties;
  Outcome outcome;
  outcome.error = property.empty() ? FE::read_polygon_soup_file(path, points, polygons)
                                   : FE::read_PLY_mesh_file(path, points, polygons, properties);
  if(outcome.error.empty() && !property.empty())
    outcome.error = FE::vertex_property_values(path, properties, property, values);
  if(outcome.error.empty())
  {
    CGAL::Surface_mesh<Point> mesh;
    std::size_t triangulated = 0;
    outcome.error = FE::make_triangle_mesh(path, points, polygons, mesh, triangulated);
    outcome.vertices = mesh.number_of_vertices();
    outcome.faces = mesh.number_of_faces();
  }
  outcome.values = values.size();
  return outcome;
}

int main()
{
  struct File
  {
    std::string path, property;
  };
  std::vector<File> files;
  for(const auto& entry : std::filesystem::directory_iterator(CONSTRAINED_FAIRING_BAD_INPUT_DIR))
    files.push_back({entry.path().string(), ""});
  const std::string bad = CONSTRAINED_FAIRING_BAD_INPUT_DIR;
  files.push_back({bad + "/nan.ply", "accuracy"});
  files.push_back({bad + "/no_such_mesh.off", ""});
  files.push_back({bad + "/mesh.unknown", ""});
  files.push_back({bad, ""});
  files.push_back({std::string(CONSTRAINED_FAIRING_DATA_DIR) + "/head.off", ""});

  std::vector<Outcome> alone;
  for(const File& file : files)
    alone.push_back(read(file.path, file.property));

  // The bad files that are still soups of a mesh (the library rejects them later); every
  // failure names the file and says why in one line.
  const std::set<std::string> readable = {"empty.off", "points_only.off", "nan.ply", "zero_area.off", "quad.off",
                                          "not_a_mesh.stl", "head.off"};
  for(std::size_t i = 0; i < files.size(); ++i)
  {
    const std::string& error = alone[i].error;
    const std::string name = std::filesystem::path(files[i].path).filename().string();
    CHECK(error.empty() == (readable.count(name) > 0 && files[i].property.empty()));
    CHECK(error.empty() || error.find(files[i].path) != std::string::npos);
    CHECK(error.find('\n') == std::string::npos);
  }
  const std::size_t n = files.size();
  CHECK(alone[n - 5].error.find("has no float or double vertex property accuracy") != std::string::npos);
  CHECK(alone[n - 4].error.find("(no such file)") != std::string::npos);
  CHECK(alone[n - 3].error.find("(no such file)") != std::string::npos);
  CHECK(alone[n - 2].error.find("(a directory)") != std::string::npos);
  CHECK(alone[n - 1].vertices == 1487 && alone[n - 1].faces == 2918);

  constexpr int threads = 4, rounds = 25;
  std::atomic<int> mismatches{0};
  std::atomic<bool> reading{true};
  std::thread writer([&] {
    while(reading)
      std::cerr << "" << std::flush;
  });
  std::vector<std::thread> readers;
  for(int t = 0; t < threads; ++t)
    readers.emplace_back([&, t] {
      for(int round = 0; round < rounds; ++round)
        for(std::size_t k = 0; k < files.size(); ++k)
        {
          const std::size_t i = (k + std::size_t(t) * 3) % files.size(); // each thread its own order
          if(!(read(files[i].path, files[i].property) == alone[i]))
            ++mismatches;
        }
    });
  for(std::thread& reader : readers)
    reader.join();
  reading = false;
  writer.join();
  CHECK(mismatches == 0);
  return test::report("test_mesh_files");
}
