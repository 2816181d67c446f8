// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A label map file, its format told by its extension (case aside): NIfTI-1 (.nii, .nii.gz,
// Nifti_file.h), INRIMAGE-4 (.inr, .inr.gz, CGAL's images, Inr_file.h) or numpy's .npy
// (Npy_file.h), read into a Label_map (Label_map.h). The one place that says which files are
// label maps and what a label map's outputs are named after, for the tool and the Python module.

#ifndef CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_FILE_H
#define CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_FILE_H

#include "front_end/Inr_file.h"
#include "front_end/Label_map.h"
#include "front_end/Npy_file.h"
#include "front_end/Nifti_file.h"

#include <array>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

namespace Constrained_fairing_front_end {

// The extensions of label map files, for messages.
constexpr const char* label_map_extensions = ".nii, .nii.gz, .inr, .inr.gz, .npy";

namespace internal {

// The extension of the label map file `path` among label_map_extensions, longest first, or
// nullptr; the file's name must be longer than it.
inline const char* label_map_extension(const std::string& path)
{
  const std::string name = std::filesystem::path(path).filename().string();
  for(const char* extension : {".nii.gz", ".inr.gz", ".nii", ".inr", ".npy"})
  {
    const std::size_t n = std::char_traits<char>::length(extension);
    if(name.size() <= n)
      continue;
    bool same = true;
    for(std::size_t c = 0; c < n; ++c)
      same = same && std::tolower(static_cast<unsigned char>(name[name.size() - n + c])) == extension[c];
    if(same)
      return extension;
  }
  return nullptr;
}

} // namespace internal

inline bool is_label_map_file(const std::string& path) { return internal::label_map_extension(path) != nullptr; }

// The file name of the label map `path` without its extension (`seg.inr.gz` -> `seg`): what its
// surfaces are named after.
inline std::string label_map_stem(const std::string& path)
{
  const std::string name = std::filesystem::path(path).filename().string();
  const char* extension = internal::label_map_extension(path);
  return extension ? name.substr(0, name.size() - std::char_traits<char>::length(extension)) : name;
}

// Reads `path` into `map`, in the format of its extension; returns the reason it cannot, or an
// empty string. All or nothing: on a defect `map` is left as it was.
inline std::string read_label_map(const std::string& path, Label_map& map)
{
  const char* extension = internal::label_map_extension(path);
  if(!extension)
    return path + ": a label map must be a " + label_map_extensions + " file";
  const std::string format = std::string(extension).substr(1, 3);
  Label_map read;
  std::string error;
  try
  {
    error = format == "nii" ? read_nifti_file(path, read) : format == "inr" ? read_inr_file(path, read)
                                                                              : read_npy_file(path, read);
  }
  catch(const std::bad_alloc&)
  {
    return path + ": not enough memory for its " + size_text(read.size) + " voxels";
  }
  catch(const std::length_error&)
  {
    return path + ": not enough memory for its " + size_text(read.size) + " voxels";
  }
  if(error.empty())
    map = std::move(read);
  return error;
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_LABEL_MAP_FILE_H
