#!/usr/bin/env bash
# Installs, as root and only when missing, the Debian packages the package,
# its tests, the tool and the benchmark need.
set -euo pipefail
pkgs=(build-essential cmake libcgal-dev libeigen3-dev libboost-dev libtet1.5-dev libtbb-dev
      libcgal-demo python3-vtk9 python3-matplotlib python3-meshio python3-numpy doxygen xvfb xauth)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
