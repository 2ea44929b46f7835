#!/usr/bin/env bash
# Installs the Debian 12 packages NeedleBench builds, tests and runs with.
# Only what is missing is installed; needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config lld
  qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  linguist-qt6 qt6-serialport-dev qt6-svg-dev qt6-translations-l10n libgl-dev
  libqcustomplot-dev libqcustomplot2.1-qt6
  libeigen3-dev libopencv-dev libusb-1.0-0-dev libhdf5-dev hdf5-tools
  umockdev libumockdev-dev
  ffmpeg xvfb xauth fonts-dejavu-core
  octave python3-h5py python3-pandas libxml2-utils poppler-utils
  xdotool imagemagick
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; install as root: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
