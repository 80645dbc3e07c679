#!/usr/bin/env bash
# A bundled replay's sound as a spectrogram with its events marked (docs/AUDIO.md):
# renders the replay's sound offline, draws the left channel's spectrogram with sox and
# marks each TICK:LABEL given with a line and its label (ImageMagick's convert).
# Usage: tools/audio_spectrogram.sh REPLAY OUT.png [TICK:LABEL ...]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 REPLAY OUT.png [TICK:LABEL ...]" >&2; exit 2; }
replay=$1 out=$2
shift 2
bin=${SPINDRIFT_BIN:-build/game/spindrift}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" replay "$replay" --headless --frames none --audio "$tmp/sound.wav" >/dev/null
width=1400 height=360
sox "$tmp/sound.wav" -n remix 1 spectrogram -r -x $width -y $height -z 90 -o "$tmp/raw.png"
seconds=$(sox --info -D "$tmp/sound.wav")
draw=()
for mark in "$@"; do
  tick=${mark%%:*} label=${mark#*:}
  x=$(awk -v t="$tick" -v d="$seconds" -v w=$width 'BEGIN { printf "%d", t / 60 / d * w }')
  draw+=(-stroke white -strokewidth 1 -draw "line $x,28 $x,$((height + 28))"
         -stroke none -fill white -annotate +$((x + 3))+14 "$label")
done
# A strip above for the labels, a time axis below (a tick mark every second).
axis=()
for ((s = 0; s <= ${seconds%.*}; ++s)); do
  x=$(awk -v s="$s" -v d="$seconds" -v w=$width 'BEGIN { printf "%d", s / d * w }')
  axis+=(-stroke white -draw "line $x,$((height + 28)) $x,$((height + 34))" -stroke none -fill white
         -annotate +$((x + 2))+$((height + 36)) "${s}s")
done
convert "$tmp/raw.png" -background black -gravity north -splice 0x28 -gravity south -splice 0x30 \
  -gravity northwest -pointsize 12 "${draw[@]}" "${axis[@]}" "$out"
echo "wrote $out ($seconds s, 0-24 kHz)"
