#!/usr/bin/env bash
# Installs the Debian packages Plastica needs, and only those that are missing. Extra package
# names given as arguments are added (`make fuzz` adds clang). It never removes a package:
# apt-get runs with --no-remove, so a conflict stops the install with an explanation instead.
set -euo pipefail
packages=(cmake ninja-build g++ make pkg-config libeigen3-dev libspectra-dev libtomlplusplus-dev nlohmann-json3-dev libboost-program-options-dev zlib1g-dev liblz4-dev
          libvtk9-dev libpng-dev libosmesa6-dev libglew-dev fonts-dejavu-core catch2 libbenchmark-dev ffmpeg parallel
          pybind11-dev python3-dev python3-venv python3-numpy python3-pytest python3-matplotlib python3-nbclient jupyter-nbconvert python3-ipykernel "$@")
# One dpkg-query for all: the check runs before every make run.
installed=$(dpkg-query -W -f='${Package} ${Status}\n' "${packages[@]}" 2>/dev/null | awk '/install ok installed/ {print $1}' || true)
missing=()
for p in "${packages[@]}"; do
  grep -qxF "$p" <<< "$installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "Installing missing Debian packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
# Another apt-get (an unattended upgrade, a second make) may hold the package lock: wait for it.
apt=($SUDO apt-get -o DPkg::Lock::Timeout=600)
"${apt[@]}" update -q
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! DEBIAN_FRONTEND=noninteractive "${apt[@]}" install -y -q --no-remove --no-install-recommends "${missing[@]}" 2>&1 | tee "$log"; then
  if grep -qi "remov" "$log"; then
    cat >&2 <<'MSG'

install-deps.sh: apt-get would have to remove a package to install Plastica's dependencies, and
this script never removes one. The usual cause on Debian 12: python3-paraview (ParaView's pvpython
and pvbatch) conflicts with python3-vtk9, which libvtk9-dev depends on, so the two cannot be
installed together. Choose one:
  - keep ParaView's Python and build Plastica in a container or another machine, or
  - remove python3-paraview yourself (apt-get remove python3-paraview), then run make again.
The ParaView GUI (package paraview) does not conflict and opens Plastica's PVD files either way.
MSG
  else
    echo "install-deps.sh: apt-get could not install: ${missing[*]} (its messages are above)" >&2
  fi
  exit 1
fi
