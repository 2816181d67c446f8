// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's progress on stderr. On a terminal, one line rewritten at most ten times a second:
// each phase as it starts (reading, checking and starting, fairing, writing), then the
// iterations. Otherwise (a log) a plain line every 100 iterations, so that a failed run's
// stderr is its one error line.

#ifndef CONSTRAINED_FAIRING_TOOL_PROGRESS_H
#define CONSTRAINED_FAIRING_TOOL_PROGRESS_H

#include <chrono>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include <unistd.h>

class Tool_progress
{
public:
  Tool_progress() : m_terminal(isatty(STDERR_FILENO) != 0), m_start(std::chrono::steady_clock::now()) {}

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
    const double elapsed = seconds();
    if(m_terminal ? elapsed - m_shown < 0.1 : iteration % 100 != 0)
      return true;
    m_shown = elapsed;
    std::ostringstream line;
    line << (m_terminal ? m_phase + ": " : std::string()) << "iteration " << iteration << ", energy " << energy << ", " << elapsed_text();
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
};

#endif // CONSTRAINED_FAIRING_TOOL_PROGRESS_H
