// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How close to the true surface the fairing ends, against the naive bounded smoothers:
//
//   fairing_accuracy [--demo DIR] [--runs N] [--counts N,...] [--fidelity-weight W]
//
// For each mesh of the set (the bundled elephant, head and bunny, and CGAL demo meshes from
// DIR when they are there: see get_demo_meshes.sh) and each noise level d in {0.25, 0.5}: seeded
// uniform-ball noise of radius d h (h the mean edge length), epsilon the noise radius. Measured
// against the clean mesh (surface_quality.h): surface RMS, normal error, bending energy, min
// angle, folded faces (and how many of them are at the clean mesh's own creases sharper than 90
// degrees), time (median of N runs).
// The yardsticks, clamped Laplacian and clamped Taubin (bounded_smoothers.h), are run for each
// iteration count of the list and judged at their best count over the whole set, for each
// measure separately (the geometric mean over the set decides). Ours: the default call
// (Constrained_fairing_objective::FAIREST) and the accurate objective. Also the noise estimate
// (estimate_noise_level) against the true noise radius.
// The noise-free control runs every method on the clean mesh itself with the same epsilon: what
// a method takes away from the clean mesh when there is no noise to remove, its own roughness
// at the scale of the bound (the terraces of an isosurface, the facets of a decimated mesh),
// which the errors above count too. Also the noise estimate of the clean mesh.

#include "bounded_smoothers.h"
#include "surface_quality.h"

#include <CGAL/Polygon_mesh_processing/constrained_fairing.h>
#include <CGAL/Polygon_mesh_processing/estimate_noise_level.h>

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

struct Mode
{
  PMP::Constrained_fairing_objective objective;
  std::string name() const
  {
    return objective == PMP::Constrained_fairing_objective::FAIREST ? "ours, fairest" : "ours, accurate";
  }
};

struct Row
{
  Quality q;
  double seconds = 0;
};

double bending_energy(const Mesh& mesh)
{
  Mesh copy = mesh;
  return PMP::constrained_fairing(copy, 1, CGAL::parameters::number_of_iterations(0)).final_bending_energy;
}

std::vector<std::string> split(const std::string& s, char separator)
{
  std::vector<std::string> parts;
  std::istringstream in(s);
  for(std::string part; std::getline(in, part, separator);)
    parts.push_back(part);
  return parts;
}

// The runs of every method on one input: the yardsticks at each iteration count, our modes.
struct Runs
{
  Row input;
  std::vector<Row> laplacian, taubin, ours;
};

// Runs every method on `input` within `eps`, measured against `surface`; our modes are timed
// over `runs` runs.
Runs run_methods(const Mesh& input, double eps, const Clean_surface& surface, const std::vector<int>& counts,
                 const std::vector<Mode>& modes, double fidelity_weight, int runs)
{
  Runs r;
  r.input.q = measure(input, input, surface, eps, bending_energy(input));
  for(auto kind : {Bounded_smoother::LAPLACIAN, Bounded_smoother::TAUBIN})
  {
    const Bounded_smoother smoother(input, eps, kind);
    Mesh m = input;
    int done = 0;
    for(int count : counts)
    {
      for(; done < count; ++done)
        smoother.iterate(m);
      (kind == Bounded_smoother::LAPLACIAN ? r.laplacian : r.taubin)
        .push_back({measure(m, input, surface, eps, bending_energy(m)), 0.});
    }
  }
  for(const Mode& mode : modes)
  {
    Mesh m;
    const double seconds = median_seconds(runs, [&] {
      m = input;
      PMP::constrained_fairing(m, eps, CFP::fairing_objective(mode.objective, CFP::fidelity_weight(fidelity_weight)));
    });
    r.ours.push_back({measure(m, input, surface, eps, bending_energy(m)), seconds});
  }
  return r;
}

double geometric_mean(const std::vector<double>& values)
{
  double sum = 0;
  for(double v : values)
    sum += std::log(v);
  return std::exp(sum / double(values.size()));
}

} // namespace

int main(int argc, char* argv[])
{
  std::cout << benchmark::machine_description() << std::endl; // the CPU and threads of every figure below
  const Arguments arguments(argc, argv);
  const std::string demo = arguments.option("demo", CONSTRAINED_FAIRING_DEMO_DATA);
  // the accurate objective's fidelity weight (the fairest objective has none)
  const double default_weight = PMP::internal::Constrained_fairing::default_fidelity_weight;
  const double fidelity_weight = std::stod(arguments.option("fidelity-weight", std::to_string(default_weight)));
  const std::vector<Mode> modes = {{PMP::Constrained_fairing_objective::FAIREST},
                                   {PMP::Constrained_fairing_objective::ACCURATE}};
  std::vector<int> counts;
  for(const std::string& c : split(arguments.option("counts", "1,2,3,4,5,6,8,10,12,15,20,25,30,40,50"), ','))
    counts.push_back(std::stoi(c));

  std::vector<std::pair<std::string, std::string> > files = {
    {"elephant", CONSTRAINED_FAIRING_DATA_DIR "/elephant.off"},
    {"head", CONSTRAINED_FAIRING_DATA_DIR "/head.off"},
    {"bunny", CONSTRAINED_FAIRING_DATA_DIR "/bunny00.off"}};
  for(const char* name : {"femur", "camel", "bull", "lion-head", "homer", "armadillo"})
  {
    const std::string path = demo + "/" + name + ".off";
    if(std::ifstream(path))
      files.emplace_back(name, path);
    else
      std::cout << "skipped " << name << ": " << path << " is absent (benchmark/get_demo_meshes.sh fetches it)\n";
  }

  struct Case
  {
    std::string name;
    std::size_t faces;
    double clean_energy, clean_min_angle, noise_ratio, clean_noise_ratio;
    std::size_t clean_creased_faces;
    Runs noisy, control; // from the noisy mesh, and from the clean mesh itself
  };
  std::vector<Case> cases;
  for(const auto& file : files)
    for(double d : {0.25, 0.5})
    {
      Mesh clean;
      if(!CGAL::IO::read_polygon_mesh(file.second, clean))
      {
        std::cerr << "error: cannot read " << file.second << std::endl;
        return EXIT_FAILURE;
      }
      const Clean_surface surface(clean);
      Mesh noisy = clean;
      const double eps = d * mean_edge_length(clean);
      add_noise(noisy, eps, 1);
      Case c;
      std::ostringstream name;
      name << file.first << " d" << d;
      c.name = name.str();
      c.faces = num_faces(clean);
      c.clean_energy = bending_energy(clean);
      c.noise_ratio = PMP::estimate_noise_level(noisy) / eps;
      c.clean_min_angle = measure(clean, clean, surface, eps, 0).min_angle_deg;
      c.clean_creased_faces = surface.creased_faces;
      c.clean_noise_ratio = PMP::estimate_noise_level(clean) / eps;
      c.noisy = run_methods(noisy, eps, surface, counts, modes, fidelity_weight, arguments.runs);
      c.control = run_methods(clean, eps, surface, counts, modes, fidelity_weight, 1);
      std::cout << c.name << ": " << num_vertices(clean) << " vertices, eps " << eps << ", clean energy "
                << c.clean_energy << ", min angle " << c.clean_min_angle << " deg, "
                << c.clean_creased_faces << " faces at creases sharper than 90"
                << " deg, input RMS " << c.noisy.input.q.surface_rms / eps << " eps, normal "
                << c.noisy.input.q.normal_error_deg << " deg, noise estimate " << c.noise_ratio
                << " eps (of the clean mesh: " << c.clean_noise_ratio << " eps)" << std::endl;
      cases.push_back(c);
    }

  // The yardsticks' best fixed counts over the set (from the noisy meshes), per measure.
  const auto best_count = [&](auto member, auto rows) {
    std::size_t best = 0;
    double best_mean = HUGE_VAL;
    for(std::size_t k = 0; k < counts.size(); ++k)
    {
      std::vector<double> values;
      for(const Case& c : cases)
        values.push_back((c.noisy.*rows)[k].q.*member);
      const double mean = geometric_mean(values);
      if(mean < best_mean)
      {
        best_mean = mean;
        best = k;
      }
    }
    return best;
  };
  const std::size_t lap_rms = best_count(&Quality::surface_rms, &Runs::laplacian),
                    lap_normal = best_count(&Quality::normal_error_deg, &Runs::laplacian),
                    tau_rms = best_count(&Quality::surface_rms, &Runs::taubin),
                    tau_normal = best_count(&Quality::normal_error_deg, &Runs::taubin);
  std::cout << "\nbest fixed counts over the set: clamped Laplacian " << counts[lap_rms] << " (RMS), "
            << counts[lap_normal] << " (normal); clamped Taubin " << counts[tau_rms] << " (RMS), "
            << counts[tau_normal] << " (normal)\n";
  std::cout << "RMS in the mesh's units; ratios to the better yardstick at its best count; energy relative to the clean mesh's\n";

  // The table of the runs on the noisy meshes, with our ratios to the better yardstick and their
  // geometric means; then that of the noise-free control, with each method's share of its own
  // error on the noisy mesh (surface RMS and normal error) that it also has without noise.
  const auto header = [](const std::string& ratio_rms, const std::string& ratio_normal) {
    std::cout << "\n" << std::left << std::setw(18) << "case" << std::setw(22) << "method" << std::right << std::setw(8)
              << "RMS" << std::setw(8) << "normal" << std::setw(8) << ratio_rms << std::setw(8) << ratio_normal
              << std::setw(9) << "energy" << std::setw(9) << "min ang" << std::setw(7) << "folds" << std::setw(8)
              << "crease" << std::setw(8) << "s" << "\n";
  };
  const auto print = [](const Case& c, const std::string& method, const Row& row, const Row* reference) {
    std::cout << std::left << std::setw(18) << c.name << std::setw(22) << method << std::right << std::fixed
              << std::setprecision(4) << std::setw(8) << row.q.surface_rms << std::setprecision(2) << std::setw(8)
              << row.q.normal_error_deg;
    if(reference)
      std::cout << std::setw(8) << row.q.surface_rms / reference->q.surface_rms << std::setw(8)
                << row.q.normal_error_deg / reference->q.normal_error_deg;
    else
      std::cout << std::setw(16) << "";
    std::cout << std::setw(9) << row.q.energy / c.clean_energy << std::setw(9) << row.q.min_angle_deg << std::setw(7)
              << row.q.folds << std::setw(8) << row.q.folds_at_creases << std::setw(8) << std::setprecision(3)
              << row.seconds << std::defaultfloat << "\n";
  };

  header("x RMS", "x norm");
  std::vector<std::vector<double> > rms_ratios(modes.size()), normal_ratios(modes.size());
  std::vector<bool> holds(modes.size(), true);
  for(const Case& c : cases)
  {
    const Runs& r = c.noisy;
    Row best; // the better yardstick's figures, per measure
    best.q.surface_rms = (std::min)(r.laplacian[lap_rms].q.surface_rms, r.taubin[tau_rms].q.surface_rms);
    best.q.normal_error_deg =
      (std::min)(r.laplacian[lap_normal].q.normal_error_deg, r.taubin[tau_normal].q.normal_error_deg);
    print(c, "input", r.input, nullptr);
    print(c, "clamped Laplacian", r.laplacian[lap_rms], nullptr);
    print(c, "clamped Taubin", r.taubin[tau_rms], nullptr);
    for(std::size_t m = 0; m < modes.size(); ++m)
    {
      const Row& row = r.ours[m];
      print(c, modes[m].name(), row, &best);
      rms_ratios[m].push_back(row.q.surface_rms / best.q.surface_rms);
      normal_ratios[m].push_back(row.q.normal_error_deg / best.q.normal_error_deg);
      holds[m] = holds[m] && row.q.ball_holds && row.q.surface_rms <= best.q.surface_rms &&
                 row.q.normal_error_deg <= best.q.normal_error_deg && row.q.energy <= 1.5 * c.clean_energy &&
                 row.q.min_angle_deg >= (std::min)(1., c.clean_min_angle) && row.q.folds * 10000 < c.faces;
    }
  }
  std::cout << "\n(targets per case: RMS and normal at most the better yardstick's, energy at most 1.5 the clean "
               "mesh's, min angle at least 1 degree or the clean mesh's, folds under 0.01 % of the faces)\n";
  for(std::size_t m = 0; m < modes.size(); ++m)
    std::cout << modes[m].name() << ": geometric mean over the set of the ratios: RMS "
              << geometric_mean(rms_ratios[m]) << ", normal " << geometric_mean(normal_ratios[m])
              << (holds[m] ? "; every case within the targets" : "; some case misses a target") << "\n";

  std::cout << "\nnoise-free control: every method run on the clean mesh itself, same epsilon, the yardsticks at their\n"
               "best count for normals; its departure from the clean mesh is the clean mesh's own roughness at the\n"
               "scale of epsilon that it takes away (of RMS, of norm: the share of the method's own error on the\n"
               "noisy mesh that it also has without noise)\n";
  header("of RMS", "of norm");
  for(const Case& c : cases)
  {
    print(c, "clamped Laplacian", c.control.laplacian[lap_normal], &c.noisy.laplacian[lap_normal]);
    print(c, "clamped Taubin", c.control.taubin[tau_normal], &c.noisy.taubin[tau_normal]);
    for(std::size_t m = 0; m < modes.size(); ++m)
      print(c, modes[m].name(), c.control.ours[m], &c.noisy.ours[m]);
  }

  double worst = 1;
  std::size_t within = 0;
  for(const Case& c : cases)
  {
    if(std::abs(std::log(c.noise_ratio)) > std::abs(std::log(worst)))
      worst = c.noise_ratio;
    within += std::abs(c.noise_ratio - 1) <= 0.25;
  }
  std::cout << "\nnoise estimate: within 25 % of the noise radius on " << within << " of " << cases.size()
            << " cases; worst ratio " << worst << "\n";
  return EXIT_SUCCESS;
}
