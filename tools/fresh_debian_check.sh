#!/usr/bin/env bash
# Checks the README's two Quick start commands on a fresh Debian 12 root made by debootstrap
# (minbase), as root in a chroot, from a clean clone of this repository's HEAD.
#   tools/fresh_debian_check.sh [WORKDIR]     (default WORKDIR: /tmp/ferro-fresh)
# Needs root, debootstrap and access to the Debian mirror. The clone is used on its own (the
# repository carries its data in data/).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-/tmp/ferro-fresh}
root=$work/root
if [ ! -x "$root/bin/bash" ]; then
  mkdir -p "$work"
  debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
rm -rf "$root/work" && mkdir -p "$root/work"
git clone -q "$repo" "$root/work/main"
for fs in proc sys dev; do mountpoint -q "$root/$fs" || mount --bind "/$fs" "$root/$fs"; done
trap 'for fs in proc sys dev; do umount -l "$root/$fs" 2>/dev/null || true; done' EXIT
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin bash -c \
  'cd /work/main && bash tools/quickstart.sh && bash tools/test.sh'
echo "fresh Debian 12: both Quick start commands succeeded"
