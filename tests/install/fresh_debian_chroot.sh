#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs HulaHoops the way a user does on a fresh Debian 12 that never saw the project: a minimal
# bookworm (debootstrap --variant=minbase) gets a clean `git archive` of the source (no build tree),
# scripts/setup-debian.sh installs what a run needs (run mode, no --test) from Debian's mirror, and then,
# as an unprivileged user, what docs/python.md says:
#   python3 -m venv --system-site-packages v && v/bin/pip install --no-build-isolation .
# every ```python block of docs/python.md, of docs/howto/*.md and of the README runs in that venv (from a
# scratch directory holding a copy of examples/, as python/tests/test_docs.py runs them);
#   v/bin/pip wheel --no-build-isolation --no-deps -w dist .
# installs into a second venv which imports hulahoops with the source and build tree moved away and
# checks a curve against its closed form, a STEP file written and read back through the helper the wheel
# ships, and a pagmo run through the plugin the wheel ships.
#
# Not in ctest: it needs root (chroot, mounts), the network (Debian's mirror) and ~30 min of CPU.
#   sudo sh tests/install/fresh_debian_chroot.sh [DIR [REF]]
# DIR (default /work/chroot-bookworm; keep it outside any git worktree) holds DIR/base, the pristine
# debootstrap (made on the first run, reused after), and DIR/root, a fresh copy of it for each run
# (removed at the start of the next run, so it can be inspected afterwards). REF is the commit whose
# `git archive` is installed (default HEAD of the repository holding this script). The build runs under
# `nice -n 19` with CMAKE_BUILD_PARALLEL_LEVEL (default 2) jobs. Each step's wall time is printed as
# "step NAME: S s". docs/python.md ("On a fresh Debian 12") records a run.
set -eu

dir=${1:-/work/chroot-bookworm}
here=$(cd "$(dirname "$0")/../.." && pwd)
ref=${2:-HEAD}
jobs=${CMAKE_BUILD_PARALLEL_LEVEL:-2}
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
base="$dir/base"
root="$dir/root"

if [ "$(id -u)" -ne 0 ]; then
  echo "fresh_debian_chroot: run as root (debootstrap, chroot and mounts need it)" >&2
  exit 1
fi
case "$dir" in
  "$here" | "$here"/*)
    echo "fresh_debian_chroot: $dir is inside the source tree; give a directory outside it" >&2
    exit 2
    ;;
esac

step_start=0
step() {
  step_name=$1
  step_start=$(date +%s)
  echo "== $step_name ($(date -u +%H:%M:%S) UTC)"
}
step_done() { echo "step $step_name: $(($(date +%s) - step_start)) s"; }

mounted=""
cleanup() {
  status=$?
  # Unmount in the reverse order of mounting; a busy mount is detached lazily rather than left behind.
  for m in $mounted; do umount "$m" 2>/dev/null || umount -l "$m" || true; done
  mounted=""
  exit "$status"
}
trap cleanup EXIT INT TERM HUP
mount_in() {  # mount_in TYPE SOURCE TARGET [OPTIONS]
  mkdir -p "$3"
  mount -t "$1" "$2" "$3" ${4:+-o "$4"}
  mounted="$3 $mounted"
}

total_start=$(date +%s)
if [ ! -x "$base/usr/bin/apt-get" ]; then
  command -v debootstrap >/dev/null 2>&1 || apt-get install -y -qq debootstrap
  step "debootstrap bookworm (minbase) into $base"
  rm -rf "$base"
  debootstrap --variant=minbase bookworm "$base" "$mirror"
  step_done
fi

step "fresh copy of the base system into $root"
rm -rf "$root"
cp -a "$base" "$root"
cp /etc/resolv.conf "$root/etc/resolv.conf"
# What debootstrap leaves: bookworm main only; the point-release updates and security fixes as a user has.
cat >"$root/etc/apt/sources.list" <<EOF
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb http://deb.debian.org/debian-security bookworm-security main
EOF
step_done

# /dev: debootstrap's device nodes (null, zero, urandom, tty, ...), not the host's /dev bound in, so that
# nothing mounted below it can reach the host's.
mount_in proc proc "$root/proc"
mount_in sysfs sysfs "$root/sys"
mount_in devpts devpts "$root/dev/pts" newinstance,ptmxmode=0666
mount_in tmpfs tmpfs "$root/dev/shm"

step "git archive $ref of $here"
rev=$(git -C "$here" rev-parse --verify "$ref^{commit}")
mkdir -p "$root/opt/hulahoops-src"
git -C "$here" archive --format=tar "$rev" | tar -x -C "$root/opt/hulahoops-src"
echo "commit $rev, $(find "$root/opt/hulahoops-src" -type f | wc -l) files"
if [ -e "$root/opt/hulahoops-src/build" ]; then
  echo "fresh_debian_chroot: the archive holds a build/ directory" >&2
  exit 1
fi
step_done

# Inside the chroot: a login-less environment, as a fresh shell has it.
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 HOME=/root "$@"; }
# The user's commands: numeric ids (the names exist only in the chroot), no PyPI (PIP_NO_INDEX: what pip
# needs comes from Debian's packages through --system-site-packages and --no-build-isolation).
as_user() { chroot --userspec="$uid:$gid" "$root" /usr/bin/env -i PATH=/usr/local/bin:/usr/bin:/bin LANG=C.UTF-8 \
  HOME=/home/hula USER=hula PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 "$@"; }

step "scripts/setup-debian.sh (run mode) as root"
in_root bash /opt/hulahoops-src/scripts/setup-debian.sh
in_root bash /opt/hulahoops-src/scripts/setup-debian.sh  # the second run finds everything present
echo "$(in_root dpkg-query -W -f='${Status}\n' | grep -c 'install ok installed') packages installed in the chroot"
step_done

step "the user's copy of the source"
in_root useradd --create-home --shell /bin/bash hula
uid=$(in_root id -u hula)
gid=$(in_root id -g hula)
cp -a "$root/opt/hulahoops-src" "$root/home/hula/hulahoops"
chroot "$root" chown -R hula:hula /home/hula/hulahoops
step_done

step "python3 -m venv --system-site-packages v && v/bin/pip install --no-build-isolation ."
as_user sh -c "cd /home/hula/hulahoops && python3 -m venv --system-site-packages /home/hula/v && \
  CMAKE_BUILD_PARALLEL_LEVEL=$jobs nice -n 19 /home/hula/v/bin/pip install --no-build-isolation ."
step_done

step "docs/python.md, docs/howto/*.md and README.md python blocks in the venv"
cat >"$root/home/hula/run_docs.py" <<'EOF'
import os, re, shutil, sys, tempfile
import hulahoops as hh
source = sys.argv[1]
print("hulahoops", hh.__version__, "from", hh.__file__, "; exchange helper", hh.exchange_helper())
assert not hh.__file__.startswith(source), hh.__file__
ran = 0
for page in [os.path.join(source, "docs", "python.md"), os.path.join(source, "README.md")] + sorted(
        os.path.join(source, "docs", "howto", p) for p in os.listdir(os.path.join(source, "docs", "howto"))
        if p.endswith(".md")):
    work = tempfile.mkdtemp()
    shutil.copytree(os.path.join(source, "examples"), os.path.join(work, "examples"))
    os.chdir(work)
    blocks = re.findall(r"```python\n(.*?)```", open(page, encoding="utf-8").read(), flags=re.S)
    namespace = {}
    for i, block in enumerate(blocks):
        exec(compile(block, f"{os.path.relpath(page, source)} block {i}", "exec"), namespace)
    print(f"{os.path.relpath(page, source)}: {len(blocks)} blocks ran")
    ran += len(blocks)
assert ran >= 10, ran
EOF
as_user sh -c "cd /home/hula && /home/hula/v/bin/python run_docs.py /home/hula/hulahoops"
step_done

step "pip wheel --no-build-isolation --no-deps -w dist ."
as_user sh -c "cd /home/hula/hulahoops && CMAKE_BUILD_PARALLEL_LEVEL=$jobs nice -n 19 \
  /home/hula/v/bin/pip wheel --no-build-isolation --no-deps -w /home/hula/dist ."
in_root ls -l /home/hula/dist
step_done

step "the wheel in a second venv, with the source and build tree moved away"
mv "$root/home/hula/hulahoops" "$root/home/hula/hulahoops.away"
cat >"$root/home/hula/check_wheel.py" <<'EOF'
import math, os, sys
import numpy as np
import hulahoops as hh
print("hulahoops", hh.__version__, "from", hh.__file__)
assert hh.__file__.startswith(sys.prefix), (hh.__file__, sys.prefix)
helper = hh.exchange_helper()
print("exchange helper", helper)
assert helper.startswith(os.path.dirname(hh.__file__)), helper
# The parabola y = 4 t (1 - t), x = 2 t as a quadratic Bezier curve: a closed form to the last bits.
parabola = hh.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [[0, 0], [1, 2], [2, 0]])
t = np.linspace(0, 1, 101)
assert np.allclose(parabola(t), np.column_stack([2 * t, 4 * t * (1 - t)]), rtol=0, atol=1e-15)
# The quarter circle: radius 1 at every parameter, length pi/2.
w = math.sqrt(0.5)
arc = hh.NurbsCurve(2, [0, 0, 0, 1, 1, 1], [[1, 0], [1, 1], [0, 1]], weights=[1, w, 1])
assert np.allclose(np.hypot(*arc(t).T), 1.0, rtol=0, atol=1e-15)
assert abs(arc.arc_length() - math.pi / 2) < 1e-12
# STEP through the helper the wheel ships: B-spline curves come back exactly.
cubic = hh.NurbsCurve(3, [0, 0, 0, 0, 0.5, 1, 1, 1, 1], [[0, 0], [1, 2], [2, -1], [3, 1], [4, 0]])
hh.write([cubic, parabola], "curves.step", names=["cubic", "parabola"])
back = hh.read("curves.step")
assert len(back) == 2
assert np.allclose(back[0].control_points[:, :2], cubic.control_points, rtol=0, atol=1e-12), back[0].control_points
assert np.allclose(back[1].control_points[:, :2], parabola.control_points, rtol=0, atol=1e-12), back[1].control_points
# The pagmo plugin the wheel ships: sphere's minimum 0 at the origin.
de = hh.optimise("sphere", "pagmo-de", dimension=3, population=20, generations=60, seed=9)
assert de.f[0] < 1e-2 and abs(float(np.sum(de.x ** 2)) - de.f[0]) <= 1e-15, (de.x, de.f)
print("wheel check: parabola, circle, STEP round trip of 2 curves, pagmo-de f =", de.f[0])
EOF
as_user sh -c "python3 -m venv --system-site-packages /home/hula/v2 && \
  /home/hula/v2/bin/pip install --no-index /home/hula/dist/hulahoops-*.whl && \
  mkdir -p /home/hula/elsewhere && cd /home/hula/elsewhere && /home/hula/v2/bin/python ../check_wheel.py"
as_user /home/hula/v2/bin/pip show -f hulahoops | sed -n '1,3p;/^Files:/,$p'
mv "$root/home/hula/hulahoops.away" "$root/home/hula/hulahoops"
step_done

echo "fresh_debian_chroot: all steps passed in $(($(date +%s) - total_start)) s (commit $rev)"
