#!/usr/bin/env bash
# Makes the README's pictures. docs/images/viewer.png: `tessera view` on the teapot under a
# virtual X server (xvfb-run), 24 frames along the orbit, patches coloured and the triangles
# drawn, the last frame saved. docs/images/cad.png: `tessera render` of a STEP model of
# FreeCAD's IDF library (Debian's freecad-common), faces coloured, triangles drawn. Run from the
# repository root after a build:
#   scripts/screenshot.sh [build/tessera] [out.png] [cad-out.png]
set -euo pipefail
tessera=${1:-build/tessera}
out=${2:-docs/images/viewer.png}
command -v xvfb-run >/dev/null || { echo "screenshot: xvfb-run is missing (apt-get install xvfb)" >&2; exit 1; }
[[ -x "$tessera" ]] || { echo "screenshot: no $tessera: build first (scripts/build.sh)" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
xvfb-run -a -s "-screen 0 1280x800x24" "$tessera" view data/teapot.bpt --size 960x540 \
  --colour patch --wireframe --frames 24 --camera-path orbit --screenshot "$out"
cad_out=${3:-docs/images/cad.png}
cad_model=/usr/share/freecad/Mod/Idf/Idflibs/SOT_96.stp
[[ -f $cad_model ]] || { echo "screenshot: no $cad_model (apt-get install freecad-common)" >&2; exit 1; }
"$tessera" render "$cad_model" --colour patch --wireframe --size 640x400 -o "$cad_out"
