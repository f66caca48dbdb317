#!/usr/bin/env bash
# Installs every Debian package in scripts/debian-packages.txt and builds multicpg into build/.
# --cluster also installs the Slurm packages of scripts/cluster-packages.txt (for a cluster node,
# and for tests/slurm_test.sh, which brings up a one-node Slurm with scripts/slurm-local.sh).
# Usage: scripts/setup.sh [--cluster]   (as root on Debian 12)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
lists=("$root/scripts/debian-packages.txt")
case "${1-}" in
  "") ;;
  --cluster) lists+=("$root/scripts/cluster-packages.txt") ;;
  *)
    echo "setup: unknown option '$1' (usage: scripts/setup.sh [--cluster])" >&2
    exit 2
    ;;
esac
mapfile -t packages < <(cat "${lists[@]}" | grep -v '^\s*#' | grep -v '^\s*$')
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
# The Python module is built for Debian's interpreter, whatever python3 comes first on PATH.
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 \
  >/dev/null
cmake --build "$root/build" -j "$(nproc)"
