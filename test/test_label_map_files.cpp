// Copyright (c) 2026  The CGAL Constrained Fairing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The label map files of front_end/Label_map_file.h. One map of 5 x 4 x 3 voxels, written in
// every type each format stores (its values use every byte of the type, negative ones where it
// is signed) and each byte order, as .inr, .inr.gz, .npy (formats 1.0 to 3.0, C and Fortran
// order) and NIfTI-1: the same labels from every file, the INR's affine the NIfTI's (the voxel
// sizes and origin, held exactly in float), the .npy's the identity. The INR files read as
// CGAL's ImageIO reads them (the voxels and voxel sizes of _readImage), also CGAL's liver where
// its data is extracted at /tmp/cgaldata. Each defective file refused with its defect named in
// one line, and the map left as it was; the extensions and the name stem.

#include "test_support.h"

#include "front_end/Label_map_file.h"

#include <CGAL/ImageIO.h>

#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace FE = Constrained_fairing_front_end;

const std::array<std::size_t, 3> size{5, 4, 3};
const std::array<std::array<double, 4>, 3> inr_affine{{{0.5, 0, 0, 10}, {0, 0.75, 0, -20}, {0, 0, 2.5, 5.25}}};

// The label of voxel (i, j, k) stored as `type`: steps that need every byte of the type.
std::int64_t label(const FE::Voxel_type& type, std::size_t i, std::size_t j, std::size_t k)
{
  const std::int64_t base = std::int64_t((i + 2 * j + 3 * k) % 5);
  if(type.kind == 'b')
    return base % 2;
  const std::int64_t step = type.bytes == 1 ? 25 : type.bytes == 2 ? 300 : type.bytes == 4 ? 70000 : 5000000000;
  return (base - (type.kind == 'u' ? 0 : 2)) * step;
}

std::vector<std::int64_t> expected_labels(const FE::Voxel_type& type)
{
  std::vector<std::int64_t> labels;
  for(std::size_t i = 0; i < size[0]; ++i)
    for(std::size_t j = 0; j < size[1]; ++j)
      for(std::size_t k = 0; k < size[2]; ++k)
        labels.push_back(label(type, i, j, k));
  return labels;
}

// The voxels stored as `type`, x fastest or z fastest; `bad` replaces voxel (3, 1, 2).
std::string voxel_bytes(const FE::Voxel_type& type, bool x_fastest, double bad = 0)
{
  std::string bytes;
  for(std::size_t a = 0; a < (x_fastest ? size[2] : size[0]); ++a)
    for(std::size_t j = 0; j < size[1]; ++j)
      for(std::size_t c = 0; c < (x_fastest ? size[0] : size[2]); ++c)
      {
        const std::size_t i = x_fastest ? c : a, k = x_fastest ? a : c;
        const double value = bad != 0 && i == 3 && j == 1 && k == 2 ? bad : double(label(type, i, j, k));
        FE::internal::with_voxel_type(type, [&](auto zero) {
          using T = decltype(zero);
          const T v = std::is_integral_v<T> ? T(label(type, i, j, k)) : T(value);
          unsigned char b[sizeof(T)];
          std::memcpy(b, &v, sizeof(T));
          if(type.big_endian != FE::internal::host_is_big_endian())
            std::reverse(b, b + sizeof(T));
          bytes.append(reinterpret_cast<const char*>(b), sizeof(T));
        });
      }
  return bytes;
}

std::filesystem::path folder()
{
  static const std::filesystem::path path = [] {
    const auto p = std::filesystem::temp_directory_path() / ("test_label_map_files_" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  return path;
}

std::string write_file(const std::string& name, const std::string& bytes)
{
  const std::string path = (folder() / name).string();
  if(name.size() > 3 && name.compare(name.size() - 3, 3, ".gz") == 0)
  {
    gzFile file = gzopen(path.c_str(), "wb");
    CHECK(file && gzwrite(file, bytes.data(), unsigned(bytes.size())) == int(bytes.size()));
    gzclose(file);
  }
  else
    std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// An INR header of these lines, padded to 256 bytes as CGAL's ImageIO writes it.
std::string inr_header(const std::vector<std::string>& lines)
{
  std::string header = "#INRIMAGE-4#{\n";
  for(const std::string& line : lines)
    header += line + "\n";
  header += std::string((252 - header.size() % 256 + 256) % 256, '\n');
  return header + "##}\n";
}

std::vector<std::string> inr_fields(const FE::Voxel_type& type)
{
  const char* kind = type.kind == 'u' ? "unsigned fixed" : type.kind == 'i' ? "signed fixed" : "float";
  return {"XDIM=005", "YDIM=4", "ZDIM=3", "VDIM=1", std::string("TYPE=") + kind,
          "PIXSIZE=" + std::to_string(8 * type.bytes) + " bits", "SCALE=2**0",
          type.big_endian ? "CPU=sun" : "CPU=decm", "VX=0.5", "VY=0.75", "VZ=2.5", "TX=10", "TY=-20", "TZ=5.25",
          "#GEOMETRY=CARTESIAN"};
}

// A NIfTI-1 file: sform diag(0.5, 0.75, 2.5) plus (10, -20, 5.25), voxels in the host's order.
std::string nifti(const FE::Voxel_type& type, int code)
{
  std::string header(352, '\0');
  const auto put = [&header](std::size_t at, auto value) { std::memcpy(&header[at], &value, sizeof(value)); };
  put(0, std::int32_t(348));
  for(std::size_t d = 0; d < 8; ++d)
    put(40 + 2 * d, std::int16_t(d == 0 ? 3 : d < 4 ? size[d - 1] : 1));
  put(70, std::int16_t(code));
  put(72, std::int16_t(8 * type.bytes));
  for(std::size_t d = 0; d < 4; ++d)
    put(76 + 4 * d, float(d == 0 ? 1 : inr_affine[d - 1][d - 1]));
  put(108, float(352));
  put(254, std::int16_t(1));
  for(std::size_t r = 0; r < 3; ++r)
    for(std::size_t c = 0; c < 4; ++c)
      put(280 + 16 * r + 4 * c, float(inr_affine[r][c]));
  std::memcpy(&header[344], "n+1", 4);
  FE::Voxel_type host = type;
  host.big_endian = FE::internal::host_is_big_endian();
  return header + voxel_bytes(host, true);
}

// A .npy file of this header dict, padded to 64 bytes.
std::string npy(const std::string& dict, int version = 1)
{
  const std::size_t prefix = version == 1 ? 10 : 12;
  std::string text = dict + std::string(63 - (prefix + dict.size()) % 64, ' ') + "\n";
  std::string file = "\x93NUMPY";
  file += char(version);
  file += '\0';
  for(std::size_t b = 0; b < prefix - 8; ++b)
    file += char((text.size() >> (8 * b)) & 0xff);
  return file + text;
}

std::string npy_dict(const std::string& descr, bool fortran, const std::string& shape = "(5, 4, 3)")
{
  return "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") + ", 'shape': " + shape + ", }";
}

std::string descr(const FE::Voxel_type& type)
{
  return std::string(1, type.bytes == 1 ? '|' : type.big_endian ? '>' : '<') + type.kind + std::to_string(type.bytes);
}

FE::Label_map read(const std::string& path)
{
  FE::Label_map map;
  const std::string error = FE::read_label_map(path, map);
  if(!error.empty())
    std::cerr << "unexpected: " << error << std::endl;
  CHECK(error.empty());
  return map;
}

// The voxels of CGAL's ImageIO's reading of `path`, x fastest, and its voxel sizes.
bool cgal_image(const std::string& path, std::vector<double>& voxels, std::array<double, 6>& geometry)
{
  _image* image = ::_readImage(path.c_str());
  if(!image)
    return false;
  const std::size_t n = image->xdim * image->ydim * image->zdim, w = image->wdim;
  const bool is_float = image->wordKind == WK_FLOAT, is_signed = image->sign == SGN_SIGNED;
  voxels.clear();
  for(std::size_t v = 0; v < n; ++v)
  {
    const unsigned char* p = static_cast<const unsigned char*>(image->data) + v * w;
    FE::internal::with_voxel_type({is_float ? 'f' : is_signed ? 'i' : 'u', w, FE::internal::host_is_big_endian()},
                                  [&](auto zero) {
                                    decltype(zero) x;
                                    std::memcpy(&x, p, w);
                                    voxels.push_back(double(x));
                                  });
  }
  geometry = {image->vx, image->vy, image->vz, image->tx, image->ty, image->tz};
  ::_freeImage(image);
  return true;
}

void check_as_cgal_reads(const std::string& path, const FE::Label_map& map)
{
  std::vector<double> voxels;
  std::array<double, 6> geometry;
  CHECK(cgal_image(path, voxels, geometry));
  CHECK(voxels.size() == map.labels.size());
  const std::size_t I = map.size[0], J = map.size[1], K = map.size[2];
  bool same = voxels.size() == map.labels.size();
  for(std::size_t v = 0; same && v < voxels.size(); ++v)
    same = voxels[v] == double(map.labels[(v % I * J + v / I % J) * K + v / (I * J)]);
  CHECK(same);
  for(std::size_t r = 0; r < 3; ++r)
    CHECK(geometry[r] == map.affine[r][r] && double(float(map.affine[r][3])) == geometry[3 + r]);
}

// Every type of each format, each byte order: the same labels; the INR's affine the NIfTI's.
void check_formats()
{
  const std::vector<std::pair<FE::Voxel_type, int> > types{
    {{'u', 1}, 2}, {{'i', 1}, 256}, {{'u', 2}, 512}, {{'i', 2}, 4},   {{'u', 4}, 768},
    {{'i', 4}, 8}, {{'u', 8}, 1280}, {{'i', 8}, 1024}, {{'f', 4}, 16}, {{'f', 8}, 64}};
  for(const auto& [stored, code] : types)
  {
    const std::string name = descr(stored).substr(1);
    const FE::Label_map reference = read(write_file(name + ".nii", nifti(stored, code)));
    CHECK(reference.labels == expected_labels(stored) && reference.affine == inr_affine);
    for(bool big_endian : {false, true})
    {
      FE::Voxel_type type = stored;
      type.big_endian = big_endian;
      const std::string inr = inr_header(inr_fields(type)) + voxel_bytes(type, true);
      const std::string tag = name + (big_endian ? "_big" : "_little");
      for(const std::string extension : {".inr", ".INR.gz"})
      {
        const std::string path = write_file(tag + extension, inr);
        const FE::Label_map map = read(path);
        CHECK(map.size == size && map.labels == reference.labels && map.affine == reference.affine);
        if(extension == ".inr")
          check_as_cgal_reads(path, map);
      }
      for(int version : {1, 2, 3})
        for(bool fortran : {false, true})
        {
          const std::string file = npy(npy_dict(descr(type), fortran), version) + voxel_bytes(type, fortran);
          const FE::Label_map map = read(write_file(tag + std::to_string(version) + (fortran ? "_f" : "_c") + ".npy", file));
          CHECK(map.size == size && map.labels == reference.labels);
          CHECK(map.affine == (std::array<std::array<double, 4>, 3>{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}}));
        }
    }
  }
  // bool, and a 4-D array of one volume.
  const FE::Voxel_type boolean{'b', 1};
  const std::string bits = npy(npy_dict("|b1", true)) + voxel_bytes(boolean, true);
  CHECK(read(write_file("bool.npy", bits)).labels == expected_labels(boolean));
  const std::string volume = npy(npy_dict("<i2", false, "(5, 4, 3, 1)")) + voxel_bytes({'i', 2}, false);
  CHECK(read(write_file("volume.npy", volume)).labels == expected_labels({'i', 2}));
}

// `bytes` written as `name` refused, the file and `defect` named in one line, `map` untouched.
void check_refused(const std::string& name, const std::string& bytes, const std::string& defect)
{
  const std::string path = write_file(name, bytes);
  FE::Label_map map;
  map.size = {1, 1, 1};
  map.labels = {42};
  const std::string error = FE::read_label_map(path, map);
  const bool named = error.find(path) != std::string::npos && error.find(defect) != std::string::npos &&
                     error.find('\n') == std::string::npos;
  if(!named)
    std::cerr << name << ": expected \"" << defect << "\", got \"" << error << "\"" << std::endl;
  CHECK(named);
  CHECK(map.size == (std::array<std::size_t, 3>{1, 1, 1}) && map.labels == std::vector<std::int64_t>{42});
}

// The INR fields of 16-bit signed voxels with `line` replaced by `by` (removed if empty).
std::string inr_with(const std::string& line, const std::string& by, const std::string& voxels = "")
{
  std::vector<std::string> fields = inr_fields({'i', 2});
  const auto at = std::find_if(fields.begin(), fields.end(), [&](const std::string& f) { return f.rfind(line, 0) == 0; });
  if(at == fields.end())
    fields.push_back(by);
  else if(by.empty())
    fields.erase(at);
  else
    *at = by;
  return inr_header(fields) + (voxels.empty() ? voxel_bytes({'i', 2}, true) : voxels);
}

void check_inr_defects()
{
  const std::string good = inr_with("VDIM", "VDIM=1");
  check_refused("magic.inr", "#INRIMAGE-5#{\n" + good.substr(14), "not an INRIMAGE-4 file");
  check_refused("short.inr", good.substr(0, 100), "truncated header (no ##} line)");
  check_refused("long.inr", "#INRIMAGE-4#{\n" + std::string(std::size_t(1) << 20, '\n') + "##}\n",
                "no end of header (##}) in its first MiB");
  check_refused("no_xdim.inr", inr_with("XDIM", ""), "its header gives no XDIM");
  check_refused("no_zdim.inr.gz", inr_with("ZDIM", ""), "its header gives no ZDIM");
  check_refused("zero.inr", inr_with("YDIM", "YDIM=0"), "YDIM=0 is not a positive whole number");
  check_refused("letters.inr", inr_with("XDIM", "XDIM=5a"), "XDIM=5a is not a positive whole number");
  check_refused("vector.inr", inr_with("VDIM", "VDIM=3"), "VDIM=3: a label map has one value per voxel");
  check_refused("no_type.inr", inr_with("TYPE", ""), "its header gives no TYPE");
  check_refused("type.inr", inr_with("TYPE", "TYPE=complex"), "unknown TYPE=complex");
  check_refused("no_pixsize.inr", inr_with("PIXSIZE", ""), "its header gives no PIXSIZE");
  check_refused("pixsize.inr", inr_with("PIXSIZE", "PIXSIZE=12 bits"),
                "TYPE=signed fixed with PIXSIZE=12 bits: not a type of voxels");
  check_refused("bits.inr", inr_with("PIXSIZE", "PIXSIZE=16"), "PIXSIZE=16 is not a size in bits");
  check_refused("half.inr", inr_with("TYPE", "TYPE=float"), "TYPE=float with PIXSIZE=16 bits: not a type of voxels");
  check_refused("cpu.inr", inr_with("CPU", "CPU=vax"), "unknown CPU=vax");
  check_refused("no_cpu.inr", inr_with("CPU", ""), "its header gives no CPU, the byte order of its 16-bit voxels");
  check_refused("vx.inr", inr_with("VX", "VX=-1"), "VX=-1 is not a positive voxel size");
  check_refused("vz.inr", inr_with("VZ", "VZ=1,5"), "VZ=1,5 is not a positive voxel size");
  check_refused("tx.inr", inr_with("TX", "TX=nan"), "TX=nan is not a finite number");
  check_refused("line.inr", inr_with("SCALE", "garbage"), "header line \"garbage\" is neither KEY=VALUE nor a comment");
  check_refused("late.inr", inr_with("XO", "XO=3"),
                "header line \"XO=3\" follows its comments or padding, where CGAL's ImageIO reads no field");
  check_refused("data.inr.gz", good.substr(0, good.size() - 1), "truncated (5 x 4 x 3 voxels announced)");
  const FE::Voxel_type f4{'f', 4};
  const std::string fraction = inr_header(inr_fields(f4)) + voxel_bytes(f4, true, 0.5);
  check_refused("fraction.inr", fraction, "voxel (3, 1, 2) is not a whole number: not a label map");
  check_refused("broken.inr.gz", "\x1f\x8b\x08 broken", "not an INRIMAGE-4 file");
  check_refused("missing/none.inr", "", "cannot open");
  // Without CPU, 8-bit voxels need no byte order.
  FE::Voxel_type u1{'u', 1};
  std::vector<std::string> fields = inr_fields(u1);
  fields.erase(std::find(fields.begin(), fields.end(), "CPU=decm"));
  CHECK(read(write_file("no_cpu_8.inr", inr_header(fields) + voxel_bytes(u1, true))).labels == expected_labels(u1));
}

void check_npy_defects()
{
  const FE::Voxel_type i2{'i', 2}, f8{'f', 8}, u8{'u', 8};
  const std::string voxels = voxel_bytes(i2, false), dict = npy_dict("<i2", false);
  check_refused("magic.npy", "\x93NUMPX" + npy(dict).substr(6) + voxels, "not a .npy file (it does not start with \\x93NUMPY)");
  check_refused("version.npy", npy(dict, 4) + voxels, "unsupported .npy format 4.0");
  check_refused("short.npy", npy(dict).substr(0, 40), "truncated header");
  check_refused("long.npy", std::string("\x93NUMPY\x02\x00\x00\x00\x00\x01", 12), "no .npy header is so long");
  check_refused("list.npy", npy("['descr']") + voxels, "its header does not read as a dict of 'key': value");
  check_refused("value.npy", npy("{'descr': <i2}") + voxels, "its header's 'descr' is not a string, True, False");
  check_refused("no_shape.npy", npy("{'descr': '<i2', 'fortran_order': False}") + voxels, "its header gives no 'shape'");
  check_refused("order.npy", npy("{'descr': '<i2', 'fortran_order': 'C', 'shape': (5, 4, 3)}") + voxels,
                "its header's 'fortran_order' is not True or False");
  check_refused("keys.npy", npy("{'descr': '<i2', 'fortran_order': False, 'shape': (5, 4, 3), 'x': 1,}") + voxels,
                "its header's 'x' is not a string");
  check_refused("extra.npy", npy("{'descr': '<i2', 'fortran_order': False, 'shape': (5, 4, 3), 'x': (1,)}") + voxels,
                "keys other than 'descr', 'fortran_order' and 'shape'");
  check_refused("complex.npy", npy(npy_dict("<c8", false)) + voxels, "dtype '<c8' is not a label map's");
  check_refused("half.npy", npy(npy_dict("<f2", false)) + voxels, "dtype '<f2' is not a label map's");
  check_refused("flat.npy", npy(npy_dict("<i2", false, "(4, 4)")) + voxels, "a label map must be 3-D (shape (4, 4))");
  check_refused("line.npy", npy(npy_dict("<i2", false, "(60,)")) + voxels, "a label map must be 3-D (shape (60,))");
  check_refused("volumes.npy", npy(npy_dict("<i2", false, "(5, 4, 3, 2)")) + voxels, "a label map must be 3-D");
  check_refused("empty.npy", npy(npy_dict("<i2", false, "(5, 0, 3)")), "an image dimension is not positive");
  check_refused("data.npy", npy(dict) + voxels.substr(1), "truncated (5 x 4 x 3 voxels announced)");
  // The voxel found in either order; beyond the range of labels.
  for(bool fortran : {false, true})
    check_refused(fortran ? "fraction_f.npy" : "fraction_c.npy",
                  npy(npy_dict("<f8", fortran)) + voxel_bytes(f8, fortran, 0.5),
                  "voxel (3, 1, 2) is not a whole number: not a label map");
  check_refused("nan.npy", npy(npy_dict("<f8", false)) + voxel_bytes(f8, false, std::nan("")), "voxel (3, 1, 2) is not a whole number");
  check_refused("huge.npy", npy(npy_dict("<f8", false)) + voxel_bytes(f8, false, 1e17), "voxel (3, 1, 2) is beyond the labels' range");
  std::string big = voxel_bytes(u8, false);
  std::memset(&big[8 * ((3 * 4 + 1) * 3 + 2)], 0xff, 8);
  check_refused("unsigned.npy", npy(npy_dict("<u8", false)) + big, "voxel (3, 1, 2) is beyond the labels' range");
}

void check_names()
{
  for(const char* name : {"seg.nii", "dir/SEG.NII.GZ", "seg.inr", "seg.Inr.Gz", "seg.npy"})
  {
    CHECK(FE::is_label_map_file(name));
    CHECK(FE::label_map_stem(name) == (name[0] == 'd' ? "SEG" : "seg"));
  }
  for(const char* name : {"seg.gz", "seg.inr.gzip", "seg.off", "dir/.inr", ".npy", "seg.nii.gz.off"})
    CHECK(!FE::is_label_map_file(name));
  check_refused("labels.txt", "1 2 3", "a label map must be a .nii, .nii.gz, .inr, .inr.gz, .npy file");
}

// CGAL's liver, where its data is extracted: the labels and voxel sizes that CGAL reads.
void check_liver()
{
  const std::string liver = "/tmp/cgaldata/data/images/liver.inr.gz";
  if(!std::filesystem::exists(liver))
  {
    std::cout << "  no " << liver << " (CGAL's data, libcgal-dev's data.tar.gz): not checked" << std::endl;
    return;
  }
  const FE::Label_map map = read(liver);
  CHECK(map.size == (std::array<std::size_t, 3>{438, 353, 165}));
  CHECK(std::set<std::int64_t>(map.labels.begin(), map.labels.end()) == (std::set<std::int64_t>{0, 84, 85, 127, 255}));
  // CGAL's ImageIO here reads no gzip: the file decompressed.
  gzFile file = gzopen(liver.c_str(), "rb");
  std::string bytes;
  char buffer[1 << 16];
  for(int n; (n = gzread(file, buffer, sizeof(buffer))) > 0;)
    bytes.append(buffer, std::size_t(n));
  gzclose(file);
  check_as_cgal_reads(write_file("liver.inr", bytes), map);
  std::cout << "  " << liver << ": " << FE::size_text(map.size) << " voxels, labels 0, 84, 85, 127, 255, as CGAL reads them"
            << std::endl;
}

int main()
{
  check_formats();
  check_inr_defects();
  check_npy_defects();
  check_names();
  check_liver();
  std::filesystem::remove_all(folder());
  return test::report("test_label_map_files");
}
