// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one grammar of a tolerance written as text, which the command-line tool's --eps and the
// Python batch's eps both read (the batch through the Python module), so that a text means the
// same everywhere:
//   0.002    absolute, in the mesh's units
//   0.25h    relative: that many mean edge lengths h; "h" alone is 1 h
//   auto     the noise level estimated from the mesh (estimate_noise_level())
// Case and blanks around the number and the h are ignored. A number is written in decimal (digits, a point, an
// exponent), with no sign but an optional "+", and must be positive and finite: "inf", "nan",
// hexadecimal and locale-dependent forms are refused rather than read differently by C++ and
// Python.

#ifndef CONSTRAINED_FAIRING_FRONT_END_EPSILON_GRAMMAR_H
#define CONSTRAINED_FAIRING_FRONT_END_EPSILON_GRAMMAR_H

#include <cctype>
#include <cmath>
#include <cstddef>
#include <locale>
#include <sstream>
#include <string>

namespace Constrained_fairing_front_end {

// The tolerance of a front end's call that names none: a quarter of the mean edge length, the
// noise that the default call's figures in the manual were measured at.
inline const std::string default_epsilon_text = "0.25h";

struct Epsilon_text
{
  enum class Kind
  {
    ABSOLUTE,
    RELATIVE, // times the mean edge length
    AUTO      // the estimated noise level
  };

  Kind kind = Kind::ABSOLUTE;
  double value = 0; // the number written (1 for "h" alone, 0 for auto)
  std::string error; // empty if the text is well formed, else why not, for "EPS " + error
};

namespace internal {

// Whether `text` is a decimal number: digits with at most one point (and at least one digit),
// then optionally an exponent.
inline bool is_decimal(const std::string& text)
{
  std::size_t i = 0, digits = 0;
  if(i < text.size() && text[i] == '+')
    ++i;
  for(; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i)
    ++digits;
  if(i < text.size() && text[i] == '.')
    for(++i; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i)
      ++digits;
  if(digits == 0)
    return false;
  if(i < text.size() && text[i] == 'e')
  {
    ++i;
    if(i < text.size() && (text[i] == '+' || text[i] == '-'))
      ++i;
    const std::size_t exponent = i;
    while(i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])))
      ++i;
    if(i == exponent)
      return false;
  }
  return i == text.size();
}

} // namespace internal

inline Epsilon_text parse_epsilon(const std::string& written)
{
  std::string text;
  for(char c : written)
    text += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const char* const blanks = " \t\n\r\f\v";
  text.erase(text.find_last_not_of(blanks) + 1);
  text.erase(0, text.find_first_not_of(blanks));

  Epsilon_text eps;
  if(text == "auto")
  {
    eps.kind = Epsilon_text::Kind::AUTO;
    return eps;
  }
  std::string number = text;
  if(!text.empty() && text.back() == 'h')
  {
    eps.kind = Epsilon_text::Kind::RELATIVE;
    number = text.substr(0, text.size() - 1);
    number.erase(number.find_last_not_of(blanks) + 1); // npos + 1 == 0: all blanks
    if(number.empty())
      number = "1";
  }
  if(number.size() > 1 && number[0] == '-' && internal::is_decimal(number.substr(1)))
  {
    eps.error = "must be positive (got '" + written + "')";
    return eps;
  }
  if(!internal::is_decimal(number))
  {
    eps.error = "must be a number, a number followed by h, or auto (got '" + written + "')";
    return eps;
  }
  // The classic locale: a point is the decimal point whatever the user's locale.
  std::istringstream stream(number);
  stream.imbue(std::locale::classic());
  // Out of range (1e400, 1e-400) fails the stream: neither is a usable tolerance.
  if(!(stream >> eps.value) || !(std::isfinite(eps.value) && eps.value > 0))
    eps.error = "must be positive and finite (got '" + written + "')";
  return eps;
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_EPSILON_GRAMMAR_H
