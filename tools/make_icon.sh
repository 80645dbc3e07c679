#!/usr/bin/env bash
# Draws packaging/spindrift.png, the desktop icon, from a frame the project renders and
# checks in every test run: the demo replay's golden at tick 90 (the harbour road, the
# car in the chase camera), its middle cut square and scaled to 256 x 256 (ImageMagick).
set -euo pipefail
cd "$(dirname "$0")/.."
frame=replays/harbour_drive/tick_000090.png
side=$(identify -format '%h' "$frame")
convert "$frame" -gravity center -crop "${side}x${side}+0+0" +repage -resize 256x256 -strip packaging/spindrift.png
echo "wrote packaging/spindrift.png"
