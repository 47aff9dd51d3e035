#!/usr/bin/env bash
# Install what fourier-ssi needs from Debian 12 packages, only if missing.
set -euo pipefail
packages=(cmake g++ make libdeal.ii-dev gmsh libopenblas0-pthread
          python3 python3-numpy python3-scipy python3-matplotlib python3-sympy)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}"
fi
