#!/usr/bin/env bash
# Installs the Debian packages Plastica needs, and only those that are missing. Extra package
# names given as arguments are added (`make fuzz` adds clang).
set -euo pipefail
packages=(cmake g++ make pkg-config libeigen3-dev libtomlplusplus-dev libboost-program-options-dev
          libvtk9-dev libosmesa6-dev libglew-dev catch2 libbenchmark-dev ffmpeg "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "Installing missing Debian packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
