#!/bin/sh
# Renders the key frames of the elastic and inelastic rings at 640x360 into DIR/<scene>/:
# the unloaded ring, first yield, contact spreading, the first fully plastic hinge, the last step,
# and the chart; and of every gallery scene (models/gallery/) its first and last frames, its first yield and its peak into
# DIR/gallery/<scene>/. Used to update tests/snapshots/ on purpose and by the snapshot test.
# Usage: render-snapshots.sh PLASTICA DIR [extra render options]
# PLASTICA_MODELS=FOLDER takes the scene files from FOLDER instead of models/.
set -eu
plastica=$1
dir=$2
shift 2
here=$(cd "$(dirname "$0")/.." && pwd)
steps_elastic=0,117,200
steps_inelastic=0,80,104,129,200
scene_file() { echo "${PLASTICA_MODELS:-$here/models}/$1.toml"; }
"$plastica" run "$(scene_file ring_elastic)" -o "$dir/runs/ring_elastic" --no-render --force -q
"$plastica" run "$(scene_file ring_inelastic)" -o "$dir/runs/ring_inelastic" --no-render --force -q
"$plastica" render "$dir/runs/ring_elastic" -o "$dir/ring_elastic" --size 640x360 --steps $steps_elastic --no-animation -q "$@"
"$plastica" render "$dir/runs/ring_inelastic" -o "$dir/ring_inelastic" --size 640x360 --steps $steps_inelastic --no-animation -q "$@"
for scene in "$here"/models/gallery/*.toml; do
    name=$(basename "$scene" .toml)
    "$plastica" run "$scene" -o "$dir/runs/$name" --no-render --force -q
    # --every larger than any run: the first and the last step, and the first yield and the peak.
    "$plastica" render "$dir/runs/$name" -o "$dir/gallery/$name" --size 640x360 --every 1000000 --no-animation -q "$@"
done
rm -rf "$dir/runs"
