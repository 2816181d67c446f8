// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A file read through zlib, gzip-compressed or not (zlib reads a plain file as it is): the one
// way the label map readers read their bytes, so that each format comes compressed for free.

#ifndef CONSTRAINED_FAIRING_FRONT_END_ZLIB_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_ZLIB_FILE_H

#include <zlib.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace Constrained_fairing_front_end {

class Zlib_file
{
public:
  explicit Zlib_file(const std::string& path) : m_file(gzopen(path.c_str(), "rb"), &gzclose) {}

  bool is_open() const { return bool(m_file); }

  // The next `n` bytes; false if the file ends first (or is not valid gzip).
  bool read(void* into, std::size_t n)
  {
    unsigned char* bytes = static_cast<unsigned char*>(into);
    while(n > 0)
    {
      // gzread() takes an unsigned count.
      const unsigned chunk = unsigned((std::min)(n, std::size_t(1) << 30));
      if(gzread(m_file.get(), bytes, chunk) != int(chunk))
        return false;
      bytes += chunk;
      n -= chunk;
    }
    return true;
  }

  // The next `n` bytes, read in steps, so that a file shorter than `n` is found short before
  // `n` bytes of memory are used; false if it ends first.
  bool read(std::size_t n, std::vector<unsigned char>& bytes)
  {
    bytes.clear();
    bytes.reserve(n);
    const std::size_t step = std::size_t(1) << 24;
    for(std::size_t done = 0; done < n; done += step)
    {
      const std::size_t chunk = (std::min)(step, n - done);
      bytes.resize(done + chunk);
      if(!read(bytes.data() + done, chunk))
        return false;
    }
    return true;
  }

  // Past the next `n` bytes; false if the file ends first.
  bool skip(std::size_t n)
  {
    unsigned char buffer[1 << 16];
    for(; n > sizeof(buffer); n -= sizeof(buffer))
      if(!read(buffer, sizeof(buffer)))
        return false;
    return read(buffer, n);
  }

  // The next line without its '\n', at most `limit` characters; false at the end of the file
  // or on a longer line.
  bool read_line(std::string& line, std::size_t limit)
  {
    line.clear();
    for(int c = gzgetc(m_file.get()); c != '\n'; c = gzgetc(m_file.get()))
    {
      if(c < 0 || line.size() == limit)
        return false;
      line.push_back(char(c));
    }
    return true;
  }

private:
  std::unique_ptr<gzFile_s, int (*)(gzFile)> m_file;
};

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_ZLIB_FILE_H
