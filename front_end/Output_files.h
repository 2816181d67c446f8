// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the front ends write their outputs so that nothing a user had is lost: every file is
// written beside its target under a hidden temporary name and renamed into place once complete,
// so that a failed or interrupted run leaves earlier files as they were; and a run writes only
// the files it names. A folder of outputs (a label map's surfaces, label_<L>.<ext>) is created
// whole when it is new; an existing folder only gets the run's own files, and one of them that
// exists is replaced only when asked (force): the folder's other files are never touched.

#ifndef CONSTRAINED_FAIRING_FRONT_END_OUTPUT_FILES_H
#define CONSTRAINED_FAIRING_FRONT_END_OUTPUT_FILES_H

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace Constrained_fairing_front_end {

// Whether `a` and `b` name one existing file (through links and relative paths alike).
inline bool is_same_file(const std::filesystem::path& a, const std::filesystem::path& b)
{
  std::error_code error;
  const bool same = std::filesystem::equivalent(a, b, error);
  return !error && same;
}

// The hidden name beside `target` that a run writes first: the extension kept, since the
// writers choose the format by it, and the process id in it, so that two runs never share one.
inline std::filesystem::path partial_path(const std::filesystem::path& target)
{
  std::filesystem::path partial = target;
  partial.replace_filename("." + target.stem().string() + ".partial-" + std::to_string(::getpid()) +
                           target.extension().string());
  return partial;
}

// write(path) writes a file to `path` and returns an empty string or why it could not; this
// calls it on the partial path of `target`, then renames the file to `target`. Returns an empty
// string or the reason; the partial file never stays.
template <typename Write>
std::string write_file_through_partial(const std::filesystem::path& target, const Write& write)
{
  const std::filesystem::path partial = partial_path(target);
  std::string reason = write(partial.string());
  std::error_code error;
  if(reason.empty())
  {
    std::filesystem::rename(partial, target, error);
    if(!error)
      return std::string();
    reason = "cannot write " + target.string() + " (" + error.message() + ")";
  }
  std::filesystem::remove(partial, error);
  return reason;
}

// Why a run that writes the files `names` into the folder `out` from the input `in` must not
// start, or an empty string: `out` is `in`, or an existing file; or one of the files exists in
// `out` and `force` is not given (a folder of that name is never replaced). With no names, the
// checks that need no name.
inline std::string output_folder_error(const std::filesystem::path& in, const std::filesystem::path& out,
                                       const std::vector<std::string>& names, bool force)
{
  namespace fs = std::filesystem;
  std::error_code error;
  if(is_same_file(in, out))
    return "OUT is IN (" + out.string() + "): the surfaces would replace the label map; give a folder as OUT";
  const fs::file_status status = fs::status(out, error);
  if(fs::exists(status) && !fs::is_directory(status))
    return "OUT " + out.string() + " is an existing file: the surfaces go into a folder; give a new or existing folder";
  const fs::path parent = fs::absolute(out, error).parent_path();
  if(!fs::is_directory(parent, error))
    return "cannot write " + out.string() + " (no folder " + parent.string() + ")";
  for(const std::string& name : names)
  {
    const fs::file_status file = fs::symlink_status(out / name, error);
    if(fs::is_directory(file))
      return (out / name).string() + " is a folder: it is not replaced";
    if(fs::exists(file) && !force)
      return (out / name).string() + " exists: --force replaces the files of this run, and only those";
  }
  return std::string();
}

namespace internal {

// The files written into a new folder, created beside `out` and renamed to it once complete.
template <typename Write>
std::string write_new_folder(const std::filesystem::path& out, const std::vector<std::string>& names,
                             const Write& write)
{
  namespace fs = std::filesystem;
  const fs::path partial = partial_path(out);
  std::error_code error;
  if(!fs::create_directory(partial, error))
    return "cannot write " + out.string() + " (cannot create " + partial.string() +
           (error ? ": " + error.message() : std::string()) + ")";
  std::string reason;
  for(std::size_t k = 0; k < names.size() && reason.empty(); ++k)
    reason = write((partial / names[k]).string(), k);
  if(reason.empty())
  {
    fs::rename(partial, out, error);
    if(!error)
      return std::string();
    reason = "cannot write " + out.string() + " (" + error.message() + ")";
  }
  // Only what this run wrote is in the folder it created.
  for(const std::string& name : names)
    fs::remove(partial / name, error);
  fs::remove(partial, error);
  return reason;
}

// The files written into the existing folder `out` under their partial names, then renamed into
// place once all are complete.
template <typename Write>
std::string write_into_folder(const std::filesystem::path& out, const std::vector<std::string>& names,
                              const Write& write)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> partials;
  std::string reason;
  for(std::size_t k = 0; k < names.size() && reason.empty(); ++k)
  {
    partials.push_back(partial_path(out / names[k]));
    reason = write(partials.back().string(), k);
  }
  std::error_code error;
  for(std::size_t k = 0; k < partials.size() && reason.empty(); ++k)
  {
    fs::rename(partials[k], out / names[k], error);
    if(error)
      reason = "cannot write " + (out / names[k]).string() + " (" + error.message() + ")";
  }
  if(!reason.empty())
    for(const fs::path& partial : partials)
      fs::remove(partial, error);
  return reason;
}

} // namespace internal

// write(path, k) writes file k of `names` to `path` and returns an empty string or why it could
// not; this writes them all into the folder `out`, as the header says, once
// output_folder_error() has let the run start. Returns an empty string or the reason.
template <typename Write>
std::string write_files_into_folder(const std::filesystem::path& out, const std::vector<std::string>& names,
                                    const Write& write)
{
  std::error_code error;
  return std::filesystem::is_directory(out, error) ? internal::write_into_folder(out, names, write)
                                                   : internal::write_new_folder(out, names, write);
}

} // namespace Constrained_fairing_front_end

#endif // CONSTRAINED_FAIRING_FRONT_END_OUTPUT_FILES_H
