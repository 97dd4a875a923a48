#!/usr/bin/env bash
# Installs the Debian packages tirefem needs to build, test and plot. Safe to run repeatedly.
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libopenblas-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev libgtest-dev gnuplot-nox)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
