// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's progress on stderr. On a terminal, one line rewritten at most ten times a second:
// each phase as it starts (reading, checking and starting, fairing, writing), then the
// iterations with what the stopping rule measures (the energy's relative decrease per iteration
// over its window, Stopping_rule.h) against the threshold under which it may stop. Otherwise (a
// log) a plain line every 100 iterations, so that a failed run's stderr is its one error line.

#ifndef CONSTRAINED_FAIRING_TOOL_PROGRESS_H
#define CONSTRAINED_FAIRING_TOOL_PROGRESS_H

#include <CGAL/Polygon_mesh_processing/Constrained_fairing_settings.h>

#include <chrono>
#include <cstddef>
#include <deque>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <type_traits>

#include <unistd.h>

class Tool_progress
{
public:
  Tool_progress() : m_terminal(isatty(STDERR_FILENO) != 0), m_start(std::chrono::steady_clock::now())
  {
    judge_by(CGAL::Polygon_mesh_processing::Constrained_fairing_settings());
  }

  // The stopping rule of the call's settings (the defaults until told).
  void judge_by(const CGAL::Polygon_mesh_processing::Constrained_fairing_settings& settings)
  {
    m_window = settings.energy_decrease_window();
    settings.for_each_named_setting([this](const char* name, const char*, const auto& value) {
      if constexpr(std::is_same_v<std::decay_t<decltype(value)>, double>)
        if(std::string(name) == "energy_decrease_threshold")
          m_threshold = value;
    });
  }

  // A phase starts: "reading scan.ply", "fairing 1234 vertices", ...
  void phase(const std::string& what)
  {
    m_phase = what;
    if(m_terminal)
      show(what + ", " + elapsed_text());
  }

  // The iteration callback.
  bool operator()(std::size_t iteration, double energy)
  {
    if(m_phase.compare(0, 7, "fairing") != 0)
      m_phase = "fairing"; // the check and the start are done
    m_energies.push_back(energy);
    if(m_energies.size() > m_window + 1)
      m_energies.pop_front();
    const double elapsed = seconds();
    if(m_terminal ? elapsed - m_shown < 0.1 : iteration % 100 != 0)
      return true;
    m_shown = elapsed;
    std::ostringstream line;
    line << (m_terminal ? m_phase + ": " : std::string()) << "iteration " << iteration << ", energy " << energy << ", "
         << decrease_text() << elapsed_text();
    show(line.str());
    return true;
  }

  // Clears the terminal line.
  void done()
  {
    if(m_dirty)
      std::cerr << "\r\x1b[K" << std::flush;
    m_dirty = false;
  }

  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }

private:
  // "decrease 3.1e-04/it (threshold 0.000125), " once the window is full.
  std::string decrease_text() const
  {
    if(m_energies.size() <= m_window || !(m_energies.front() > 0))
      return std::string();
    std::ostringstream text;
    text << "decrease " << std::setprecision(2)
         << (m_energies.front() - m_energies.back()) / (double(m_window) * m_energies.front()) << "/it (threshold "
         << std::setprecision(3) << m_threshold << "), ";
    return text.str();
  }

  std::string elapsed_text() const
  {
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << seconds() << " s";
    return text.str();
  }

  void show(const std::string& line)
  {
    if(m_terminal)
      std::cerr << "\r" << line << "\x1b[K" << std::flush;
    else
      std::cerr << line << std::endl;
    m_dirty = m_terminal;
  }

  bool m_terminal, m_dirty = false;
  std::chrono::steady_clock::time_point m_start;
  double m_shown = -1;
  std::string m_phase = "fairing";
  std::size_t m_window = 0;
  double m_threshold = 0;
  std::deque<double> m_energies; // the last window + 1
};

#endif // CONSTRAINED_FAIRING_TOOL_PROGRESS_H
