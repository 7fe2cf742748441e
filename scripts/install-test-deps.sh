#!/usr/bin/env bash
# Installs what Weft's tests need on Debian when it is missing: OpenSubdiv and
# OpenMesh (the references the subdivision is compared with), a C and C++
# compiler with sanitizer runtimes (the C tests), Mono (the C# wrapper and the
# Grasshopper compile check), and the Rust components rustfmt and clippy.
set -euo pipefail
packages=(libosd-dev libopenmesh-dev g++ gcc mono-devel python3 python3-pip ca-certificates cmake pkg-config)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "Missing Debian packages: ${missing[*]}" >&2
    echo "Install them (sudo apt-get install -y ${missing[*]}) or run this script as root." >&2
    exit 1
  fi
  echo "Installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if command -v rustup >/dev/null 2>&1; then
  for component in rustfmt clippy; do
    rustup component list --installed 2>/dev/null | grep -q "^$component" || rustup component add "$component"
  done
fi
