#!/bin/bash
# Fetches the CGAL demo meshes that fairing_accuracy measures (femur, camel, bull, lion-head,
# homer, armadillo) and the CAD parts that fairing_features measures (fandisk, joint, blade,
# part, dragknob, anchor, cube-meshed, pinion, rotor, turbine, spool, couplingdown,
# mech-holes-shark), and the real scans that point_set_scans and the
# manual's point set figure read (kitten, oni, hippo, building, of data/points_3), and the CT
# label image that label_map_speed.py reads (data/images/liver.inr.gz), from Debian's
# libcgal-demo package (in /usr/share/doc/libcgal-dev/data.tar.gz), into DIR (default:
# cgal_demo_data in the current folder, which is where a build folder's benchmarks look).
#
#   get_demo_meshes.sh [DIR]
set -euo pipefail
dir=$(realpath -m "${1:-cgal_demo_data}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
apt-get download libcgal-demo >/dev/null
dpkg -x libcgal-demo_*.deb package
mkdir -p "$dir"
tar -xzf package/usr/share/doc/libcgal-dev/data.tar.gz -C "$work"
mkdir -p "$dir/meshes"
for name in femur camel bull lion-head homer armadillo fandisk joint blade part dragknob anchor cube-meshed \
    pinion rotor turbine spool couplingdown mech-holes-shark; do
  cp "$(find "$work" -path "*/data/meshes/$name.off" | head -1)" "$dir/meshes/"
done
mkdir -p "$dir/points_3"
for name in kitten.xyz oni.pwn hippo1.ply building.ply; do
  cp "$(find "$work" -path "*/data/points_3/$name" | head -1)" "$dir/points_3/"
done
mkdir -p "$dir/images"
cp "$(find "$work" -path "*/data/images/liver.inr.gz" | head -1)" "$dir/images/"
echo "CGAL demo meshes in $dir/meshes, scans in $dir/points_3, the liver in $dir/images"
