#!/usr/bin/env bash
# Renders the README's pictures with rmsc itself: every scene in samples/scenes/ to
# docs/images/<scene>.png, plus the demo's AOVs. Usage: tools/render-gallery.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
rmsc="${1:-build}/bin/rmsc"
mkdir -p docs/images
for scene in samples/scenes/*.json; do
  name=$(basename "$scene" .json)
  "$rmsc" render "$scene" -o "docs/images/$name.png" --size 640x360
done
"$rmsc" render -o docs/images/demo-small.png --size 320x180
for aov in depth normal id; do
  "$rmsc" render -o "docs/images/demo-$aov.png" --size 320x180 --aov "$aov"
done
"$rmsc" render samples/assets/sphere.gltf -o docs/images/gltf-viewer.png --size 320x180
# The viewer with its panels, under a virtual display when there is no display.
view=("$rmsc" view samples/scenes/pawn.json --size 1280x720 --embedded-shaders --script tools/viewer-gallery.txt)
if [ -n "${DISPLAY:-}" ]; then "${view[@]}"; else xvfb-run -a -s "-screen 0 1280x720x24" "${view[@]}"; fi
