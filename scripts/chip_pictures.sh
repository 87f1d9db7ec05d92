#!/bin/sh
# Meshes each chip shape with `chipflex mesh chip` and draws it with gmsh (offscreen, under
# xvfb-run) into docs/chips/SHAPE.png, the pictures of docs/chips.md.
#   usage: scripts/chip_pictures.sh [CHIPFLEX]    (default build/bin/chipflex)
# Needs gmsh and xvfb-run (Debian: apt-get install gmsh xvfb).
set -e
chipflex=${1:-build/bin/chipflex}
out=$(pwd)/docs/chips
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir -p "$out"

# picture NAME ROTATION_X ROTATION_Z MESH_ARGUMENTS...
picture() {
  name=$1 rx=$2 rz=$3
  shift 3
  echo "chipflex mesh chip $* -o $name.msh"
  "$chipflex" mesh chip "$@" -o "$dir/$name.msh"
  cat > "$dir/$name.geo" << GEO
Merge "$dir/$name.msh";
General.Trackball = 0;
General.RotationX = $rx;
General.RotationZ = $rz;
General.SmallAxes = 0;
General.Color.Background = {255, 255, 255};
General.Color.BackgroundGradient = {255, 255, 255};
Geometry.Points = 0;
Geometry.Curves = 0;
Mesh.SurfaceFaces = 1;
Mesh.SurfaceEdges = 1;
Mesh.ColorCarousel = 0;
Mesh.Color.Quadrangles = {200, 160, 90};
Mesh.Light = 1;
Print "$out/$name.png";
Exit;
GEO
  xvfb-run -a gmsh "$dir/$name.geo" > /dev/null
}

picture helical -60 20 --shape helical
picture spiral -30 0 --shape spiral
picture arc -50 0 --shape arc
picture ring -50 0 --shape arc --arc-angle 360
picture ribbon -60 30 --shape ribbon
