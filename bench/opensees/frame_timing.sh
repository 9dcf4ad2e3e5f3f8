#!/bin/sh
# Whole-process time of the shaken elastic portal (tests/reference/opensees/frame_elastic.*) in
# Plastica and in OpenSees, each writing a VTU per step (1 004 and 1 000 files: displacement,
# velocity and acceleration among their arrays), run alternately; prints the medians.
# Usage: bench/opensees/frame_timing.sh PLASTICA OPENSEES [RUNS]
set -eu
plastica=$(realpath "$1")
opensees=$(realpath "$2")
runs=${3:-9}
here=$(cd "$(dirname "$0")/../../tests/reference/opensees" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here"/frame_elastic.toml "$here"/frame_elastic.tcl "$here"/ARL360.dat "$work"/
sed -i 's|file = "../../../models/records/ARL360.at2"|file = "'"$here"'/../../../models/records/ARL360.at2"|' "$work/frame_elastic.toml"
# OpenSees writes its series with its PVD recorder, beside the drift it records.
sed -i 's|^recorder Node|recorder PVD frame_pvd disp vel accel\nrecorder Node|' "$work/frame_elastic.tcl"
cd "$work"
seconds() { start=$(date +%s.%N); "$@" > /dev/null 2>&1; end=$(date +%s.%N); echo "$end - $start" | bc; }
: > plastica.times
: > opensees.times
for k in $(seq "$runs"); do
    rm -rf out frame_pvd*
    mkdir frame_pvd
    seconds "$plastica" run frame_elastic.toml --no-render -q -o out >> plastica.times
    seconds "$opensees" frame_elastic.tcl >> opensees.times
done
median() { sort -n "$1" | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
p=$(median plastica.times)
o=$(median opensees.times)
echo "plastica: $p s (median of $runs; $(ls out/vtu | wc -l) VTU files)"
echo "opensees: $o s (median of $runs; $(ls frame_pvd 2>/dev/null | wc -l) VTU files)"
echo "ratio: $(echo "scale=2; $o / $p" | bc)"
