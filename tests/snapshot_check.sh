#!/bin/sh
# Renders the ring and gallery snapshots again and compares them with tests/snapshots/ through
# `plastica compare`. CASE unchanged must pass (exit 0); each deliberate change must fail (exit 1):
# load (the ring pushed 10 % further per step, to 110), colours (another field), hinges (layer left out;
# compared in the structure view alone, so that the markers, not the legend's entries, must differ).
# Usage: snapshot_check.sh PLASTICA SOURCE_DIR WORK_DIR CASE
set -eu
plastica=$1
source=$2
work=$3/$4
rm -rf "$work"
mkdir -p "$work"
expected=1
region=0,0,1,1
case $4 in
    unchanged) expected=0; "$source/scripts/render-snapshots.sh" "$plastica" "$work/pictures" ;;
    load)
        mkdir -p "$work/models"
        sed 's/^increment = 0.5$/increment = 0.55/; s/^target_displacement = 100.0$/target_displacement = 110.0/' "$source/models/ring_elastic.toml" > "$work/models/ring_elastic.toml"
        sed 's/^increment = 0.5$/increment = 0.55/; s/^target_displacement = 100.0$/target_displacement = 110.0/' "$source/models/ring_inelastic.toml" > "$work/models/ring_inelastic.toml"
        if cmp -s "$source/models/ring_inelastic.toml" "$work/models/ring_inelastic.toml"; then
            echo "the edit did not apply"; exit 2
        fi
        PLASTICA_MODELS="$work/models" "$source/scripts/render-snapshots.sh" "$plastica" "$work/pictures" ;;
    colours) "$source/scripts/render-snapshots.sh" "$plastica" "$work/pictures" --field axial_force ;;
    hinges) region=0,0.11,0.43,1
            "$source/scripts/render-snapshots.sh" "$plastica" "$work/pictures" --hide hinges ;;
    *) echo "unknown case $4"; exit 2 ;;
esac
status=0
"$plastica" compare "$work/pictures" "$source/tests/snapshots" --region "$region" --diff "$work/diff" || status=$?
echo "compare exited with $status, expected $expected"
test "$status" -eq "$expected"
