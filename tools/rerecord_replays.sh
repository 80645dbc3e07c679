#!/usr/bin/env bash
# Re-records bundled replays from their scripts and rewrites their golden frames. Needed
# after any sim change that alters results (bump kSimVersion in sim/world/World.cpp first)
# and after a level or asset change. Look at the new goldens before committing them.
#   tools/rerecord_replays.sh [NAME ...]     (default: every replays/*.script)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${SPINDRIFT:-build/game/spindrift}
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for s in replays/*.script; do names+=("$(basename "$s" .script)"); done
fi
for name in "${names[@]}"; do
  script=replays/$name.script
  [ -f "$script" ] || { echo "rerecord: no $script" >&2; exit 2; }
  level=$(awk '$1 == "level" { print $2; exit }' "$script")
  "$bin" record --level "${level:-harbour}" --script "$script" --out "replays/$name.replay"
  rm -f "replays/$name"/tick_*.png  # checkpoints may have moved
  "$bin" replay "replays/$name.replay" --headless --update-goldens
done
