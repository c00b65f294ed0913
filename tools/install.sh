#!/bin/sh
# install.sh -- make install and make uninstall, with a manifest
#
#   sh tools/install.sh install DESTDIR MANIFEST < LIST
#   sh tools/install.sh uninstall DESTDIR MANIFEST
#
# install puts the files of LIST, one a line:
#   MODE SOURCE TARGET    the file SOURCE as TARGET (install -m MODE)
#   link VALUE TARGET     a symbolic link TARGET -> VALUE
# and writes MANIFEST: "file TARGET" for each, and "dir D" for each
# directory it had to make, parents first.  Paths are absolute and
# DESTDIR comes before each of them (the GNU convention of staged
# installs; the manifest names them without it).  A second install over
# the first adds to its manifest.
#
# uninstall removes the files of MANIFEST, the manifest, then the
# directories it names that are empty, children first: what install made
# and nothing else (a directory that was there before stays, a file of
# someone else's in a directory of lac's keeps that directory).
set -eu
what=${1:?usage: install.sh install|uninstall DESTDIR MANIFEST}
D=$2
M=$3

# mkdirs DIR: make DIR and its missing parents, "dir" lines for them
mkdirs () {
  [ -d "$D$1" ] && return 0
  case $1 in */*/*) mkdirs "${1%/*}" ;; esac
  mkdir "$D$1"
  echo "dir $1" >> "$tmp"
}

# the manifest, the old one and then the new lines (also after a failure:
# what was put is removed by uninstall)
record () {
  { [ -f "$D$M" ] && cat "$D$M"; cat "$tmp"; } | awk '!seen[$0]++' > "$tmp.all"
  cat "$tmp.all" > "$D$M"
  rm -f "$tmp" "$tmp.all"
}

case $what in
install)
  tmp=$(mktemp)
  trap record EXIT
  mkdir -p "$D/"
  mkdirs "${M%/*}"
  while read -r mode src dst; do
    mkdirs "${dst%/*}"
    if [ "$mode" = link ]; then ln -sf "$src" "$D$dst"
    else install -m "$mode" "$src" "$D$dst"; fi
    echo "file $dst" >> "$tmp"
  done
  echo "lac: $(grep -c '^file' "$tmp") files installed, listed in $D$M"
  ;;
uninstall)
  if [ ! -f "$D$M" ]; then
    echo "lac: $D$M: no such file (nothing of lac's installed there)" >&2
    exit 1
  fi
  dirs=$(sed -n 's/^dir //p' "$D$M" |
         awk '{ l[NR] = $0 } END { for (i = NR; i > 0; i--) print l[i] }')
  sed -n 's/^file //p' "$D$M" | while read -r f; do rm -f "$D$f"; done
  rm -f "$D$M"
  [ -z "$dirs" ] || printf '%s\n' "$dirs" | while read -r d; do
    [ -d "$D$d" ] || continue
    rmdir "$D$d" 2>/dev/null || echo "lac: kept $D$d (not empty)"
  done
  ;;
*)
  echo "usage: install.sh install|uninstall DESTDIR MANIFEST" >&2; exit 2 ;;
esac
