#!/usr/bin/env bash
# Runs a command inside a Debian chroot of another release (run as root):
#   bash Scripts/debian_chroot.sh trixie|sid COMMAND [ARG...]
# Makes the chroot with debootstrap if it does not exist yet (about 30 s; later runs reuse it),
# mounts /proc, /sys, /dev, /dev/pts and /dev/shm (Xvfb and MPI need them) and this source tree
# at the same path inside, runs COMMAND there from the source tree, and unmounts again.
# The chroots live under ${PR_CHROOT_ROOT:-/var/lib/particlerendering/chroots}; packages come
# from the Debian mirror the host's apt uses (or ${PR_DEBIAN_MIRROR}). Packages inside are installed by
# Scripts/install_dependencies.sh, which run_tests.sh calls in the chroot like on the host.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
release=${1:-}
case "$release" in
  trixie | sid) shift ;;
  *) echo "usage: $0 trixie|sid COMMAND [ARG...]" >&2; exit 2 ;;
esac
[ $# -gt 0 ] || { echo "usage: $0 trixie|sid COMMAND [ARG...]" >&2; exit 2; }
if [ "$(id -u)" -ne 0 ]; then
  echo "debian_chroot: debootstrap, mount and chroot need root" >&2
  exit 1
fi
root=${PR_CHROOT_ROOT:-/var/lib/particlerendering/chroots}
dir=$root/$release
mkdir -p "$root"

# One user of a chroot at a time: the mounts below are shared by everything inside it.
exec 9>"$root/$release.lock"
flock 9

# The mirror the host's apt uses for Debian's main archive.
# (deb822 "URIs:" lines or one-line "deb" entries)
mirror=${PR_DEBIAN_MIRROR:-}
[ -n "$mirror" ] || mirror=$( { cat /etc/apt/sources.list.d/*.sources /etc/apt/sources.list \
  /etc/apt/sources.list.d/*.list 2>/dev/null || true; } | awk '$1 == "URIs:" || $1 == "deb" {
    for (i = 2; i <= NF; ++i) if ($i ~ /\/debian\/?$/) { print $i; exit } }')

if [ ! -e "$dir/.particlerendering-ready" ]; then
  [ -n "$mirror" ] || { echo "debian_chroot: no Debian mirror in the host's apt sources; set PR_DEBIAN_MIRROR" >&2; exit 1; }
  command -v debootstrap >/dev/null || {
    echo "debian_chroot: installing debootstrap"
    apt-get update -q
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap
  }
  echo "debian_chroot: creating the Debian $release chroot in $dir from $mirror"
  rm -rf "$dir.partial"
  start=$SECONDS
  debootstrap --variant=minbase "$release" "$dir.partial" "$mirror" > "$root/$release.debootstrap.log" 2>&1 || {
    echo "debian_chroot: debootstrap failed; the last lines of $root/$release.debootstrap.log:" >&2
    tail -n 20 "$root/$release.debootstrap.log" >&2
    exit 1
  }
  # The mirror's copy of unstable may carry a Release file past its validity date.
  echo 'Acquire::Check-Valid-Until "false";' > "$dir.partial/etc/apt/apt.conf.d/99particlerendering"
  touch "$dir.partial/.particlerendering-ready"
  mv "$dir.partial" "$dir"
  echo "debian_chroot: chroot made in $((SECONDS - start)) s"
fi
cp /etc/resolv.conf "$dir/etc/resolv.conf" 2>/dev/null || true

# Holding the lock, every mount under the chroot is left over from a run that was killed before
# it could unmount (SIGKILL skips the EXIT trap). Mounting again over them fails ("already
# mounted"), so take them down first, deepest first.
stale() { awk -v d="$dir" '$2 == d || index($2, d "/") == 1 { print $2 }' /proc/self/mounts | sort -r; }
for m in $(stale); do
  echo "debian_chroot: unmounting $m, left over from an earlier run"
  umount "$m" 2>/dev/null || umount -l "$m" || true
done
if [ -n "$(stale)" ]; then
  echo "debian_chroot: cannot unmount what an earlier run left under $dir:" >&2
  stale >&2
  exit 1
fi

mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; --i)); do
    umount "${mounted[$i]}" 2>/dev/null || umount -l "${mounted[$i]}" || true
  done
}
trap cleanup EXIT
bind() { # bind SOURCE TARGET-inside-the-chroot
  mkdir -p "$dir$2"
  mount --bind "$1" "$dir$2"
  mounted+=("$dir$2")
}
mkdir -p "$dir/proc" "$dir/sys"
mount -t proc proc "$dir/proc"; mounted+=("$dir/proc")
mount -t sysfs sysfs "$dir/sys"; mounted+=("$dir/sys")
bind /dev /dev
bind /dev/pts /dev/pts
bind /dev/shm /dev/shm
bind "$top" "$top"

# A clean environment: the host's PATH, Python and library variables mean nothing inside.
env_vars=(HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
  LANG=C.UTF-8 TERM="${TERM:-dumb}" PR_CHROOT_RELEASE="$release")
for v in CI BUILD_DIR OUT_DIR MESA_DEBUG PR_XVFB_SCREEN CTEST_PARALLEL_LEVEL PR_CMAKE_ARGS; do
  [ -n "${!v:-}" ] && env_vars+=("$v=${!v}")
done
status=0
chroot "$dir" /usr/bin/env -i "${env_vars[@]}" /bin/bash -c 'cd "$0" && exec "$@"' "$top" "$@" || status=$?
exit $status
