// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Creases kept sharp: the default call against the same call with `feature_angle`, on noisy CAD
// parts, and what the detection marks on organic meshes.
//
//   fairing_features [--demo DIR] [--angle DEG] [--faces N] [--runs N] [--threads K]
//                    [--parts NAME,NAME...] [--seed S] [--write DIR] [--detection 1]
//
// CAD parts: fandisk, joint, blade, part, dragknob, anchor, cube-meshed, pinion, rotor, turbine,
// spool, couplingdown and mech-holes-shark from CGAL's demo data in DIR (see get_demo_meshes.sh;
// skipped cleanly without them), and chamfered-block, gear, stepped-shaft and pyramid-boss, made
// here (made_parts.h) since their edges are mostly 40 to 60 degrees. Each is a coarse
// tessellation, so it is first remeshed with CGAL's isotropic_remeshing to about N faces
// (default 20000), its edges sharper than the angle kept as constraints; that mesh is the clean
// truth, and its edges whose dihedral angle is over the angle (default 30 degrees) are its sharp
// edges. Then seeded uniform-ball noise of radius d h, d in {0.25, 0.5}, h the mean edge length,
// and epsilon the noise radius. Measured against the clean mesh (surface_quality.h): the RMS
// distance to the clean surface, the mean normal error over all faces and over the faces within
// 2 h of a sharp edge, the smallest angle, the folded faces, the bound, the time (median of N
// runs), and the detection: the share of the clean edges sharper than 40 degrees that are found,
// and of the found edges that are not clean edges sharper than 20 degrees (false). Methods: the
// default call, the accurate objective, the call with `feature_angle(DEG)`, and the call given
// the clean sharp edges (`edge_is_constrained_map`: what a perfect detection would give).
// --parts runs only the parts named; --seed draws other noise (default 1); --write writes each
// case's meshes into DIR, as OFF files with the clean mesh's connectivity (NAME_clean.off,
// NAME_D_noisy.off, NAME_D_default.off, NAME_D_features.off) and the edges feature_angle found
// (NAME_D_creases.txt, a pair of vertex indices per line), from which doc/make_figures.py draws the
// manual's figure.
// --detection 1 measures the detection alone (the feature_angle call stopped after one iteration).
// Organic meshes (the bundled bunny and elephant, 0.25 h of noise): the share of edges the
// detection marks, and the bending energy over all hinges against the default call's.

#include "made_parts.h"
#include "surface_quality.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace benchmark;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace CFP = PMP::constrained_fairing_parameters;

namespace {

using Edge_flags = Mesh::Property_map<Mesh::Edge_index, bool>;

// The clean part: `coarse` remeshed to about `target_faces` faces, its sharp edges kept.
Mesh remeshed(Mesh coarse, double angle, double target_faces)
{
  auto sharp = coarse.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(coarse, angle, sharp);
  const double area = PMP::area(coarse);
  const double length = std::sqrt(4 * area / (std::sqrt(3.) * target_faces));
  PMP::isotropic_remeshing(faces(coarse), length, coarse,
                           CGAL::parameters::number_of_iterations(5).edge_is_constrained_map(sharp));
  coarse.remove_property_map(sharp);
  coarse.collect_garbage();
  return coarse;
}

// The interior edges of `mesh` whose dihedral angle is over `angle` degrees (CGAL's
// detect_sharp_edges also marks the border edges).
Edge_flags sharp_edges(Mesh& mesh, double angle, const std::string& name)
{
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>(name, false).first;
  PMP::detect_sharp_edges(mesh, angle, sharp);
  for(auto e : edges(mesh))
    sharp[e] = sharp[e] && !is_border(e, mesh);
  return sharp;
}

// Each edge's dihedral angle in degrees on `mesh`, by edge index (0 on the border).
std::vector<double> dihedral_angles(const Mesh& mesh)
{
  std::vector<double> angle(num_edges(mesh), 0.);
  for(auto e : edges(mesh))
    if(!is_border(e, mesh))
    {
      const auto h = halfedge(e, mesh);
      angle[e.idx()] = angle_deg(PMP::compute_face_normal(face(h, mesh), mesh),
                                 PMP::compute_face_normal(face(opposite(h, mesh), mesh), mesh));
    }
  return angle;
}

double segment_distance(const Point& p, const Point& a, const Point& b)
{
  const K::Vector_3 ab = b - a, ap = p - a;
  const double t = std::clamp(ap * ab / ab.squared_length(), 0., 1.);
  return std::sqrt(CGAL::squared_distance(p, a + t * ab));
}

// The faces of `clean` whose centroid lies within `radius` of one of its sharp edges.
std::vector<bool> faces_near(const Mesh& clean, const Edge_flags& sharp, double radius)
{
  std::vector<std::pair<Point, Point> > segments;
  for(auto e : edges(clean))
    if(sharp[e])
      segments.emplace_back(clean.point(source(halfedge(e, clean), clean)), clean.point(target(halfedge(e, clean), clean)));
  std::vector<bool> near(num_faces(clean), false);
  for(auto f : faces(clean))
  {
    const auto h = halfedge(f, clean);
    const Point c = CGAL::centroid(clean.point(source(h, clean)), clean.point(target(h, clean)),
                                   clean.point(target(next(h, clean), clean)));
    for(const auto& s : segments)
      if(segment_distance(c, s.first, s.second) <= radius)
      {
        near[f.idx()] = true;
        break;
      }
  }
  return near;
}

double normal_error_near(const Mesh& result, const Clean_surface& clean, const std::vector<bool>& near)
{
  double sum = 0;
  std::size_t count = 0;
  for(auto f : faces(result))
    if(near[f.idx()])
    {
      sum += angle_deg(PMP::compute_face_normal(f, result), clean.normal[f.idx()]);
      ++count;
    }
  return count > 0 ? sum / double(count) : 0;
}

struct Row
{
  Quality q;
  double near_error = 0, seconds = 0, found = -1, false_share = 0; // found: -1 where not measured
  std::size_t marked = 0, iterations = 0, evaluations = 0;
};

enum Method { DEFAULT, ACCURATE, FEATURES, GIVEN, METHODS };
const char* method_name[] = {"default", "accurate objective", "feature_angle", "given sharp edges"};

void write(const std::string& path, const Mesh& mesh)
{
  if(!CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "error: cannot write " << path << std::endl;
    std::exit(1);
  }
}

// The detection's shares: of the clean edges sharper than 40 degrees, those marked (found); of
// the marked edges, those that are no clean edge sharper than 20 degrees (false).
void measure_detection(const Mesh& mesh, const Edge_flags& marks, const std::vector<double>& clean_angle, Row& row)
{
  std::size_t sharp = 0, found = 0, wrong = 0, marked = 0;
  for(auto e : edges(mesh))
  {
    const double a = clean_angle[e.idx()];
    sharp += a > 40;
    found += a > 40 && marks[e];
    wrong += marks[e] && !(a > 20);
    marked += marks[e];
  }
  row.found = sharp > 0 ? double(found) / double(sharp) : 1;
  row.false_share = marked > 0 ? double(wrong) / double(marked) : 0;
}

// One method on `noisy`: the result measured against the clean mesh, and written to
// `prefix`.off (with the creases found, for feature_angle) unless `prefix` is empty.
Row run(Method method, const Mesh& noisy, const Clean_surface& clean, Edge_flags clean_sharp,
        const std::vector<double>& clean_angle, const std::vector<bool>& near, double eps, double angle, int runs,
        const std::string& prefix)
{
  Row row;
  Mesh result;
  PMP::Constrained_fairing_result r;
  Edge_flags marks;
  row.seconds = median_seconds(runs, [&] {
    result = noisy;
    marks = result.add_property_map<Mesh::Edge_index, bool>("e:marks", false).first;
    if(method == GIVEN)
      for(auto e : edges(result))
        marks[e] = clean_sharp[e];
    if(method == DEFAULT)
      r = PMP::constrained_fairing(result, eps);
    else if(method == ACCURATE)
      r = PMP::constrained_fairing(result, eps, CFP::fairing_objective(PMP::Constrained_fairing_objective::ACCURATE));
    else if(method == FEATURES)
      r = PMP::constrained_fairing(result, eps, CFP::feature_angle(angle, CGAL::parameters::edge_is_constrained_map(marks)));
    else
      r = PMP::constrained_fairing(result, eps, CGAL::parameters::edge_is_constrained_map(marks));
  });
  if(!r)
  {
    std::cerr << "error: " << r.message << std::endl;
    std::exit(1);
  }
  row.q = measure(result, noisy, clean, eps, r.final_bending_energy);
  if(!prefix.empty())
  {
    write(prefix + ".off", result);
    if(method == FEATURES)
    {
      std::ofstream creases(prefix + "_creases.txt");
      for(auto e : edges(result))
        if(marks[e])
          creases << source(halfedge(e, result), result).idx() << ' ' << target(halfedge(e, result), result).idx()
                  << '\n';
    }
  }
  row.near_error = normal_error_near(result, clean, near);
  row.marked = r.number_of_feature_edges;
  row.iterations = r.number_of_iterations;
  row.evaluations = r.number_of_energy_evaluations;
  if(method == FEATURES)
    measure_detection(result, marks, clean_angle, row);
  return row;
}

// The detection alone: the call with `feature_angle` stopped after one iteration, its marks
// measured (`--detection 1`: every part and noise level in seconds, to compare detections).
Row detection(const Mesh& noisy, const std::vector<double>& clean_angle, double eps, double angle)
{
  Row row;
  Mesh result = noisy;
  Edge_flags marks = result.add_property_map<Mesh::Edge_index, bool>("e:marks", false).first;
  const auto r = PMP::constrained_fairing(
    result, eps, CFP::feature_angle(angle, CGAL::parameters::edge_is_constrained_map(marks).number_of_iterations(1)));
  if(!r)
  {
    std::cerr << "error: " << r.message << std::endl;
    std::exit(1);
  }
  row.marked = r.number_of_feature_edges;
  measure_detection(result, marks, clean_angle, row);
  return row;
}

void print(const std::string& label, const Row& row)
{
  std::cout << "  " << std::left << std::setw(20) << label << std::right << std::setprecision(4)
            << " RMS " << std::setw(9) << row.q.surface_rms << "  normal " << std::setw(6) << row.q.normal_error_deg
            << " deg  near edges " << std::setw(6) << row.near_error << " deg  min angle " << std::setw(5)
            << row.q.min_angle_deg << "  folds " << row.q.folds << "  bound " << (row.q.ball_holds ? "exact" : "BROKEN")
            << "  " << std::setprecision(3) << row.seconds << " s (" << row.iterations << " iterations, "
            << row.evaluations << " evaluations)";
  if(row.marked > 0)
    std::cout << "  edges " << row.marked;
  if(row.found >= 0)
    std::cout << "  found " << std::setprecision(3) << 100 * row.found << " %  false " << 100 * row.false_share << " %";
  std::cout << std::endl;
}

} // namespace

const char* const all_parts = "fandisk,joint,blade,part,dragknob,anchor,cube-meshed,pinion,rotor,turbine,spool,"
                              "couplingdown,mech-holes-shark,chamfered-block,gear,stepped-shaft,pyramid-boss";

// The part's coarse mesh, made or read from `demo`.
bool read_part(const std::string& name, const std::string& demo, Mesh& coarse)
{
  return made_part(name, coarse) || CGAL::IO::read_polygon_mesh(demo + "/" + name + ".off", coarse);
}

int main(int argc, char* argv[])
{
  const Arguments arguments(argc, argv);
  const Thread_limit threads(arguments);
  const std::string demo = arguments.option("demo", CONSTRAINED_FAIRING_DEMO_DATA);
  const double angle = std::stod(arguments.option("angle", "30"));
  const double target_faces = std::stod(arguments.option("faces", "20000"));
  const int runs = arguments.runs;
  const std::string parts =
    "," + arguments.option("parts", all_parts) + ",";
  const std::string out = arguments.option("write", "");
  const auto seed = static_cast<unsigned int>(std::stoul(arguments.option("seed", "1")));
  const bool detection_only = arguments.option("detection", "0") == "1";
  std::cout << machine_description() << std::endl;
  std::cout << "feature_angle(" << angle << "), runs " << runs << " (median time), noise seed " << seed << std::endl;

  // ratios of feature_angle to the default call, for the geometric means
  double log_normal = 0, log_near = 0, log_rms = 0, log_time = 0, log_near_accurate = 0, log_normal_accurate = 0;
  int cases = 0;
  std::stringstream names(all_parts);
  for(std::string name; std::getline(names, name, ',');)
  {
    if(parts.find("," + name + ",") == std::string::npos)
      continue;
    Mesh coarse;
    if(!read_part(name, demo, coarse))
    {
      std::cout << name << ": not in " << demo << " (see get_demo_meshes.sh), skipped" << std::endl;
      continue;
    }
    Mesh clean = remeshed(coarse, angle, target_faces);
    const Edge_flags sharp = sharp_edges(clean, angle, "e:clean_sharp");
    const std::vector<double> clean_angle = dihedral_angles(clean);
    const double h = mean_edge_length(clean);
    const Clean_surface surface(clean);
    const std::vector<bool> near = faces_near(clean, sharp, 2 * h);
    std::size_t sharp_count = 0, over_40 = 0;
    for(auto e : edges(clean))
      sharp_count += sharp[e], over_40 += clean_angle[e.idx()] > 40;
    if(!out.empty())
      write(out + "/" + name + "_clean.off", clean);
    for(double d : {0.25, 0.5})
    {
      Mesh noisy = clean;
      add_noise(noisy, d * h, seed);
      const std::string prefix = out.empty() ? "" : out + "/" + name + "_" + (d == 0.25 ? "0.25" : "0.5") + "_";
      if(!out.empty())
        write(prefix + "noisy.off", noisy);
      const double eps = d * h;
      std::cout << name << ", " << num_faces(clean) << " faces, " << sharp_count << " sharp edges (" << over_40
                << " over 40 degrees), noise " << d << " h:" << std::endl;
      if(detection_only)
      {
        const Row row = detection(noisy, clean_angle, eps, angle);
        std::cout << "  detection: edges " << row.marked << "  found " << std::setprecision(3) << 100 * row.found
                  << " %  false " << 100 * row.false_share << " %" << std::endl;
        continue;
      }
      Row rows[METHODS];
      for(int m = 0; m < METHODS; ++m)
      {
        const bool written = !prefix.empty() && (m == DEFAULT || m == FEATURES);
        rows[m] = run(Method(m), noisy, surface, sharp, clean_angle, near, eps, angle, runs,
                      written ? prefix + (m == DEFAULT ? "default" : "features") : "");
        print(method_name[m], rows[m]);
      }
      const Row& base = rows[DEFAULT];
      const Row& ours = rows[FEATURES];
      std::cout << "  feature_angle / default: normal " << ours.q.normal_error_deg / base.q.normal_error_deg
                << ", near edges " << ours.near_error / base.near_error << ", RMS " << ours.q.surface_rms / base.q.surface_rms
                << ", time " << ours.seconds / base.seconds << std::endl;
      log_normal += std::log(ours.q.normal_error_deg / base.q.normal_error_deg);
      log_near += std::log(ours.near_error / base.near_error);
      log_rms += std::log(ours.q.surface_rms / base.q.surface_rms);
      log_time += std::log(ours.seconds / base.seconds);
      log_normal_accurate += std::log(ours.q.normal_error_deg / rows[ACCURATE].q.normal_error_deg);
      log_near_accurate += std::log(ours.near_error / rows[ACCURATE].near_error);
      ++cases;
    }
  }
  if(cases > 0)
    std::cout << "\ngeometric means over " << cases << " cases, feature_angle against the default call: normal error "
              << std::exp(log_normal / cases) << ", near sharp edges " << std::exp(log_near / cases) << ", RMS "
              << std::exp(log_rms / cases) << ", time " << std::exp(log_time / cases)
              << "; against the accurate objective: normal error " << std::exp(log_normal_accurate / cases)
              << ", near sharp edges " << std::exp(log_near_accurate / cases) << std::endl;

  std::cout << "\norganic meshes, noise 0.25 h:" << std::endl;
  for(const std::string name : {"bunny00", "elephant"})
  {
    Mesh noisy;
    if(!CGAL::IO::read_polygon_mesh(std::string(CONSTRAINED_FAIRING_DATA_DIR) + "/" + name + ".off", noisy))
      continue;
    const double eps = 0.25 * mean_edge_length(noisy);
    add_noise(noisy, eps, seed);
    if(detection_only)
    {
      Mesh featured = noisy;
      const auto marked = PMP::constrained_fairing(featured, eps, CFP::feature_angle(angle, CGAL::parameters::number_of_iterations(1)))
                            .number_of_feature_edges;
      std::cout << "  " << name << ": " << marked << " of " << num_edges(noisy) << " edges marked ("
                << 100. * double(marked) / double(num_edges(noisy)) << " %)" << std::endl;
      continue;
    }
    Mesh plain = noisy, featured = noisy;
    const auto base = PMP::constrained_fairing(plain, eps);
    const auto ours = PMP::constrained_fairing(featured, eps, CFP::feature_angle(angle));
    std::cout << "  " << name << ": " << ours.number_of_feature_edges << " of " << num_edges(noisy) << " edges marked ("
              << 100. * double(ours.number_of_feature_edges) / double(num_edges(noisy)) << " %), energy "
              << bending_energy(featured, noisy) / bending_energy(plain, noisy)
              << " times the default's (over all hinges; without those across the marked edges "
              << ours.final_bending_energy / base.final_bending_energy << ")" << std::endl;
  }
  return 0;
}
